import esper
import numpy as np

from polygolf.engine.components import Bumper
from polygolf.engine.components.resources import HEARD_LIMIT, Resources
from polygolf.engine.physics.contact import K_OTHER, P_APPROACH, P_X, P_Y
from polygolf.engine.physics.settings import RESTITUTION_THRESHOLD


class ImpactsProcessor(esper.Processor):
    """After `resolve`: each manifold whose points were closing faster than a bounce needs is one
    impact (its fastest point's approach speed), told to whoever listens (`Events.impacts`: the
    front end's sound, the shot preview), naming the two entities. Reads the contacts only; changes
    nothing. Looks only at manifolds with a point not resting (few, and in most substeps none)."""

    name = "impacts"

    def __init__(self, res: Resources) -> None:
        self.contacts, self.events = res.contacts, res.events

    def process(self) -> None:
        table = self.contacts.table
        if not len(table):
            return
        approach = table.points[:, P_APPROACH]
        resting = approach >= -RESTITUTION_THRESHOLD
        if resting.all():
            return
        closing = np.flatnonzero(~resting)
        first = table.first
        struck = np.unique(np.searchsorted(first, closing, side="right") - 1)
        # Each of these manifolds is one impact, and a listener keeps only the last HEARD_LIMIT.
        for k in struck[-HEARD_LIMIT:].tolist():
            speeds = approach[first[k]:first[k + 1]].tolist()
            fastest = min(range(len(speeds)), key=speeds.__getitem__)  # the first of the fastest
            if speeds[fastest] >= -RESTITUTION_THRESHOLD:
                continue
            p = first[k] + fastest
            ea, eb = table.ents[k].tolist()
            if eb != -1:
                kind = "body"
            else:
                kind = "bumper" if esper.has_component(table.keys[p, K_OTHER].item(), Bumper) else "wall"
            self.events.strike(kind, -speeds[fastest], table.points[p, P_X].item(), table.points[p, P_Y].item(),
                               (ea, eb))
