import math

import esper

from engine.components import Ball, Body, Cup
from engine.context import PhysicsContext


class CupProcessor(esper.Processor):
    """Drops the ball into the cup when it is over the cup and slow enough there; announces it with
    the esper event "holed". A holed ball is put to rest in the cup and never touched again."""

    name = "cup"

    def __init__(self, ctx: PhysicsContext) -> None:
        self.ctx = ctx
        self.holed: set[int] = set()

    def process(self) -> None:
        cups = esper.get_component(Cup)
        for ent, (body, _) in esper.get_components(Body, Ball):
            if ent in self.holed or body.asleep:
                continue
            for _, cup in cups:
                distance = math.hypot(body.x - cup.x, body.y - cup.y)
                if distance < cup.radius and math.hypot(body.vx, body.vy) < cup.capture_speed(distance):
                    self.holed.add(ent)
                    body.x, body.y = cup.x, cup.y
                    body.vx = body.vy = body.spin = 0.0
                    body.asleep = True
                    esper.dispatch_event("holed", ent)
                    break
