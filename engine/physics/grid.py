"""Bounding boxes: a uniform grid over a fixed set of them, and every overlapping pair of a set.

`BoxGrid` files each box under every cell it touches, once, when it is built (the walls of a world,
or this substep's windmill arms); a query looks only at the cells its own box touches, so the work
grows with the neighbourhood, not with the number of boxes. Neither can blow up: a box spanning more
than MAX_CELLS cells is kept on a short list every query checks, and a query spanning more cells
than there are boxes checks the boxes instead. `box_pairs` pairs a set of boxes (the bodies, which
move every substep): a few swept along x, a crowd filed afresh in a grid of its own. Between substeps
the bodies keep their walls (`FatBoxes`) and their pairs (`FatPairs`) while their boxes stay inside
fat ones, so the grid is asked, and a crowd searched, only when a box leaves.

Boxes are rows (min x, min y, max x, max y) of a float64 array; answers are row indices, ascending.
"""

from __future__ import annotations

import math

import numpy as np

from polygolf.engine.physics.body import ASLEEP, COLUMNS, INV_MASS, SPIN, VX, VY, X0, Y0, X, Y
from polygolf.engine.physics.jit import inlined_leaf, kernel, leaf_kernel, warm_up

MAX_CELLS = 256  # cells one box may be filed under
MAX_GRID = 1 << 20  # cells in a grid; a coarser cell is taken beyond it
FAT_MARGIN = 0.25  # m: a body's walls are looked up for its box grown by this, and kept while it stays inside
FAT_KEEP = 32  # walls kept a body; a body with more near it asks the grid every time
PAIR_FAT_MARGIN = 0.05  # m: bodies' boxes grown by this for the pairs kept between substeps (`FatPairs`)


@inlined_leaf
def overlaps(box: np.ndarray, boxes: np.ndarray, i: int) -> bool:
    """Whether `box` and row i of `boxes` overlap (a row by index: taking it as a view of its own
    costs more than the test)."""
    return (box[0] <= boxes[i, 2]) & (boxes[i, 0] <= box[2]) & (box[1] <= boxes[i, 3]) & (boxes[i, 1] <= box[3])


@inlined_leaf
def rows_overlap(boxes: np.ndarray, i: int, j: int) -> bool:
    return boxes[i, 0] <= boxes[j, 2] and boxes[j, 0] <= boxes[i, 2] and boxes[i, 1] <= boxes[j, 3] \
        and boxes[j, 1] <= boxes[i, 3]


@leaf_kernel
def _cell(value: float, origin: float, inv: float, count: int) -> int:
    """The cell index of a coordinate, clamped to the grid (every filed box lies inside it; a
    coordinate beyond it, infinite or not a number is clamped too)."""
    f = (value - origin) * inv
    if not f >= 0.0:
        return 0
    if f >= count:
        return count - 1
    return int(f)


@leaf_kernel
def _cell_range(box: np.ndarray, x0: float, y0: float, inv: float, nx: int, ny: int) -> tuple[int, int, int, int]:
    """The cells a box touches."""
    return (_cell(box[0], x0, inv, nx), _cell(box[1], y0, inv, ny),
            _cell(box[2], x0, inv, nx), _cell(box[3], y0, inv, ny))


@kernel
def _file(boxes: np.ndarray, x0: float, y0: float, inv: float, nx: int, ny: int
          ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(cell_first, cell_items, large): box indices by cell, in compressed rows, and the boxes too
    large to file cell by cell."""
    counts = np.zeros(nx * ny + 1, dtype=np.int64)
    large = np.zeros(len(boxes), dtype=np.bool_)
    _count_cells(boxes, x0, y0, inv, nx, ny, counts, large)
    first = np.cumsum(counts)
    items = np.empty(first[-1], dtype=np.int64)
    fill = first[:-1].copy()
    _fill_cells(boxes, x0, y0, inv, nx, ny, large, fill, items)
    return first, items, np.nonzero(large)[0]


@leaf_kernel
def _count_cells(boxes: np.ndarray, x0: float, y0: float, inv: float, nx: int, ny: int, counts: np.ndarray,
                 large: np.ndarray) -> None:
    """`_file`'s first pass: how many boxes each cell holds (counts[cell + 1]), and which are too large."""
    for i in range(len(boxes)):
        cx0, cy0, cx1, cy1 = _cell_range(boxes[i], x0, y0, inv, nx, ny)
        if (cx1 - cx0 + 1) * (cy1 - cy0 + 1) > MAX_CELLS:
            large[i] = True
            continue
        for cy in range(cy0, cy1 + 1):
            for cx in range(cx0, cx1 + 1):
                counts[cy * nx + cx + 1] += 1


@leaf_kernel
def _fill_cells(boxes: np.ndarray, x0: float, y0: float, inv: float, nx: int, ny: int, large: np.ndarray,
                fill: np.ndarray, items: np.ndarray) -> None:
    """`_file`'s second pass: each box into the rows of the cells it touches (fill: each cell's next row)."""
    for i in range(len(boxes)):
        if large[i]:
            continue
        cx0, cy0, cx1, cy1 = _cell_range(boxes[i], x0, y0, inv, nx, ny)
        for cy in range(cy0, cy1 + 1):
            for cx in range(cx0, cx1 + 1):
                items[fill[cy * nx + cx]] = i
                fill[cy * nx + cx] += 1


@leaf_kernel
def overlapping(boxes: np.ndarray, x0: float, y0: float, inv: float, nx: int, ny: int, cell_first: np.ndarray,
           cell_items: np.ndarray, large: np.ndarray, box: np.ndarray, seen: np.ndarray, out: np.ndarray) -> int:
    """Indices of the boxes overlapping `box` into `out`, ascending; returns how many. `seen` (one
    flag per box, all False) is left all False."""
    count = 0
    if len(boxes) == 0:
        return 0
    cx0, cy0, cx1, cy1 = _cell_range(box, x0, y0, inv, nx, ny)
    if (cx1 - cx0 + 1) * (cy1 - cy0 + 1) > len(boxes):  # wider than there are boxes: each box once
        for i in range(len(boxes)):
            if overlaps(box, boxes, i):
                out[count] = i
                count += 1
        return count
    several = cx1 > cx0 or cy1 > cy0  # a box filed under several of these cells could come up twice
    for cy in range(cy0, cy1 + 1):
        for cx in range(cx0, cx1 + 1):
            cell = cy * nx + cx
            for k in range(cell_first[cell], cell_first[cell + 1]):
                i = cell_items[k]
                if not seen[i] and overlaps(box, boxes, i):
                    seen[i] = several
                    out[count] = i
                    count += 1
    for i in large:
        if overlaps(box, boxes, i):
            out[count] = i
            count += 1
    if several:
        for k in range(count):
            seen[out[k]] = False
    _sort_few(out, 0, count)
    return count


@leaf_kernel
def _sort_few(values: np.ndarray, start: int, stop: int) -> None:
    """values[start:stop] in ascending order: by insertion while they are few (a query's usual answer,
    mostly in order already), else by heapsort (in place: a leaf makes no array)."""
    count = stop - start
    if count > 16:
        for root in range(count // 2 - 1, -1, -1):
            _sift_down(values, start, root, count)
        for end in range(count - 1, 0, -1):
            values[start], values[start + end] = values[start + end], values[start]
            _sift_down(values, start, 0, end)
        return
    for a in range(start + 1, stop):
        v = values[a]
        b = a - 1
        while b >= start and values[b] > v:
            values[b + 1] = values[b]
            b -= 1
        values[b + 1] = v


@leaf_kernel
def _sift_down(values: np.ndarray, start: int, root: int, end: int) -> None:
    """Heapsort's step: values[start + root] down the max-heap values[start:start + end] to its place."""
    while 2 * root + 1 < end:
        child = 2 * root + 1
        if child + 1 < end and values[start + child] < values[start + child + 1]:
            child += 1
        if values[start + root] >= values[start + child]:
            return
        values[start + root], values[start + child] = values[start + child], values[start + root]
        root = child


class FatBoxes:
    """Each body's walls near it, kept between substeps (Box2D's fat boxes): the grid is asked for
    a body's box grown by FAT_MARGIN and the answer kept; while the body's box stays inside that fat
    box, the walls its box meets are among those kept, and are picked from them (`walls_near`).
    Continuous collision (the swept box) and the broadphase (the box with the contact margin) share
    them, so a moving body asks the grid once every few substeps instead of twice each. Rows are a
    `body.BodyStore`'s; kept until the store's array changes."""

    __slots__ = ("state", "fat", "walls")

    def __init__(self) -> None:
        self.state: np.ndarray | None = None
        self.fat, self.walls = _no_fat_boxes(0, 0)

    def of(self, state: np.ndarray, walls: int) -> tuple[np.ndarray, np.ndarray]:
        """(fat boxes, kept walls: a count, then the walls) for the rows of `state`, emptied if the
        store was gathered again."""
        if state is not self.state:
            self.state = state
            self.fat, self.walls = _no_fat_boxes(len(state), min(walls, FAT_KEEP))
        return self.fat, self.walls


def _no_fat_boxes(bodies: int, keep: int) -> tuple[np.ndarray, np.ndarray]:
    """Nothing kept yet: every fat box empty (inverted), so the first look asks the grid."""
    fat = np.empty((bodies, 4))
    fat[:, :2], fat[:, 2:] = np.inf, -np.inf
    return fat, np.zeros((bodies, 1 + keep), dtype=np.int64)


@inlined_leaf
def walls_near(fat: np.ndarray, walls: np.ndarray, k: int, box: np.ndarray, boxes: np.ndarray, out: np.ndarray) -> int:
    """The grid's boxes (`boxes`) that `box` of body row k overlaps, ascending, into `out`, picked
    from those kept for its fat box (`FatBoxes`); -1 if `box` is not inside it (`look_up_walls`
    then). Few arrays pass: a call passing many costs more than this work."""
    inside = (fat[k, 0] <= box[0]) & (fat[k, 1] <= box[1]) & (box[2] <= fat[k, 2]) & (box[3] <= fat[k, 3])
    count = 0
    for m in range(1, walls[k, 0] + 1 if inside else 1):  # ascending, as kept
        i = walls[k, m]
        if overlaps(box, boxes, i):
            out[count] = i
            count += 1
    return count if inside else -1


@leaf_kernel
def look_up_walls(grid: tuple, fat: np.ndarray, walls: np.ndarray, k: int, box: np.ndarray, wide: np.ndarray,
                  seen: np.ndarray, scratch: np.ndarray, out: np.ndarray) -> int:
    """`walls_near` when `box` has left body row k's fat box: the grid is asked for the box grown by
    FAT_MARGIN (into `wide`), the answer kept, and the walls `box` meets picked from it (the same
    answer as asking for `box`, in the same order). A body with more than the table keeps near it
    asks for `box`."""
    wide[0], wide[1] = box[0] - FAT_MARGIN, box[1] - FAT_MARGIN
    wide[2], wide[3] = box[2] + FAT_MARGIN, box[3] + FAT_MARGIN
    n = overlapping(*grid, wide, seen, scratch)
    if n > walls.shape[1] - 1:
        fat[k, 0], fat[k, 1], fat[k, 2], fat[k, 3] = np.inf, np.inf, -np.inf, -np.inf
        return overlapping(*grid, box, seen, out)
    fat[k, 0], fat[k, 1], fat[k, 2], fat[k, 3] = wide[0], wide[1], wide[2], wide[3]
    walls[k, 0] = n
    for m in range(n):
        walls[k, 1 + m] = scratch[m]
    return walls_near(fat, walls, k, box, grid[0], out)


@kernel
def bodies_near(state: np.ndarray, rows: np.ndarray, radius: np.ndarray, margin: float, grid: tuple,
                fat_boxes: tuple, seen: np.ndarray, scratch: np.ndarray, near: np.ndarray, first: np.ndarray,
                found: np.ndarray) -> tuple[np.ndarray, int]:
    """For the awake dynamic bodies among `rows` of a `body.BodyStore` state (bounding radii
    `radius`, grown by `margin`), the grid's boxes each one's box overlaps (`grid`: a
    `BoxGrid.arrays`, asked through the bodies' `FatBoxes.arrays`), into the caller's arrays (kept
    from substep to substep: nothing is allocated unless `found` must grow): the bodies that have
    any (indices into `rows`) into `near`, their boxes in compressed rows (`first`, `found`).
    `seen` and `scratch`: the grid query's, one row per box; `near` and `first` need len(rows)
    and len(rows) + 1 rows. Returns `found` (grown if it had to) and how many bodies have boxes
    near."""
    both = np.empty((2, 4))
    q, bodies, total, waiting = start_near(state, rows, radius, margin, grid, fat_boxes, seen, scratch, near, first,
                                           found, both)
    return grow_near(state, rows, radius, margin, grid, fat_boxes, seen, scratch, near, first, found, both, q, bodies,
                     total, waiting)


@kernel
def grow_near(state: np.ndarray, rows: np.ndarray, radius: np.ndarray, margin: float, grid: tuple,
              fat_boxes: tuple, seen: np.ndarray, scratch: np.ndarray, near: np.ndarray, first: np.ndarray,
              found: np.ndarray, both: np.ndarray, q: int, bodies: int, total: int, waiting: int
              ) -> tuple[np.ndarray, int]:
    """`bodies_near` from where `start_near` (or `_fill_near`) stopped, at body q with `waiting`
    boxes in `scratch` and no room for them: `found` grows (twice as large and room for those) and
    the search goes on, as often as it must. Returns `found` and how many bodies have boxes near."""
    while waiting:
        grown = np.empty(2 * len(found) + waiting, dtype=np.int64)
        grown[:total] = found[:total]
        found = grown
        q, bodies, total = _put_near(scratch, waiting, near, first, found, q, bodies, total)
        q, bodies, total, waiting = _fill_near(state, rows, radius, margin, grid, fat_boxes, seen, scratch, near,
                                               first, found, both, q, bodies, total)
    return found, bodies


@leaf_kernel
def start_near(state: np.ndarray, rows: np.ndarray, radius: np.ndarray, margin: float, grid: tuple,
               fat_boxes: tuple, seen: np.ndarray, scratch: np.ndarray, near: np.ndarray, first: np.ndarray,
               found: np.ndarray, both: np.ndarray) -> tuple[int, int, int, int]:
    """`bodies_near`'s search from the first body, as far as `found` has room (`_fill_near`; `both`:
    room for two boxes). With nothing waiting (the last answer), `near`, `first` and `found` hold
    the whole answer, and the second number is how many bodies have boxes near."""
    first[0] = 0
    return _fill_near(state, rows, radius, margin, grid, fat_boxes, seen, scratch, near, first, found, both, 0, 0, 0)


@leaf_kernel
def _fill_near(state: np.ndarray, rows: np.ndarray, radius: np.ndarray, margin: float, grid: tuple,
               fat_boxes: tuple, seen: np.ndarray, scratch: np.ndarray, near: np.ndarray, first: np.ndarray,
               found: np.ndarray, both: np.ndarray, q: int, bodies: int, total: int) -> tuple[int, int, int, int]:
    """`bodies_near`'s work from body q on, until a body's boxes do not fit in `found`: returns
    where it got to (q, bodies, total) and how many boxes wait in `scratch` for room (0: done)."""
    box, wide = both[0], both[1]
    fat, walls = fat_boxes
    boxes = grid[0]
    while q < len(rows):
        k = rows[q]
        if state[k, ASLEEP] != 0.0 or state[k, INV_MASS] == 0.0:
            q += 1
            continue
        r = radius[q] + margin
        box[0], box[1], box[2], box[3] = state[k, X] - r, state[k, Y] - r, state[k, X] + r, state[k, Y] + r
        n = walls_near(fat, walls, k, box, boxes, scratch)
        if n < 0:
            n = look_up_walls(grid, fat, walls, k, box, wide, seen, scratch, scratch)
        if n == 0:
            q += 1
            continue
        if total + n > len(found):
            return q, bodies, total, n
        q, bodies, total = _put_near(scratch, n, near, first, found, q, bodies, total)
    return q, bodies, total, 0


@inlined_leaf
def _put_near(scratch: np.ndarray, n: int, near: np.ndarray, first: np.ndarray, found: np.ndarray, q: int,
              bodies: int, total: int) -> tuple[int, int, int]:
    """Body q's n boxes (from `scratch`) after the first `total` of `found`; where `bodies_near` goes on."""
    for m in range(n):
        found[total + m] = scratch[m]
    total += n
    near[bodies] = q
    bodies += 1
    first[bodies] = total
    return q + 1, bodies, total


@kernel
def _add_pair(pairs: np.ndarray, count: int, i: int, j: int) -> np.ndarray:
    """(min, max) of i and j into row `count` of `pairs`, grown (doubled) if full; the array to use."""
    if count == len(pairs):
        grown = np.empty((2 * len(pairs), 2), dtype=np.int64)
        grown[:count] = pairs[:count]
        pairs = grown
    pairs[count, 0], pairs[count, 1] = min(i, j), max(i, j)
    return pairs


@kernel
def _sorted_pairs(pairs: np.ndarray, count: int, n: int) -> np.ndarray:
    """The first `count` pairs (i, j) of indices below n, each once, sorted: counted out by i, then
    each i's few j sorted (`_sort_few`), rather than a sort of all of them."""
    first = np.zeros(n + 1, dtype=np.int64)
    seconds, out = np.empty(count, dtype=np.int64), np.empty((count, 2), dtype=np.int64)
    _count_out(pairs, count, first, seconds, out)
    return out


@leaf_kernel
def _count_out(pairs: np.ndarray, count: int, first: np.ndarray, seconds: np.ndarray, out: np.ndarray) -> None:
    """`_sorted_pairs`' work (first: n + 1 zeros; seconds, out: room for the pairs' j and the pairs)."""
    for g in range(count):
        first[pairs[g, 0] + 1] += 1
    for i in range(1, len(first)):
        first[i] += first[i - 1]
    for g in range(count):  # each j after those of its i so far; first[i] moves on as it fills
        i = pairs[g, 0]
        seconds[first[i]] = pairs[g, 1]
        first[i] += 1
    start = 0
    for i in range(len(first) - 1):  # first[i] is now where i's pairs end
        stop = first[i]
        _sort_few(seconds, start, stop)
        for g in range(start, stop):
            out[g, 0], out[g, 1] = i, seconds[g]
        start = stop


@kernel
def _decoded(keys: np.ndarray, base: int) -> np.ndarray:
    """The pairs (key // base, key % base) of `keys`, in their order."""
    out = np.empty((len(keys), 2), dtype=np.int64)
    for g in range(len(keys)):
        out[g, 0], out[g, 1] = keys[g] // base, keys[g] % base
    return out


@kernel
def _swept_pairs(boxes: np.ndarray, active: np.ndarray) -> np.ndarray:
    """`box_pairs` by a sweep along x (few boxes, or some not finite)."""
    order = np.argsort(boxes[:, 0], kind="mergesort")
    pairs = np.empty((16, 2), dtype=np.int64)
    count = 0
    for a in range(len(order)):
        i = order[a]
        for b in range(a + 1, len(order)):
            j = order[b]
            if boxes[j, 0] > boxes[i, 2]:
                break
            if (active[i] or active[j]) and boxes[j, 1] <= boxes[i, 3] and boxes[i, 1] <= boxes[j, 3]:
                pairs = _add_pair(pairs, count, i, j)
                count += 1
    return _sorted_pairs(pairs, count, len(boxes))


@kernel
def _hashed_pairs(boxes: np.ndarray, active: np.ndarray, cell: float) -> np.ndarray:
    """`box_pairs` through a uniform grid of cells a little larger than the largest box: each box is
    filed once, under the cell of its lower-left corner, so two boxes that overlap are filed in the
    same cell or in neighbouring ones; each cell is paired with itself and with four of its
    neighbours (right, above left, above, above right), so each two cells once."""
    x0, y0 = boxes[:, 0].min(), boxes[:, 1].min()
    width, height = boxes[:, 2].max() - x0, boxes[:, 3].max() - y0
    cell *= 1.0 + 1e-6  # larger than any box, however the cell indices round
    while (width / cell + 1.0) * (height / cell + 1.0) > MAX_GRID:
        cell *= 2.0
    inv = 1.0 / cell
    nx, ny = int(width * inv) + 1, int(height * inv) + 1
    counts = np.zeros(nx * ny + 1, dtype=np.int64)
    corner = np.empty(len(boxes), dtype=np.int64)
    _corner_cells(boxes, x0, y0, inv, nx, ny, corner, counts)
    cell_first = np.cumsum(counts)
    cell_items = np.empty(len(boxes), dtype=np.int64)
    _file_by_corner(corner, cell_first[:-1].copy(), cell_items)
    pairs = np.empty((max(16, 4 * len(boxes)), 2), dtype=np.int64)
    count = _neighbour_pairs(boxes, active, nx, ny, corner, cell_first, cell_items, pairs)
    while count < 0:  # more pairs than room: again with twice the room
        pairs = np.empty((2 * len(pairs), 2), dtype=np.int64)
        count = _neighbour_pairs(boxes, active, nx, ny, corner, cell_first, cell_items, pairs)
    return _sorted_pairs(pairs, count, len(boxes))


@leaf_kernel
def _corner_cells(boxes: np.ndarray, x0: float, y0: float, inv: float, nx: int, ny: int, corner: np.ndarray,
                  counts: np.ndarray) -> None:
    """Each box's cell (that of its lower-left corner) into `corner`, and how many each cell holds
    into counts[cell + 1]."""
    for i in range(len(boxes)):
        c = _cell(boxes[i, 1], y0, inv, ny) * nx + _cell(boxes[i, 0], x0, inv, nx)
        corner[i] = c
        counts[c + 1] += 1


@leaf_kernel
def _file_by_corner(corner: np.ndarray, fill: np.ndarray, items: np.ndarray) -> None:
    """Each box, in ascending order, into the rows of its cell (fill: each cell's next row)."""
    for i in range(len(corner)):
        items[fill[corner[i]]] = i
        fill[corner[i]] += 1


@leaf_kernel
def _neighbour_pairs(boxes: np.ndarray, active: np.ndarray, nx: int, ny: int, corner: np.ndarray,
                     cell_first: np.ndarray, cell_items: np.ndarray, pairs: np.ndarray) -> int:
    """`_hashed_pairs`' search into `pairs` (each (smaller, larger) index, unsorted); how many, or -1
    if they do not fit. Box by box (a crowd leaves most cells empty, and a pass over the cells paid
    for each): the boxes after it in its own cell, then those of four neighbours (right, above left,
    above, above right), so each two cells once."""
    count = 0
    for i in range(len(boxes)):
        c = corner[i]
        cx, cy = c % nx, c // nx
        for n in range(5):
            if n == 0:
                other = c
            elif n == 1:
                if cx + 1 >= nx:
                    continue
                other = c + 1
            else:
                dx = n - 3  # above left, above, above right
                if cy + 1 >= ny or not 0 <= cx + dx < nx:
                    continue
                other = c + nx + dx
            for b in range(cell_first[other], cell_first[other + 1]):
                j = cell_items[b]
                if n == 0 and j <= i:
                    continue
                if (active[i] or active[j]) and rows_overlap(boxes, i, j):
                    if count == len(pairs):
                        return -1
                    pairs[count, 0], pairs[count, 1] = min(i, j), max(i, j)
                    count += 1
    return count


SWEEP_BELOW = 48  # fewer boxes than this: the sweep is as quick as filing them in a grid


@kernel
def box_pairs(boxes: np.ndarray, active: np.ndarray) -> np.ndarray:
    """Every pair (i, j), i < j, of overlapping boxes of which at least one is `active`, sorted.
    A crowd is filed in a grid of cells as large as its largest box (a sweep along x meets every
    box of a column); a few boxes, or boxes not all finite, are swept along x."""
    cell = 0.0
    for i in range(len(boxes)):
        w, h = boxes[i, 2] - boxes[i, 0], boxes[i, 3] - boxes[i, 1]
        if not (math.isfinite(w) and math.isfinite(h) and math.isfinite(boxes[i, 0])
                and math.isfinite(boxes[i, 1])):
            return _swept_pairs(boxes, active)
        cell = max(cell, w, h)
    if len(boxes) < SWEEP_BELOW or not cell > 0.0:
        return _swept_pairs(boxes, active)
    return _hashed_pairs(boxes, active, cell)


@kernel
def body_pairs(state: np.ndarray, rows: np.ndarray, radius: np.ndarray, grow: float, swept: bool, meet: bool,
               turning_is_active: bool, dynamic_pairs: bool, kept: tuple) -> np.ndarray:
    """Pairs (i, j) of `rows` of a `body.BodyStore` state whose boxes overlap: each body's box about
    its pose (or, `swept`, about its motion from the substep's start), its bounding radius plus
    `grow`. With `meet`, every pair of which one is active (awake and dynamic, or kinematic and
    moving; `turning_is_active`: a kinematic body that turns counts even when marked at rest), by
    `box_pairs` (or from the pairs `kept` between substeps, `FatPairs.of`: the same pairs;
    `no_fat_pairs()`: none kept), or with `dynamic_pairs` False only those with a kinematic body
    (for a caller that knows no two dynamic bodies can need it: no search at all without a
    kinematic body); without `meet`, only a kinematic body with an awake dynamic one (bodies that
    meet walls and kinematic bodies only: K balls, no K² pairs). i < j, sorted."""
    n = len(rows)
    if not (meet and dynamic_pairs):
        kinematic = 0
        for q in range(n):
            kinematic += state[rows[q], INV_MASS] == 0.0
        if kinematic == 0:  # a fan of shots on a hole without windmills, a pile: no pair to look for
            return np.zeros((0, 2), dtype=np.int64)
    boxes = np.empty((n, 4))
    active = np.zeros(n, dtype=np.bool_)
    moving = np.zeros(n, dtype=np.bool_)
    for q in range(n):
        k = rows[q]
        x, y, r = state[k, X], state[k, Y], radius[q] + grow
        x0, y0 = (state[k, X0], state[k, Y0]) if swept else (x, y)
        boxes[q, 0], boxes[q, 1] = min(x0, x) - r, min(y0, y) - r
        boxes[q, 2], boxes[q, 3] = max(x0, x) + r, max(y0, y) + r
        awake, dynamic = state[k, ASLEEP] == 0.0, state[k, INV_MASS] != 0.0
        moving[q] = awake and dynamic
        if turning_is_active:
            active[q] = moving[q] or (not dynamic and state[k, SPIN] != 0.0)
        else:
            active[q] = awake and (dynamic or state[k, VX] != 0.0 or state[k, VY] != 0.0 or state[k, SPIN] != 0.0)
    if meet and dynamic_pairs:
        if len(kept[0]) == n and n > 0:
            return kept_box_pairs(boxes, active, kept[0], kept[1], kept[2])
        return box_pairs(boxes, active)
    # A kinematic body with each dynamic one: those `box_pairs` would give (one of the two active), or
    # without `meet` those with an awake one.
    pairs = np.empty((16, 2), dtype=np.int64)
    count = 0
    for i in range(n):
        if state[rows[i], INV_MASS] != 0.0:
            continue
        for j in range(n):
            if state[rows[j], INV_MASS] != 0.0 and (moving[j] or (meet and active[i])) and rows_overlap(boxes, i, j):
                pairs = _add_pair(pairs, count, i, j)
                count += 1
    return _sorted_pairs(pairs, count, n)


def no_fat_pairs() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """`FatPairs.of` for a caller that keeps no pairs: `body_pairs` then searches every time."""
    return np.empty((0, 4)), np.empty((0, 2), dtype=np.int64), np.full(2, -1, dtype=np.int64)


class FatPairs:
    """The pairs of bodies whose fat boxes overlap, kept between substeps (as Box2D keeps a pair
    while the bodies stay inside their fat boxes): each box grown by PAIR_FAT_MARGIN, all of them
    at once when one leaves its own, so the next rebuild is as far off as the fastest body makes it.
    While every body's box stays inside its fat box, every pair whose boxes overlap is among those
    kept, and is picked from them (`kept_box_pairs`: `box_pairs`' answer) instead of searching a
    crowd every substep. Rows are those of the indices the caller passes (`Shapes.current`'s); kept
    until those change."""

    __slots__ = ("key", "fat", "pairs", "count")

    def __init__(self) -> None:
        self.key: tuple = (None, None)
        self.fat, self.pairs, self.count = no_fat_pairs()

    def of(self, state: np.ndarray, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(fat boxes, room for the pairs, (how many are kept, or -1 if none are; how many the last
        rebuild found)) for bodies `rows` of `state`: emptied if they changed, given more room if
        the last rebuild found more pairs than it had."""
        if self.key[0] is not state or self.key[1] is not rows:
            self.key = (state, rows)
            self.fat = np.empty((len(rows), 4))
            self.pairs = np.empty((4 * len(rows) + 64, 2), dtype=np.int64)
            self.count = np.array([-1, 0], dtype=np.int64)
        elif self.outgrown():
            self.pairs = np.empty((2 * int(self.count[1]), 2), dtype=np.int64)
        return self.fat, self.pairs, self.count

    def outgrown(self) -> bool:
        """Whether the last rebuild found more pairs than there is room for (until `of` is asked
        again, the pairs are searched for every substep)."""
        return bool(self.count[1] > len(self.pairs))


@kernel
def kept_box_pairs(boxes: np.ndarray, active: np.ndarray, fat: np.ndarray, kept: np.ndarray, count: np.ndarray
                   ) -> np.ndarray:
    """`box_pairs(boxes, active)`, from the pairs of fat boxes kept (`FatPairs`): the kept ones
    again (every fat box made anew) if a box is not inside its own, then those of them whose boxes
    overlap, one active. Boxes not all finite go to `box_pairs` (and nothing is kept)."""
    inside = count[0] >= 0
    for i in range(len(boxes)):
        if not (math.isfinite(boxes[i, 0]) and math.isfinite(boxes[i, 1]) and math.isfinite(boxes[i, 2])
                and math.isfinite(boxes[i, 3])):
            count[0] = -1
            return box_pairs(boxes, active)
        inside &= (fat[i, 0] <= boxes[i, 0]) & (fat[i, 1] <= boxes[i, 1]) & (boxes[i, 2] <= fat[i, 2]) \
            & (boxes[i, 3] <= fat[i, 3])
    source, total = kept, count[0]
    if not inside:
        for i in range(len(boxes)):
            fat[i, 0], fat[i, 1] = boxes[i, 0] - PAIR_FAT_MARGIN, boxes[i, 1] - PAIR_FAT_MARGIN
            fat[i, 2], fat[i, 3] = boxes[i, 2] + PAIR_FAT_MARGIN, boxes[i, 3] + PAIR_FAT_MARGIN
        source = box_pairs(fat, np.ones(len(boxes), dtype=np.bool_))
        total = len(source)
        count[0], count[1] = total, total
        if total <= len(kept):
            kept[:total] = source
        else:  # no room: these serve this substep; the caller gives more room before the next call
            count[0] = -1
    out = np.empty((total, 2), dtype=np.int64)
    found = 0
    for g in range(total):
        i, j = source[g, 0], source[g, 1]
        if (active[i] or active[j]) and rows_overlap(boxes, i, j):
            out[found, 0], out[found, 1] = i, j
            found += 1
    return out[:found]


@kernel
def by_entity(pairs: np.ndarray, ents: np.ndarray) -> np.ndarray:
    """Pairs of indices as pairs of the entities `ents` names, each (smaller, larger), sorted: one
    order, whatever order the bodies were listed in."""
    out = np.empty((len(pairs), 2), dtype=np.int64)
    top = 0
    ordered = True
    for g in range(len(pairs)):
        a, b = ents[pairs[g, 0]], ents[pairs[g, 1]]
        out[g, 0], out[g, 1] = min(a, b), max(a, b)
        top = max(top, out[g, 1])
        if g:
            ordered &= out[g - 1, 0] < out[g, 0] or (out[g - 1, 0] == out[g, 0] and out[g - 1, 1] < out[g, 1])
    if ordered:  # the entities ascend with the indices (as esper lists them): sorted already
        return out
    return _decoded(np.sort(out[:, 0] * (top + 1) + out[:, 1]), top + 1)


class BoxGrid:
    """A uniform grid over a fixed set of boxes ((n, 4) float64)."""

    def __init__(self, boxes: np.ndarray, cell_size: float) -> None:
        if not cell_size > 0.0:
            raise ValueError("cell size must be positive")
        self.boxes = np.ascontiguousarray(boxes, dtype=np.float64).reshape(-1, 4)
        if len(self.boxes):
            self.x0, self.y0 = float(self.boxes[:, 0].min()), float(self.boxes[:, 1].min())
            width = float(self.boxes[:, 2].max()) - self.x0
            height = float(self.boxes[:, 3].max()) - self.y0
        else:
            self.x0 = self.y0 = width = height = 0.0
        while (width / cell_size + 1.0) * (height / cell_size + 1.0) > MAX_GRID:
            cell_size *= 2.0
        self.cell_size = cell_size
        self.inv = 1.0 / cell_size
        self.nx, self.ny = int(width * self.inv) + 1, int(height * self.inv) + 1
        self.cell_first, self.cell_items, self.large = _file(self.boxes, self.x0, self.y0, self.inv, self.nx, self.ny)
        self._seen = np.zeros(len(self.boxes), dtype=np.bool_)
        self._out = np.empty(len(self.boxes), dtype=np.int64)
        # What a kernel needs to query the grid itself (the arguments of `overlapping` before `box`).
        self.arrays = (self.boxes, self.x0, self.y0, self.inv, self.nx, self.ny, self.cell_first, self.cell_items,
                       self.large)

    def __len__(self) -> int:
        return len(self.boxes)

    def query(self, box) -> np.ndarray:
        """Indices of the boxes overlapping `box`, ascending."""
        count = overlapping(*self.arrays, np.asarray(box, dtype=np.float64), self._seen, self._out)
        return self._out[:count].copy()


@warm_up("grid")
def _warm() -> None:
    boxes = np.array([[0.0, 0.0, 1.0, 1.0], [0.5, 0.5, 2.0, 2.0], [-500.0, -500.0, 500.0, -400.0]])
    grid = BoxGrid(boxes, 1.0)
    grid.query((0.2, 0.2, 0.6, 0.6))
    state = np.zeros((1, len(COLUMNS)))
    state[0, INV_MASS] = 1.0
    bodies_near(state, np.zeros(1, dtype=np.int64), np.ones(1), 0.01, grid.arrays, FatBoxes().of(state, len(grid)),
                np.zeros(3, dtype=np.bool_), np.empty(3, dtype=np.int64), np.empty(1, dtype=np.int64),
                np.empty(2, dtype=np.int64), np.empty(1, dtype=np.int64))
    box_pairs(boxes, np.ones(3, dtype=np.bool_))
    by_entity(np.array([[1, 0]], dtype=np.int64), np.array([5, 3], dtype=np.int64))
    for meet in (True, False):
        body_pairs(state, np.zeros(1, dtype=np.int64), np.ones(1), 0.01, meet, meet, meet, meet, no_fat_pairs())
    fat_pairs = FatPairs()
    body_pairs(state, np.zeros(1, dtype=np.int64), np.ones(1), 0.01, False, True, False, True,
               fat_pairs.of(state, np.zeros(1, dtype=np.int64)))
