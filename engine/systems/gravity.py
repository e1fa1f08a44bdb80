import esper
import numpy as np

from polygolf.engine.components import Body
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.motion import accelerate


class GravityProcessor(esper.Processor):
    """A constant acceleration on every awake dynamic body: the velocity half of semi-implicit Euler
    for a tilted table. Bodies at rest are left alone, so a ball resting against a wall stays put."""

    name = "gravity"

    def __init__(self, res: Resources) -> None:
        self.config, self.bodies = res.config, res.bodies
        self._every = (np.zeros(0, dtype=np.int64), np.zeros(0), np.zeros(0))  # rows, gx, gy for a world's size

    def process(self) -> None:
        state = self.bodies.gather(esper.get_component(Body))
        rows, ax, ay = self._every
        gx, gy = self.config.gravity
        if len(rows) != len(state) or (len(rows) and (ax[0] != gx or ay[0] != gy)):
            n = len(state)
            rows, ax, ay = self._every = np.arange(n, dtype=np.int64), np.full(n, float(gx)), np.full(n, float(gy))
        accelerate(state, rows, ax, ay, self.config.dt)
