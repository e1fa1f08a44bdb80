import esper
import numpy as np

from polygolf.engine.components import Body, Collider
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.grid import FatPairs, body_pairs, by_entity, grow_near, start_near
from polygolf.engine.physics.jit import counted_kernel, kernel, leaf_kernel, structure
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
        self._both = np.empty((2, 4))  # the search's room for two boxes
        self.fat_pairs = FatPairs()

    def inputs(self) -> tuple:
        """What `pick` reads besides the state, the shapes, the walls, the fat boxes and the found
        walls' array: the grid query's scratch, the answer's arrays (and no pairs, to hand on when
        there is one body), whether there are pairs to look for, whether bodies meet each other, the
        pairs kept (`FatPairs.of`) and the search's room for two boxes."""
        bodies = esper.get_components(Body, Collider)
        state, _, rows = self.shapes.current(self.bodies, esper.get_component(Body), bodies)
        if len(self._near) != len(rows):
            self._near, self._first = np.empty(len(rows), dtype=np.int64), np.empty(len(rows) + 1, dtype=np.int64)
        return (self._seen, self._scratch, self._near, self._first, _NO_PAIRS, len(bodies) > 1,
                self.config.collide_bodies, self.fat_pairs.of(state, rows), self._both)

    def process(self) -> None:
        inputs = self.inputs()  # first: it gathers the state
        state = self.bodies.state
        (self.candidates.near, self.candidates.near_first, self.candidates.near_found,
         self.candidates.pair_ents), self.found = pick(state, self.shapes.packed, self.statics.packed,
                                                       self.fat_boxes.of(state, len(self._seen)), inputs, self.found)


# Where `pick_into` puts what it finds (a kernel a leaf may call returns no array): the candidates
# (`Candidates.arrays`) and the found walls' array.
Picked = structure(__name__, "Picked", ["candidates", "found"],
                   "The candidates `pick_into` found, and its found walls' array (grown if it had to).")


@kernel
def pick(state: np.ndarray, shapes: tuple, walls: tuple, fat_boxes: tuple, inputs: tuple, found: np.ndarray
         ) -> tuple[tuple, np.ndarray]:
    """`pick_into`'s candidates and found walls' array, for a caller without a `Picked`."""
    picked = Picked((found[:0], found[:1], found[:0], inputs[4]), found)
    pick_into(state, shapes, walls, fat_boxes, inputs, found, picked)
    return picked.candidates, picked.found


@leaf_kernel
def pick_into(state: np.ndarray, shapes: tuple, walls: tuple, fat_boxes: tuple, inputs: tuple, found: np.ndarray,
              picked: Picked) -> bool:
    """The stage on a store's state (`Shapes.packed`, `StaticWorld.packed`, `FatBoxes.of`): the
    candidates (`Candidates.arrays`: bodies with walls near, as entities; their walls in compressed
    rows; body pairs as entities, in entity order however they were found) into
    `picked.candidates`; returns whether `found` had to grow (the grown one is `picked.found`). The
    walls' rows are views of the `first` of `inputs` and of `found`: good until the next call. (A
    leaf: a run of stages hands it its tuples, and it takes them apart, without counting a reference
    to each array in them.)"""
    _, _, _, _, _, rows, radius, _, _, ents, _ = shapes
    seen, scratch, near, first, no_pairs, several, meet, kept, both = inputs
    q, count, total, waiting = start_near(state, rows, radius, CONTACT_MARGIN, walls[5], fat_boxes, seen, scratch, near,
                                          first, found, both)
    if waiting:  # `found` must grow: on from where the search stopped
        _grow_and_pick(picked, state, rows, radius, walls[5], fat_boxes, seen, scratch, near, first, found, both, q,
                       count, total, waiting, ents, no_pairs, several, meet, kept)
        return True
    _pick(picked, state, rows, radius, ents, near, first, found, count, no_pairs, several, meet, kept)
    return False


@counted_kernel
def _grow_and_pick(picked: Picked, state: np.ndarray, rows: np.ndarray, radius: np.ndarray, grid: tuple,
                   fat_boxes: tuple, seen: np.ndarray, scratch: np.ndarray, near: np.ndarray, first: np.ndarray,
                   found: np.ndarray, both: np.ndarray, q: int, count: int, total: int, waiting: int, ents: np.ndarray,
                   no_pairs: np.ndarray, several: bool, meet: bool, kept: tuple) -> None:
    """`pick_into`'s search on from where it stopped, into a `found` that grows (`grid.grow_near`)."""
    found, count = grow_near(state, rows, radius, CONTACT_MARGIN, grid, fat_boxes, seen, scratch, near, first, found,
                             both, q, count, total, waiting)
    picked.found = found
    _pick(picked, state, rows, radius, ents, near, first, found, count, no_pairs, several, meet, kept)


@counted_kernel
def _pick(picked: Picked, state: np.ndarray, rows: np.ndarray, radius: np.ndarray, ents: np.ndarray,
          near: np.ndarray, first: np.ndarray, found: np.ndarray, count: int, no_pairs: np.ndarray, several: bool,
          meet: bool, kept: tuple) -> None:
    """`pick_into`'s candidates, once the search has found the walls near `count` bodies."""
    pairs = no_pairs
    if several:
        pairs = by_entity(body_pairs(state, rows, radius, CONTACT_MARGIN, False, meet, False, True, kept), ents)
    picked.candidates = (ents[near[:count]], first[:count + 1], found[:first[count]], pairs)
