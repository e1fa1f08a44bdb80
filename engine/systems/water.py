import esper

from engine.components import Ball, Body, Region, Water
from engine.context import PhysicsContext


class WaterProcessor(esper.Processor):
    """A ball whose centre goes in the water is taken out, a penalty stroke is added (esper event
    "penalty"), and it is put back at rest where it last rested."""

    name = "water"

    def __init__(self, ctx: PhysicsContext) -> None:
        self.ctx = ctx

    def process(self) -> None:
        zones = esper.get_components(Region, Water)
        for _, (body, ball) in esper.get_components(Body, Ball):
            if body.asleep:
                continue
            for _, (region, water) in zones:
                if region.contains(body.x, body.y):
                    body.x, body.y = ball.rest_x, ball.rest_y
                    body.x0, body.y0 = body.x, body.y
                    body.vx = body.vy = body.spin = 0.0
                    body.asleep = True
                    esper.dispatch_event("penalty", water.penalty)
                    break
