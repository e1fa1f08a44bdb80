import esper
import numpy as np

from polygolf.engine.components import Ball, Body, Region, Slope
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.body import Selection
from polygolf.engine.physics.geometry import first_area
from polygolf.engine.physics.jit import leaf_kernel
from polygolf.engine.physics.motion import accelerate
from polygolf.engine.systems.areas import AreaIndex


class SlopeProcessor(esper.Processor):
    """A ball whose centre is on a slope is pushed at the slope's constant acceleration. A ball at
    rest stays at rest (it can only rest on a slope against something that holds it)."""

    name = "slope"

    def __init__(self, res: Resources) -> None:
        self.config, self.bodies = res.config, res.bodies
        self._balls, self._slopes = Selection(), AreaIndex(lambda slope: slope.push, columns=2)

    def inputs(self) -> tuple:
        """The balls' rows, the slopes packed (`AreaIndex.inputs`, values: pushes)."""
        self.bodies.gather(esper.get_component(Body))
        rows = self._balls.of(self.bodies, esper.get_components(Body, Ball))
        return self._slopes.inputs(rows, esper.get_components(Region, Slope))

    def process(self) -> None:
        inputs = self.inputs()  # first: it gathers the state
        push_on_slopes(self.bodies.state, inputs, self.config.dt)


@leaf_kernel
def push_on_slopes(state: np.ndarray, inputs: tuple, dt: float) -> None:
    """The stage on a store's state."""
    rows, verts, first, boxes, pushes, on = inputs
    if first_area(state, rows, verts, first, boxes, on):
        accelerate(state, rows, pushes, on, dt)
