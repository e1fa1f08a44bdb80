import esper

from engine.components import Ball, Body, Drag, Region, Sand
from engine.context import PhysicsContext


class SandProcessor(esper.Processor):
    """A ball whose centre is in a bunker rolls under the green's drag times the sand's scale."""

    name = "sand"

    def __init__(self, ctx: PhysicsContext) -> None:
        self.ctx = ctx

    def process(self) -> None:
        zones = esper.get_components(Region, Sand)
        for _, (body, drag, _) in esper.get_components(Body, Drag, Ball):
            if body.asleep:
                continue
            for _, (region, sand) in zones:
                if region.contains(body.x, body.y):
                    drag.scale = sand.drag_scale
                    break
