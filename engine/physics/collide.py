"""Convex polygon against convex polygon: separating axes, then reference-face clipping.

This is the manifold of box2d-lite / Box2D v2 (`b2CollidePolygons`): find the axis of least
penetration on either polygon, take that edge as the reference face, pick the most anti-parallel edge
of the other polygon as the incident edge, clip it to the reference face's side planes and keep the
clipped points that lie within `margin` of the face. A flat face-to-face touch therefore gives two
points that are solved together, never two unrelated contacts.
"""

from __future__ import annotations

from dataclasses import dataclass

from polygolf.engine.physics.polygon import Vec

# Prefer polygon A's face unless B's is clearly better: stops the reference face flickering between
# the two polygons when they are nearly parallel, which would spoil warm starting.
_REFERENCE_TOLERANCE = 5e-4
# At a seam, the wall's face replaces A's as the reference only if it is about as near (m).
_SEAM_SWITCH = 0.005


@dataclass(slots=True)
class RawContact:
    """One clipped point: where it is, how deep, which features made it, and the geometry NGS needs."""

    x: float  # midway between the incident point and the reference face
    y: float
    separation: float  # negative when overlapping
    feature: int  # stable id of the (reference edge, incident feature) pair, for warm starting
    ref_is_a: bool  # True when the reference face belongs to polygon A
    clip_x: float  # the point on the incident polygon
    clip_y: float
    face_x: float  # a point on the reference face
    face_y: float


def max_separation(verts1: list[Vec], normals1: list[Vec], verts2: list[Vec],
                   skip: frozenset[int] = frozenset()) -> tuple[float, int]:
    """Largest separation of polygon 2 from the faces of polygon 1 (but the `skip` ones), and that
    face's index."""
    best, best_edge = -1e300, 0
    for i, (nx, ny) in enumerate(normals1):
        if i in skip:
            continue
        vx, vy = verts1[i]
        lowest = 1e300
        for x, y in verts2:
            d = (x - vx) * nx + (y - vy) * ny
            if d < lowest:
                lowest = d
        if lowest > best:
            best, best_edge = lowest, i
    return best, best_edge


def separation(verts_a: list[Vec], normals_a: list[Vec], verts_b: list[Vec], normals_b: list[Vec]) -> float:
    """Separating-axis distance: a lower bound on the true distance, exact when it is negative."""
    sa, _ = max_separation(verts_a, normals_a, verts_b)
    sb, _ = max_separation(verts_b, normals_b, verts_a)
    return sa if sa > sb else sb


def collide_polygons(
    verts_a: list[Vec], normals_a: list[Vec], verts_b: list[Vec], normals_b: list[Vec], margin: float,
    internal_b: frozenset[int] = frozenset(), hidden_b: frozenset[int] = frozenset(),
) -> tuple[Vec, list[RawContact]] | None:
    """Contact manifold of two convex CCW polygons, or None if they are more than `margin` apart.

    Returns the unit normal pointing from A to B and up to two points. For a wall piece B,
    `internal_b` are edges covered by other pieces (never a reference face) and `hidden_b` vertices
    on a flat or reflex stretch of the walls' boundary (never a contact point): see physics.seams.
    """
    sep_a, edge_a = max_separation(verts_a, normals_a, verts_b)
    if sep_a > margin:
        return None
    sep_b, edge_b = max_separation(verts_b, normals_b, verts_a)
    if sep_b > margin:
        return None
    if internal_b:
        if len(internal_b) == len(verts_b):
            return None  # a piece covered all round: the pieces around it answer for it
        if edge_b in internal_b:
            sep_b, edge_b = max_separation(verts_b, normals_b, verts_a, internal_b)

    if sep_b > sep_a + _REFERENCE_TOLERANCE:
        ref_v, ref_n, inc_v, inc_n, edge, ref_is_a = verts_b, normals_b, verts_a, normals_a, edge_b, False
    else:
        ref_v, ref_n, inc_v, inc_n, edge, ref_is_a = verts_a, normals_a, verts_b, normals_b, edge_a, True

    inc_edge = _incident_edge(inc_n, ref_n[edge], internal_b if ref_is_a else frozenset())
    count_inc = len(inc_v)
    i1, i2 = inc_edge, (inc_edge + 1) % count_inc
    if ref_is_a and (i1 in hidden_b or i2 in hidden_b) and sep_b >= sep_a - _SEAM_SWITCH:
        # A's face would meet a wall corner that lies on a flat stretch of wall: the wall's own face
        # there, as near as A's, is the true surface, so it is the reference (a slanted face of A
        # would make a ghost hit). Otherwise the hidden corner is just left out below.
        ref_v, ref_n, inc_v, inc_n, edge, ref_is_a = verts_b, normals_b, verts_a, normals_a, edge_b, False
        inc_edge = _incident_edge(inc_n, ref_n[edge], frozenset())
        count_inc = len(inc_v)
        i1, i2 = inc_edge, (inc_edge + 1) % count_inc
    nx, ny = ref_n[edge]
    p1, p2 = inc_v[i1], inc_v[i2]

    r1 = ref_v[edge]
    r2 = ref_v[(edge + 1) % len(ref_v)]
    tx, ty = r2[0] - r1[0], r2[1] - r1[1]
    tlen = (tx * tx + ty * ty) ** 0.5
    tx, ty = tx / tlen, ty / tlen

    # Clip the incident segment to the slab between the reference face's two side planes.
    # Feature ids: an unclipped point keeps its incident vertex; a clipped one takes the side plane.
    points = [(p1[0], p1[1], i1), (p2[0], p2[1], i2)]
    lo = tx * r1[0] + ty * r1[1]
    hi = tx * r2[0] + ty * r2[1]
    points = _clip(points, -tx, -ty, -lo, 100)
    if len(points) < 2:
        return None
    points = _clip(points, tx, ty, hi, 101)
    if len(points) < 2:
        return None

    face_offset = nx * r1[0] + ny * r1[1]
    contacts = []
    base_id = (edge * 128 + inc_edge) * 2 + (0 if ref_is_a else 1)
    for px, py, feature in points:
        sep = nx * px + ny * py - face_offset
        if ref_is_a and feature in hidden_b:
            continue  # a wall's corner on a flat stretch of wall: the faces around it answer for it
        if sep <= margin:
            contacts.append(RawContact(
                x=px - 0.5 * sep * nx, y=py - 0.5 * sep * ny, separation=sep,
                feature=base_id * 256 + feature, ref_is_a=ref_is_a,
                clip_x=px, clip_y=py, face_x=r1[0], face_y=r1[1],
            ))
    if not contacts:
        return None
    normal = (nx, ny) if ref_is_a else (-nx, -ny)
    return normal, contacts


def _incident_edge(normals: list[Vec], reference: Vec, skip: frozenset[int]) -> int:
    """The face most opposed to the reference normal (a wall's internal edges face nothing)."""
    nx, ny = reference
    best, lowest = 0, 1e300
    for i, (mx, my) in enumerate(normals):
        d = mx * nx + my * ny
        if d < lowest and i not in skip:
            lowest, best = d, i
    return best


def _clip(points: list[tuple[float, float, int]], nx: float, ny: float, offset: float, plane_id: int
          ) -> list[tuple[float, float, int]]:
    """Keep the part of a segment where n·p <= offset (Sutherland-Hodgman on one plane)."""
    (x0, y0, f0), (x1, y1, f1) = points
    d0 = nx * x0 + ny * y0 - offset
    d1 = nx * x1 + ny * y1 - offset
    out = []
    if d0 <= 0.0:
        out.append((x0, y0, f0))
    if d1 <= 0.0:
        out.append((x1, y1, f1))
    if d0 * d1 < 0.0:
        t = d0 / (d0 - d1)
        out.append((x0 + t * (x1 - x0), y0 + t * (y1 - y0), plane_id))
    return out
