import esper
import numpy as np

from polygolf.engine.components import Body, Bumper
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.body import INV_INERTIA, INV_MASS, SPIN, VX, VY
from polygolf.engine.physics.contact import K_OTHER, M_NX, M_NY, P_APPROACH, P_RA_X, P_RA_Y
from polygolf.engine.physics.jit import leaf_kernel
from polygolf.engine.physics.settings import RESTITUTION_THRESHOLD

LIT_SECONDS = 0.25


class BumperProcessor(esper.Processor):
    """After restitution: a ball that struck a bumper this substep gets its kick, an impulse at the
    centre of the struck points that adds `kick` m/s to the normal speed there (one kick per
    manifold, so a flat hit on two points is kicked once; an off-centre hit also turns the ball).
    Reads the contact table's struck points only (few, and in most substeps none).

    The kernel (`kick`) keeps each bumper's light (`Bumper.lit`, seconds left, for drawing) in an
    array, so a run of compiled stages can kick in any of its substeps; `tell` hands the lights to
    the components when it ends."""

    name = "bumper"

    def __init__(self, res: Resources) -> None:
        self.config, self.contacts, self.bodies = res.config, res.contacts, res.bodies
        self._bumpers: list | None = None
        self._index = np.zeros(0, dtype=np.int64)  # each entity's bumper (-1: none)
        self._kicks, self._lit = np.zeros(0), np.zeros(0)

    def inputs(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """What `kick` reads besides the state, the table and dt: each entity's bumper, and each
        bumper's kick and light."""
        bumpers = esper.get_component(Bumper)
        if bumpers is not self._bumpers:
            self.tell()  # (of the list it was for)
            ents = [ent for ent, _ in bumpers]
            self._index = np.full(max(ents, default=-1) + 1, -1, dtype=np.int64)
            self._index[ents] = np.arange(len(ents))
            self._kicks = np.array([bumper.kick for _, bumper in bumpers], dtype=np.float64)
            self._lit = np.array([bumper.lit for _, bumper in bumpers], dtype=np.float64)
            self._bumpers = bumpers
        return self._index, self._kicks, self._lit

    def process(self) -> None:
        inputs = self.inputs()
        state = self.bodies.gather(esper.get_component(Body))
        kick(state, self.contacts.table.arrays, inputs, self.config.dt)
        self.tell()

    def tell(self) -> None:
        """Hand each bumper its light."""
        for (_, bumper), lit in zip(self._bumpers or (), self._lit.tolist()):
            bumper.lit = lit


@leaf_kernel
def kick(state: np.ndarray, table: tuple, inputs: tuple, dt: float) -> None:
    """The stage on a store's state and a table's columns (`ContactTable.arrays`): every bumper's
    light goes down by dt; each manifold against a bumper with a point closing faster than a bounce
    needs (its approach speed) kicks its body once, and its struck points are marked as answered."""
    ents, pair, normals, _, first, points, keys = table
    index, kicks, lit = inputs
    for b in range(len(lit)):
        if lit[b] != 0.0:
            left = lit[b] - dt
            lit[b] = left if left > 0.0 else 0.0
    for k in range(len(ents)):
        if ents[k, 1] != -1:
            continue  # bumpers are walls: static manifolds only
        struck, rx, ry, other = 0, 0.0, 0.0, -1
        for p in range(first[k], first[k + 1]):
            if points[p, P_APPROACH] < -RESTITUTION_THRESHOLD:
                if struck == 0:
                    other = keys[p, K_OTHER]
                struck += 1
                rx += points[p, P_RA_X]
                ry += points[p, P_RA_Y]
        if struck == 0 or other >= len(index) or index[other] < 0:
            continue
        b = index[other]
        rx, ry = rx / struck, ry / struck
        nx, ny = -normals[k, M_NX], -normals[k, M_NY]  # away from the bumper
        rn = rx * ny - ry * nx
        a = pair[k, 0]
        lam = kicks[b] / (state[a, INV_MASS] + state[a, INV_INERTIA] * rn * rn)
        state[a, VX] += state[a, INV_MASS] * lam * nx
        state[a, VY] += state[a, INV_MASS] * lam * ny
        state[a, SPIN] += state[a, INV_INERTIA] * lam * rn
        for p in range(first[k], first[k + 1]):
            if points[p, P_APPROACH] < -RESTITUTION_THRESHOLD:
                points[p, P_APPROACH] = 0.0  # one kick per impact, even if the points linger
        lit[b] = LIT_SECONDS
