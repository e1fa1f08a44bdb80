"""Polygon outlines: generation, validation, normalisation and convex decomposition.

Every outline leaving this module is counter-clockwise, simple, non-degenerate and centred on its
centroid, so the rest of the engine can rely on those facts instead of re-checking them.
"""

from __future__ import annotations

import math
import random
from collections.abc import Sequence

Vec = tuple[float, float]
Outline = tuple[Vec, ...]

MIN_SIDES, MAX_SIDES = 3, 64
_AREA_EPS = 1e-9


class PolygonError(ValueError):
    """An outline that is not a usable polygon (too few vertices, zero area, self-intersecting)."""


def cross(ax: float, ay: float, bx: float, by: float) -> float:
    return ax * by - ay * bx


def signed_area(vertices: Sequence[Vec]) -> float:
    n = len(vertices)
    total = 0.0
    for i in range(n):
        x0, y0 = vertices[i]
        x1, y1 = vertices[(i + 1) % n]
        total += x0 * y1 - x1 * y0
    return 0.5 * total


def centroid(vertices: Sequence[Vec]) -> Vec:
    """Area centroid of a simple polygon (convex or not)."""
    n = len(vertices)
    # Shift to the first vertex so far-from-origin outlines keep their precision.
    ox, oy = vertices[0]
    area2 = cx = cy = 0.0
    for i in range(n):
        x0, y0 = vertices[i][0] - ox, vertices[i][1] - oy
        x1, y1 = vertices[(i + 1) % n][0] - ox, vertices[(i + 1) % n][1] - oy
        c = x0 * y1 - x1 * y0
        area2 += c
        cx += (x0 + x1) * c
        cy += (y0 + y1) * c
    if abs(area2) < _AREA_EPS:
        raise PolygonError("polygon has zero area")
    return ox + cx / (3.0 * area2), oy + cy / (3.0 * area2)


def contains(vertices: Sequence[Vec], x: float, y: float) -> bool:
    """Whether (x, y) is inside a simple polygon (even-odd ray crossing)."""
    inside = False
    n = len(vertices)
    for i in range(n):
        (ax, ay), (bx, by) = vertices[i], vertices[(i + 1) % n]
        if (ay > y) != (by > y) and x < ax + (y - ay) * (bx - ax) / (by - ay):
            inside = not inside
    return inside


def bounding_radius(vertices: Sequence[Vec]) -> float:
    return max(math.hypot(x, y) for x, y in vertices)


def placed(vertices: Sequence[Vec], x: float, y: float, angle: float) -> Outline:
    """`vertices` (about their own origin) turned by `angle` (rad) and moved to (x, y)."""
    c, s = math.cos(angle), math.sin(angle)
    return tuple((x + c * px - s * py, y + s * px + c * py) for px, py in vertices)


def regular_polygon(sides: int, radius: float) -> Outline:
    """Regular n-gon with its first vertex on the +x axis."""
    if not MIN_SIDES <= sides <= MAX_SIDES:
        raise PolygonError(f"a regular polygon needs {MIN_SIDES} to {MAX_SIDES} sides, got {sides}")
    if radius <= 0:
        raise PolygonError(f"radius must be positive, got {radius}")
    step = 2.0 * math.pi / sides
    return tuple((radius * math.cos(k * step), radius * math.sin(k * step)) for k in range(sides))


def star_polygon(points: int, density: int, radius: float) -> Outline:
    """Outline of the star {p/q}: p tips on the circle, p notches where the chords cross.

    The notch radius is R·cos(πq/p)/cos(π(q-1)/p) (MathWorld, "Star Polygon"); q = 1 is the
    regular p-gon.
    """
    if density == 1:
        return regular_polygon(points, radius)
    if points < 5 or not 2 <= density < points / 2:
        raise PolygonError(f"a star {{p/q}} needs p >= 5 and 2 <= q < p/2, got {{{points}/{density}}}")
    if radius <= 0:
        raise PolygonError(f"radius must be positive, got {radius}")
    inner = radius * math.cos(math.pi * density / points) / math.cos(math.pi * (density - 1) / points)
    step = math.pi / points
    out = []
    for k in range(2 * points):
        r = radius if k % 2 == 0 else inner
        out.append((r * math.cos(k * step), r * math.sin(k * step)))
    return tuple(out)


def random_polygon(seed: int, vertices: int, radius: float) -> Outline:
    """A seeded random simple polygon, star-shaped about the origin so it is simple by construction.

    Angles keep a minimum gap and radii stay within [0.45R, R], which keeps it far from degenerate.
    """
    if not MIN_SIDES <= vertices <= MAX_SIDES:
        raise PolygonError(f"a random polygon needs {MIN_SIDES} to {MAX_SIDES} vertices, got {vertices}")
    if radius <= 0:
        raise PolygonError(f"radius must be positive, got {radius}")
    rng = random.Random(seed)
    slot = 2.0 * math.pi / vertices
    pts = []
    for k in range(vertices):
        angle = (k + rng.uniform(0.15, 0.85)) * slot
        r = radius * rng.uniform(0.45, 1.0)
        pts.append((r * math.cos(angle), r * math.sin(angle)))
    # The farthest vertex touches the circle so the radius means what it says.
    far = bounding_radius(pts)
    return tuple((x * radius / far, y * radius / far) for x, y in pts)


def _segments_intersect(a: Vec, b: Vec, c: Vec, d: Vec) -> bool:
    """Closed-segment intersection, touching included. Orientations within rounding of zero count as
    collinear: a star's outline has several edges on one chord, which must not read as crossing."""
    scale = max(abs(v) for p in (a, b, c, d) for v in p) or 1.0
    eps = 1e-12 * scale * scale

    def orient(p: Vec, q: Vec, r: Vec) -> float:
        value = cross(q[0] - p[0], q[1] - p[1], r[0] - p[0], r[1] - p[1])
        return 0.0 if abs(value) <= eps else value

    def on_segment(p: Vec, q: Vec, r: Vec) -> bool:
        return min(p[0], q[0]) <= r[0] <= max(p[0], q[0]) and min(p[1], q[1]) <= r[1] <= max(p[1], q[1])

    d1, d2 = orient(c, d, a), orient(c, d, b)
    d3, d4 = orient(a, b, c), orient(a, b, d)
    if ((d1 > 0 > d2) or (d1 < 0 < d2)) and ((d3 > 0 > d4) or (d3 < 0 < d4)):
        return True
    return (
        (d1 == 0 and on_segment(c, d, a))
        or (d2 == 0 and on_segment(c, d, b))
        or (d3 == 0 and on_segment(a, b, c))
        or (d4 == 0 and on_segment(a, b, d))
    )


def is_simple(vertices: Sequence[Vec]) -> bool:
    n = len(vertices)
    if len(set(vertices)) != n:
        return False
    for i in range(n):
        a, b = vertices[i], vertices[(i + 1) % n]
        for j in range(i + 1, n):
            if j == i or (j + 1) % n == i or j == (i + 1) % n:
                continue
            if _segments_intersect(a, b, vertices[j], vertices[(j + 1) % n]):
                return False
    return True


def _drop_collinear(vertices: Sequence[Vec], tolerance: float) -> list[Vec]:
    pts = list(vertices)
    changed = True
    while changed and len(pts) > 3:
        changed = False
        for i in range(len(pts)):
            p, q, r = pts[i - 1], pts[i], pts[(i + 1) % len(pts)]
            edge = math.hypot(r[0] - p[0], r[1] - p[1])
            if abs(cross(q[0] - p[0], q[1] - p[1], r[0] - p[0], r[1] - p[1])) <= tolerance * edge:
                del pts[i]
                changed = True
                break
    return pts


def normalise(vertices: Sequence[Sequence[float]]) -> tuple[Outline, Vec]:
    """Validate an outline and return it counter-clockwise about its centroid, plus that centroid.

    Raises PolygonError naming what is wrong.
    """
    try:
        pts = [(float(v[0]), float(v[1])) for v in vertices]
    except (TypeError, ValueError, IndexError) as exc:
        raise PolygonError("vertices must be [x, y] pairs of numbers") from exc
    if len(pts) < 3:
        raise PolygonError(f"a polygon needs at least 3 vertices, got {len(pts)}")
    if not all(math.isfinite(c) for p in pts for c in p):
        raise PolygonError("vertices must be finite numbers")
    if len(set(pts)) != len(pts):
        raise PolygonError("polygon has repeated vertices")
    # Zero area for its own size, worked out about its first vertex: a half-square-metre triangle
    # 100 km out is a triangle (measured against its distance from the origin, it had "zero area").
    ox, oy = pts[0]
    area = signed_area([(x - ox, y - oy) for x, y in pts])
    extent = max(max(x for x, _ in pts) - min(x for x, _ in pts), max(y for _, y in pts) - min(y for _, y in pts))
    if not is_simple(pts):  # (first: a bowtie's halves cancel, and "zero area" would not say why)
        raise PolygonError("polygon edges cross each other (it must be simple)")
    if abs(area) <= _AREA_EPS * extent * extent:
        raise PolygonError("polygon has zero area")
    return about_centroid(pts)


def about_centroid(vertices: Sequence[Vec]) -> tuple[Outline, Vec]:
    """`normalise` of an outline known to be valid (a rigid copy of one that was checked: a
    windmill placed on its tile), without the checks: their tolerances grow with the distance from
    the origin, and a windmill placed 10 km out read as crossing itself."""
    pts = [(float(x), float(y)) for x, y in vertices]
    scale = max(max(abs(x), abs(y)) for x, y in pts) or 1.0
    ox, oy = pts[0]
    if signed_area([(x - ox, y - oy) for x, y in pts]) < 0:
        pts.reverse()
    pts = _drop_collinear(pts, 1e-12 * scale)
    cx, cy = centroid(pts)
    return tuple((x - cx, y - cy) for x, y in pts), (cx, cy)


def is_convex(vertices: Sequence[Vec], tolerance: float = 1e-12) -> bool:
    n = len(vertices)
    for i in range(n):
        p, q, r = vertices[i - 1], vertices[i], vertices[(i + 1) % n]
        if cross(q[0] - p[0], q[1] - p[1], r[0] - q[0], r[1] - q[1]) < -tolerance:
            return False
    return True


def _point_in_triangle(p: Vec, a: Vec, b: Vec, c: Vec) -> bool:
    """Inside or on the boundary of the counter-clockwise triangle abc."""
    return (
        cross(b[0] - a[0], b[1] - a[1], p[0] - a[0], p[1] - a[1]) >= 0
        and cross(c[0] - b[0], c[1] - b[1], p[0] - b[0], p[1] - b[1]) >= 0
        and cross(a[0] - c[0], a[1] - c[1], p[0] - c[0], p[1] - c[1]) >= 0
    )


def triangulate(vertices: Sequence[Vec]) -> list[tuple[int, int, int]]:
    """Ear clipping of a counter-clockwise simple polygon; returns vertex-index triangles."""
    idx = list(range(len(vertices)))
    tris: list[tuple[int, int, int]] = []
    guard = 0
    while len(idx) > 3:
        guard += 1
        if guard > 10 * len(vertices) ** 2:
            raise PolygonError("could not triangulate polygon")
        m = len(idx)
        for k in range(m):
            i0, i1, i2 = idx[k - 1], idx[k], idx[(k + 1) % m]
            a, b, c = vertices[i0], vertices[i1], vertices[i2]
            if cross(b[0] - a[0], b[1] - a[1], c[0] - b[0], c[1] - b[1]) <= 0:
                continue  # reflex or flat: not an ear
            if any(
                _point_in_triangle(vertices[j], a, b, c) for j in idx if j not in (i0, i1, i2)
            ):
                continue
            tris.append((i0, i1, i2))
            del idx[k]
            break
        else:
            raise PolygonError("could not triangulate polygon")
    tris.append((idx[0], idx[1], idx[2]))
    return tris


def convex_pieces(vertices: Sequence[Vec]) -> list[Outline]:
    """Split a simple CCW outline into convex CCW pieces (ear clipping, then Hertel-Mehlhorn merging)."""
    if is_convex(vertices):
        return [tuple(vertices)]
    pieces = [list(t) for t in triangulate(vertices)]
    merged = True
    while merged:
        merged = False
        for a in range(len(pieces)):
            for b in range(a + 1, len(pieces)):
                joined = _merge_along_shared_edge(pieces[a], pieces[b])
                if joined is not None and is_convex([vertices[i] for i in joined]):
                    pieces[a] = joined
                    del pieces[b]
                    merged = True
                    break
            if merged:
                break
    return [tuple(_drop_collinear([vertices[i] for i in p], 1e-12)) for p in pieces]


def _merge_along_shared_edge(p: list[int], q: list[int]) -> list[int] | None:
    """Join two CCW index polygons that share an edge (i, j) in p and (j, i) in q."""
    for s in range(len(p)):
        i, j = p[s], p[(s + 1) % len(p)]
        for t in range(len(q)):
            if q[t] == j and q[(t + 1) % len(q)] == i:
                # Walk p from j round to i, then q from i round to j, skipping the shared edge.
                p_run = [p[(s + 1 + k) % len(p)] for k in range(len(p))]  # starts at j, ends at i
                q_run = [q[(t + 1 + k) % len(q)] for k in range(len(q))]  # starts at i, ends at j
                return p_run[:-1] + q_run[:-1]
    return None


def min_width(vertices: Sequence[Vec]) -> float:
    """The thinnest width of a convex polygon: over its edges, the farthest vertex from the edge's line."""
    n = len(vertices)
    best = math.inf
    for i in range(n):
        (ax, ay), (bx, by) = vertices[i], vertices[(i + 1) % n]
        length = math.hypot(bx - ax, by - ay)
        if length > 0.0:
            best = min(best, max(abs(cross(bx - ax, by - ay, x - ax, y - ay)) / length for x, y in vertices))
    return best


def edge_normals(vertices: Sequence[Vec]) -> tuple[Vec, ...]:
    """Outward unit normals of a CCW outline; normal k belongs to edge (k, k+1)."""
    out = []
    n = len(vertices)
    for k in range(n):
        x0, y0 = vertices[k]
        x1, y1 = vertices[(k + 1) % n]
        ex, ey = x1 - x0, y1 - y0
        length = math.hypot(ex, ey)
        out.append((ey / length, -ex / length))
    return tuple(out)
