import esper

from polygolf.engine.components import Body
from polygolf.engine.components.resources import Resources


class GravityProcessor(esper.Processor):
    """A constant acceleration on every awake dynamic body: the velocity half of semi-implicit Euler
    for a tilted table. Bodies at rest are left alone, so a ball resting against a wall stays put."""

    name = "gravity"

    def __init__(self, res: Resources) -> None:
        self.config = res.config

    def process(self) -> None:
        gx, gy = self.config.gravity
        dt = self.config.dt
        for _, body in esper.get_component(Body):
            if body.inv_mass > 0.0 and not body.asleep:
                body.vx += gx * dt
                body.vy += gy * dt
