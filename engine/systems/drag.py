import math

import esper

from engine.components import Body, Drag
from engine.context import PhysicsContext


class DragProcessor(esper.Processor):
    """Linear and angular drag as exact exponential decay over the substep: v <- v·exp(-k·dt).

    Exact for any step size, so a long roll matches v0·exp(-k·t) whatever the preset."""

    name = "drag"

    def __init__(self, ctx: PhysicsContext) -> None:
        self.ctx = ctx

    def process(self) -> None:
        dt = self.ctx.dt
        for _, (body, drag) in esper.get_components(Body, Drag):
            if body.asleep or body.inv_mass == 0.0:
                continue
            if drag.linear:
                factor = math.exp(-drag.linear * dt)
                body.vx *= factor
                body.vy *= factor
            if drag.angular:
                body.spin *= math.exp(-drag.angular * dt)
