import esper
import numpy as np

from polygolf.engine.components import Body, Drag
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.body import Selection
from polygolf.engine.physics.motion import advance, mark_touching
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
        self._dragged_mask = np.zeros(0, dtype=np.bool_)  # bodies slowed by drag, for the rows above
        self._settles = np.zeros(0, dtype=np.bool_)
        self._touched = False  # whether `_settles` holds touching bodies besides the dragged

    def process(self) -> None:
        state = self.bodies.gather(esper.get_component(Body))
        dragged = self._dragged.of(self.bodies, esper.get_components(Body, Drag))
        if dragged is not self._rows or len(self._dragged_mask) != len(state):
            self._dragged_mask = np.zeros(len(state), dtype=np.bool_)
            self._dragged_mask[dragged] = True
            self._settles, self._rows, self._touched = self._dragged_mask.copy(), dragged, True
        settles = self._settles  # dragged, or touching something (this substep's contacts)
        table = self.contacts.table
        if len(table) or self._touched:
            settles[:] = self._dragged_mask
            mark_touching(settles, table.ents, self.bodies.lookup)
            self._touched = len(table) > 0
        dt = self.config.dt
        advance(state, settles, dt, REST_LINEAR * dt, REST_ANGULAR * dt, REST_SPEED_CAP, TIME_TO_REST)
