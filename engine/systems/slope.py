import esper

from polygolf.engine.components import Ball, Body, Region, Slope
from polygolf.engine.components.resources import Resources


class SlopeProcessor(esper.Processor):
    """A ball whose centre is on a slope is pushed at the slope's constant acceleration. A ball at
    rest stays at rest (it can only rest on a slope against something that holds it)."""

    name = "slope"

    def __init__(self, res: Resources) -> None:
        self.config = res.config

    def process(self) -> None:
        dt = self.config.dt
        zones = esper.get_components(Region, Slope)
        for _, (body, _) in esper.get_components(Body, Ball):
            if body.asleep:
                continue
            for _, (region, slope) in zones:
                if region.contains(body.x, body.y):
                    body.vx += slope.push[0] * dt
                    body.vy += slope.push[1] * dt
                    break
