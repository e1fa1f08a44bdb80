"""What a shot does to the ball: a push at a point, as an impulse, with its two parts capped apart.

The arrow the player draws sets the linear velocity the shot asks for (SHOT_POWER m/s for every
metre of arrow, so every polygon goes as far for the same arrow: the push is scaled by the ball's
mass). Applied at the grab point r, that impulse J also turns the ball: Δω = (r × J) / I. The linear
part is capped at MAX_SHOT_SPEED; the angular part is capped on its own, both absolutely
(MAX_SHOT_SPIN) and relative to the linear part (the rim may not move faster than SPIN_RATIO times
the ball), so a soft shot cannot carry a huge spin that a wall would turn into speed.
"""

from __future__ import annotations

import math

from polygolf.engine.physics.settings import MAX_SHOT_SPEED, MAX_SHOT_SPIN, SHOT_POWER, SPIN_RATIO

MIN_SHOT_SPEED = 0.05  # m/s; a shorter arrow is a click, not a shot


def clamp_arrow(arrow: tuple[float, float]) -> tuple[float, float] | None:
    """The arrow a shot actually uses: no longer than the fastest shot's, or None for a click."""
    length = math.hypot(*arrow)
    if length * SHOT_POWER < MIN_SHOT_SPEED:
        return None
    full = MAX_SHOT_SPEED / SHOT_POWER
    if length > full:
        return arrow[0] * full / length, arrow[1] * full / length
    return arrow


def shot_power(arrow: tuple[float, float]) -> float:
    """How strong a shot the arrow asks for: 0 to 1 (the fastest shot)."""
    return min(1.0, math.hypot(*arrow) * SHOT_POWER / MAX_SHOT_SPEED)


def shot_velocity(mass: float, inertia: float, radius: float, rx: float, ry: float, dx: float, dy: float,
                  rotates: bool = True) -> tuple[float, float, float]:
    """Velocity change (dvx, dvy, dspin) of a shot with arrow (dx, dy) grabbed at r from the centroid."""
    vx, vy = SHOT_POWER * dx, SHOT_POWER * dy
    speed = math.hypot(vx, vy)
    if speed > MAX_SHOT_SPEED:
        vx, vy, speed = vx * MAX_SHOT_SPEED / speed, vy * MAX_SHOT_SPEED / speed, MAX_SHOT_SPEED
    if not rotates or inertia <= 0.0:
        return vx, vy, 0.0
    jx, jy = mass * vx, mass * vy
    spin = (rx * jy - ry * jx) / inertia
    cap = min(MAX_SHOT_SPIN, SPIN_RATIO * speed / radius)
    return vx, vy, max(-cap, min(cap, spin))
