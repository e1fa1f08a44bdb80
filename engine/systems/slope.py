import esper

from polygolf.engine.components import Ball, Body, Region, Slope
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.body import Selection
from polygolf.engine.physics.motion import accelerate
from polygolf.engine.systems.areas import AreaIndex


class SlopeProcessor(esper.Processor):
    """A ball whose centre is on a slope is pushed at the slope's constant acceleration. A ball at
    rest stays at rest (it can only rest on a slope against something that holds it)."""

    name = "slope"

    def __init__(self, res: Resources) -> None:
        self.config, self.bodies = res.config, res.bodies
        self._balls, self._slopes = Selection(), AreaIndex(lambda slope: slope.push)

    def process(self) -> None:
        state = self.bodies.gather(esper.get_component(Body))
        rows = self._balls.of(self.bodies, esper.get_components(Body, Ball))
        zones = esper.get_components(Region, Slope)
        on = self._slopes.under(state, rows, zones)
        if on is not None:
            accelerate(state, rows, self._slopes.values, on, self.config.dt)
