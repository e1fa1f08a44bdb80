import math

import esper
import numpy as np

from polygolf.engine.components import Body, Collider
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.body import ANGLE, ANGLE0, ASLEEP, INV_MASS, X0, Y0, X, Y
from polygolf.engine.physics.collide import max_separation
from polygolf.engine.physics.geometry import pose_piece
from polygolf.engine.physics.grid import body_pairs, no_fat_pairs, overlapping
from polygolf.engine.physics.jit import counted_kernel, kernel, leaf_kernel
from polygolf.engine.physics.motion import pose_at, rewind
from polygolf.engine.physics.settings import CONTACT_MARGIN, LINEAR_SLOP, TOI_TARGET
from polygolf.engine.physics.toi import body_pair_hits, first_wall_hits, toi_work


class CCDProcessor(esper.Processor):
    """Continuous collision: a body whose motion this substep would carry it into or through a wall,
    or into or through another body, is moved back to its time of impact; the discrete contact that
    follows bounces it, and the time the motion lost is made up in the next substep
    (`BodyScratch.lag`), so a fast body that bounces ends up where it should rather than a substep
    behind. Of two bodies that meet, both go back to that time.

    A kinematic body (a windmill) goes back too when it would drive the body it meets into a wall that
    body lies against: it would crush it, so it stalls at the impact, standing still for the rest of
    the substep, and turns on once the ball has got out of the way (or been shot away)."""

    name = "ccd"

    def __init__(self, res: Resources) -> None:
        self.statics, self.stats, self.config = res.statics, res.stats, res.config
        walls = len(res.statics.grid)
        self._seen, self._found = np.zeros(walls, dtype=np.bool_), np.empty(walls, dtype=np.int64)
        self.shapes, self.bodies, self.fat_boxes = res.shapes, res.bodies, res.fat_boxes
        self._hits = np.empty(0)  # each body's time of impact this substep, kept between substeps
        self._boxes = np.empty((2, 4))  # a body's swept box and its grown box (the grid query's)
        self._work: tuple = ()  # the time of impact's scratch, for the widest piece of a body or a wall
        self._table = None  # the shape table it is for
        self._no_kept = no_fat_pairs()  # its pair sweep keeps no pairs between substeps (made once)

    def inputs(self) -> tuple:
        """What `sweep` reads besides the state, the shapes, the walls and the fat boxes: the grid
        query's scratch, the times of impact's array and scratch, room for two boxes, whether
        there are pairs to sweep, whether bodies meet each other and no kept pairs."""
        bodies = esper.get_components(Body, Collider)
        _, table, rows = self.shapes.current(self.bodies, esper.get_component(Body), bodies)
        if len(self._hits) != len(rows):
            self._hits = np.empty(len(rows))
        if table is not self._table:
            widest = max(np.diff(table.pieces.first).max(initial=0), np.diff(self.statics.pieces.first).max(initial=0))
            self._work, self._table = toi_work(int(widest)), table
        return (self._seen, self._found, self._hits, self._work, self._boxes, len(bodies) > 1,
                self.config.collide_bodies, self._no_kept, self.config.sweep_bodies)

    def process(self) -> None:
        inputs = self.inputs()  # first: it gathers the state
        state = self.bodies.state
        self.stats.toi_hits += sweep(state, self.shapes.packed, self.statics.packed,
                                     self.fat_boxes.of(state, len(self._seen)), inputs)


@leaf_kernel
def sweep(state: np.ndarray, shapes: tuple, walls: tuple, fat_boxes: tuple, inputs: tuple) -> int:
    """The stage on a store's state (`Shapes.packed`, `StaticWorld.packed`, `FatBoxes.of`); returns
    how many bodies went back. (A leaf: a run of stages hands it its tuples without counting a
    reference to each array in them, every substep; `_body_hits` counts those it takes itself.)"""
    moved, count = _sweep_walls(state, shapes, walls, fat_boxes, inputs)
    if moved and inputs[5]:  # bodies that stepped, and several of them
        count += _body_hits(state, shapes, walls, inputs)
    return _rewind_hits(state, shapes, inputs) if count else 0


@leaf_kernel
def _sweep_walls(state: np.ndarray, shapes: tuple, walls: tuple, fat_boxes: tuple, inputs: tuple) -> tuple[bool, int]:
    """Every body against the walls its motion sweeps (`toi.first_wall_hits`)."""
    lv, ln, first, reach, body_first, rows, radius, _, _, _, _ = shapes
    (wv, wn, wfirst, internal, hidden), _, _, _, _, grid = walls
    seen, found, hits, work, boxes, _, _, _, _ = inputs
    # No pair can need sweeping while no body steps half the linear slop.
    return first_wall_hits(lv, ln, first, reach, body_first, state, rows, radius, LINEAR_SLOP, grid, fat_boxes, seen,
                           found, wv, wn, wfirst, internal, hidden, TOI_TARGET, 0.25 * LINEAR_SLOP, LINEAR_SLOP,
                           0.5 * LINEAR_SLOP, hits, work, boxes)


@leaf_kernel
def _rewind_hits(state: np.ndarray, shapes: tuple, inputs: tuple) -> int:
    """Each body back to its time of impact (`motion.rewind`)."""
    return rewind(state, shapes[5], inputs[2])


@counted_kernel
def _body_hits(state: np.ndarray, shapes: tuple, walls: tuple, inputs: tuple) -> int:
    """Pairs of bodies whose swept boxes overlap and that move fast relative to each other: each
    one's earliest impact goes into the hits (by its index in the rows); a windmill's arm that would
    crush the ball it meets stalls too. Returns how many pairs hit."""
    lv, ln, first, reach, body_first, rows, radius, thickness, _, ents, _ = shapes
    (wv, wn, wfirst, _, _), _, _, _, _, grid = walls
    seen, found, hits, _, _, _, meet, no_kept, sweep_all = inputs
    pairs = body_pairs(state, rows, radius, TOI_TARGET, True, meet, True,
                       meet and _dynamic_pairs_may_step_far(state, rows, radius, thickness, sweep_all), no_kept)
    # A is the smaller entity, as in the contact table. The rows follow esper's sets, whose order
    # changes with the other entities (with K balls the windmill's row came first): a pair's impact,
    # rounded one way or the other, would then differ between a shot alone and the same shot among K.
    for g in range(len(pairs)):
        if ents[pairs[g, 0]] > ents[pairs[g, 1]]:
            pairs[g, 0], pairs[g, 1] = pairs[g, 1], pairs[g, 0]
    arm_hits = np.empty(len(pairs))
    count = body_pair_hits(lv, ln, first, reach, body_first, pairs, state, rows, radius, thickness, meet, sweep_all,
                           LINEAR_SLOP, TOI_TARGET, 0.25 * LINEAR_SLOP, LINEAR_SLOP, hits, arm_hits)
    if sweep_all:  # (also for a wall's impact alone: the ball pushing the one it put back)
        _together(state, rows, radius, pairs, hits)
    if count == 0:
        return 0
    for g in range(len(pairs)):
        hit = arm_hits[g]
        if hit >= 1.0:
            continue
        a, b = pairs[g, 0], pairs[g, 1]
        arm, ball = (a, b) if state[rows[a], INV_MASS] == 0.0 else (b, a)
        if _pinched(lv, ln, first, body_first, state, rows, radius, arm, ball, hit, grid, seen, found, wv, wn, wfirst):
            hits[arm] = min(hits[arm], hit)
    return count


@leaf_kernel
def _together(state: np.ndarray, rows: np.ndarray, radius: np.ndarray, pairs: np.ndarray, hits: np.ndarray) -> None:
    """Awake dynamic bodies within the contact margin of each other (their bounding circles) at the
    substep's start go back to the earliest impact either has: a ball pushing another into a wall
    would otherwise drive on into the one the wall put back."""
    changed = True
    while changed:
        changed = False
        for g in range(len(pairs)):
            a, b = pairs[g, 0], pairs[g, 1]
            ka, kb = rows[a], rows[b]
            if hits[a] == hits[b] or state[ka, INV_MASS] == 0.0 or state[kb, INV_MASS] == 0.0 \
                    or state[ka, ASLEEP] != 0.0 or state[kb, ASLEEP] != 0.0:
                continue
            dx, dy = state[ka, X0] - state[kb, X0], state[ka, Y0] - state[kb, Y0]
            reach = radius[a] + radius[b] + CONTACT_MARGIN
            if dx * dx + dy * dy <= reach * reach:
                hits[a] = hits[b] = min(hits[a], hits[b])
                changed = True


@leaf_kernel
def _dynamic_pairs_may_step_far(state: np.ndarray, rows: np.ndarray, radius: np.ndarray, thickness: np.ndarray,
                                sweep_all: bool) -> bool:
    """Whether two dynamic bodies could step past each other as far as `toi.body_pair_hits` asks
    before it sweeps them (half the thinner one's width; the slop with `sweep_all`): their relative
    step is at most the sum of their steps (each its centre's |dx| + |dy| and its turn at its
    bounding radius), so not while twice the longest step is below that (a pile's substep, as a
    rule: then no pair of dynamic bodies is looked for at all). The margin covers the rounding of
    the steps' differences, which grows with the coordinates."""
    longest, thinnest, largest = 0.0, math.inf, 0.0
    for q in range(len(rows)):
        k = rows[q]
        if state[k, INV_MASS] == 0.0:
            continue
        x, y, a, x0, y0, a0 = state[k, X], state[k, Y], state[k, ANGLE], state[k, X0], state[k, Y0], state[k, ANGLE0]
        step = abs(x - x0) + abs(y - y0) + abs(a - a0) * radius[q]
        if not math.isfinite(step):
            return True
        longest = max(longest, step)
        thinnest = min(thinnest, thickness[q])
        largest = max(largest, abs(x), abs(y), abs(x0), abs(y0), (abs(a) + abs(a0)) * radius[q])
    if sweep_all:
        return 2.0 * longest * (1.0 + 1e-9) + 1e-12 * largest >= LINEAR_SLOP
    return 4.0 * longest * (1.0 + 1e-9) + 1e-12 * largest >= thinnest


@kernel
def _posed(lv: np.ndarray, ln: np.ndarray, first: np.ndarray, body_first: np.ndarray, q: int, x: float, y: float,
           angle: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Shape q of a shape table at a pose: its vertices, normals and piece rows from 0."""
    v0, v1 = first[body_first[q]], first[body_first[q + 1]]
    verts, normals = np.empty((v1 - v0, 2)), np.empty((v1 - v0, 2))
    pose_piece(lv, ln, v0, v1, x, y, angle, verts, normals)
    return verts, normals, first[body_first[q]:body_first[q + 1] + 1] - v0


@kernel
def _pinched(lv: np.ndarray, ln: np.ndarray, first: np.ndarray, body_first: np.ndarray, state: np.ndarray,
             rows: np.ndarray, radius: np.ndarray, arm: int, ball: int, t: float, grid: tuple, seen: np.ndarray,
             found: np.ndarray, wv: np.ndarray, wn: np.ndarray, wfirst: np.ndarray) -> bool:
    """Whether the arm (shape `arm`), meeting the ball (shape `ball`) at fraction `t` of the
    substep, drives it into a wall it lies against (within the contact margin): the push (the
    separating axis between arm and ball at the impact) points at least 15° into that wall's face.
    A ball it meets along the wall, or away from one, is pushed as usual. Both are where they are at
    the impact (QA: with the ball where its step ended, a fast ball heading for a wall 15 cm off
    counted as lying against it, and stalled the windmill for every ball of a fan)."""
    ka, kb = rows[arm], rows[ball]
    arm_x, arm_y, arm_angle = pose_at(state, ka, t)
    arm_v, arm_n, arm_first = _posed(lv, ln, first, body_first, arm, arm_x, arm_y, arm_angle)
    x, y, angle = pose_at(state, kb, t)
    verts, normals, own_first = _posed(lv, ln, first, body_first, ball, x, y, angle)
    no_seams = np.zeros(0, dtype=np.bool_)
    best, push_x, push_y = -np.inf, 0.0, 0.0
    for i in range(len(arm_first) - 1):
        for j in range(len(own_first) - 1):
            gap, face = max_separation(arm_v, arm_n, arm_first[i], arm_first[i + 1], verts, own_first[j],
                                       own_first[j + 1], no_seams, -1, math.inf)
            if gap > best:
                row = arm_first[i] + face
                best, push_x, push_y = gap, arm_n[row, 0], arm_n[row, 1]
            gap, face = max_separation(verts, normals, own_first[j], own_first[j + 1], arm_v, arm_first[i],
                                       arm_first[i + 1], no_seams, -1, math.inf)
            if gap > best:
                row = own_first[j] + face
                best, push_x, push_y = gap, -normals[row, 0], -normals[row, 1]
    r = radius[ball] + CONTACT_MARGIN
    box = np.array([x - r, y - r, x + r, y + r])
    boxes, x0, y0, inv, nx, ny, cell_first, cell_items, large = grid
    for n in range(overlapping(boxes, x0, y0, inv, nx, ny, cell_first, cell_items, large, box, seen, found)):
        g = found[n]
        for j in range(len(own_first) - 1):
            gap, face = max_separation(wv, wn, wfirst[g], wfirst[g + 1], verts, own_first[j], own_first[j + 1],
                                       no_seams, -1, math.inf)
            row = wfirst[g] + face
            # wn[row] points out of the wall, towards the ball.
            if gap < CONTACT_MARGIN and push_x * wn[row, 0] + push_y * wn[row, 1] < -0.25:
                return True
    return False
