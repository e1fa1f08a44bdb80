import esper
import numpy as np

from polygolf.engine.components import Body, Collider
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.grid import bodies_near, body_pairs, by_entity
from polygolf.engine.physics.settings import CONTACT_MARGIN

_NO_PAIRS = np.zeros((0, 2), dtype=np.int64)
_NONE_NEAR = np.zeros(0, dtype=np.int64)
_NO_ROWS = np.zeros(1, dtype=np.int64)


class BroadphaseProcessor(esper.Processor):
    """Candidate pairs from bounding boxes (`physics.grid`): moving bodies against the walls' grid,
    and bodies against each other. Resting bodies are not looked up at all. Reads the static index;
    writes the candidates."""

    name = "broadphase"

    def __init__(self, res: Resources) -> None:
        self.statics, self.candidates, self.config = res.statics, res.candidates, res.config
        self.shapes, self.bodies, self.fat_boxes = res.shapes, res.bodies, res.fat_boxes
        walls = len(res.statics.grid)  # the grid query's scratch, and the answer's arrays, kept between substeps
        self._seen, self._scratch = np.zeros(walls, dtype=np.bool_), np.empty(walls, dtype=np.int64)
        self._near, self._first = np.empty(0, dtype=np.int64), np.empty(1, dtype=np.int64)
        self._found = np.empty(16, dtype=np.int64)

    def process(self) -> None:
        bodies = esper.get_components(Body, Collider)
        state, _, rows = self.shapes.current(self.bodies, esper.get_component(Body), bodies)
        ents = self.shapes.ents
        if len(self._near) != len(rows):
            self._near, self._first = np.empty(len(rows), dtype=np.int64), np.empty(len(rows) + 1, dtype=np.int64)
        self._found, count = bodies_near(state, rows, self.shapes.radius, CONTACT_MARGIN, self.statics.grid.arrays,
                                         self.fat_boxes.of(state, len(self._seen)), self._seen, self._scratch,
                                         self._near, self._first, self._found)
        candidates = self.candidates
        if count:
            candidates.near = ents[self._near[:count]]
            candidates.near_first = self._first[:count + 1].copy()
            candidates.near_found = self._found[:self._first[count]].copy()
        else:  # most substeps of a ball in the open
            candidates.near, candidates.near_first, candidates.near_found = _NONE_NEAR, _NO_ROWS, _NONE_NEAR
        pairs = _NO_PAIRS
        if len(bodies) > 1:
            pairs = by_entity(body_pairs(state, rows, self.shapes.radius, CONTACT_MARGIN, False,
                                         self.config.collide_bodies, False), ents)
        self.candidates.pair_ents = pairs  # in entity order, whichever way they were found
