"""Many candidate shots of one hole at once: K balls in one world that meet the walls, windmills,
hazards and cup but not each other (`collide_bodies=False`), stepped in lockstep. Each ball's physics
is exactly that of the same shot played alone (contacts are solved island by island), so a search can
try a thousand shots in one world and trust the one it picks."""

from __future__ import annotations

import gc
import math
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field, replace

import esper
import numpy as np

from polygolf.engine.assembly.assemble import assemble
from polygolf.engine.assembly.spec import DynamicPart, WallPart
from polygolf.engine.components import Ball, Body, HoleState, Material
from polygolf.engine.golf.holes import Hole
from polygolf.engine.golf.world import DEFAULT_BALL, hole_spec
from polygolf.engine.loading.scene import ShapeSpec
from polygolf.engine.physics.body import ANGLE, Selection, X, Y
from polygolf.engine.physics.mass import mass_properties
from polygolf.engine.physics.motion import came_to_rest
from polygolf.engine.physics.polygon import Outline, bounding_radius
from polygolf.engine.physics.presets import Knobs
from polygolf.engine.physics.settings import FRAME_DT
from polygolf.engine.physics.shot import clamp_arrow, shot_velocity


@dataclass(frozen=True)
class Shot:
    """A ball at rest at `start` turned `angle` (rad), pushed at `grab` (offset from its centre, m)
    along `arrow` (m)."""

    start: tuple[float, float]
    arrow: tuple[float, float]
    grab: tuple[float, float] = (0.0, 0.0)
    angle: float = 0.0


@dataclass
class ShotResult:
    rest: tuple[float, float]  # where the ball ended (the cup's centre if it dropped)
    angle: float  # how it lies there (rad)
    holed: bool
    seconds: float  # game time until it dropped or came to rest (or the limit)
    penalties: int  # strokes added by water
    path: list[tuple[float, float]] = field(default_factory=list)  # a point a frame until then, if asked for
    # With the path: how many of its points come before the ball first struck a wall, bumper or body
    # (it struck during the next frame), and the point where it struck; None if it never did.
    contact: int | None = None
    contact_at: tuple[float, float] | None = None


@contextmanager
def _collector_paused() -> Iterator[None]:
    """The cyclic collector off meanwhile: a fan makes thousands of objects (a body, a collider and
    components a shot) that all live until it returns, and the collector's passes over them found
    nothing to free (3 to 8 ms of 85 for 1000 shots)."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


@_collector_paused()
def simulate_shots(hole: Hole, shots: Sequence[Shot], preset: Knobs | str = "balanced", *,
                   shape: ShapeSpec = DEFAULT_BALL, max_seconds: float = 20.0, path: bool = False,
                   windmills: Sequence[float] = (), until_contact: bool = False,
                   obstacles: Sequence[Outline] = ()) -> list[ShotResult]:
    """Every shot of a ball of `shape` simulated to rest (or `max_seconds`) in one world, at the
    accuracy `preset` (a name or knobs); results in the shots' order.
    `windmills`: each windmill's angle when the shots are taken (rad, in the layout's order; the
    game's windmills have turned since the hole began), else as at the start of the hole. With
    `path`, each result also says when its ball first struck something (the impacts stage names the
    bodies of every manifold that closed fast enough to bounce; exact while a frame has fewer than
    `HEARD_LIMIT` impacts, i.e. for a preview, not a search's fan); `until_contact` stops following a
    ball there (the shot preview: its path up to the first bounce, no further). `obstacles`: outlines
    (world coordinates) of resting bodies the shots may meet, as walls: the other players' balls, for
    a path up to its first contact (after one, a real ball would move and a wall does not)."""
    if not shots:
        return []
    alone = hole_spec(hole, shape)
    template = alone.bodies[0]
    props = mass_properties(template.outline, template.density)
    radius = bounding_radius(template.outline)
    balls = [_pushed(f"shot-{k}", template, shot, props.mass, props.inertia, radius,
                     (Ball(*shot.start), HoleState(par=hole.spec.par, max_strokes=99)))
             for k, shot in enumerate(shots)]
    turned = [replace(part, angle=angle) for part, angle in zip(alone.kinematic, windmills)]
    walls = alone.walls + [WallPart(tuple(outline), Material()) for outline in obstacles]
    # Impacts only tell a listener what was struck: without a path, nobody listens (and a fan strikes
    # hundreds of times a substep).
    rules = alone.rules if path or until_contact else {k: v for k, v in alone.rules.items() if k != "impacts"}
    sim = assemble(replace(alone, bodies=balls, walls=walls, kinematic=turned + alone.kinematic[len(turned):],
                           collide_bodies=False, rules=rules), preset)
    try:
        esper.switch_world(sim.world)
        # Entity order = shots' order; scoring asks esper the same question (one list for both).
        rows = sorted(esper.get_components(Body, Ball, HoleState))
        done: list[float | None] = [None] * len(shots)
        paths: list[list[tuple[float, float]]] = [[] for _ in shots]
        contact: list[int | None] = [None] * len(shots)
        contact_at: list[tuple[float, float] | None] = [None] * len(shots)
        index = {ent: k for k, (ent, _) in enumerate(rows)} if path or until_contact else {}
        balls, running = Selection(), np.ones(len(shots), dtype=np.bool_)
        # Each ball's rest as last seen, and room for the balls that came to rest since (`came_to_rest`).
        asleep, resting = np.zeros(len(shots), dtype=np.bool_), np.empty(len(shots), dtype=np.int64)
        frames, left = 0, len(shots)  # (left: how many still run)
        sim.res.events.drain()
        while frames < round(max_seconds / FRAME_DT) and left:
            sim.step(1, measure=False)
            frames += 1
            if path or until_contact:
                for impact in sim.res.events.drain()[1]:
                    for ent in impact.bodies if impact.kind != "shot" else ():
                        k = index.get(ent)
                        if k is not None and contact[k] is None and done[k] is None:
                            contact[k], contact_at[k] = frames - 1, (impact.x, impact.y)
            store, picked = sim.res.bodies.gather(esper.get_component(Body)), balls.of(sim.res.bodies, rows)
            if path:
                moving = picked[running]
                for k, x, y in zip(np.flatnonzero(running).tolist(), store[moving, X].tolist(),
                                   store[moving, Y].tolist()):
                    paths[k].append((x, y))
            # A holed ball rests in the cup, so resting covers it; a ball ends the first time it rests.
            ended = resting[:came_to_rest(store, picked, asleep, resting)].tolist()
            if until_contact:
                ended += [k for k, c in enumerate(contact) if c is not None]
            for k in ended:
                if running[k]:
                    done[k], running[k] = frames * FRAME_DT, False
                    left -= 1
        store, picked = sim.res.bodies.gather(esper.get_component(Body)), balls.of(sim.res.bodies, rows)
        poses = store[picked][:, [X, Y, ANGLE]].tolist()
        return [ShotResult(rest=(x, y), angle=angle, holed=state.holed,
                           seconds=done[k] if done[k] is not None else frames * FRAME_DT,
                           penalties=state.penalties, path=paths[k], contact=contact[k], contact_at=contact_at[k])
                for k, ((x, y, angle), (_, (_, _, state))) in enumerate(zip(poses, rows))]
    finally:
        sim.close()


def _pushed(name: str, template: DynamicPart, shot: Shot, mass: float, inertia: float, radius: float,
            extras: tuple[object, ...]) -> DynamicPart:
    """The template's ball at rest at the shot's start, already given the shot's push: the velocity
    `push_resting` adds to a resting ball (the shot stage's way, as at the start of the first frame
    of the shot played alone; the same floats, the grab measured from the centre the same way),
    without a thousand pushes on built bodies. A world that does not turn bodies drops the spin."""
    velocity, spin, asleep = template.velocity, template.spin, template.asleep
    arrow = clamp_arrow(shot.arrow)
    if arrow is not None:
        x, y = shot.start
        dvx, dvy, dspin = shot_velocity(mass, inertia, radius, (x + shot.grab[0]) - x, (y + shot.grab[1]) - y, *arrow)
        if dvx != 0.0 or dvy != 0.0:
            velocity, spin, asleep = (velocity[0] + dvx, velocity[1] + dvy), spin + dspin, False
    return DynamicPart(name, template.outline, shot.start, template.density, template.material, shot.angle, velocity,
                       spin, template.drag, asleep, template.top_speed, extras)


def fan(start: tuple[float, float], directions: int, powers: list[float]) -> list[Shot]:
    """Shots from `start` in `directions` evenly spread directions at each power (arrow length, m)."""
    return [Shot(start, (p * math.cos(2 * math.pi * k / directions), p * math.sin(2 * math.pi * k / directions)))
            for p in powers for k in range(directions)]
