"""Contact manifolds between two bodies, merged across convex pieces.

A non-convex body touches a wall through several convex pieces. Solving each piece's contact on its
own is the original PolyGolf fault (a star landing flat on two tips got two full impulses). Here every
point between the same two bodies that shares a normal goes into one manifold, reduced to the two
points that span the contact, and the solver treats those two points as one block.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

from polygolf.engine.physics.body import Body, Material
from polygolf.engine.physics.collide import CLIP_X, CLIP_Y, FACE_X, FACE_Y, NX, NY, REF_IS_A, SEP, X, Y
from polygolf.engine.physics.settings import RESTITUTION_THRESHOLD

# Normals closer than this (cosine) are the same contact plane.
SAME_NORMAL_COS = math.cos(math.radians(2.0))


@dataclass(slots=True)
class ContactPoint:
    x: float
    y: float
    separation: float
    key: tuple  # (other piece, own piece, feature): matches this point across substeps
    restitution: float
    friction: float
    # Local geometry for non-linear position correction: the reference face in its body's frame and
    # the incident point in its body's frame.
    ref_is_a: bool = True
    local_normal: tuple[float, float] = (0.0, 0.0)
    local_face: tuple[float, float] = (0.0, 0.0)
    local_clip: tuple[float, float] = (0.0, 0.0)
    # Solver state.
    ra_x: float = 0.0
    ra_y: float = 0.0
    rb_x: float = 0.0
    rb_y: float = 0.0
    normal_mass: float = 0.0
    tangent_mass: float = 0.0
    normal_impulse: float = 0.0
    tangent_impulse: float = 0.0
    push_impulse: float = 0.0
    approach_speed: float = 0.0  # relative normal velocity before solving; negative when closing


@dataclass(slots=True)
class Manifold:
    """Up to two points between body A and body B sharing one normal (from A to B)."""

    entity_a: int
    entity_b: int  # -1 for the static world
    body_a: Body
    body_b: Body
    nx: float
    ny: float
    points: list[ContactPoint] = field(default_factory=list)
    # Block solver data for two-point manifolds (filled by the solver).
    k11: float = 0.0
    k12: float = 0.0
    k22: float = 0.0
    block: bool = False


def _to_local(body: Body, x: float, y: float) -> tuple[float, float]:
    c, s = math.cos(body.angle), math.sin(body.angle)
    dx, dy = x - body.x, y - body.y
    return c * dx + s * dy, -s * dx + c * dy


def _rotate_to_local(body: Body, x: float, y: float) -> tuple[float, float]:
    c, s = math.cos(body.angle), math.sin(body.angle)
    return c * x + s * y, -s * x + c * y


def make_point(row: list[float], key: tuple, body_a: Body, body_b: Body, material: Material,
               ngs: bool) -> ContactPoint:
    """A solver point from a contact row of `collide.collide_sets` (a list, as `tolist` gives)."""
    ref_is_a = row[REF_IS_A] != 0.0
    point = ContactPoint(x=row[X], y=row[Y], separation=row[SEP], key=key, restitution=material.restitution,
                         friction=material.friction, ref_is_a=ref_is_a)
    if ngs:
        ref, inc = (body_a, body_b) if ref_is_a else (body_b, body_a)
        face_normal = (row[NX], row[NY]) if ref_is_a else (-row[NX], -row[NY])
        point.local_normal = _rotate_to_local(ref, *face_normal)
        point.local_face = _to_local(ref, row[FACE_X], row[FACE_Y])
        point.local_clip = _to_local(inc, row[CLIP_X], row[CLIP_Y])
    return point


def reduce_points(points: list[ContactPoint], nx: float, ny: float) -> list[ContactPoint]:
    """Keep the two points that span the contact along the tangent (the deepest breaks ties)."""
    if len(points) <= 2:
        return points
    tx, ty = ny, -nx
    lo = min(points, key=lambda p: (p.x * tx + p.y * ty, p.separation))
    hi = max(points, key=lambda p: (p.x * tx + p.y * ty, -p.separation))
    if lo is hi:
        return [min(points, key=lambda p: p.separation)]
    return [lo, hi]


def group_by_normal(raw: list[tuple[float, float, ContactPoint]]) -> list[tuple[float, float, list[ContactPoint]]]:
    """Collect (normal, point) pairs into planes of (nearly) equal normal."""
    groups: list[tuple[float, float, list[ContactPoint]]] = []
    for nx, ny, point in raw:
        for gx, gy, members in groups:
            if gx * nx + gy * ny >= SAME_NORMAL_COS:
                members.append(point)
                break
        else:
            groups.append((nx, ny, [point]))
    return groups


def combine(a: Material, b: Material) -> Material:
    """Materials multiply (design notes): walls default to 1.0, so the ball's own values rule."""
    return Material(restitution=a.restitution * b.restitution, friction=a.friction * b.friction)


Carried = dict[tuple, tuple[float, float]]


def persistent_impulses(manifolds: list[Manifold]) -> Carried:
    """Last substep's impulses of points that were resting, keyed by (entity a, entity b, point key).

    Only persistent contacts are warm-started: an impact's impulse belongs to that impact, and
    re-applying it to a contact that is now opening would add energy."""
    carried: Carried = {}
    for m in manifolds:
        for p in m.points:
            if (p.normal_impulse or p.tangent_impulse) and p.approach_speed >= -RESTITUTION_THRESHOLD:
                carried[(m.entity_a, m.entity_b, p.key)] = (p.normal_impulse, p.tangent_impulse)
    return carried


def contact_points(rows: list[list[float]], body_a: Body, body_b: Body, material: Material, ngs: bool,
                   key: Callable[[list[float]], tuple]) -> list[tuple[float, float, ContactPoint]]:
    """(normal, point) for every contact row between two bodies; `key(row)` names a point so it can
    be matched in the next substep."""
    return [(row[NX], row[NY], make_point(row, key(row), body_a, body_b, material, ngs)) for row in rows]


def add_manifolds(out: list[Manifold], raw: list[tuple[float, float, ContactPoint]], entity_a: int, entity_b: int,
                  body_a: Body, body_b: Body, carried: Carried) -> float:
    """Group the points between two bodies into one manifold per normal (at most two points each),
    carry over the impulses of persisting points, append to `out`; returns the deepest overlap."""
    deepest = 0.0
    for nx, ny, points in group_by_normal(raw):
        points = reduce_points(points, nx, ny)
        for p in points:
            if -p.separation > deepest:
                deepest = -p.separation
            previous = carried.get((entity_a, entity_b, p.key))
            if previous is not None:
                p.normal_impulse, p.tangent_impulse = previous
        out.append(Manifold(entity_a=entity_a, entity_b=entity_b, body_a=body_a, body_b=body_b, nx=nx, ny=ny,
                            points=points))
    return deepest
