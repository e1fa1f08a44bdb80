import esper

from polygolf.engine.components import Bumper
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.settings import RESTITUTION_THRESHOLD


class ImpactsProcessor(esper.Processor):
    """After `resolve`: each manifold whose points were closing faster than a bounce needs is one
    impact (its fastest point's approach speed), told to whoever listens (`Events.impacts`: the
    front end's sound, the shot preview), naming the two entities. Reads the contacts only; changes
    nothing."""

    name = "impacts"

    def __init__(self, res: Resources) -> None:
        self.contacts, self.events = res.contacts, res.events

    def process(self) -> None:
        for m in self.contacts.manifolds:
            fastest = min(m.points, key=lambda p: p.approach_speed, default=None)
            if fastest is None or fastest.approach_speed >= -RESTITUTION_THRESHOLD:
                continue
            if m.entity_b != -1:
                kind = "body"
            else:
                kind = "bumper" if esper.has_component(fastest.key[0], Bumper) else "wall"
            self.events.strike(kind, -fastest.approach_speed, fastest.x, fastest.y, (m.entity_a, m.entity_b))
