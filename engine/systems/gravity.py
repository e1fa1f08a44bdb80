import esper

from engine.components import Body
from engine.context import PhysicsContext


class GravityProcessor(esper.Processor):
    """A constant acceleration on every awake dynamic body: the velocity half of semi-implicit Euler
    for a tilted table. Bodies at rest are left alone, so a ball resting against a wall stays put."""

    name = "gravity"

    def __init__(self, ctx: PhysicsContext) -> None:
        self.ctx = ctx

    def process(self) -> None:
        gx, gy = self.ctx.gravity
        dt = self.ctx.dt
        for _, body in esper.get_component(Body):
            if body.inv_mass > 0.0 and not body.asleep:
                body.vx += gx * dt
                body.vy += gy * dt
