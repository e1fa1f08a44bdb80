import esper
import numpy as np

from polygolf.engine.components import Body, Collider
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.grid import FatPairs, body_pairs, by_entity, grow_near, start_near
from polygolf.engine.physics.jit import inlined_kernel, leaf_kernel
from polygolf.engine.physics.settings import CONTACT_MARGIN

_NO_PAIRS = np.zeros((0, 2), dtype=np.int64)


class BroadphaseProcessor(esper.Processor):
    """Candidate pairs from bounding boxes (`physics.grid`): moving bodies against the walls' grid,
    and bodies against each other (picked from the pairs of fat boxes it keeps, `FatPairs`).
    Resting bodies are not looked up at all. Reads the static index; writes the candidates."""

    name = "broadphase"

    def __init__(self, res: Resources) -> None:
        self.statics, self.candidates, self.config = res.statics, res.candidates, res.config
        self.shapes, self.bodies, self.fat_boxes = res.shapes, res.bodies, res.fat_boxes
        walls = len(res.statics.grid)  # the grid query's scratch, and the answer's arrays, kept between substeps
        self._seen, self._scratch = np.zeros(walls, dtype=np.bool_), np.empty(walls, dtype=np.int64)
        self._near, self._first = np.empty(0, dtype=np.int64), np.empty(1, dtype=np.int64)
        self.found = np.empty(16, dtype=np.int64)  # grown by `pick` when it must be (so passed and given back)
        self.fat_pairs = FatPairs()

    def inputs(self) -> tuple:
        """What `pick` reads besides the state, the shapes, the walls, the fat boxes and the found
        walls' array: the grid query's scratch, the answer's arrays (and no pairs, to hand on when
        there is one body), whether there are pairs to look for, whether bodies meet each other and
        the pairs kept (`FatPairs.of`)."""
        bodies = esper.get_components(Body, Collider)
        state, _, rows = self.shapes.current(self.bodies, esper.get_component(Body), bodies)
        if len(self._near) != len(rows):
            self._near, self._first = np.empty(len(rows), dtype=np.int64), np.empty(len(rows) + 1, dtype=np.int64)
        return (self._seen, self._scratch, self._near, self._first, _NO_PAIRS, len(bodies) > 1,
                self.config.collide_bodies, self.fat_pairs.of(state, rows))

    def process(self) -> None:
        inputs = self.inputs()  # first: it gathers the state
        state = self.bodies.state
        (self.candidates.near, self.candidates.near_first, self.candidates.near_found,
         self.candidates.pair_ents), self.found = pick(state, self.shapes.packed, self.statics.packed,
                                                       self.fat_boxes.of(state, len(self._seen)), inputs, self.found)


@inlined_kernel
def pick(state: np.ndarray, shapes: tuple, walls: tuple, fat_boxes: tuple, inputs: tuple, found: np.ndarray
         ) -> tuple[tuple, np.ndarray]:
    """The stage on a store's state (`Shapes.packed`, `StaticWorld.packed`, `FatBoxes.of`): the
    candidates (`Candidates.arrays`: bodies with walls near, as entities; their walls in compressed
    rows; body pairs as entities, in entity order however they were found), and `found` (grown if
    it had to). The walls' rows are views of `first` and `found`: good until the next call."""
    both = np.empty((2, 4))
    q, count, total, waiting = _near(state, shapes, walls, fat_boxes, inputs, found, both)
    if waiting:  # `found` must grow: on from where the search stopped
        found, count = grow_near(state, shapes[5], shapes[6], CONTACT_MARGIN, walls[5], fat_boxes, inputs[0], inputs[1],
                                 inputs[2], inputs[3], found, both, q, count, total, waiting)
    pairs = inputs[4]  # (none)
    if inputs[5]:  # several bodies
        pairs = by_entity(body_pairs(state, shapes[5], shapes[6], CONTACT_MARGIN, False, inputs[6], False, True,
                                     inputs[7]), shapes[9])
    near, first = inputs[2], inputs[3]
    return (shapes[9][near[:count]], first[:count + 1], found[:first[count]], pairs), found


@leaf_kernel
def _near(state: np.ndarray, shapes: tuple, walls: tuple, fat_boxes: tuple, inputs: tuple, found: np.ndarray,
          both: np.ndarray) -> tuple[int, int, int, int]:
    """`grid.start_near` with the stage's tuples (where it stopped, how many bodies have walls near,
    how many boxes they hold, how many wait for room in `found`: 0, none). (A leaf takes the tuples
    apart for nothing; `pick`, inlined in every run of stages, would count a reference to each array
    it took out, every substep.)"""
    _, _, _, _, _, rows, radius, _, _, _, _ = shapes
    seen, scratch, near, first, _, _, _, _ = inputs
    return start_near(state, rows, radius, CONTACT_MARGIN, walls[5], fat_boxes, seen, scratch, near, first, found, both)
