import esper
import numpy as np

from polygolf.engine.components import Body, Drag
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.body import Selection
from polygolf.engine.physics.motion import drag


class DragProcessor(esper.Processor):
    """Drag on the green: exponential damping (`linear`, `angular`, 1/s) together with rolling
    resistance (`rolling`, `rolling_angular`, a constant deceleration), integrated exactly over the
    substep (`motion.drag`), so a roll follows the closed form whatever the preset. The surface
    under the body (sand, ice) scales every rate for this substep through the body's `drag_scale`.
    A body's `Drag` is read when the world's bodies change, not every substep."""

    name = "drag"

    def __init__(self, res: Resources) -> None:
        self.config, self.bodies = res.config, res.bodies
        self._dragged = Selection()
        self._found: list | None = None
        self._rates = np.zeros((0, 4))

    def inputs(self) -> tuple[np.ndarray, np.ndarray]:
        """`motion.drag`'s rows and rates."""
        self.bodies.gather(esper.get_component(Body))
        found = esper.get_components(Body, Drag)
        rows = self._dragged.of(self.bodies, found)
        if found is not self._found:
            self._rates = np.array([(d.linear, d.angular, d.rolling, d.rolling_angular) for _, (_, d) in found],
                                   dtype=np.float64).reshape(-1, 4)
            self._found = found
        return rows, self._rates

    def process(self) -> None:
        inputs = self.inputs()  # first: it gathers the state
        drag(self.bodies.state, *inputs, self.config.dt)
