import math

import esper

from polygolf.engine.components import Ball, Body, Cup
from polygolf.engine.components.resources import Resources


class CupProcessor(esper.Processor):
    """Drops the ball into the cup when it is over the cup and slow enough there, and says so
    ("holed"). A holed ball is put to rest in the cup and never touched again."""

    name = "cup"

    def __init__(self, res: Resources) -> None:
        self.events = res.events

    def process(self) -> None:
        cups = esper.get_component(Cup)
        for ent, (body, ball) in esper.get_components(Body, Ball):
            if ball.holed or body.asleep:
                continue
            for _, cup in cups:
                distance = math.hypot(body.x - cup.x, body.y - cup.y)
                if distance < cup.radius and math.hypot(body.vx, body.vy) < cup.capture_speed(distance):
                    ball.holed = True
                    body.x, body.y = cup.x, cup.y
                    body.rest()
                    self.events.emit("holed", ent)
                    break
