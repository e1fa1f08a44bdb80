"""The one stage table: every processor of a substep, physics and golf alike, in the order they run,
with the effect that brings each into a world. `assemble`, `explain` and the accuracy report all read
this table; nothing else decides what a world runs or in what order.

Order (a substep): the shot becomes velocity; kinematic bodies are driven; positions advance with the
velocities the solver left; forces and surfaces change velocities; continuous collision stops what
would enter a wall; the contact pipeline constrains the new velocities before they move anything
(symplectic Euler, so a ball pressed into a corner by a slope neither sinks in nor creeps); then the
golf rules look at where things ended up.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import esper

from polygolf.engine.assembly.spec import WorldSpec
from polygolf.engine.physics.presets import Knobs
from polygolf.engine.systems.broadphase import BroadphaseProcessor
from polygolf.engine.systems.bumper import BumperProcessor
from polygolf.engine.systems.ccd import CCDProcessor
from polygolf.engine.systems.cup import CupProcessor
from polygolf.engine.systems.drag import DragProcessor
from polygolf.engine.systems.gravity import GravityProcessor
from polygolf.engine.systems.ice import IceProcessor
from polygolf.engine.systems.impacts import ImpactsProcessor
from polygolf.engine.systems.integrate import IntegrateProcessor
from polygolf.engine.systems.launch import LaunchProcessor
from polygolf.engine.systems.narrowphase import NarrowphaseProcessor
from polygolf.engine.systems.resolve import ResolveProcessor
from polygolf.engine.systems.restitution import RestitutionProcessor
from polygolf.engine.systems.sand import SandProcessor
from polygolf.engine.systems.scoring import ScoringProcessor
from polygolf.engine.systems.shot import ShotProcessor
from polygolf.engine.systems.slope import SlopeProcessor
from polygolf.engine.systems.spin import SpinProcessor
from polygolf.engine.systems.water import WaterProcessor
from polygolf.engine.systems.windmill import WindmillProcessor

Condition = Callable[[WorldSpec, Knobs], bool]


def _always(spec: WorldSpec, knobs: Knobs) -> bool:
    return True


def _touchable(spec: WorldSpec, knobs: Knobs) -> bool:
    return spec.touchable


def _touchable_and_ccd_knob(spec: WorldSpec, knobs: Knobs) -> bool:
    return spec.touchable and knobs.ccd


@dataclass(frozen=True)
class Stage:
    name: str
    processor: type[esper.Processor]
    effect: str | None = None  # the effect that brings it in; None: the content's shape alone decides
    needs: Condition = _always  # and what the content and knobs must also allow
    why: str = ""  # for a stage no effect brings in: why it is there

    def wanted(self, effects: dict[str, str] | frozenset[str], spec: WorldSpec, knobs: Knobs) -> bool:
        return (self.effect is None or self.effect in effects) and self.needs(spec, knobs)


STAGES: tuple[Stage, ...] = (
    Stage("shot", ShotProcessor, "shot"),
    Stage("launch", LaunchProcessor, "launch"),
    Stage("windmill", WindmillProcessor, "windmill"),
    Stage("integrate", IntegrateProcessor, why="always: moves bodies and puts stopped ones to rest"),
    Stage("spin", SpinProcessor, "spin"),
    Stage("gravity", GravityProcessor, "gravity"),
    Stage("slope", SlopeProcessor, "slope"),
    Stage("sand", SandProcessor, "sand"),
    Stage("ice", IceProcessor, "ice"),
    Stage("drag", DragProcessor, "drag"),
    Stage("ccd", CCDProcessor, "ccd", needs=_touchable_and_ccd_knob),
    Stage("broadphase", BroadphaseProcessor, needs=_touchable,
          why="walls or other bodies can be touched: grid of bounding boxes"),
    Stage("narrowphase", NarrowphaseProcessor, needs=_touchable,
          why="separating axes and clipping on the broadphase's candidates"),
    Stage("resolve", ResolveProcessor, needs=_touchable, why="sequential impulses on contacts"),
    Stage("impacts", ImpactsProcessor, "impacts", needs=_touchable),
    Stage("restitution", RestitutionProcessor, "restitution", needs=_touchable),
    Stage("bumper", BumperProcessor, "bumper", needs=_touchable),
    Stage("water", WaterProcessor, "water"),
    Stage("cup", CupProcessor, "cup"),
    Stage("scoring", ScoringProcessor, "scoring"),
)
STAGE_NAMES = tuple(stage.name for stage in STAGES)


def stages_for(effects: dict[str, str] | frozenset[str], spec: WorldSpec, knobs: Knobs) -> list[Stage]:
    return [stage for stage in STAGES if stage.wanted(effects, spec, knobs)]
