"""A hole as a world spec: a ball per player on the tee (each with its own shot input and score),
walls, hazards and the cup, and the effects the hole brings (the game's rules always; hazards as its
content has them)."""

from __future__ import annotations

import math
from collections.abc import Iterable

from polygolf.engine.assembly.effects import effects_for
from polygolf.engine.assembly.spec import DynamicPart, KinematicPart, WallPart, WorldSpec
from polygolf.engine.components import (
    Ball,
    Bumper,
    Cup,
    Drag,
    HoleState,
    Ice,
    Launcher,
    Material,
    Region,
    Sand,
    ShotInput,
    Slope,
    Water,
    Windmill,
)
from polygolf.engine.golf.holes import Hole
from polygolf.engine.golf.layout import HoleLayout, ball_fits, ball_outline
from polygolf.engine.loading.scene import ShapeSpec
from polygolf.engine.physics.polygon import bounding_radius
from polygolf.engine.physics.settings import MAX_SHOT_SPEED

MAX_PLAYERS = 4
TEE_SPACING = 2.5  # ball radii between the centres of neighbouring balls on the tee

_ZONE_WORDS = {"sand": "bunker", "water": "pond", "ice": "ice sheet", "slope": "slope"}
_MARKERS = {"sand": Sand, "ice": Ice}

DEFAULT_BALL = ShapeSpec(regular=5, radius=1.0)  # the pentagon: the ball a hole is played with unless another is chosen


def _count(n: int, word: str) -> str:
    return f"{n} {word}{'s' if n > 1 else ''}"


def tee_spots(layout: HoleLayout, radius: float, players: int) -> list[tuple[float, float]]:
    """Where each player's ball starts: one ball alone on the tee itself; several side by side across
    the way out of the tee, TEE_SPACING radii apart, each spot moved to the nearest place where a ball
    fits clear of walls, hazards and the other balls (searched on rings around the tee)."""
    tee = layout.tee
    if players == 1:
        return [tee]
    ahead = layout.route[1] if len(layout.route) > 1 else (tee[0] + 1.0, tee[1])
    heading = math.atan2(ahead[1] - tee[1], ahead[0] - tee[0])
    across = (-math.sin(heading), math.cos(heading))
    step = TEE_SPACING * radius
    wanted = [(tee[0] + across[0] * step * (k - (players - 1) / 2), tee[1] + across[1] * step * (k - (players - 1) / 2))
              for k in range(players)]
    candidates = [tee] + [(tee[0] + ring * step * 0.5 * math.cos(a * math.pi / 12),
                           tee[1] + ring * step * 0.5 * math.sin(a * math.pi / 12))
                          for ring in range(1, 13) for a in range(24)]
    spots: list[tuple[float, float]] = []

    def nearest_free(want: tuple[float, float], places: Iterable[tuple[float, float]],
                     off_cup: float) -> tuple[float, float] | None:
        """The place nearest `want` where a ball fits, clear of the balls placed and `off_cup` from the
        cup's centre (the first in the list of those as near; each looked at only until one is found)."""
        return next((c for c in sorted(places, key=lambda c: math.dist(c, want))
                     if math.dist(c, layout.cup) >= off_cup and all(math.dist(c, s) >= step * 0.9 for s in spots)
                     and ball_fits(layout, *c, radius * 1.1)), None)

    away = _off_cup(layout, radius)
    for want in wanted:
        # Near the tee; else (a ball too big for the tee's tile) anywhere on the green, off the cup if
        # it can be (`start_problem` says when it cannot); else on the tee.
        spot = nearest_free(want, [want, *candidates], away) \
            or nearest_free(want, drop_spots(layout, radius), away) \
            or nearest_free(want, drop_spots(layout, radius), layout.cup_radius + radius)
        spots.append(spot or tee)
    return spots


def start_problem(layout: HoleLayout, radius: float, players: int) -> str | None:
    """Why `players` balls of this radius cannot start this hole as they should (apart, and clear of
    the cup), or None."""
    spots = tee_spots(layout, radius, players)
    if any(math.dist(a, b) < 2.0 * radius for k, a in enumerate(spots) for b in spots[k + 1:]):
        return f"{players} players' balls ({2 * radius:g} m across) do not fit apart on the green"
    if any(math.dist(spot, layout.cup) < _off_cup(layout, radius) for spot in spots):
        return f"with {players} players a ball ({2 * radius:g} m across) starts beside the cup: no room near the tee"
    return None


def _off_cup(layout: HoleLayout, radius: float) -> float:
    """How far from the cup's centre a ball starts: its edge a tee spacing clear of the cup's rim."""
    return layout.cup_radius + radius + TEE_SPACING * radius


def drop_spots(layout: HoleLayout, radius: float) -> tuple[tuple[float, float], ...]:
    """Spots where water may put a ball back when its own spot is taken: every 2.5 radii over the
    green, where a ball fits (clear of walls, water and windmills' sweeps). Worked out once a
    layout and radius (every world of the hole, every shot preview, asks again)."""
    known = layout.drops.get(radius)
    if known is None:
        known = layout.drops[radius] = _drop_spots(layout, radius)
    return known


def _drop_spots(layout: HoleLayout, radius: float) -> tuple[tuple[float, float], ...]:
    step = TEE_SPACING * radius
    spots = []
    for x0, y0, x1, y1 in layout.floor:
        nx, ny = int((x1 - x0) / step), int((y1 - y0) / step)
        for i in range(nx):
            for j in range(ny):
                x, y = x0 + (i + 0.5) * (x1 - x0) / nx, y0 + (j + 0.5) * (y1 - y0) / ny
                if ball_fits(layout, x, y, radius * 1.1):  # clear of sweeps too
                    spots.append((x, y))
    return tuple(spots)


def hole_spec(hole: Hole, shape: ShapeSpec, players: int = 1) -> WorldSpec:
    """The world of `hole` played with `shape` (scaled to the library's ball radius) by `players`
    players, each with a ball of their own: they meet each other on the green. The balls are swept
    against each other beyond the slop (`StepConfig.sweep_bodies`): continuous collision puts a
    pair back to its time of impact (both, if they touch, to the earlier of theirs), and a ball put
    back makes up at most a substep's time in the next (`motion.advance`), so one held back in a row
    of balls does not jump on into the next."""
    if not 1 <= players <= MAX_PLAYERS:
        raise ValueError(f"players must be 1 to {MAX_PLAYERS}, not {players}")
    lib, spec, layout = hole.library, hole.spec, hole.layout
    green = spec.green or lib.green
    outline = ball_outline(shape, lib.ball.radius)
    max_strokes = spec.max_strokes or lib.max_strokes
    spots = tee_spots(layout, lib.ball.radius, players)
    balls = [DynamicPart(
        name="ball" if players == 1 else f"ball-{k + 1}", outline=outline, position=spot, density=lib.ball.density,
        material=Material(lib.ball.restitution, lib.ball.friction),
        drag=Drag(**green.model_dump()) if green.any else None,
        asleep=spec.launch is None, top_speed=MAX_SHOT_SPEED,
        extras=(Ball(*spot), ShotInput(), HoleState(par=spec.par, max_strokes=max_strokes)),
    ) for k, spot in enumerate(spots)]
    walls = [WallPart(outline, Material()) for outline in layout.borders]
    walls += [WallPart(outline, material) for outline, material in layout.obstacles]
    walls += [WallPart(outline, material, (Bumper(kick),)) for outline, material, kick in layout.bumpers]
    entities: list[tuple[object, ...]] = [
        (Cup(layout.cup[0], layout.cup[1], lib.cup.radius, lib.cup.max_speed),),
    ]
    sweeps = tuple((px, py, bounding_radius(local) + lib.ball.radius) for local, (px, py), _ in layout.windmills)
    drops = drop_spots(layout, lib.ball.radius) if layout.zone_outlines("water") else ()
    for kind, zone, push in layout.zones:
        xs, ys = zip(*zone)
        region = Region(zone, (min(xs), min(ys), max(xs), max(ys)))
        if kind == "slope":
            marker: object = Slope(push)
        elif kind == "water":
            # never back into a windmill's sweep, nor onto another ball
            marker = Water(keep_out=sweeps, fallback=layout.tee, drops=drops)
        else:
            marker = _MARKERS[kind]()
        entities.append((region, marker))
    if spec.launch is not None:
        entities.append((Launcher(spec.launch.velocity, spec.launch.every, layout.tee, spots=tuple(spots)),))
    windmills = [KinematicPart("windmill", local, pivot, speed, extras=(Windmill(speed),))
                 for local, pivot, speed in layout.windmills]

    content: dict[str, str] = {}
    for kind, word in _ZONE_WORDS.items():
        count = sum(1 for k, _, _ in layout.zones if k == kind)
        if count:
            content[kind] = _count(count, word)
    if layout.bumpers:
        content["bumper"] = _count(len(layout.bumpers), "bumper")
    if layout.windmills:
        content["windmill"] = _count(len(layout.windmills), "windmill")
    if spec.launch is not None:
        content["launch"] = f"collision test: the ball is launched every {spec.launch.every:g} s"
    rules = {"shot": "the player shoots", "cup": "the ball can drop into the cup",
             "impacts": "the player hears what the ball strikes",
             "scoring": f"par {spec.par}, picked up after {max_strokes} strokes"}
    return WorldSpec(name=f"hole-{hole.id}", bodies=balls, walls=walls, kinematic=windmills, entities=entities,
                     rules=rules, content_effects=content,
                     listed=tuple(spec.effects) if spec.effects is not None else None, listed_by="the hole",
                     cell_size=lib.tile_size / 2.0, sweep_bodies=players >= 2)


def hole_effects(hole: Hole, substeps: int = 4) -> dict[str, str]:
    """Effect -> why the hole's world has it (the ball's shape does not change the answer)."""
    return effects_for(hole_spec(hole, DEFAULT_BALL), substeps)
