import math

import esper

from polygolf.engine.components import Ball, Body, Collider, ShotInput
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.shot import shot_velocity


def push_resting(body: Body, radius: float, origin: tuple[float, float], vector: tuple[float, float]) -> float | None:
    """A shot on a body of bounding radius `radius`: pushed at `origin` along the arrow `vector`,
    but only while it rests. Returns the speed it was given (0.0 for a click: nothing given), or
    None if it was moving. (The shot stage's way; a fan of shots builds its balls already given this
    velocity, `golf.shots`.)"""
    x, y, _, vx, vy, spin, mass, inertia, _, inv_inertia = body.motion()
    if (vx != 0.0 or vy != 0.0 or spin != 0.0) and not body.asleep:
        return None
    dvx, dvy, dspin = shot_velocity(mass, inertia, radius, origin[0] - x, origin[1] - y, *vector,
                                    rotates=inv_inertia > 0.0)
    if dvx == 0.0 and dvy == 0.0:
        return 0.0
    body.push(dvx, dvy, dspin)
    return math.hypot(dvx, dvy)


class ShotProcessor(esper.Processor):
    """Turns a requested shot into velocity, only while the ball is at rest; remembers that resting
    place, and every other resting ball's, and says so ("shot": the scoring stage counts it)."""

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
            x, y = body.x, body.y
            speed = push_resting(body, collider.radius, shot.origin, shot.vector)
            if speed is None:
                shot.rejected += 1  # only at rest
                continue
            if speed == 0.0:
                continue
            # Where a hazard puts a ball back: where it lay when this shot was taken, for the ball
            # shot and for every other ball at rest, which the shot may knock into the water.
            for other, (other_body, ball) in esper.get_components(Body, Ball):
                if other == ent:
                    ball.rest_x, ball.rest_y = x, y
                elif other_body.asleep:
                    ball.rest_x, ball.rest_y = other_body.x, other_body.y
            shot.accepted += 1
            self.events.emit("shot", ent)
            self.events.strike("shot", speed, x, y, (ent, -1))
