import esper

from polygolf.engine.components import Ball, Body, Drag, Region
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.body import Selection
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

    def process(self) -> None:
        state = self.bodies.gather(esper.get_component(Body))
        rows = self._balls.of(self.bodies, esper.get_components(Body, Drag, Ball))
        zones = esper.get_components(Region, self.marker)
        on = self._areas.under(state, rows, zones)
        if on is not None:
            take_scale(state, rows, self._areas.values, on)
