"""Convex pieces packed in arrays, the form every compiled kernel reads.

A `ConvexSet` holds any number of convex CCW pieces back to back: piece p has vertices
`verts[first[p]:first[p + 1]]` and the outward normals of its edges at the same rows (normal k
belongs to edge k -> k+1), and `reach[p]` is its farthest vertex from the origin. A body's collider
keeps its pieces in its own frame; the walls of a world are one set in world coordinates.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from polygolf.engine.physics.body import ASLEEP, COLUMNS, X, Y
from polygolf.engine.physics.jit import inlined_leaf, leaf_kernel, warm_up
from polygolf.engine.physics.polygon import Vec
from polygolf.engine.physics.seams import PROBE


@dataclass(frozen=True, eq=False)
class ConvexSet:
    verts: np.ndarray  # (n, 2) float64
    normals: np.ndarray  # (n, 2) float64
    first: np.ndarray  # (pieces + 1,) int64
    reach: np.ndarray  # (pieces,) float64
    every_piece: np.ndarray  # (pieces,) int64: 0, 1, ... (the list "all of them" kernels take)

    @classmethod
    def of(cls, pieces: Sequence[Sequence[Vec]], normals: Sequence[Sequence[Vec]]) -> ConvexSet:
        counts = [len(p) for p in pieces]
        first = np.zeros(len(pieces) + 1, dtype=np.int64)
        first[1:] = np.cumsum(counts)
        verts = np.array([v for p in pieces for v in p], dtype=np.float64).reshape(-1, 2)
        norms = np.array([n for ns in normals for n in ns], dtype=np.float64).reshape(-1, 2)
        reach = np.array([max(math.hypot(x, y) for x, y in p) for p in pieces], dtype=np.float64)
        return cls(verts, norms, first, reach, np.arange(len(pieces), dtype=np.int64))

    def __len__(self) -> int:
        return len(self.first) - 1


@dataclass(frozen=True, eq=False)
class ShapeTable:
    """Several bodies' convex sets back to back, so one kernel call can treat them all: body k's
    pieces are pieces[body_first[k]:body_first[k + 1]] of the joined set."""

    pieces: ConvexSet
    body_first: np.ndarray  # (bodies + 1,) int64

    @classmethod
    def of(cls, sets: Sequence[ConvexSet]) -> ShapeTable:
        """(Worked out with whole arrays, not a set at a time: a search puts a thousand balls in a world.)"""
        if not sets:
            return cls(ConvexSet(np.zeros((0, 2)), np.zeros((0, 2)), np.zeros(1, dtype=np.int64), np.zeros(0),
                                 np.zeros(0, dtype=np.int64)), np.zeros(1, dtype=np.int64))
        verts = np.concatenate([s.verts for s in sets])
        normals = np.concatenate([s.normals for s in sets])
        reach = np.concatenate([s.reach for s in sets])
        pieces = np.array([len(s.first) - 1 for s in sets], dtype=np.int64)
        rows = np.array([len(s.verts) for s in sets], dtype=np.int64)
        first = np.empty(int(pieces.sum()) + 1, dtype=np.int64)
        first[:-1] = np.concatenate([s.first[:-1] for s in sets]) + np.repeat(np.cumsum(rows) - rows, pieces)
        first[-1] = len(verts)
        body_first = np.zeros(len(sets) + 1, dtype=np.int64)
        np.cumsum(pieces, out=body_first[1:])
        joined = ConvexSet(verts, normals, first, reach, np.arange(len(first) - 1, dtype=np.int64))
        return cls(joined, body_first)


@inlined_leaf
def norm(x: float, y: float) -> float:
    """hypot(x, y) as the square root of the sum of squares where the squares are normal numbers
    (there within about an ulp of `math.hypot`, and several times cheaper); `math.hypot` elsewhere."""
    squares = x * x + y * y
    return math.sqrt(squares) if 1e-290 < squares < math.inf else math.hypot(x, y)


@inlined_leaf
def pose_piece(verts: np.ndarray, normals: np.ndarray, start: int, end: int, x: float, y: float, angle: float,
               out_verts: np.ndarray, out_normals: np.ndarray) -> None:
    """Rows start..end of a body-frame set, turned by `angle` and moved to (x, y), into rows 0.. of
    the outputs (the same arithmetic, in the same order, wherever a pose is taken)."""
    c, s = math.cos(angle), math.sin(angle)
    for k in range(end - start):
        px, py = verts[start + k, 0], verts[start + k, 1]
        out_verts[k, 0] = x + c * px - s * py
        out_verts[k, 1] = y + s * px + c * py
        nx, ny = normals[start + k, 0], normals[start + k, 1]
        out_normals[k, 0] = c * nx - s * ny
        out_normals[k, 1] = s * nx + c * ny


@inlined_leaf
def face_line(wv: np.ndarray, wn: np.ndarray, s: int, e: int, r: int) -> tuple[float, float, float, float, float]:
    """Face r of the convex piece of rows s..e: its normal, its line's offset (n·p) and its stretch
    along (-ny, nx)."""
    nx, ny = wn[r, 0], wn[r, 1]
    n = s + (r - s + 1) % (e - s)
    a, b = -ny * wv[r, 0] + nx * wv[r, 1], -ny * wv[n, 0] + nx * wv[n, 1]
    return nx, ny, wv[r, 0] * nx + wv[r, 1] * ny, min(a, b), max(a, b)


@inlined_leaf
def span_on_line(wv: np.ndarray, wn: np.ndarray, s: int, e: int, nx: float, ny: float, offset: float, tx: float,
                 ty: float) -> tuple[int, float, float]:
    """The face of the convex piece of rows s..e that lies on the line n·p = offset and faces n
    (within seams.PROBE), and its stretch along (tx, ty); or (-1, inf, -inf) if it has none: where a
    face of another piece carries on across a seam."""
    for r in range(s, e):
        if wn[r, 0] * nx + wn[r, 1] * ny >= 1.0 - 1e-9 and abs(wv[r, 0] * nx + wv[r, 1] * ny - offset) <= PROBE:
            n = s + (r - s + 1) % (e - s)
            a, b = wv[r, 0] * tx + wv[r, 1] * ty, wv[n, 0] * tx + wv[n, 1] * ty
            return r, min(a, b), max(a, b)
    return -1, math.inf, -math.inf


@dataclass(frozen=True, eq=False)
class Areas:
    """Simple polygons (areas of a green: sand, water, a slope) back to back: area a has vertices
    `verts[first[a]:first[a + 1]]` and bounding box `boxes[a]` (x0, y0, x1, y1)."""

    verts: np.ndarray  # (n, 2) float64
    first: np.ndarray  # (areas + 1,) int64
    boxes: np.ndarray  # (areas, 4) float64

    @classmethod
    def of(cls, outlines: Sequence[Sequence[Vec]], boxes: Sequence[Sequence[float]]) -> Areas:
        first = np.zeros(len(outlines) + 1, dtype=np.int64)
        first[1:] = np.cumsum([len(o) for o in outlines])
        verts = np.array([v for o in outlines for v in o], dtype=np.float64).reshape(-1, 2)
        return cls(verts, first, np.array(boxes, dtype=np.float64).reshape(-1, 4))


@leaf_kernel
def inside(verts: np.ndarray, start: int, end: int, x: float, y: float) -> bool:
    """Whether (x, y) is inside the simple polygon of rows start..end (even-odd ray crossing, as
    `polygon.contains`)."""
    result = False
    n = end - start
    for i in range(n):
        ax, ay = verts[start + i, 0], verts[start + i, 1]
        j = start + (i + 1) % n
        bx, by = verts[j, 0], verts[j, 1]
        if (ay > y) != (by > y) and x < ax + (y - ay) * (bx - ax) / (by - ay):
            result = not result
    return result


@leaf_kernel
def first_area(state: np.ndarray, rows: np.ndarray, verts: np.ndarray, first: np.ndarray, boxes: np.ndarray,
               out: np.ndarray) -> int:
    """For each awake body of `rows` (a `body.BodyStore` state), the first area that holds its
    centre, or -1 (also for a body at rest). Returns how many bodies are on one."""
    found = 0
    for q in range(rows.shape[0]):
        k = rows[q]
        out[q] = -1
        if state[k, ASLEEP] != 0.0:
            continue
        x, y = state[k, X], state[k, Y]
        for a in range(boxes.shape[0]):
            if (boxes[a, 0] <= x <= boxes[a, 2] and boxes[a, 1] <= y <= boxes[a, 3]
                    and inside(verts, first[a], first[a + 1], x, y)):
                out[q] = a
                found += 1
                break
    return found


@warm_up("shapes")
def _warm() -> None:
    area = Areas.of([((0.0, 0.0), (1.0, 0.0), (0.0, 1.0))], [(0.0, 0.0, 1.0, 1.0)])
    state = np.zeros((1, len(COLUMNS)))
    state[0, X] = state[0, Y] = 0.25
    first_area(state, np.zeros(1, dtype=np.int64), area.verts, area.first, area.boxes, np.empty(1, dtype=np.int64))
