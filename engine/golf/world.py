"""A hole as a world spec: the ball on the tee, walls, hazards, the cup and the hole's state, and the
effects the hole brings (the game's rules always; hazards as its content has them)."""

from __future__ import annotations

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
from polygolf.engine.golf.layout import ball_outline
from polygolf.engine.loading.scene import ShapeSpec
from polygolf.engine.physics.settings import MAX_SHOT_SPEED

_ZONE_WORDS = {"sand": "bunker", "water": "pond", "ice": "ice sheet", "slope": "slope"}
_MARKERS = {"sand": Sand, "ice": Ice, "water": Water}


def _count(n: int, word: str) -> str:
    return f"{n} {word}{'s' if n > 1 else ''}"


def hole_spec(hole: Hole, shape: ShapeSpec) -> WorldSpec:
    """The world of `hole` played with `shape` (scaled to the library's ball radius)."""
    lib, spec, layout = hole.library, hole.spec, hole.layout
    green = spec.green or lib.green
    outline = ball_outline(shape, lib.ball.radius)
    ball = DynamicPart(
        name="ball", outline=outline, position=layout.tee, density=lib.ball.density,
        material=Material(lib.ball.restitution, lib.ball.friction),
        drag=Drag(**green.model_dump()) if green.any else None,
        asleep=spec.launch is None, top_speed=MAX_SHOT_SPEED,
        extras=(Ball(*layout.tee), ShotInput()),
    )
    walls = [WallPart(outline, Material()) for outline in layout.borders]
    walls += [WallPart(outline, material) for outline, material in layout.obstacles]
    walls += [WallPart(outline, material, (Bumper(kick),)) for outline, material, kick in layout.bumpers]
    entities: list[tuple[object, ...]] = [
        (Cup(layout.cup[0], layout.cup[1], lib.cup.radius, lib.cup.max_speed),),
        (HoleState(par=spec.par, max_strokes=spec.max_strokes or lib.max_strokes),),
    ]
    for kind, zone, push in layout.zones:
        xs, ys = zip(*zone)
        region = Region(zone, (min(xs), min(ys), max(xs), max(ys)))
        entities.append((region, Slope(push) if kind == "slope" else _MARKERS[kind]()))
    if spec.launch is not None:
        entities.append((Launcher(spec.launch.velocity, spec.launch.every, layout.tee),))
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
             "scoring": f"par {spec.par}, picked up after {spec.max_strokes or lib.max_strokes} strokes"}
    return WorldSpec(name=f"hole-{hole.id}", bodies=[ball], walls=walls, kinematic=windmills, entities=entities,
                     rules=rules, content_effects=content,
                     listed=tuple(spec.effects) if spec.effects is not None else None, listed_by="the hole",
                     cell_size=lib.tile_size / 2.0)


def hole_effects(hole: Hole, substeps: int = 4) -> dict[str, str]:
    """Effect -> why the hole's world has it (the ball's shape does not change the answer)."""
    return effects_for(hole_spec(hole, ShapeSpec(regular=5, radius=1.0)), substeps)
