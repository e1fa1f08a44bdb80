
import esper
import numpy as np

from polygolf.engine.components import Body, Collider
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.contact import ContactTable, find_contacts
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
        self._empty = ContactTable.empty()

    def process(self) -> None:
        candidates = self.candidates
        if not len(candidates.near) and not len(candidates.pair_ents):
            self.contacts.table = self._empty  # nothing near: no kernel call (most substeps of a lone ball)
            return
        knobs, statics, shapes, old = self.config.knobs, self.statics, self.shapes, self.contacts.table
        everyone = esper.get_components(Body, Collider)
        state, table, store_rows = shapes.current(self.bodies, esper.get_component(Body), everyone)
        pieces = table.pieces
        *columns, deepest = find_contacts(
            pieces.verts, pieces.normals, pieces.first, pieces.reach, table.body_first, state, store_rows,
            shapes.radius, shapes.materials, shapes.ents, shapes.lookup, candidates.pair_ents, candidates.near,
            candidates.near_first, candidates.near_found, statics.arrays, statics.materials, statics.owner,
            statics.index, statics.body._row, self.config.dt, CONTACT_MARGIN, knobs.position_correction == "ngs",
            self.stats.max_penetration, old.ents, old.first, old.keys, old.points, knobs.warm_start,
            RESTITUTION_THRESHOLD)
        self.stats.max_penetration = float(deepest)
        if not len(columns[0]):
            self.contacts.table = self._empty  # nothing touches
            return
        self.contacts.table = ContactTable(*columns[:3], np.zeros(len(columns[1]), dtype=np.bool_), *columns[3:],
                                           self.bodies, statics.body)
