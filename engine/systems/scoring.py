import esper

from polygolf.engine.components import Ball, Body, Collider, HoleState
from polygolf.engine.components.resources import Resources


class ScoringProcessor(esper.Processor):
    """Last stage: counts this substep's strokes ("shot"), penalties and balls dropping ("holed") on
    the `HoleState` of the ball they happened to (one per player), and picks a ball up once it rests
    after the last stroke allowed. A finished ball leaves the green: its collider goes, so the balls
    still in play neither hit it in the cup nor where it was picked up."""

    name = "scoring"

    def __init__(self, res: Resources) -> None:
        self.events = res.events

    def process(self) -> None:
        fired, self.events.fired = self.events.fired, []
        for kind, ent, amount in fired:
            state = esper.try_component(ent, HoleState)
            if state is None or state.finished:
                continue
            if kind == "shot":
                state.strokes += 1
            elif kind == "penalty":
                state.penalties += amount
            elif kind == "holed":
                state.holed = True
        for ent, (body, _, state) in esper.get_components(Body, Ball, HoleState):
            if not state.finished and state.score >= state.max_strokes and body.asleep:
                state.picked_up = True
            if state.finished and esper.has_component(ent, Collider):
                esper.remove_component(ent, Collider)
