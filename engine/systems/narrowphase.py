
import esper
import numpy as np

from polygolf.engine.components import Collider
from polygolf.engine.components.resources import NO_CONTACTS, PENETRATION, Resources
from polygolf.engine.physics.body import Body, BodyStore
from polygolf.engine.physics.contact import ContactTable, TableSlot, find_contacts, nothing_to_touch
from polygolf.engine.physics.jit import kernel, leaf_kernel
from polygolf.engine.physics.settings import CONTACT_MARGIN, RESTITUTION_THRESHOLD


class NarrowphaseProcessor(esper.Processor):
    """The contact table for the broadphase's candidates (see `physics.contact`), in one kernel call
    (`contact.find_contacts`): every pair of convex pieces, one manifold per normal between two
    bodies, impulses of persisting points carried over for warm starting. Reads the candidates;
    writes the contacts and the deepest overlap.

    A contact with a gap acts only if the bodies, moving on as they are, would close that gap within
    the substep (`collide.wall_contacts`, `toi.pair_reaches`): a ball passing a corner or another ball it never
    touches is never hit, and a body above a floor or another body falls until it touches instead of
    hovering on the contact margin."""

    name = "narrowphase"

    def __init__(self, res: Resources) -> None:
        self.config, self.candidates, self.contacts = res.config, res.candidates, res.contacts
        self.statics, self.stats = res.statics, res.stats
        self.shapes, self.bodies = res.shapes, res.bodies

    def inputs(self) -> tuple[bool, bool]:
        """What `touch` reads besides the state, the shapes, the walls, the candidates, the last
        table and dt: the knobs it follows (position correction by NGS, warm start)."""
        knobs = self.config.knobs
        self.shapes.current(self.bodies, esper.get_component(Body), esper.get_components(Body, Collider))
        return knobs.position_correction == "ngs", bool(knobs.warm_start)

    def process(self) -> None:
        candidates = self.candidates
        if not len(candidates.near) and not len(candidates.pair_ents):
            self.contacts.table = NO_CONTACTS  # nothing near: no kernel call (most substeps of a lone ball)
            return
        inputs = self.inputs()  # first: it gathers the state
        self.contacts.table = contact_table(
            touch(self.bodies.state, self.shapes.packed, self.statics.packed, inputs, candidates.arrays,
                  self.contacts.table.arrays, self.stats.values, self.config.dt), self.bodies, self.statics.body)


def contact_table(columns: tuple, store: BodyStore, static: Body) -> ContactTable:
    """The table object for `touch`'s columns."""
    return ContactTable(*columns, store, static) if len(columns[0]) else NO_CONTACTS


@leaf_kernel
def touch_into(state: np.ndarray, shapes: tuple, walls: tuple, inputs: tuple, candidates: tuple, old: tuple,
               stats: np.ndarray, dt: float, slot: TableSlot) -> bool:
    """The stage on a store's state (`Shapes.packed`, `StaticWorld.packed`): the new table's
    columns (`ContactTable.arrays`) for the candidates (`Candidates.arrays`), warm-started from the
    old ones, put into `slot.table` (`contact.find_contacts`); the deepest overlap goes into
    `stats`. Returns False if the old table stands as the new one (it is empty, and nothing is near
    enough to touch): then the slot is not written. (A leaf: a run of stages hands it its tuples,
    and it takes them apart, without counting a reference to each array in them.)"""
    if not len(old[1]) and nothing_to_touch(state, shapes, walls, candidates, CONTACT_MARGIN):
        return False  # (without taking a hundred arrays in and out)
    near, near_first, near_found, pair_ents = candidates
    lv, ln, first, reach, body_first, rows, radius, _, materials, ents, lookup = shapes
    arrays, wall_materials, owner, index, static, _ = walls
    ngs, warm = inputs
    old_ents, _, _, _, old_first, old_points, old_keys = old
    stats[PENETRATION] = find_contacts(
        slot, lv, ln, first, reach, body_first, state, rows, radius, materials, ents, lookup, pair_ents, near,
        near_first, near_found, arrays, wall_materials, owner, index, static, dt, CONTACT_MARGIN, ngs,
        stats[PENETRATION], old_ents, old_first, old_keys, old_points, warm, RESTITUTION_THRESHOLD)
    return True


@kernel
def touch(state: np.ndarray, shapes: tuple, walls: tuple, inputs: tuple, candidates: tuple, old: tuple,
          stats: np.ndarray, dt: float) -> tuple:
    """`touch_into`'s new table (or the old one, where it stands), for a caller without a slot."""
    slot = TableSlot(old)
    if touch_into(state, shapes, walls, inputs, candidates, old, stats, dt, slot):
        return slot.table
    return old
