"""A world spec: everything a world is built from, whatever the content it came from.

A scene and a hole both become one of these (`loading.scene.scene_spec`, `golf.world.hole_spec`), and
one assembler builds any world from a spec and the accuracy knobs (`assembly.assemble`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from polygolf.engine.components import Drag, Material
from polygolf.engine.physics.polygon import Outline, Vec, bounding_radius


@dataclass
class DynamicPart:
    """A dynamic body: outline about its centroid, placed at `position`."""

    name: str
    outline: Outline
    position: Vec
    density: float
    material: Material
    angle: float = 0.0  # radians
    velocity: Vec = (0.0, 0.0)
    spin: float = 0.0
    drag: Drag | None = None
    asleep: bool = False
    top_speed: float | None = None  # fastest it can go (m/s of its rim); default: its starting motion
    extras: tuple[object, ...] = ()  # more components for its entity

    @property
    def fastest(self) -> float:
        if self.top_speed is not None:
            return self.top_speed
        speed = math.hypot(*self.velocity)  # (the rim's share only if it turns: a fan's thousand balls do not)
        return speed + abs(self.spin) * bounding_radius(self.outline) if self.spin else speed


@dataclass
class WallPart:
    """A static wall: outline in world coordinates."""

    outline: Outline
    material: Material
    extras: tuple[object, ...] = ()


@dataclass
class KinematicPart:
    """A body driven at a set spin that no contact can slow (a windmill)."""

    name: str
    outline: Outline  # about its pivot
    position: Vec
    spin: float
    material: Material = field(default_factory=Material)
    extras: tuple[object, ...] = ()
    angle: float = 0.0  # radians at the start (a windmill already turning when the world is built)


@dataclass
class WorldSpec:
    name: str
    bodies: list[DynamicPart]
    walls: list[WallPart] = field(default_factory=list)
    kinematic: list[KinematicPart] = field(default_factory=list)
    entities: list[tuple[object, ...]] = field(default_factory=list)  # other entities, by their components
    gravity: Vec = (0.0, 0.0)
    rules: dict[str, str] = field(default_factory=dict)  # effects always present, and why (the game's rules)
    content_effects: dict[str, str] = field(default_factory=dict)  # effects the content brings (hazards), why
    listed: tuple[str, ...] | None = None  # effects the content lists itself; None: derived
    listed_by: str = "the scene"
    preset: str | None = None  # the content's own preset, if it names one
    cell_size: float | None = None  # broadphase grid cell; default 4 body radii (at least 1 m)
    collide_bodies: bool = True  # False: dynamic bodies pass through each other (parallel shots)
    sweep_bodies: bool = False  # continuous collision between dynamic bodies beyond the slop (`StepConfig`)

    @property
    def touchable(self) -> bool:
        """Whether anything can touch anything: walls, a kinematic body, or bodies that meet."""
        return bool(self.walls) or (bool(self.kinematic) and bool(self.bodies)) or (
            self.collide_bodies and len(self.bodies) > 1)
