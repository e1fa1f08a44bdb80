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
        self._every = (np.zeros(0, dtype=np.int64), np.zeros((1, 2)), np.zeros(0, dtype=np.int64))  # rows, push, which

    def inputs(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """`motion.accelerate`'s rows, push and which (every body, the one push)."""
        state = self.bodies.gather(esper.get_component(Body))
        rows, push, which = self._every
        gx, gy = self.config.gravity
        if len(rows) != len(state) or push[0, 0] != gx or push[0, 1] != gy:
            n = len(state)
            self._every = (np.arange(n, dtype=np.int64), np.array([[gx, gy]], dtype=np.float64),
                           np.zeros(n, dtype=np.int64))
        return self._every

    def process(self) -> None:
        inputs = self.inputs()  # first: it gathers the state
        accelerate(self.bodies.state, *inputs, self.config.dt)
