import esper
import numpy as np

from polygolf.engine.components import Ball, Body, Cup
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.body import ASLEEP, Selection, X, Y
from polygolf.engine.physics.jit import leaf_kernel
from polygolf.engine.physics.motion import cup_under, put_to_rest


class CupProcessor(esper.Processor):
    """Drops the ball into the cup when it is over the cup and slow enough there (`Cup.capture_speed`,
    `motion.cup_under`), and says so ("holed"). A holed ball is put to rest in the cup and never
    touched again.

    The kernel (`drop`) puts the ball in the cup and notes it in rows kept here, so a run of
    compiled stages can drop balls in any of its substeps; `tell` marks them holed and says so, in
    the order they dropped."""

    name = "cup"

    def __init__(self, res: Resources) -> None:
        self.events, self.bodies = res.events, res.bodies
        self._selection = Selection()
        self._cups: list | None = None
        self._packed = np.zeros((0, 4))  # each cup's x, y, radius, max_speed
        self._balls: list | None = None
        self._holed = np.zeros(0, dtype=np.bool_)  # each ball's `Ball.holed`, as the kernel sees it
        self._dropped = np.zeros(0, dtype=np.int64)  # the balls that dropped since the last `tell`
        self._count = np.zeros(1, dtype=np.int64)  # how many

    def inputs(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """What `drop` reads besides the state: the balls' rows, the cups, whether each ball is
        holed, and the dropped balls' room and count."""
        cups = esper.get_component(Cup)
        if cups is not self._cups:
            self._packed = np.array([(c.x, c.y, c.radius, c.max_speed) for _, c in cups],
                                    dtype=np.float64).reshape(-1, 4)
            self._cups = cups
        self.bodies.gather(esper.get_component(Body))
        balls = esper.get_components(Body, Ball)
        rows = self._selection.of(self.bodies, balls)
        if balls is not self._balls:
            self.tell()  # (of the list it was for)
            self._holed = np.array([ball.holed for _, (_, ball) in balls], dtype=np.bool_)
            self._dropped = np.empty(len(balls), dtype=np.int64)
            self._balls = balls
        return rows, self._packed, self._holed, self._dropped, self._count

    def process(self) -> None:
        inputs = self.inputs()  # first: it gathers the state
        drop(self.bodies.state, inputs)
        self.tell()

    def tell(self) -> None:
        """Mark the balls that dropped since the last time holed, and say so."""
        count = int(self._count[0])
        if not count:
            return
        self._count[0] = 0
        for q in self._dropped[:count].tolist():
            ent, (_, ball) = self._balls[q]
            ball.holed = True
            self.events.emit("holed", ent)


@leaf_kernel
def drop(state: np.ndarray, inputs: tuple) -> None:
    """The stage on a store's state: each awake ball not yet holed that a cup catches
    (`motion.cup_under`) is put to rest at the cup's centre and noted."""
    rows, cups, holed, dropped, count = inputs
    for q in range(len(rows)):
        k = rows[q]
        if state[k, ASLEEP] != 0.0 or holed[q]:
            continue
        c = cup_under(state, k, cups)
        if c < 0:
            continue
        holed[q] = True
        state[k, X], state[k, Y] = cups[c, 0], cups[c, 1]
        put_to_rest(state, k)
        dropped[count[0]] = q
        count[0] += 1
