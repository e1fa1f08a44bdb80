"""The front end's facade on a hole being played: shoot, step, switch the preset, time the stages, and
read what to draw. Views talk to this, never to the simulation's insides."""

from __future__ import annotations

from dataclasses import dataclass

import esper

from polygolf.engine.assembly.assemble import assemble, resolve_knobs
from polygolf.engine.assembly.simulation import Simulation
from polygolf.engine.components import Ball, Body, Bumper, Collider, HoleState, ShotInput, Windmill
from polygolf.engine.components.hazards import free_spot
from polygolf.engine.components.resources import Impact
from polygolf.engine.golf.holes import Hole
from polygolf.engine.golf.layout import HoleLayout
from polygolf.engine.golf.world import drop_spots, hole_spec
from polygolf.engine.loading.scene import ShapeSpec
from polygolf.engine.physics.polygon import Outline
from polygolf.engine.physics.presets import Knobs
from polygolf.engine.physics.settings import LINEAR_SLOP
from polygolf.engine.physics.shot import clamp_arrow, shot_velocity

RESTART_PENALTY = 1  # strokes a restart adds: the strokes already taken stay too


@dataclass(frozen=True, slots=True)
class PlayerBall:
    """One player's ball in the hole's world: its body, shape, hazard memory, shot input and score."""

    entity: int
    body: Body
    collider: Collider
    marker: Ball
    shot: ShotInput
    state: HoleState
    tee: tuple[float, float]


class HolePlay:
    """One hole being played by one to four players: its own esper world (see `golf.world.hole_spec`)
    with a ball per player, and the verbs on it. `turn` is whose ball `ball`, `state` and `shoot`
    mean (the round decides it); `players[k]` reaches any player's ball."""

    def __init__(self, hole: Hole, shape: ShapeSpec, knobs: Knobs | str = "balanced", players: int = 1) -> None:
        self.hole = hole
        self.sim: Simulation = assemble(hole_spec(hole, shape, players), knobs)
        esper.switch_world(self.sim.world)
        self.players: list[PlayerBall] = [
            PlayerBall(ent, body, collider, ball, shot, state, (body.x, body.y))
            for ent, (body, collider, ball, shot, state) in esper.get_components(Body, Collider, Ball, ShotInput,
                                                                                 HoleState)]
        self.turn = 0
        self.bumpers: list[Bumper] = [b for _, b in esper.get_component(Bumper)]
        self.windmills: list[Body] = [body for _, (body, _) in esper.get_components(Body, Windmill)]

    # -- reading -----------------------------------------------------------------------------------

    @property
    def ball(self) -> Body:
        """The ball of the player whose turn it is."""
        return self.players[self.turn].body

    @property
    def collider(self) -> Collider:
        return self.players[self.turn].collider

    @property
    def state(self) -> HoleState:
        """The score on this hole of the player whose turn it is."""
        return self.players[self.turn].state

    @property
    def ball_entity(self) -> int:
        return self.players[self.turn].entity

    @property
    def finished(self) -> bool:
        """Every ball is in the cup or picked up."""
        return all(p.state.finished for p in self.players)

    @property
    def all_at_rest(self) -> bool:
        """Nothing a player shot is still moving (the next turn waits for this)."""
        return all(p.body.asleep for p in self.players)

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

    def drain_events(self) -> tuple[list[tuple[str, int, int]], list[Impact]]:
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
        self.players[self.turn].shot.request(origin, vector)
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
        """Put the ball of the player whose turn it is at rest at (x, y) (where a hazard would put it
        back too)."""
        player = self.players[self.turn]
        player.body.x, player.body.y = x, y
        player.body.rest()
        player.marker.rest_x, player.marker.rest_y = x, y

    def restart_ball(self) -> bool:
        """The player whose turn it is starts the hole again: the ball back on its tee spot, the
        strokes taken kept and a penalty stroke added (counted by the scoring stage, like water's).
        False if that ball is already finished."""
        player = self.players[self.turn]
        if player.state.finished:
            return False
        player.shot.withdraw()  # a shot released this frame is not taken from the tee
        self.place_ball(*self._free_spot(player))
        player.body.angle = 0.0
        self.sim.res.events.emit("restart", player.entity, RESTART_PENALTY)
        return True

    def _free_spot(self, player: PlayerBall) -> tuple[float, float]:
        """The player's tee spot, or if another ball lies on it now, the nearest spot where a ball fits
        that no ball covers (a restart never drops a ball onto another)."""
        others = [(p.body.x, p.body.y, p.collider.radius + player.collider.radius + LINEAR_SLOP)
                  for p in self.players if p is not player and not p.state.finished]  # (a finished one left)
        spot = free_spot(player.tee, drop_spots(self.layout, self.hole.library.ball.radius), others)
        return spot if spot is not None else player.tee

    def step(self, frames: int = 1, profile: bool = False) -> None:
        self.sim.step(frames, measure=False, profile=profile)

    def set_preset(self, knobs: Knobs | str) -> None:
        name, knobs = resolve_knobs(knobs)
        self.sim.set_knobs(knobs, name)

    def close(self) -> None:
        self.sim.close()
