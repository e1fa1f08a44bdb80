"""The front end's facade on a hole being played: shoot, step, switch the preset, time the stages, and
read what to draw. Views talk to this, never to the simulation's insides."""

from __future__ import annotations

import esper

from polygolf.engine.assembly.assemble import assemble, resolve_knobs
from polygolf.engine.assembly.simulation import Simulation
from polygolf.engine.components import Ball, Body, Bumper, Collider, HoleState, ShotInput, Windmill
from polygolf.engine.components.resources import Impact
from polygolf.engine.golf.holes import Hole
from polygolf.engine.golf.layout import HoleLayout
from polygolf.engine.golf.world import hole_spec
from polygolf.engine.loading.scene import ShapeSpec
from polygolf.engine.physics.polygon import Outline
from polygolf.engine.physics.presets import Knobs
from polygolf.engine.physics.shot import clamp_arrow, shot_velocity


class HolePlay:
    """One hole being played: its own esper world (see `golf.world.hole_spec`) and the verbs on it."""

    def __init__(self, hole: Hole, shape: ShapeSpec, knobs: Knobs | str = "balanced") -> None:
        self.hole = hole
        self.sim: Simulation = assemble(hole_spec(hole, shape), knobs)
        esper.switch_world(self.sim.world)
        (ent, (self.ball, self.collider, self._ball, self._shot)), = esper.get_components(Body, Collider, Ball,
                                                                                         ShotInput)
        self.ball_entity = ent
        self.state: HoleState = esper.get_component(HoleState)[0][1]
        self.bumpers: list[Bumper] = [b for _, b in esper.get_component(Bumper)]
        self.windmills: list[Body] = [body for _, (body, _) in esper.get_components(Body, Windmill)]

    # -- reading -----------------------------------------------------------------------------------

    @property
    def layout(self) -> HoleLayout:
        return self.hole.layout

    @property
    def outline(self) -> Outline:
        return self.collider.outline

    @property
    def ball_at_rest(self) -> bool:
        return self.ball.asleep

    @property
    def preset_name(self) -> str:
        return self.sim.preset_name

    @property
    def knobs(self) -> Knobs:
        return self.sim.knobs

    @property
    def system_names(self) -> list[str]:
        return self.sim.system_names

    @property
    def contact_count(self) -> int:
        return self.sim.res.contacts.count

    def drain_events(self) -> tuple[list[tuple[str, int]], list[Impact]]:
        """What happened since the last call, for the front end's sound and drawing: golf events
        ("shot", "holed", "penalty") and impacts (`components.resources.Impact`), oldest first."""
        return self.sim.res.events.drain()

    def system_seconds(self) -> dict[str, float]:
        """Seconds each stage has spent in profiled steps so far."""
        return dict(self.sim.metrics.system_seconds)

    # -- verbs -------------------------------------------------------------------------------------

    def shoot(self, origin: tuple[float, float], arrow: tuple[float, float]) -> bool:
        """Ask for a shot: a push at `origin` along `arrow` (clamped to the fastest shot). False if
        the arrow is too short to be a shot (a click); the shot stage takes it only at rest."""
        vector = clamp_arrow(arrow)
        if vector is None:
            return False
        self._shot.request(origin, vector)
        return True

    def shot_spin(self, origin: tuple[float, float], arrow: tuple[float, float]) -> float:
        """The spin (rad/s) this shot would give the ball, for the aiming arrow to show."""
        ball = self.ball
        vector = clamp_arrow(arrow)
        if vector is None:
            return 0.0
        return shot_velocity(ball.mass, ball.inertia, self.collider.radius, origin[0] - ball.x, origin[1] - ball.y,
                             *vector, rotates=ball.inv_inertia > 0.0)[2]

    def place_ball(self, x: float, y: float) -> None:
        """Put the ball at rest at (x, y) (where a hazard would put it back too)."""
        self.ball.x, self.ball.y = x, y
        self.ball.rest()
        self._ball.rest_x, self._ball.rest_y = x, y

    def step(self, frames: int = 1, profile: bool = False) -> None:
        self.sim.step(frames, measure=False, profile=profile)

    def set_preset(self, knobs: Knobs | str) -> None:
        name, knobs = resolve_knobs(knobs)
        self.sim.set_knobs(knobs, name)

    def close(self) -> None:
        self.sim.close()
