import esper
import numpy as np

from polygolf.engine.components import Body, Collider
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.body import ASLEEP, INV_MASS, SPIN, VX, VY, X, Y
from polygolf.engine.physics.grid import BoxGrid, bodies_near, box_pairs
from polygolf.engine.physics.settings import CONTACT_MARGIN


class BroadphaseProcessor(esper.Processor):
    """Candidate pairs from bounding boxes (`physics.grid`): moving bodies against the walls' grid,
    and bodies against each other. Resting bodies are not looked up at all. Reads the static index;
    writes the candidates."""

    name = "broadphase"

    def __init__(self, res: Resources) -> None:
        self.statics, self.candidates, self.config = res.statics, res.candidates, res.config
        self.shapes, self.bodies = res.shapes, res.bodies

    def process(self) -> None:
        self.bodies.gather(esper.get_component(Body))
        bodies = esper.get_components(Body, Collider)
        rows = self.shapes.rows(self.bodies, bodies)
        ents = self.shapes.ents
        near, first, found = bodies_near(self.bodies.state, rows, self.shapes.radius, CONTACT_MARGIN,
                                         *self.statics.grid.arrays)
        candidates = self.candidates
        candidates.near, candidates.near_first, candidates.near_found = ents[near], first, found
        if len(bodies) > 1:
            self.candidates.pairs = self._pairs(self.bodies.state[rows], ents)
        else:
            self.candidates.pairs = []

    def _pairs(self, state: np.ndarray, ents: np.ndarray) -> list[tuple[int, int]]:
        """Body pairs whose boxes overlap, one of them moving (with `collide_bodies` off: a moving
        dynamic body and a kinematic one)."""
        box = boxes(state, self.shapes.radius)
        awake = state[:, ASLEEP] == 0.0
        dynamic = state[:, INV_MASS] != 0.0
        pairs = np.zeros((0, 2), dtype=np.int64)
        if self.config.collide_bodies:
            active = awake & (dynamic | (state[:, VX] != 0.0) | (state[:, VY] != 0.0) | (state[:, SPIN] != 0.0))
            pairs = ents[box_pairs(box, active)]
        else:  # bodies meet kinematic ones only: index those, look each moving body up (K shots: no K²)
            kinematic, moving = np.flatnonzero(~dynamic), np.flatnonzero(awake & dynamic)
            if len(kinematic) and len(moving):
                first, found = BoxGrid(box[kinematic], self.statics.grid.cell_size).query_many(box[moving])
                pairs = np.stack((np.repeat(ents[moving], first[1:] - first[:-1]), ents[kinematic[found]]), axis=1)
        pairs = np.sort(pairs.reshape(-1, 2), axis=1)
        pairs = pairs[np.lexsort((pairs[:, 1], pairs[:, 0]))]  # one order whichever way they were found
        return [(a, b) for a, b in pairs.tolist()]


def boxes(state: np.ndarray, radius: np.ndarray, margin: float = CONTACT_MARGIN) -> np.ndarray:
    """Each body's bounding box (rows of `state`, their bounding radii), grown by the contact margin."""
    r = radius + margin
    x, y = state[:, X], state[:, Y]
    return np.stack((x - r, y - r, x + r, y + r), axis=1)
