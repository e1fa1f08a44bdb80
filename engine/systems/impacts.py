import esper
import numpy as np

from polygolf.engine.components import Bumper
from polygolf.engine.components.resources import HEARD_LIMIT, Resources
from polygolf.engine.physics.contact import K_OTHER, P_APPROACH, P_X, P_Y
from polygolf.engine.physics.jit import leaf_kernel
from polygolf.engine.physics.settings import RESTITUTION_THRESHOLD

KINDS = ("wall", "bumper", "body")  # an impact's kind, by its code in the heard rows
HEARD_COLUMNS = 6  # kind, speed, x, y, entity A, entity B


class ImpactsProcessor(esper.Processor):
    """After `resolve`: each manifold whose points were closing faster than a bounce needs is one
    impact (its fastest point's approach speed), told to whoever listens (`Events.impacts`: the
    front end's sound, the shot preview), naming the two entities. Reads the contacts only; changes
    nothing. Looks only at manifolds with a point not resting (few, and in most substeps none).

    The kernel (`hear`) writes the impacts into rows kept here, the last HEARD_LIMIT of them (as
    many as a listener keeps), so a run of compiled stages can hear a whole frame's; `tell` passes
    them on in the order they happened."""

    name = "impacts"

    def __init__(self, res: Resources) -> None:
        self.contacts, self.events = res.contacts, res.events
        self._heard = np.zeros((HEARD_LIMIT, HEARD_COLUMNS))
        self._count = np.zeros(1, dtype=np.int64)  # impacts written since the last `tell`
        self._bumpers: list | None = None
        self._is_bumper = np.zeros(0, dtype=np.bool_)

    def inputs(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """What `hear` reads besides the table: which entities are bumpers, the rows and their count."""
        bumpers = esper.get_component(Bumper)
        if bumpers is not self._bumpers:
            ents = [ent for ent, _ in bumpers]
            self._is_bumper = np.zeros(max(ents, default=-1) + 1, dtype=np.bool_)
            self._is_bumper[ents] = True
            self._bumpers = bumpers
        return self._is_bumper, self._heard, self._count

    def process(self) -> None:
        table = self.contacts.table
        if len(table):
            hear(table.arrays, self.inputs())
            self.tell()

    def tell(self) -> None:
        """Pass on the impacts heard since the last time, oldest first."""
        count = int(self._count[0])
        if not count:
            return
        for k in range(max(0, count - HEARD_LIMIT), count):
            kind, speed, x, y, ea, eb = self._heard[k % HEARD_LIMIT].tolist()
            self.events.strike(KINDS[int(kind)], speed, x, y, (int(ea), int(eb)))
        self._count[0] = 0


@leaf_kernel
def hear(table: tuple, inputs: tuple) -> None:
    """The stage on a table's columns (`ContactTable.arrays`): each manifold with a point closing
    faster than RESTITUTION_THRESHOLD, in the table's order, as a row (its kind: a body, a bumper or
    another wall; its first fastest point's approach speed and place; its two entities)."""
    ents, _, _, _, first, points, keys = table
    is_bumper, heard, count = inputs
    for k in range(len(ents)):
        fastest = -1
        for p in range(first[k], first[k + 1]):
            if points[p, P_APPROACH] < -RESTITUTION_THRESHOLD and (
                    fastest < 0 or points[p, P_APPROACH] < points[fastest, P_APPROACH]):
                fastest = p
        if fastest < 0:
            continue
        other = keys[fastest, K_OTHER]
        kind = 2 if ents[k, 1] != -1 else (1 if other < len(is_bumper) and is_bumper[other] else 0)
        row = heard[count[0] % len(heard)]
        row[0], row[1], row[2], row[3] = kind, -points[fastest, P_APPROACH], points[fastest, P_X], points[fastest, P_Y]
        row[4], row[5] = ents[k, 0], ents[k, 1]
        count[0] += 1
