"""Physics scenes (`content/scenes/*.yaml`): the typed form of the design notes' scene contract.

Angles are degrees in YAML and radians everywhere after loading. A body's `position` is where its
centroid goes; a `vertices` shape is re-centred on its centroid.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Annotated, Any, Literal

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, field_validator, model_validator

from polygolf.engine.assembly.assemble import assemble
from polygolf.engine.assembly.simulation import Simulation
from polygolf.engine.assembly.spec import DynamicPart, WallPart, WorldSpec
from polygolf.engine.components import Drag, Material
from polygolf.engine.loading.limits import (
    MAX_BODIES,
    MAX_RADIUS,
    MAX_STAR_POINTS,
    MAX_WALL_VERTICES,
    MAX_WALLS,
    Acceleration,
    Angle,
    Density,
    Friction,
    Half,
    Name,
    Point,
    Radius,
    Rate,
    Restitution,
    Seed,
    Speed,
    Spin,
    check_start_pairs,
    check_vertex_budget,
    count,
)
from polygolf.engine.loading.yamlsource import load
from polygolf.engine.physics import polygon
from polygolf.engine.physics.presets import PRESETS, Knobs

EFFECTS = ("drag", "gravity", "spin", "friction", "restitution", "ccd")
Effect = Literal["drag", "gravity", "spin", "friction", "restitution", "ccd"]


class Strict_(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class RandomShape(Strict_):
    seed: Seed
    vertices: count(polygon.MIN_SIDES, polygon.MAX_SIDES)


class ShapeSpec(Strict_):
    """Exactly one of regular / star / vertices / random; `radius` for all but `vertices`."""

    regular: count(polygon.MIN_SIDES, polygon.MAX_SIDES) | None = None
    star: tuple[count(5, MAX_STAR_POINTS), count(2, MAX_STAR_POINTS // 2)] | None = None
    vertices: Annotated[list[Point], Field(min_length=3, max_length=polygon.MAX_SIDES)] | None = None
    random: RandomShape | None = None
    radius: Radius | None = None

    @model_validator(mode="after")
    def _one_kind(self) -> ShapeSpec:
        kinds = [k for k in ("regular", "star", "vertices", "random") if getattr(self, k) is not None]
        if len(kinds) != 1:
            raise ValueError("give exactly one of regular, star, vertices, random")
        if kinds[0] == "vertices":
            if self.radius is not None:
                raise ValueError("radius does not apply to a vertices shape")
        elif self.radius is None:
            raise ValueError(f"a {kinds[0]} shape needs a radius")
        outline = self.outline()  # raises PolygonError (a ValueError) with the reason
        if kinds[0] == "vertices" and polygon.bounding_radius(outline) > MAX_RADIUS:
            raise ValueError(f"a body reaches {polygon.bounding_radius(outline):,.4g} m from its centroid: at most "
                             f"{MAX_RADIUS:g} m, as a radius")
        return self

    def outline(self) -> polygon.Outline:
        """Counter-clockwise outline about the centroid."""
        if self.regular is not None:
            raw = polygon.regular_polygon(self.regular, self.radius)
        elif self.star is not None:
            raw = polygon.star_polygon(self.star[0], self.star[1], self.radius)
        elif self.random is not None:
            raw = polygon.random_polygon(self.random.seed, self.random.vertices, self.radius)
        else:
            raw = self.vertices
        return polygon.normalise(raw)[0]

    def label(self) -> str:
        if self.regular is not None:
            return f"{self.regular}-gon"
        if self.star is not None:
            return f"star {{{self.star[0]}/{self.star[1]}}}"
        if self.random is not None:
            return f"random #{self.random.seed} ({self.random.vertices} vertices)"
        return f"polygon ({len(self.vertices)} vertices)"


class DragSpec(Strict_):
    linear: Rate = 0.0  # 1/s, exponential
    angular: Rate = 0.0  # 1/s, exponential
    rolling: Rate = 0.0  # m/s², constant deceleration
    rolling_angular: Rate = 0.0  # rad/s², constant deceleration

    @property
    def any(self) -> bool:
        return bool(self.linear or self.angular or self.rolling or self.rolling_angular)


class BodySpec(Strict_):
    name: Name
    shape: ShapeSpec
    angle: Angle = 0.0  # degrees
    position: Point
    velocity: tuple[Speed, Speed] = (0.0, 0.0)
    spin: Spin = 0.0  # rad/s
    density: Density = 1.0
    restitution: Restitution = 0.5
    friction: Friction = 0.2
    drag: DragSpec = DragSpec()


class BoxSpec(Strict_):
    center: Point
    half: tuple[Half, Half]
    angle: Angle = 0.0  # degrees

    def outline(self) -> list[tuple[float, float]]:
        (cx, cy), (hx, hy) = self.center, self.half
        return list(polygon.placed(((-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy)), cx, cy, math.radians(self.angle)))

    @model_validator(mode="after")
    def _has_area(self) -> BoxSpec:
        """A box too thin for its place: its corners meet (or enclose nothing) in floating point. Said
        as such, not as the polygon it makes (QA8: 1e-300 m thick was "repeated vertices")."""
        try:
            polygon.normalise(self.outline())
        except polygon.PolygonError:
            raise ValueError(f"a box of half-size {list(self.half)} is too thin to have an area where it stands") \
                from None
        return self


class WallSpec(Strict_):
    box: BoxSpec | None = None
    polygon: Annotated[list[Point], Field(min_length=3, max_length=MAX_WALL_VERTICES)] | None = None
    restitution: Restitution = 1.0
    friction: Friction = 1.0

    @model_validator(mode="after")
    def _one_kind(self) -> WallSpec:
        if (self.box is None) == (self.polygon is None):
            raise ValueError("a wall is either a box or a polygon")
        self.outline()
        return self

    @property
    def vertex_count(self) -> int:
        return 4 if self.box is not None else len(self.polygon)

    def outline(self) -> list[tuple[float, float]]:
        """World-space CCW outline (not re-centred: walls stay where they are written)."""
        raw = self.box.outline() if self.box is not None else self.polygon
        local, (cx, cy) = polygon.normalise(raw)
        return [(x + cx, y + cy) for x, y in local]


def _raw_list(value: Any) -> list:
    return value if isinstance(value, list) else []


def _raw_count(value: Any, most: int) -> int:
    """A count as written, if it is one its own field accepts (else 0: that field's check says why)."""
    return value if isinstance(value, int) and not isinstance(value, bool) and 0 < value <= most else 0


def _raw_vertices(shape: Any) -> int:
    """How many vertices a shape as written will have (0 where it is malformed: its own check says so)."""
    if not isinstance(shape, dict):
        return 0
    if shape.get("regular") is not None:
        return _raw_count(shape["regular"], polygon.MAX_SIDES)
    star = shape.get("star")
    if isinstance(star, list) and star:
        return 2 * _raw_count(star[0], MAX_STAR_POINTS)
    if isinstance(shape.get("vertices"), list):
        return _raw_count(len(shape["vertices"]), polygon.MAX_SIDES)
    random = shape.get("random")
    return _raw_count(random.get("vertices"), polygon.MAX_SIDES) if isinstance(random, dict) else 0


def _raw_wall_vertices(wall: Any) -> int:
    if not isinstance(wall, dict):
        return 0
    if isinstance(wall.get("polygon"), list):
        return _raw_count(len(wall["polygon"]), MAX_WALL_VERTICES)
    return 4 * (wall.get("box") is not None)


class Scene(Strict_):
    name: Name
    preset: Literal[tuple(PRESETS)] | None = None  # type: ignore[valid-type]
    effects: list[Effect] | None = None
    gravity: tuple[Acceleration, Acceleration] = (0.0, 0.0)  # m/s², a push on every body (a tilted table)
    bodies: Annotated[list[BodySpec], Field(min_length=1, max_length=MAX_BODIES)]
    walls: Annotated[list[WallSpec], Field(max_length=MAX_WALLS)] = []
    hole: Name | None = None  # COURSE:N, or a hole file beside the scene: its walls, hazards, green and cup
    collide_bodies: bool = True  # false: bodies meet walls but not each other (parallel shots)

    @model_validator(mode="before")
    @classmethod
    def _vertex_budget_first(cls, data: Any) -> Any:
        """The vertex budget from the file's own counts, before any outline is built and checked: a
        file of 2 000 stars of 128 points each took 70 s to check one by one before it was refused.
        (Malformed entries are left to the fields' own checks; `_budgets` counts again.)"""
        if isinstance(data, dict):
            check_vertex_budget(sum(_raw_vertices((body or {}).get("shape") if isinstance(body, dict) else None)
                                    for body in _raw_list(data.get("bodies")))
                                + sum(_raw_wall_vertices(wall) for wall in _raw_list(data.get("walls"))))
        return data

    @model_validator(mode="after")
    def _budgets(self) -> Scene:
        """The vertex budget, then room to start (each body's outline built once for both)."""
        outlines = [b.shape.outline() for b in self.bodies]
        check_vertex_budget(sum(len(o) for o in outlines) + sum(w.vertex_count for w in self.walls))
        if self.collide_bodies:
            check_start_pairs(np.array([b.position for b in self.bodies], dtype=np.float64).reshape(-1, 2),
                              np.array([polygon.bounding_radius(o) for o in outlines]))
        return self

    @field_validator("bodies")
    @classmethod
    def _unique_names(cls, bodies: list[BodySpec]) -> list[BodySpec]:
        """(A check of the list, not of the whole scene: the error names the bodies' line and both
        bodies, not line 1.)"""
        seen: dict[str, int] = {}
        for k, body in enumerate(bodies):
            if body.name in seen:
                raise ValueError(f"bodies[{seen[body.name]}] and bodies[{k}] are both named {body.name!r}")
            seen[body.name] = k
        return bodies


def load_scene(path: str | Path) -> Scene:
    """Load and validate a scene; raises ContentError with file, line and field."""
    return load(Scene, path)


def scene_spec(scene: Scene) -> WorldSpec:
    """The world spec of a scene: its bodies, walls and gravity, its preset and effect list."""
    bodies = [DynamicPart(name=b.name, outline=b.shape.outline(), position=b.position, density=b.density,
                          material=Material(b.restitution, b.friction), angle=math.radians(b.angle),
                          velocity=b.velocity, spin=b.spin, drag=Drag(**b.drag.model_dump()) if b.drag.any else None)
              for b in scene.bodies]
    walls = [WallPart(tuple(w.outline()), Material(w.restitution, w.friction)) for w in scene.walls]
    listed = tuple(e for e in EFFECTS if e in scene.effects) if scene.effects is not None else None
    return WorldSpec(name=scene.name, bodies=bodies, walls=walls, gravity=scene.gravity, listed=listed,
                     listed_by="the scene", preset=scene.preset, collide_bodies=scene.collide_bodies)


def build_scene(scene: Scene, knobs: Knobs | str | None = None) -> Simulation:
    """A ready-to-step simulation of a scene without a hole (`golf.scenes` builds those too);
    `knobs` defaults to the scene's preset, then balanced."""
    return assemble(scene_spec(scene), knobs)
