"""Time of impact of a moving convex piece against a static convex polygon, by conservative advancement.

Mirtich's conservative advancement: at time t the separating-axis distance d is a lower bound on the
true distance, and no point of the piece can close it faster than a bound mu, so the piece may safely
advance by (d - target)/mu. Fixed axes (the wall's face normals) get the sharper bound
max(0, -n.v) + |w|·R, which makes a head-on approach converge in one or two steps. The piece moves
linearly in position and angle over the substep, which is exactly what the integrator did.
"""

from __future__ import annotations

import math

from engine.polygon import Vec

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
) -> float | None:
    """Fraction of the motion start->end at which the piece first comes within `target` of the wall.

    `piece` is in body coordinates and rotates about the body origin; `reach` is the largest distance
    of its vertices from that origin. Returns None if the piece stays farther than `target` throughout,
    or if it is already within `target` at the start (the discrete contact deals with that).
    """
    x0, y0, a0 = start
    dx, dy, da = end[0] - x0, end[1] - y0, end[2] - a0
    turn = abs(da) * reach  # largest distance any vertex moves by rotation over the whole motion
    general_rate = math.hypot(dx, dy) + turn
    if general_rate <= 0.0:
        return None
    # Per unit of t, the wall face k can approach no faster than this.
    wall_rates = [max(0.0, -(dx * nx + dy * ny)) + turn for nx, ny in wall_normals]

    t = 0.0
    for iteration in range(MAX_ITERATIONS):
        verts = _pose_vertices(piece, x0 + t * dx, y0 + t * dy, a0 + t * da)
        best_step = -1.0
        distance = -math.inf
        # The wall's faces: fixed axes with their own approach bound.
        for k, (nx, ny) in enumerate(wall_normals):
            wx, wy = wall[k]
            sep = min((vx - wx) * nx + (vy - wy) * ny for vx, vy in verts)
            distance = max(distance, sep)
            rate = wall_rates[k]
            if sep > target and rate == 0.0:
                return None  # this face separates them for the whole motion
            if rate > 0.0:
                best_step = max(best_step, (sep - target) / rate)
        # The piece's faces: they turn with it, so only the general bound holds.
        for k, (nx, ny) in enumerate(_pose_normals(piece_normals, a0 + t * da)):
            vx, vy = verts[k]
            sep = min((wx - vx) * nx + (wy - vy) * ny for wx, wy in wall)
            distance = max(distance, sep)
            best_step = max(best_step, (sep - target) / general_rate)
        if distance < target + tolerance:
            return None if iteration == 0 else t
        t += best_step
        if t >= 1.0:
            return None
    return t
