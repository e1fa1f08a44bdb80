import esper

from polygolf.engine.components import Ball, Body, Region, Water
from polygolf.engine.components.resources import Resources


class WaterProcessor(esper.Processor):
    """A ball whose centre goes in the water is taken out, a penalty stroke is added ("penalty"),
    and it is put back at rest where it last rested."""

    name = "water"

    def __init__(self, res: Resources) -> None:
        self.events = res.events

    def process(self) -> None:
        zones = esper.get_components(Region, Water)
        for ent, (body, ball) in esper.get_components(Body, Ball):
            if body.asleep:
                continue
            for _, (region, water) in zones:
                if region.contains(body.x, body.y):
                    body.x, body.y = water.put_back(ball.rest_x, ball.rest_y)
                    body.rest()
                    self.events.emit("penalty", ent, water.penalty)
                    break
