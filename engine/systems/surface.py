import esper

from polygolf.engine.components import Ball, Body, Drag, Region
from polygolf.engine.components.resources import Resources


class SurfaceProcessor(esper.Processor):
    """A ball whose centre is on a surface of kind `marker` rolls under the green's drag times the
    surface's `drag_scale` this substep (the drag processor applies and resets it)."""

    marker: type

    def __init__(self, res: Resources) -> None:
        pass  # reads components only

    def process(self) -> None:
        zones = esper.get_components(Region, self.marker)
        for _, (body, drag, _) in esper.get_components(Body, Drag, Ball):
            if body.asleep:
                continue
            for _, (region, surface) in zones:
                if region.contains(body.x, body.y):
                    drag.scale = surface.drag_scale
                    break
