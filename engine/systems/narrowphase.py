
import esper
import numpy as np

from polygolf.engine.components import Body, Collider
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.body import ANGLE, SPIN, X
from polygolf.engine.physics.collide import ROW, bodies_pair_contacts, bodies_wall_contacts, kept_pairs
from polygolf.engine.physics.contact import ContactTable, build_contacts, carry_impulses
from polygolf.engine.physics.motion import wake_pairs
from polygolf.engine.physics.settings import CONTACT_MARGIN, RESTITUTION_THRESHOLD
from polygolf.engine.physics.toi import pairs_apart

_NO_WALLS = (np.zeros((0, ROW)), np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64), np.zeros((0, 2)))
_NOT_TOUCHING = np.zeros((0, 2), dtype=np.int64)  # body pairs (table rows) that touch
_NO_PAIRS = (np.zeros((0, ROW)), np.zeros(1, dtype=np.int64), np.zeros((0, 2), dtype=np.int64),
             np.zeros((0, 2), dtype=np.int64), np.zeros((0, 4)))


class NarrowphaseProcessor(esper.Processor):
    """The contact table for the broadphase's candidates (see `physics.contact`): every pair of
    convex pieces, one manifold per normal between two bodies (`contact.build_contacts`, one call for
    every body), impulses of persisting points carried over for warm starting
    (`contact.carry_impulses`). Reads the candidates; writes the contacts and the deepest overlap.

    A contact with a gap acts only if the bodies, moving on as they are, would close that gap within
    the substep (`collide.wall_contacts`, `toi.pair_reaches`): a ball passing a corner or another ball it never
    touches is never hit, and a body above a floor or another body falls until it touches instead of
    hovering on the contact margin."""

    name = "narrowphase"

    def __init__(self, res: Resources) -> None:
        self.config, self.candidates, self.contacts = res.config, res.candidates, res.contacts
        self.statics, self.stats = res.statics, res.stats
        self.shapes, self.bodies = res.shapes, res.bodies
        self._empty = ContactTable.empty()
        self._pressed = self._unpressed = np.zeros(0, dtype=np.bool_)

    def process(self) -> None:
        knobs, dt = self.config.knobs, self.config.dt
        everyone = esper.get_components(Body, Collider)
        state, table, store_rows = self.shapes.current(self.bodies, esper.get_component(Body), everyone)

        # Pairs first (added after the walls, as always): a body another one presses on this substep
        # can be pushed into a wall it is not moving towards yet, so its wall gaps must stay contacts.
        pairs = _NOT_TOUCHING
        if len(self._pressed) != len(store_rows):
            self._pressed = np.zeros(len(store_rows), dtype=np.bool_)
            self._unpressed = np.zeros(len(store_rows), dtype=np.bool_)
        pressed = self._unpressed  # nobody, unless `pairs_apart` says otherwise below (never written)
        if len(self.candidates.pair_ents):
            pair_rows, pair_first, pairs, gaps = bodies_pair_contacts(
                table.pieces.verts, table.pieces.normals, table.pieces.first, table.body_first,
                self.shapes.index(self.candidates.pair_ents), state[store_rows, X:ANGLE + 1], self.shapes.radius,
                CONTACT_MARGIN)
        if len(pairs):
            apart, pressed = np.empty(len(pairs), dtype=np.bool_), self._pressed
            pairs_apart(table.pieces.verts, table.pieces.normals, table.pieces.first, table.pieces.reach,
                        table.body_first, pairs, gaps, state, store_rows, self.shapes.radius,
                        self.shapes.index(self.candidates.near), dt, apart, pressed)

        # The contact rows against walls (body by body), then between bodies (pair by pair).
        walls = _NO_WALLS
        near_walls = self.candidates.near
        if len(near_walls):
            rows_of_near = self.shapes.index(near_walls)
            near_rows = store_rows[rows_of_near]
            held = pressed[rows_of_near]
            wall_rows = bodies_wall_contacts(
                table.pieces.verts, table.pieces.normals, table.pieces.first, table.pieces.reach, table.body_first,
                rows_of_near, state[near_rows, X:SPIN + 1],
                held, self.candidates.near_first, self.candidates.near_found, self.statics.arrays, dt,
                CONTACT_MARGIN)
            walls = (wall_rows, near_walls, near_rows, self.shapes.materials[rows_of_near])
        pair_groups = _NO_PAIRS
        if len(pairs):  # as for walls: bodies that will not meet do not touch
            pair_groups = kept_pairs(pair_rows, pair_first, pairs, apart, self.shapes.ents, store_rows,
                                     self.shapes.materials)
            if len(pair_groups[2]):
                wake_pairs(state, pair_groups[3])
            else:
                pair_groups = _NO_PAIRS

        if not len(walls[0]) and pair_groups is _NO_PAIRS:
            self.contacts.table = self._empty  # nothing touches: no kernel call (most substeps of a lone ball)
            return
        statics = self.statics
        made = build_contacts(*walls, statics.materials, statics.owner, statics.index, *pair_groups, state,
                              statics.body._row, knobs.position_correction == "ngs", self.stats.max_penetration)
        *columns, deepest = made
        self.stats.max_penetration = float(deepest)
        new = ContactTable(*columns[:3], np.zeros(len(columns[1]), dtype=np.bool_), *columns[3:], self.bodies,
                           statics.body)
        old = self.contacts.table
        if knobs.warm_start and len(old):
            carry_impulses(old.ents, old.first, old.keys, old.points, new.ents, new.first, new.keys, new.points,
                           RESTITUTION_THRESHOLD)
        self.contacts.table = new
