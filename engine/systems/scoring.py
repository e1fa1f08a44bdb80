import esper

from engine.components import Ball, Body, HoleState
from engine.context import PhysicsContext


class ScoringProcessor(esper.Processor):
    """Counts strokes ("shot" events) and the ball dropping ("holed"), and picks the ball up once it
    rests after the last stroke allowed."""

    name = "scoring"

    def __init__(self, ctx: PhysicsContext) -> None:
        self.ctx = ctx
        esper.set_handler("shot", self.on_shot)
        esper.set_handler("holed", self.on_holed)
        esper.set_handler("penalty", self.on_penalty)

    def _state(self) -> HoleState | None:
        states = esper.get_component(HoleState)
        return states[0][1] if states else None

    def on_shot(self, _entity: int) -> None:
        state = self._state()
        if state is not None and not state.finished:
            state.strokes += 1

    def on_holed(self, _entity: int) -> None:
        state = self._state()
        if state is not None and not state.finished:
            state.holed = True

    def on_penalty(self, strokes: int) -> None:
        state = self._state()
        if state is not None and not state.finished:
            state.penalties += strokes

    def process(self) -> None:
        state = self._state()
        if state is None or state.finished or state.score < state.max_strokes:
            return
        for _, (body, _) in esper.get_components(Body, Ball):
            if body.asleep:
                state.picked_up = True
