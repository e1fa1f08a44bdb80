import esper

from engine.components import Ball, Body, Drag, Ice, Region
from engine.context import PhysicsContext


class IceProcessor(esper.Processor):
    """A ball whose centre is on ice keeps only a small part of the green's drag: it glides."""

    name = "ice"

    def __init__(self, ctx: PhysicsContext) -> None:
        self.ctx = ctx

    def process(self) -> None:
        zones = esper.get_components(Region, Ice)
        for _, (body, drag, _) in esper.get_components(Body, Drag, Ball):
            if body.asleep:
                continue
            for _, (region, ice) in zones:
                if region.contains(body.x, body.y):
                    drag.scale = ice.drag_scale
                    break
