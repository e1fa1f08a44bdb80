import esper
import numpy as np

from polygolf.engine.components import Body, Windmill
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.body import SPIN, Selection
from polygolf.engine.physics.jit import leaf_kernel


class WindmillProcessor(esper.Processor):
    """Drives each windmill at its set speed. It is kinematic (no inverse mass or inertia), so no
    contact can slow it; the contact solver sees its surface velocity, ω × r, like any body's. (A
    windmill that would crush a ball stalls for the rest of a substep: continuous collision stops it;
    this stage turns it on again at the next.)"""

    name = "windmill"

    def __init__(self, res: Resources) -> None:
        self.bodies = res.bodies
        self._selection = Selection()
        self._mills: list | None = None
        self._speeds = np.zeros(0)

    def inputs(self) -> tuple[np.ndarray, np.ndarray]:
        """What `drive` reads besides the state: the windmills' rows and speeds (a `Windmill` is
        frozen: its speed is read when the world's lists change)."""
        self.bodies.gather(esper.get_component(Body))
        mills = esper.get_components(Body, Windmill)
        if mills is not self._mills:
            self._speeds = np.array([mill.speed for _, (_, mill) in mills], dtype=np.float64)
            self._mills = mills
        return self._selection.of(self.bodies, mills), self._speeds

    def process(self) -> None:
        inputs = self.inputs()  # first: it gathers the state
        drive(self.bodies.state, inputs)


@leaf_kernel
def drive(state: np.ndarray, inputs: tuple) -> None:
    """The stage on a store's state: each windmill's spin is its speed."""
    rows, speeds = inputs
    for q in range(len(rows)):
        state[rows[q], SPIN] = speeds[q]
