import math

import esper

from polygolf.engine.components import Body, Drag
from polygolf.engine.components.resources import Resources


def decay(value: float, rate: float, resistance: float, dt: float) -> float:
    """Magnitude after dt under d|v|/dt = -rate·|v| - resistance, solved exactly; never below zero.

    |v|(dt) = (|v| + c/k)·exp(-k·dt) - c/k, or |v| - c·dt when k = 0."""
    if rate > 0.0:
        after = (value + resistance / rate) * math.exp(-rate * dt) - resistance / rate
    else:
        after = value - resistance * dt
    return after if after > 0.0 else 0.0


class DragProcessor(esper.Processor):
    """Drag on the green: exponential damping (`linear`, `angular`, 1/s) together with rolling
    resistance (`rolling`, `rolling_angular`, a constant deceleration), integrated exactly over the
    substep, so a roll follows the closed form whatever the preset. The surface under the body
    (sand, ice) scales every rate for this substep through `Drag.scale`."""

    name = "drag"

    def __init__(self, res: Resources) -> None:
        self.config = res.config

    def process(self) -> None:
        dt = self.config.dt
        for _, (body, drag) in esper.get_components(Body, Drag):
            if body.asleep or body.inv_mass == 0.0:
                continue
            scale, drag.scale = drag.scale, 1.0
            if drag.linear or drag.rolling:
                speed = math.hypot(body.vx, body.vy)
                if speed > 0.0:
                    factor = decay(speed, drag.linear * scale, drag.rolling * scale, dt) / speed
                    body.vx *= factor
                    body.vy *= factor
            if (drag.angular or drag.rolling_angular) and body.spin:
                turned = decay(abs(body.spin), drag.angular * scale, drag.rolling_angular * scale, dt)
                body.spin = math.copysign(turned, body.spin)
