"""Time of impact of a moving convex piece against a static convex polygon (or another moving piece),
by conservative advancement.

Mirtich's conservative advancement: at time t the separating-axis distance d is a lower bound on the
true distance, and no point of the piece can close it faster than a bound mu, so the piece may safely
advance by (d - target)/mu. Fixed axes (the wall's face normals) get the sharper bound
max(0, -n.v) + |w|·R, which makes a head-on approach converge in one or two steps. The piece moves
linearly in position and angle over the substep, which is exactly what the integrator did.
"""

from __future__ import annotations

import math

from polygolf.engine.physics.polygon import Vec
from polygolf.engine.physics.settings import GAP_TOLERANCE

MAX_ITERATIONS = 24


def _pose_vertices(local: tuple[Vec, ...], x: float, y: float, angle: float) -> list[Vec]:
    c, s = math.cos(angle), math.sin(angle)
    return [(x + c * px - s * py, y + s * px + c * py) for px, py in local]


def _pose_normals(local: tuple[Vec, ...], angle: float) -> list[Vec]:
    c, s = math.cos(angle), math.sin(angle)
    return [(c * nx - s * ny, s * nx + c * ny) for nx, ny in local]


def time_of_impact(
    piece: tuple[Vec, ...],
    piece_normals: tuple[Vec, ...],
    reach: float,
    start: tuple[float, float, float],
    end: tuple[float, float, float],
    wall: tuple[Vec, ...],
    wall_normals: tuple[Vec, ...],
    target: float,
    tolerance: float,
    allowance: float,
) -> float | None:
    """Fraction of the motion start->end at which the piece first comes within `target` of the wall.

    `piece` is in body coordinates and rotates about the body origin; `reach` is the largest distance
    of its vertices from that origin. Returns None if the piece stays farther than `target` throughout.
    A piece already touching at the start (sliding along the wall, say) is stopped only if it would
    sink `allowance` deeper than it already is: a corner swinging into the wall while another rests
    on it is caught, but sliding is not interrupted.
    """
    x0, y0, a0 = start
    dx, dy, da = end[0] - x0, end[1] - y0, end[2] - a0
    turn = abs(da) * reach  # largest distance any vertex moves by rotation over the whole motion
    general_rate = math.hypot(dx, dy) + turn
    if general_rate <= 0.0:
        return None
    # Per unit of t, wall face k can approach no faster than this; the piece's own faces turn with
    # it, so only the general bound holds for them.
    rates = [max(0.0, -(dx * nx + dy * ny)) + turn for nx, ny in wall_normals]
    rates += [general_rate] * len(piece_normals)

    def separations(t: float) -> list[float]:
        """Separation along every candidate axis at time t: wall faces first, then the piece's."""
        verts = _pose_vertices(piece, x0 + t * dx, y0 + t * dy, a0 + t * da)
        normals = _pose_normals(piece_normals, a0 + t * da)
        return _axis_separations(wall, wall_normals, verts) + _axis_separations(verts, normals, wall)

    return _advance(separations, rates, target, tolerance, allowance)


def pair_time_of_impact(
    piece_a: tuple[Vec, ...], normals_a: tuple[Vec, ...], reach_a: float,
    start_a: tuple[float, float, float], end_a: tuple[float, float, float],
    piece_b: tuple[Vec, ...], normals_b: tuple[Vec, ...], reach_b: float,
    start_b: tuple[float, float, float], end_b: tuple[float, float, float],
    target: float, tolerance: float, allowance: float, at_start: list[float] | None = None,
) -> float | None:
    """The same for two pieces that both move (two bodies): every axis turns with its body, so every
    axis takes the bound on their relative motion, |dA - dB| + |ΔθA|·RA + |ΔθB|·RB. `at_start`: the
    separations at the start poses, if already measured (they do not depend on the motion)."""
    rate = (math.hypot(end_a[0] - start_a[0] - end_b[0] + start_b[0], end_a[1] - start_a[1] - end_b[1] + start_b[1])
            + abs(end_a[2] - start_a[2]) * reach_a + abs(end_b[2] - start_b[2]) * reach_b)
    if rate <= 0.0:
        return None

    def pose(start: tuple[float, float, float], end: tuple[float, float, float], t: float) -> tuple[float, ...]:
        return tuple(s + t * (e - s) for s, e in zip(start, end))

    def separations(t: float) -> list[float]:
        xa, ya, aa = pose(start_a, end_a, t)
        xb, yb, ab = pose(start_b, end_b, t)
        va, vb = _pose_vertices(piece_a, xa, ya, aa), _pose_vertices(piece_b, xb, yb, ab)
        return (_axis_separations(va, _pose_normals(normals_a, aa), vb)
                + _axis_separations(vb, _pose_normals(normals_b, ab), va))

    return _advance(separations, [rate] * (len(piece_a) + len(piece_b)), target, tolerance, allowance, at_start)


def _axis_separations(verts: list[Vec] | tuple[Vec, ...], normals, others: list[Vec] | tuple[Vec, ...]
                      ) -> list[float]:
    """Separation of `others` from each face of `verts`."""
    return [min((ox - vx) * nx + (oy - vy) * ny for ox, oy in others) for (nx, ny), (vx, vy) in zip(normals, verts)]


def _advance(separations, rates: list[float], target: float, tolerance: float, allowance: float,
             at_start: list[float] | None = None) -> float | None:
    """Conservative advancement over t in [0, 1]: the first t at which the separating-axis distance
    comes within `target` (see time_of_impact for `allowance`), or None."""
    seps = separations(0.0) if at_start is None else at_start
    # Already touching (sliding along the wall, say): only sinking `allowance` deeper counts.
    level = target if max(seps) >= target + tolerance else min(max(seps), target) - allowance
    t = 0.0
    for _ in range(MAX_ITERATIONS):
        # Any axis gives a safe step: its separation cannot fall to `level` sooner than this.
        step = max((sep - level) / rate if rate > 0.0 else (math.inf if sep > level else 0.0)
                   for sep, rate in zip(seps, rates))
        t += step
        if t >= 1.0:
            return None
        seps = separations(t)
        if max(seps) < level + tolerance:
            return t
    return t

def reaches(collider, body, wall: tuple[Vec, ...], wall_normals: tuple[Vec, ...], dt: float) -> bool:
    """Whether the body, moving on with its velocity for dt, would press into the wall piece (by more
    than GAP_TOLERANCE: a face that only grazes a corner, level with it, is not a hit)."""
    start = (body.x, body.y, body.angle)
    end = (body.x + body.vx * dt, body.y + body.vy * dt, body.angle + body.spin * dt)
    return any(time_of_impact(piece, collider.normals[i], collider.piece_reach[i], start, end, wall, wall_normals,
                              -GAP_TOLERANCE, GAP_TOLERANCE / 2, 0.0) is not None
               for i, piece in enumerate(collider.pieces))


def pair_reaches(collider_a, a, collider_b, b, dt: float, gap: float = 0.0, may_halt_a: bool = True,
                 may_halt_b: bool = True) -> bool:
    """The same for two bodies: whether they would press into each other (by more than
    GAP_TOLERANCE) within dt, moving on as they are, or with either one halted (if `may_halt_` it:
    it has something else to meet). The solve that follows may stop a body against something else (a
    light ball the heavy block drives into a wall); a kept gap between bodies that then part costs
    nothing, as the solver only stops approach. `gap` (their separation now, if known) rules out at
    once bodies too slow to close it."""
    turn_a, turn_b = abs(a.spin) * collider_a.radius, abs(b.spin) * collider_b.radius
    start_a, start_b = (a.x, a.y, a.angle), (b.x, b.y, b.angle)
    end_a = (a.x + a.vx * dt, a.y + a.vy * dt, a.angle + a.spin * dt)
    end_b = (b.x + b.vx * dt, b.y + b.vy * dt, b.angle + b.spin * dt)
    # Each motion, with the most it can close the gap by (no point moves farther); too little: skip it.
    motions = [((end_a, end_b), math.hypot(a.vx - b.vx, a.vy - b.vy) + turn_a + turn_b)]
    if may_halt_a:
        motions.append(((start_a, end_b), math.hypot(b.vx, b.vy) + turn_b))
    if may_halt_b:
        motions.append(((end_a, start_b), math.hypot(a.vx, a.vy) + turn_a))
    motions = [m for m, speed in motions if speed * dt >= gap + GAP_TOLERANCE and m != (start_a, start_b)]
    if not motions:
        return False
    for i, piece_a in enumerate(collider_a.pieces):
        for j, piece_b in enumerate(collider_b.pieces):
            va = _pose_vertices(piece_a, *start_a)
            vb = _pose_vertices(piece_b, *start_b)
            at_start = (_axis_separations(va, _pose_normals(collider_a.normals[i], a.angle), vb)
                        + _axis_separations(vb, _pose_normals(collider_b.normals[j], b.angle), va))
            for moved_a, moved_b in motions:
                if pair_time_of_impact(piece_a, collider_a.normals[i], collider_a.piece_reach[i], start_a, moved_a,
                                       piece_b, collider_b.normals[j], collider_b.piece_reach[j], start_b, moved_b,
                                       -GAP_TOLERANCE, GAP_TOLERANCE / 2, 0.0, at_start) is not None:
                    return True
    return False
