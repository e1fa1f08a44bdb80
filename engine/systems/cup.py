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
        self._cups: list | None = None
        self._packed = np.zeros((0, 4))  # each cup's x, y, radius, max_speed
        self._caught = np.zeros(0, dtype=np.int64)

    def process(self) -> None:
        cups = esper.get_component(Cup)
        if cups is not self._cups:
            self._packed = np.array([(c.x, c.y, c.radius, c.max_speed) for _, c in cups],
                                    dtype=np.float64).reshape(-1, 4)
            self._cups = cups
        state = self.bodies.gather(esper.get_component(Body))
        balls = esper.get_components(Body, Ball)
        rows = self._balls.of(self.bodies, balls)
        if len(self._caught) != len(rows):
            self._caught = np.empty(len(rows), dtype=np.int64)
        if not cups or not captured(state, rows, self._packed, self._caught):
            return
        for q in np.flatnonzero(self._caught >= 0).tolist():
            ent, (body, ball) = balls[q]
            if ball.holed:
                continue
            cup = cups[self._caught[q]][1]
            ball.holed = True
            body.x, body.y = cup.x, cup.y
            body.rest()
            self.events.emit("holed", ent)
