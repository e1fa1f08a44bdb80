import math

import esper

from polygolf.engine.components import Ball, Body, Collider, ShotInput
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.shot import shot_velocity


class ShotProcessor(esper.Processor):
    """Turns a requested shot into velocity, only while the ball is at rest; remembers that resting
    place and says so ("shot": the scoring stage counts it)."""

    name = "shot"

    def __init__(self, res: Resources) -> None:
        self.events = res.events
        self._seen = -1  # ShotInput.requests when this stage last looked

    def quiet(self) -> bool:
        """Whether no shot was asked for since it last looked (nothing asks in the middle of a frame)."""
        return ShotInput.requests == self._seen

    def process(self) -> None:
        if ShotInput.requests == self._seen:
            return  # nothing asked for since
        self._seen = ShotInput.requests
        for ent, (body, collider, shot) in esper.get_components(Body, Collider, ShotInput):
            if not shot.pending:
                continue
            shot.pending = False
            x, y, _, vx, vy, spin, mass, inertia, _, inv_inertia = body.motion()
            if not (body.asleep or (vx == 0.0 and vy == 0.0 and spin == 0.0)):
                shot.rejected += 1  # only at rest
                continue
            dvx, dvy, dspin = shot_velocity(mass, inertia, collider.radius, shot.origin[0] - x, shot.origin[1] - y,
                                            *shot.vector, rotates=inv_inertia > 0.0)
            if dvx == 0.0 and dvy == 0.0:
                continue
            ball = esper.try_component(ent, Ball)
            if ball is not None:
                ball.rest_x, ball.rest_y = x, y  # where a hazard puts it back
            body.push(dvx, dvy, dspin)
            shot.accepted += 1
            self.events.emit("shot", ent)
            self.events.strike("shot", math.hypot(dvx, dvy), x, y, (ent, -1))
