import esper
import numpy as np

from polygolf.engine.components import Ball, Body, Cup
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.body import Selection
from polygolf.engine.physics.motion import captured


class CupProcessor(esper.Processor):
    """Drops the ball into the cup when it is over the cup and slow enough there (`Cup.capture_speed`,
    `motion.captured`), and says so ("holed"). A holed ball is put to rest in the cup and never
    touched again."""

    name = "cup"

    def __init__(self, res: Resources) -> None:
        self.events, self.bodies = res.events, res.bodies
        self._balls = Selection()

    def process(self) -> None:
        cups = esper.get_component(Cup)
        if not cups:
            return
        state = self.bodies.gather(esper.get_component(Body))
        balls = esper.get_components(Body, Ball)
        rows = self._balls.of(self.bodies, balls)
        caught = np.empty(len(rows), dtype=np.int64)
        captured(state, rows, np.array([(c.x, c.y, c.radius, c.max_speed) for _, c in cups], dtype=np.float64),
                 caught)
        for q in np.flatnonzero(caught >= 0).tolist():
            ent, (body, ball) = balls[q]
            if ball.holed:
                continue
            cup = cups[caught[q]][1]
            ball.holed = True
            body.x, body.y = cup.x, cup.y
            body.rest()
            self.events.emit("holed", ent)
