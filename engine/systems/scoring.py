import esper
import numpy as np

from polygolf.engine.components import Ball, Body, Collider, HoleState
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.body import Selection
from polygolf.engine.physics.motion import came_to_rest


class ScoringProcessor(esper.Processor):
    """Last stage: counts this substep's strokes ("shot"), penalties and balls dropping ("holed") on
    the `HoleState` of the ball they happened to (one per player), and picks a ball up once it rests
    after the last stroke allowed. A finished ball leaves the green: its collider goes, so the balls
    still in play neither hit it in the cup nor where it was picked up. A ball that another's shot
    knocks into the cup is holed with a stroke added, the putt it was spared (never a hole in none).

    A ball's state can change only through an event or by its coming to rest, so only those balls
    are looked at (all of them when the world's entities change); and a rest matters only to a ball
    on its last stroke, so while there is none and no event, a substep is not looked at at all (a
    thousand shots' search has none)."""

    name = "scoring"

    def __init__(self, res: Resources) -> None:
        self.events, self.bodies = res.events, res.bodies
        self._balls = Selection()
        self._was_asleep = np.zeros(0, dtype=np.bool_)  # each ball's rest as last seen (now, after a look)
        self._rested = np.zeros(0, dtype=np.int64)
        self._listed: list | None = None  # the balls `_waiting` is about
        self._waiting = False  # whether a ball still in play is on its last stroke
        self._shooter: int | None = None  # the ball of the last shot taken

    def quiet(self) -> bool:
        """Whether its next call would pass over the substep: no event, no ball on its last stroke,
        the same balls (only the cup's drop, which ends a run of compiled stages, tells it news)."""
        return not self.events.fired and not self._waiting and \
            esper.get_components(Body, Ball, HoleState) is self._listed

    def process(self) -> None:
        fired, self.events.fired = self.events.fired, []
        for kind, ent, amount in fired:
            hole = esper.try_component(ent, HoleState)
            if hole is None or hole.finished:
                continue
            if kind == "shot":
                hole.strokes += 1
                self._shooter = ent
            elif kind in ("penalty", "restart"):  # (water's, or the player's own back to the tee)
                hole.penalties += amount
            elif kind == "holed":
                hole.holed = True
                if self._shooter is not None and ent != self._shooter:
                    hole.strokes += 1  # knocked in by another's shot: the putt it was spared
        balls = esper.get_components(Body, Ball, HoleState)
        if not fired and balls is self._listed and not self._waiting:
            return  # no event, and no ball a rest would pick up
        state = self.bodies.gather(esper.get_component(Body))
        known = self._balls.rows
        rows = self._balls.of(self.bodies, balls)
        if rows is not known or len(self._was_asleep) != len(rows):  # new entities: look at every ball once
            self._was_asleep = np.zeros(len(rows), dtype=np.bool_)
            self._rested = np.empty(len(rows), dtype=np.int64)
            came_to_rest(state, rows, self._was_asleep, self._rested)
            look: list[int] = list(range(len(rows)))
        else:
            look = self._rested[:came_to_rest(state, rows, self._was_asleep, self._rested)].tolist()
            if fired:
                named = {ent for _, ent, _ in fired}
                look = sorted({*look, *(q for q, (ent, _) in enumerate(balls) if ent in named)})
        for q in look:
            ent, (_, _, hole) = balls[q]
            if not hole.finished and hole.score >= hole.max_strokes and self._was_asleep[q]:
                hole.picked_up = True
            if hole.finished and esper.has_component(ent, Collider):
                esper.remove_component(ent, Collider)
        self._waiting = any(not hole.finished and hole.score >= hole.max_strokes for _, (_, _, hole) in balls)
        self._listed = balls
