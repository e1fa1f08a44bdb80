"""Assembly: content -> components -> an esper world holding only the processors its effects need."""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterable, Sequence

import esper

from engine import polygon
from engine.components import Body, Collider, Drag, Material, Name, Wall
from engine.context import PhysicsContext
from engine.effects import effects_for
from engine.grid import SpatialGrid
from engine.mass import mass_properties
from engine.presets import Knobs, preset
from engine.scene import Scene
from engine.simulation import Simulation
from engine.systems.broadphase import BroadphaseProcessor
from engine.systems.bumper import BumperProcessor
from engine.systems.ccd import CCDProcessor
from engine.systems.drag import DragProcessor
from engine.systems.gravity import GravityProcessor
from engine.systems.ice import IceProcessor
from engine.systems.integrate import IntegrateProcessor
from engine.systems.narrowphase import NarrowphaseProcessor
from engine.systems.resolve import ResolveProcessor
from engine.systems.restitution import RestitutionProcessor
from engine.systems.sand import SandProcessor
from engine.systems.slope import SlopeProcessor
from engine.systems.spin import SpinProcessor
from engine.systems.water import WaterProcessor
from engine.systems.windmill import WindmillProcessor

_world_ids = itertools.count(1)


def make_collider(outline: polygon.Outline, material: Material) -> Collider:
    """Collider of a normalised outline (CCW, centroid at the origin)."""
    pieces = tuple(polygon.convex_pieces(outline))
    return Collider(
        outline=tuple(outline), pieces=pieces,
        normals=tuple(polygon.edge_normals(p) for p in pieces),
        radius=polygon.bounding_radius(outline), material=material,
        piece_reach=tuple(polygon.bounding_radius(p) for p in pieces),
    )


def make_body(outline: polygon.Outline, position: Sequence[float], density: float, angle: float = 0.0,
              velocity: Sequence[float] = (0.0, 0.0), spin: float = 0.0, rotates: bool = True) -> Body:
    """Dynamic body with the exact mass and inertia of its outline. `rotates=False` (no `spin`
    effect) gives infinite inertia: contacts then cannot turn it."""
    props = mass_properties(outline, density)
    body = Body.dynamic(float(position[0]), float(position[1]), props.mass, props.inertia,
                        angle=angle, vx=float(velocity[0]), vy=float(velocity[1]), spin=spin if rotates else 0.0)
    if not rotates:
        body.inv_inertia = 0.0
    return body


def make_wall(outline: Sequence[polygon.Vec], material: Material) -> Wall:
    """Static wall from a world-space CCW outline."""
    outline = tuple(outline)
    pieces = tuple(polygon.convex_pieces(outline))

    def box(points: Iterable[polygon.Vec]) -> tuple[float, float, float, float]:
        xs, ys = zip(*points)
        return min(xs), min(ys), max(xs), max(ys)

    return Wall(outline=outline, pieces=pieces, normals=tuple(polygon.edge_normals(p) for p in pieces),
                material=material, piece_aabbs=tuple(box(p) for p in pieces))


def processors_for(ctx: PhysicsContext, effects: Iterable[str], contacts: bool, has_walls: bool,
                   cell_size: float) -> list[esper.Processor]:
    """The substep's processors in order, each present only if an effect or the content needs it."""
    effects = set(effects)

    def wanted(*pairs: tuple[str, type]) -> list[esper.Processor]:
        return [cls(ctx) for effect, cls in pairs if effect in effects]

    # A windmill is driven first; positions then advance with the velocities the solver left; then
    # forces and surfaces change velocities, and the contact solver constrains those before they move
    # anything: symplectic Euler in the order that keeps a ball pressed into a corner by a slope
    # from sinking in and creeping.
    procs = wanted(("windmill", WindmillProcessor))
    procs.append(IntegrateProcessor(ctx))
    procs += wanted(("spin", SpinProcessor), ("gravity", GravityProcessor), ("slope", SlopeProcessor),
                    ("sand", SandProcessor), ("ice", IceProcessor), ("drag", DragProcessor))
    if contacts:
        if "ccd" in effects and ctx.knobs.ccd and has_walls:
            procs.append(CCDProcessor(ctx))
        procs.append(BroadphaseProcessor(ctx, cell_size))
        procs.append(NarrowphaseProcessor(ctx))
        procs.append(ResolveProcessor(ctx, friction="friction" in effects))
        procs += wanted(("restitution", RestitutionProcessor), ("bumper", BumperProcessor))
    procs += wanted(("water", WaterProcessor))
    return procs


def new_world(prefix: str) -> str:
    name = f"{prefix}-{next(_world_ids)}"
    esper.switch_world(name)
    return name


def build_scene(scene: Scene, knobs: Knobs | str | None = None, effects: Iterable[str] | None = None,
                cell_size: float | None = None) -> Simulation:
    """A ready-to-step simulation of a scene. `knobs` defaults to the scene's preset, then balanced;
    `effects` defaults to the scene's list, then to what its content needs."""
    preset_name = scene.preset or "balanced"
    if knobs is None or isinstance(knobs, str):
        preset_name = knobs or preset_name
        knobs = preset(preset_name)
    else:
        preset_name = "custom"
    chosen = dict(effects_for(scene, knobs.substeps)) if effects is None else {e: "requested" for e in effects}
    rotates = "spin" in chosen

    world = new_world(f"scene-{scene.name}")
    radius = 0.0
    names: dict[int, str] = {}
    for spec in scene.bodies:
        outline = spec.shape.outline()
        body = make_body(outline, spec.position, spec.density, math.radians(spec.angle), spec.velocity,
                         spec.spin, rotates)
        collider = make_collider(outline, Material(spec.restitution, spec.friction))
        radius = max(radius, collider.radius)
        components: list[object] = [body, collider, Name(spec.name)]
        if spec.drag.any:
            components.append(Drag(**spec.drag.model_dump()))
        names[esper.create_entity(*components)] = spec.name

    cell = cell_size or max(1.0, 4.0 * radius)
    grid = SpatialGrid(cell)
    for spec in scene.walls:
        wall = make_wall(spec.outline(), Material(spec.restitution, spec.friction))
        ent = esper.create_entity(wall)
        for k, box in enumerate(wall.piece_aabbs):
            grid.insert((ent, k), box)

    ctx = PhysicsContext(knobs=knobs, effects=frozenset(chosen), static_grid=grid, gravity=scene.gravity)
    contacts = bool(scene.walls) or len(scene.bodies) > 1
    procs = processors_for(ctx, chosen, contacts, bool(scene.walls), cell)
    return Simulation(world, ctx, procs, names, preset_name=preset_name, reasons=chosen, scene_name=scene.name)
