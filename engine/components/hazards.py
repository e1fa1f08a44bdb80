"""Hazards: areas of the green (sand, ice, slope, water) and special obstacles (bumper, windmill).

An area entity carries a `Region` and one kind marker; a bumper is a `Wall` with a `Bumper`; a
windmill is a kinematic `Body` + `Collider` with a `Windmill`.
"""

from collections.abc import Iterable
from dataclasses import dataclass

from polygolf.engine.physics.polygon import Outline, contains

Circle = tuple[float, float, float]  # x, y, radius


@dataclass(slots=True)
class Region:
    """A polygonal area of the green, in world coordinates."""

    outline: Outline
    aabb: tuple[float, float, float, float]

    def contains(self, x: float, y: float) -> bool:
        x0, y0, x1, y1 = self.aabb
        return x0 <= x <= x1 and y0 <= y <= y1 and contains(self.outline, x, y)


@dataclass(slots=True)
class Sand:
    """Heavy going: the green's drag is multiplied by `drag_scale` while the ball is in it."""

    drag_scale: float = 5.0


@dataclass(slots=True)
class Ice:
    """Hardly any drag: the green's drag is multiplied by `drag_scale` (well below 1)."""

    drag_scale: float = 0.08


@dataclass(slots=True)
class Slope:
    """A constant push (m/s²) on the ball while it is on the slope."""

    push: tuple[float, float]


@dataclass(slots=True)
class Water:
    """A ball whose centre goes in costs `penalty` strokes and goes back where it last rested, unless
    that spot is in a windmill's sweep (`keep_out`: circles x, y, r), where an arm would crush it, or
    another ball now lies there; then it goes to the nearest of `drops` (spots where a ball fits,
    clear of walls, water and sweeps) that no ball covers, and failing that to `fallback` (the tee)."""

    penalty: int = 1
    keep_out: tuple[tuple[float, float, float], ...] = ()
    fallback: tuple[float, float] | None = None
    drops: tuple[tuple[float, float], ...] = ()

    def put_back(self, x: float, y: float, others: tuple[Circle, ...] = ()) -> tuple[float, float]:
        """Where the ball goes; `others`: the other balls as circles (x, y, clearance they need)."""
        spot = free_spot((x, y), self.drops, others, self.keep_out)
        if spot is not None:
            return spot
        return self.fallback if self.fallback is not None else (x, y)


def free_spot(spot: tuple[float, float], candidates: Iterable[tuple[float, float]], others: Iterable[Circle],
              blocked: Iterable[Circle] = ()) -> tuple[float, float] | None:
    """`spot` if no circle of `others` or `blocked` covers it, else the nearest of `candidates` that no
    circle of `others` covers, else None: where a ball may be put down without landing on another."""
    others = tuple(others)

    def free(px: float, py: float, circles: Iterable[Circle] = others) -> bool:
        return all((px - cx) ** 2 + (py - cy) ** 2 >= r * r for cx, cy, r in circles)

    if free(*spot) and free(*spot, blocked):
        return spot
    clear = [c for c in candidates if free(*c)]
    return min(clear, key=lambda c: (c[0] - spot[0]) ** 2 + (c[1] - spot[1]) ** 2) if clear else None


@dataclass(slots=True)
class Bumper:
    """A wall that kicks: every impact leaves `kick` m/s faster along the normal than restitution
    alone would. `lit` counts down after a hit, for drawing."""

    kick: float
    lit: float = 0.0


@dataclass(frozen=True, slots=True)
class Windmill:
    """A kinematic obstacle turning at `speed` rad/s (counter-clockwise) about its centroid; set once
    (the windmill stage packs the speeds when the world's entities change)."""

    speed: float
