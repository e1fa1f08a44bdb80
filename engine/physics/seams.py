"""Where wall pieces meet: the edges and vertices of one piece that are covered by others.

Walls are built of convex pieces (boxes along tile sides, pattern obstacles, the convex parts of a
non-convex wall). Where two pieces meet flush, a face of one lies against the other (an internal
edge, if others cover it all along: a face that walls cross here and there is a face between them)
and corners sit on a flat stretch of the solid's boundary (hidden vertices). A ball sliding
across such a seam must feel one flat surface: an internal edge may never be a contact's reference
face, and a hidden vertex never a contact point (Box2D's chain shapes and ghost vertices serve the
same end). A vertex is hidden when the solid around it covers at least half of a small circle (flat
or reflex); a real corner covers less. A reflex one (the inside corner of a V, a step's foot) is
also where the free space is a wedge: there each face's line bounds it beyond the face's end too
(`collide.collide_convex`).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

from polygolf.engine.physics.polygon import Vec

# m: an edge's cover is looked for this far outside it, and may leave this much of it bare; a face
# passing this near a vertex counts as passing through it.
PROBE = 1e-4
END_SLACK = 50 * PROBE  # uncovered at an edge's end, still internal: neighbours meeting it at 1.1° or more
_TURN = 2.0 * math.pi
_FLAT = 1e-6  # rad: the solid round a vertex fills half the turn within this: a flat stretch
_REFLEX = 0.05  # rad: the solid round a vertex fills more than half the turn by this: a reflex corner
# A wall vertex row's mark, as the kernels read it (`StaticWorld.hidden`): a hidden vertex, and a
# hidden one at a reflex corner.
HIDDEN, REFLEX = 1, 2


def _inside_span(piece: Sequence[Vec], normals: Sequence[Vec], x: float, y: float, dx: float, dy: float
                 ) -> tuple[float, float] | None:
    """The open interval of t in [0, 1] for which (x, y) + t (dx, dy) is strictly inside a convex CCW
    piece, or None: each face keeps the t on its inner side."""
    lo, hi = 0.0, 1.0
    for (px, py), (nx, ny) in zip(piece, normals):
        level, rate = (x - px) * nx + (y - py) * ny, dx * nx + dy * ny  # beyond the face by level + t rate
        if rate > 0.0:
            hi = min(hi, -level / rate)
        elif rate < 0.0:
            lo = max(lo, -level / rate)
        elif level >= 0.0:
            return None
    return (lo, hi) if lo < hi else None


def _covered_along(spans: list[tuple[float, float]], margin: float, ends: float) -> bool:
    """Whether the spans, joined, cover [ends, 1 - ends], a gap of up to `margin` between two
    counting as none (two pieces side by side cover the line where they touch, give or take a
    rounding of their coordinates). `ends`: what may stay uncovered at either end: the probe line,
    PROBE outside the edge, leaves a neighbour that meets the edge's end at an acute angle well
    before that end (0.1 mm / tan 5.7° = 1 mm), and the edge was taken for a face."""
    reach = ends
    for lo, hi in sorted(spans):
        if lo > reach + margin:
            return False
        reach = max(reach, hi)
    return reach >= 1.0 - ends


def _meet(a: float, wa: float, b: float, wb: float) -> tuple[float, float]:
    """The arc two arcs (start angle, width) share, for arcs at most a half turn wide or the whole
    turn: (start, width), width 0 if none."""
    if wa >= _TURN:
        return b, wb
    d = (b - a) % _TURN
    lo, hi = max(0.0, d - _TURN), min(wa, d + wb - _TURN)  # B as it wraps round to meet A's start
    if hi <= lo:
        lo, hi = d, min(wa, d + wb)
    return a + lo, max(0.0, hi - lo)


def _cone(piece: Sequence[Vec], normals: Sequence[Vec], x: float, y: float) -> tuple[float, float] | None:
    """The directions from (x, y) that lead into a convex CCW piece, as an arc (start angle, width):
    the whole turn from inside it, the directions behind every face that passes within PROBE of the
    point from on its boundary, None from farther outside."""
    start, width = 0.0, _TURN
    for (px, py), (nx, ny) in zip(piece, normals):
        level = (x - px) * nx + (y - py) * ny
        if level > PROBE:
            return None
        if level >= -PROBE:  # the face passes by the point: only the directions behind it lead in
            start, width = _meet(start, width, math.atan2(ny, nx) + 0.5 * math.pi, math.pi)
            if width <= 0.0:
                return None
    return start, width


def _covered_turn(arcs: list[tuple[float, float]]) -> float:
    """How much of the turn the arcs (start angle, width) cover together, in radians."""
    spans = []
    for start, width in arcs:
        if width >= _TURN:
            return _TURN
        start %= _TURN
        spans += [(start, _TURN), (0.0, start + width - _TURN)] if start + width > _TURN else [(start, start + width)]
    total, reach = 0.0, 0.0
    for lo, hi in sorted(spans):
        lo = max(lo, reach)
        if hi > lo:
            total, reach = total + hi - lo, hi
    return total


def covered_features(pieces: Sequence[Sequence[Vec]], normals: Sequence[Sequence[Vec]],
                     neighbours: Callable[[int], Sequence[int]]
                     ) -> tuple[list[frozenset[int]], list[frozenset[int]], list[frozenset[int]]]:
    """Per piece: (internal edge indices, hidden vertex indices, reflex vertex indices: the hidden
    ones round which the solid fills more than half the turn). `neighbours(i)` lists the pieces
    whose boxes touch piece i (the broadphase grid answers it)."""
    internal: list[frozenset[int]] = []
    hidden: list[frozenset[int]] = []
    reflex: list[frozenset[int]] = []
    for i, piece in enumerate(pieces):
        others = [j for j in neighbours(i) if j != i]

        n = len(piece)
        edges = set()
        for e in range(n):
            # Internal only if other pieces cover it end to end, just outside it: a long edge that other
            # walls cross here and there (a side wall four tiles long, the tiles' border walls meeting it)
            # is a face everywhere else.
            (ax, ay), (bx, by) = piece[e], piece[(e + 1) % n]
            nx, ny = normals[i][e]
            spans = [span for j in others
                     if (span := _inside_span(pieces[j], normals[j], ax + PROBE * nx, ay + PROBE * ny, bx - ax,
                                              by - ay)) is not None]
            length = max(math.hypot(bx - ax, by - ay), PROBE)
            if spans and _covered_along(spans, PROBE / length, min(END_SLACK / length, 0.25)):
                edges.add(e)
        corners, inside_corners = set(), set()
        for v, (vx, vy) in enumerate(piece):
            # Hidden if the solid round it (this piece's corner and the other pieces there) fills half
            # the turn or more, worked out from the faces' directions: sampled in 16 directions, corners
            # of 158 to 180 degrees counted as flat, and a box resting on such a ridge sank into it.
            arcs = [cone for cone in [_cone(piece, normals[i], vx, vy)]
                    + [_cone(pieces[j], normals[j], vx, vy) for j in others] if cone is not None]
            covered = _covered_turn(arcs) if others else 0.0
            if covered >= math.pi - _FLAT:
                corners.add(v)
            if covered > math.pi + _REFLEX:
                inside_corners.add(v)
        internal.append(frozenset(edges))
        hidden.append(frozenset(corners))
        reflex.append(frozenset(inside_corners))
    return internal, hidden, reflex
