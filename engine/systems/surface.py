import esper
import numpy as np

from polygolf.engine.components import Ball, Body, Drag, Region
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.body import Selection
from polygolf.engine.physics.geometry import first_area
from polygolf.engine.physics.jit import leaf_kernel
from polygolf.engine.physics.motion import take_scale
from polygolf.engine.systems.areas import AreaIndex


class SurfaceProcessor(esper.Processor):
    """A ball whose centre is on a surface of kind `marker` rolls under the green's drag times the
    surface's `drag_scale` this substep (the body's `drag_scale`: the drag processor applies and
    resets it)."""

    marker: type

    def __init__(self, res: Resources) -> None:
        self.bodies = res.bodies
        self._balls, self._areas = Selection(), AreaIndex(lambda surface: surface.drag_scale)

    def inputs(self) -> tuple:
        """The dragged balls' rows, the surfaces packed (`AreaIndex.inputs`, values: drag scales)."""
        self.bodies.gather(esper.get_component(Body))
        rows = self._balls.of(self.bodies, esper.get_components(Body, Drag, Ball))
        return self._areas.inputs(rows, esper.get_components(Region, self.marker))

    def process(self) -> None:
        inputs = self.inputs()  # first: it gathers the state
        scale_on_surfaces(self.bodies.state, inputs)


@leaf_kernel
def scale_on_surfaces(state: np.ndarray, inputs: tuple) -> None:
    """The stage on a store's state."""
    rows, verts, first, boxes, scales, on = inputs
    if first_area(state, rows, verts, first, boxes, on):
        take_scale(state, rows, scales, on)
