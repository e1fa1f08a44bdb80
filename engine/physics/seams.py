"""Where wall pieces meet: the edges and vertices of one piece that are covered by others.

Walls are built of convex pieces (boxes along tile sides, pattern obstacles, the convex parts of a
non-convex wall). Where two pieces meet flush, a face of one lies against the other (an internal
edge, if others cover it all along: a face that walls cross here and there is a face between them)
and corners sit on a flat stretch of the solid's boundary (hidden vertices). A ball sliding
across such a seam must feel one flat surface: an internal edge may never be a contact's reference
face, and a hidden vertex never a contact point (Box2D's chain shapes and ghost vertices serve the
same end). A vertex is hidden when the solid around it covers at least half of a small circle (flat
or reflex); a real corner covers less.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

from polygolf.engine.physics.polygon import Vec

PROBE = 1e-4  # m: how far from an edge or vertex the cover is sampled (and what of an edge's ends may stay bare)
_DIRECTIONS = [(math.cos((k + 0.5) * math.pi / 8), math.sin((k + 0.5) * math.pi / 8)) for k in range(16)]


def _inside(piece: Sequence[Vec], normals: Sequence[Vec], x: float, y: float) -> bool:
    """Strictly inside a convex CCW piece (points on its boundary are outside)."""
    return all((x - px) * nx + (y - py) * ny < 0.0 for (px, py), (nx, ny) in zip(piece, normals))


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


def _covered_along(spans: list[tuple[float, float]], margin: float) -> bool:
    """Whether the spans, joined, cover [margin, 1 - margin], a gap of up to `margin` between two
    counting as none (two pieces side by side cover the line where they touch, give or take a
    rounding of their coordinates)."""
    reach = margin
    for lo, hi in sorted(spans):
        if lo > reach + margin:
            return False
        reach = max(reach, hi)
    return reach >= 1.0 - margin


def covered_features(pieces: Sequence[Sequence[Vec]], normals: Sequence[Sequence[Vec]],
                     neighbours: Callable[[int], Sequence[int]]
                     ) -> tuple[list[frozenset[int]], list[frozenset[int]]]:
    """Per piece: (internal edge indices, hidden vertex indices). `neighbours(i)` lists the pieces
    whose boxes touch piece i (the broadphase grid answers it)."""
    internal: list[frozenset[int]] = []
    hidden: list[frozenset[int]] = []
    for i, piece in enumerate(pieces):
        others = [j for j in neighbours(i) if j != i]

        def covered(x: float, y: float, others: list[int] = others) -> bool:
            return any(_inside(pieces[j], normals[j], x, y) for j in others)

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
            if spans and _covered_along(spans, PROBE / max(math.hypot(bx - ax, by - ay), PROBE)):
                edges.add(e)
        corners = set()
        for v, (vx, vy) in enumerate(piece):
            around = sum(covered(vx + PROBE * dx, vy + PROBE * dy) or _inside(piece, normals[i], vx + PROBE * dx,
                                                                                vy + PROBE * dy)
                         for dx, dy in _DIRECTIONS)
            if others and around >= len(_DIRECTIONS) // 2:
                corners.add(v)
        internal.append(frozenset(edges))
        hidden.append(frozenset(corners))
    return internal, hidden
