import esper

from polygolf.engine.components import Ball, Body, HoleState
from polygolf.engine.components.resources import Resources


class ScoringProcessor(esper.Processor):
    """Last stage: counts this substep's strokes ("shot"), penalties and the ball dropping ("holed"),
    and picks the ball up once it rests after the last stroke allowed."""

    name = "scoring"

    def __init__(self, res: Resources) -> None:
        self.events = res.events

    def process(self) -> None:
        fired, self.events.fired = self.events.fired, []
        for _, state in esper.get_component(HoleState):
            for kind, value in fired:
                if state.finished:
                    break
                if kind == "shot":
                    state.strokes += 1
                elif kind == "penalty":
                    state.penalties += value
                elif kind == "holed":
                    state.holed = True
            if state.finished or state.score < state.max_strokes:
                continue
            if any(body.asleep for _, (body, _) in esper.get_components(Body, Ball)):
                state.picked_up = True
