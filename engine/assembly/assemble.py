"""The one assembler: a world spec and the accuracy knobs -> an esper world holding the spec's
entities and only the stages (from the one stage table) that its effects call for."""

from __future__ import annotations

import functools
import itertools
from collections.abc import Iterable, Sequence

import esper
import numpy as np

from polygolf.engine.assembly.effects import effects_for
from polygolf.engine.assembly.simulation import Simulation
from polygolf.engine.assembly.spec import DynamicPart, WorldSpec
from polygolf.engine.assembly.stages import stages_for
from polygolf.engine.components import Body, Collider, Material, Name, Wall
from polygolf.engine.components.resources import Resources, StaticWorld, StepConfig
from polygolf.engine.physics import polygon
from polygolf.engine.physics.geometry import ConvexSet
from polygolf.engine.physics.grid import BoxGrid
from polygolf.engine.physics.mass import mass_properties
from polygolf.engine.physics.presets import DEFAULT_PRESET, PRESETS, Knobs, preset
from polygolf.engine.physics.seams import PROBE, covered_features

_world_ids = itertools.count(1)


def make_collider(outline: polygon.Outline, material: Material) -> Collider:
    """Collider of a normalised outline (CCW, centroid at the origin)."""
    shape, radius, thickness = _collider_geometry(tuple(outline))
    return Collider(outline=tuple(outline), shape=shape, radius=radius, material=material, thickness=thickness)


@functools.lru_cache(maxsize=256)
def _collider_geometry(outline: polygon.Outline) -> tuple[ConvexSet, float, float]:
    """Convex pieces, bounding radius and thinnest width of an outline, worked out once per shape
    (a search puts a thousand balls of one shape in a world; a `ConvexSet` is never changed)."""
    pieces = tuple(polygon.convex_pieces(outline))
    return (ConvexSet.of(pieces, [polygon.edge_normals(p) for p in pieces]), polygon.bounding_radius(outline),
            min(polygon.min_width(p) for p in pieces))


def make_body(outline: polygon.Outline, position: Sequence[float], density: float, angle: float = 0.0,
              velocity: Sequence[float] = (0.0, 0.0), spin: float = 0.0, rotates: bool = True,
              asleep: bool = False) -> Body:
    """Dynamic body with the exact mass and inertia of its outline. `rotates=False` (no `spin`
    effect) gives infinite inertia: contacts then cannot turn it."""
    return Body.on_rows([_body_row(outline, position, density, angle, velocity, spin, rotates, asleep)])[0]


def make_bodies(parts: Sequence[DynamicPart], rotates: bool) -> list[Body]:
    """`make_body` of each part, their rows made as one array."""
    return Body.on_rows([_body_row(p.outline, p.position, p.density, p.angle, p.velocity, p.spin, rotates, p.asleep)
                         for p in parts])


def _body_row(outline: polygon.Outline, position: Sequence[float], density: float, angle: float,
              velocity: Sequence[float], spin: float, rotates: bool, asleep: bool) -> list[float]:
    mass, inertia, inv_mass, inv_inertia = _masses(tuple(outline), density, rotates)
    return Body.row(float(position[0]), float(position[1]), angle, float(velocity[0]), float(velocity[1]),
                    spin if rotates else 0.0, mass, inertia, inv_mass, inv_inertia, asleep)


@functools.lru_cache(maxsize=256)
def _masses(outline: polygon.Outline, density: float, rotates: bool) -> tuple[float, float, float, float]:
    """Mass, inertia and their inverses (`Body.dynamic`'s), once per shape, density and whether it
    turns (a search puts a thousand balls of one shape in a world)."""
    props = mass_properties(outline, density)
    body = Body.dynamic(0.0, 0.0, props.mass, props.inertia)
    return body.mass, body.inertia, body.inv_mass, body.inv_inertia if rotates else 0.0


def make_wall(outline: Sequence[polygon.Vec], material: Material) -> Wall:
    """Static wall from a world-space CCW outline."""
    outline = tuple(outline)
    pieces = tuple(polygon.convex_pieces(outline))

    def box(points: Iterable[polygon.Vec]) -> tuple[float, float, float, float]:
        xs, ys = zip(*points)
        return min(xs), min(ys), max(xs), max(ys)

    nothing_covered = tuple(frozenset() for _ in pieces)  # until mark_seams sees the other walls
    return Wall(outline=outline, pieces=pieces, normals=tuple(polygon.edge_normals(p) for p in pieces),
                material=material, piece_aabbs=tuple(box(p) for p in pieces), internal=nothing_covered,
                hidden=nothing_covered)


def mark_seams(walls: Sequence[Wall]) -> None:
    """Tell every wall piece which of its edges and vertices other pieces cover (physics.seams)."""
    internal, hidden, reflex = _seams(tuple(w.pieces for w in walls), tuple(w.normals for w in walls))
    start = 0
    for w in walls:
        count = len(w.pieces)
        w.internal, w.hidden = tuple(internal[start:start + count]), tuple(hidden[start:start + count])
        w.reflex = tuple(reflex[start:start + count])
        start += count


@functools.lru_cache(maxsize=64)
def _seams(pieces: tuple[tuple[polygon.Outline, ...], ...], normals: tuple[tuple[tuple[polygon.Vec, ...], ...], ...]
           ) -> tuple[list[frozenset[int]], list[frozenset[int]], list[frozenset[int]]]:
    """`covered_features` of every piece of these walls, worked out once for a set of walls (a hole's
    walls are the same each time its world is built: a restart, every shot preview)."""
    flat = [piece for wall in pieces for piece in wall]
    boxes = np.array([(min(x for x, _ in p), min(y for _, y in p), max(x for x, _ in p), max(y for _, y in p))
                      for p in flat], dtype=np.float64).reshape(-1, 4)
    index = BoxGrid(boxes + (-2 * PROBE, -2 * PROBE, 2 * PROBE, 2 * PROBE), 1.0)
    return covered_features(flat, [n for wall in normals for n in wall], lambda i: index.query(boxes[i]).tolist())


def resolve_knobs(knobs: Knobs | str | None, default: str | None = None) -> tuple[str, Knobs]:
    """(preset name, knobs): a preset by name, the given knobs ("custom" unless they are a preset's),
    or `default`, then balanced."""
    if knobs is None or isinstance(knobs, str):
        name = knobs or default or DEFAULT_PRESET
        return name, preset(name)
    return preset_name(knobs), knobs


def preset_name(knobs: Knobs) -> str:
    return next((name for name, k in PRESETS.items() if k == knobs), "custom")


def assemble(spec: WorldSpec, knobs: Knobs | str | None = None) -> Simulation:
    """A ready-to-step simulation of `spec`. `knobs` defaults to the spec's preset, then balanced."""
    name, knobs = resolve_knobs(knobs, spec.preset)
    effects = effects_for(spec, knobs.substeps)
    rotates = "spin" in effects

    world = f"{spec.name}-{next(_world_ids)}"
    esper.switch_world(world)
    names: dict[int, str] = {}
    # Bodies of one outline and one material share their collider (a component nothing changes): a
    # fan of shots puts a thousand copies of one ball in a world.
    colliders: dict[tuple[int, int], Collider] = {}
    for part, body in zip(spec.bodies, make_bodies(spec.bodies, rotates)):
        same = (id(part.outline), id(part.material))
        collider = colliders.get(same)
        if collider is None:
            collider = colliders[same] = make_collider(part.outline, part.material)
        components: list[object] = [body, collider, Name(part.name), *part.extras]
        if part.drag is not None:
            components.append(part.drag)
        names[esper.create_entity(*components)] = part.name
    radius = max((collider.radius for collider in colliders.values()), default=0.0)
    for components in spec.entities:
        esper.create_entity(*components)

    walls = [make_wall(part.outline, part.material) for part in spec.walls]
    mark_seams(walls)
    statics = StaticWorld.of([(esper.create_entity(wall, *part.extras), wall) for part, wall in zip(spec.walls, walls)],
                             spec.cell_size or max(1.0, 4.0 * radius))
    for part in spec.kinematic:
        # no inverse mass or inertia: nothing pushes it
        body = Body(x=part.position[0], y=part.position[1], angle=part.angle, spin=part.spin)
        esper.create_entity(body, make_collider(part.outline, part.material), Name(part.name), *part.extras)

    res = Resources(config=StepConfig(knobs=knobs, effects=frozenset(effects), gravity=tuple(spec.gravity),
                                      collide_bodies=spec.collide_bodies, sweep_bodies=spec.sweep_bodies),
                    statics=statics)
    processors = [stage.processor(res) for stage in stages_for(effects, spec, knobs)]
    return Simulation(world, res, processors, names, preset_name=name, reasons=effects, scene_name=spec.name)
