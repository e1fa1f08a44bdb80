import math

import esper

from engine.components import Body, Drag
from engine.context import PhysicsContext


class DragProcessor(esper.Processor):
    """Linear and angular drag as exact exponential decay over the substep, v <- v·exp(-k·dt), then
    rolling resistance as a constant deceleration that never reverses the motion.

    The decay is exact for any step size, so a long roll matches v0·exp(-k·t) whatever the preset."""

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
            if drag.rolling:
                speed = math.hypot(body.vx, body.vy)
                factor = max(0.0, speed - drag.rolling * dt) / speed if speed > 0.0 else 0.0
                body.vx *= factor
                body.vy *= factor
            if drag.rolling_angular:
                slowed = max(0.0, abs(body.spin) - drag.rolling_angular * dt)
                body.spin = math.copysign(slowed, body.spin)
