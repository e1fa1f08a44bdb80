import esper
import numpy as np

from polygolf.engine.components import Body, Drag
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.body import Selection
from polygolf.engine.physics.jit import leaf_kernel
from polygolf.engine.physics.motion import count_still, hold_islands, mark_touching, move
from polygolf.engine.physics.settings import REST_ANGULAR, REST_LINEAR, REST_SPEED_CAP, TIME_TO_REST


class IntegrateProcessor(esper.Processor):
    """Semi-implicit Euler, position half: x += v·dt with the velocity the contact solver left at
    the end of the last substep (forces then update velocities, and the solver constrains them
    before they move anything). Also rest detection (`motion.advance`).

    A body is put to rest when it is touching something or slowed by drag (a free body with no drag
    coasts for ever: sleeping it would steal its momentum) and has hardly *moved* for TIME_TO_REST.
    Judging by displacement (corrections included) rather than velocity lets a ball pressed into a
    corner by a slope fall asleep although the slope adds velocity every substep. A body at rest has
    its velocities zeroed and is skipped by every system until something wakes it."""

    name = "integrate"

    def __init__(self, res: Resources) -> None:
        self.config, self.contacts, self.bodies = res.config, res.contacts, res.bodies
        self._dragged = Selection()
        self._rows: np.ndarray | None = None
        self._inputs: tuple = ()

    def inputs(self) -> tuple:
        """What `integrate` reads besides the state, the contacts and dt: the settle mask (dragged,
        or touching something: kept between substeps), the dragged mask, whether the mask holds
        touching bodies besides the dragged, the store's entity lookup, and room for the islands of
        touching bodies (`motion.hold_islands`)."""
        state = self.bodies.gather(esper.get_component(Body))
        dragged = self._dragged.of(self.bodies, esper.get_components(Body, Drag))
        if dragged is not self._rows or len(self._inputs[1]) != len(state):
            mask = np.zeros(len(state), dtype=np.bool_)
            mask[dragged] = True
            self._inputs = (mask.copy(), mask, np.ones(1, dtype=np.bool_), self.bodies.lookup,
                            np.empty(len(state), dtype=np.int64), np.zeros(len(state), dtype=np.bool_))
            self._rows = dragged
        return self._inputs

    def process(self) -> None:
        inputs = self.inputs()
        integrate(self.bodies.state, self.contacts.table.arrays, inputs, self.config.dt)


@leaf_kernel
def integrate(state: np.ndarray, table: tuple, inputs: tuple, dt: float) -> None:
    """The stage on a store's state, given this substep's contact table (`ContactTable.arrays`: its
    entity pairs are the bodies touching): `motion.advance`, with bodies that touch each other put to
    rest together."""
    touching = table[0]
    settles, dragged, touched, lookup, island, held = inputs
    if len(touching) or touched[0]:
        for k in range(len(settles)):  # (a leaf copies element by element: numba's slice copy would need its counts)
            settles[k] = dragged[k]
        mark_touching(settles, touching, lookup)
        touched[0] = len(touching) > 0
    count_still(state, settles, dt, REST_LINEAR * dt, REST_ANGULAR * dt, REST_SPEED_CAP)
    holding = hold_islands(state, settles, touching, lookup, TIME_TO_REST, island, held)
    move(state, settles, dt, TIME_TO_REST, held, holding)
