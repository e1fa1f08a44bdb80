from collections import Counter

import esper
import numpy as np

from polygolf.engine.components import Body, Collider
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.body import ANGLE, SPIN, VX, VY, X, Y
from polygolf.engine.physics.collide import NO_SEAMS, ROW, SEP, bodies_wall_contacts, collide_sets
from polygolf.engine.physics.contact import ContactTable, build_contacts, carry_impulses
from polygolf.engine.physics.settings import CONTACT_MARGIN, GAP_TOLERANCE, RESTITUTION_THRESHOLD
from polygolf.engine.physics.toi import pair_reaches

_NO_WALLS = (np.zeros((0, ROW)), np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64), np.zeros((0, 2)))
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

    def process(self) -> None:
        knobs, dt = self.config.knobs, self.config.dt
        state = self.bodies.gather(esper.get_component(Body))

        # Pairs first (added after the walls, as always): a body another one presses on this substep
        # can be pushed into a wall it is not moving towards yet, so its wall gaps must stay contacts.
        pairs, gapped, near = [], [], []
        for ea, eb in self.candidates.pairs:
            a, col_a = esper.component_for_entity(ea, Body), esper.component_for_entity(ea, Collider)
            b, col_b = esper.component_for_entity(eb, Body), esper.component_for_entity(eb, Collider)
            reach = col_a.radius + col_b.radius + CONTACT_MARGIN
            if (a.x - b.x) ** 2 + (a.y - b.y) ** 2 > reach * reach:
                continue
            rows = _body_rows(col_a, a, col_b, b)
            if len(rows):
                pairs.append((ea, eb, a, b, rows))
                near.append((col_a, col_b, min(rows[:, SEP].tolist())))
        # A body with something else near (a wall or another body) may be halted by it in the solve.
        busy = Counter(e for ea, eb, *_ in pairs for e in (ea, eb))
        if pairs:
            busy.update(self.candidates.near.tolist())
        for (ea, eb, a, b, _), (col_a, col_b, gap) in zip(pairs, near):
            gapped.append(gap > GAP_TOLERANCE and not pair_reaches(
                *_arrays(col_a), col_a.radius, _pose(a), _velocity(a), *_arrays(col_b), col_b.radius, _pose(b),
                _velocity(b), dt, gap, busy[ea] > 1, busy[eb] > 1))
        pressed = {e for (ea, eb, *_), gap in zip(pairs, gapped) if not gap for e in (ea, eb)}
        grew = bool(pressed)
        while grew:  # through a chain of gaps, a push can reach: keep those contacts too
            grew = False
            for k, (ea, eb, *_) in enumerate(pairs):
                if gapped[k] and (ea in pressed or eb in pressed):
                    gapped[k], grew = False, True
                    pressed |= {ea, eb}

        # The contact rows against walls (body by body), then between bodies (pair by pair).
        walls = _NO_WALLS
        near_walls = self.candidates.near
        if len(near_walls):
            everyone = esper.get_components(Body, Collider)
            table, _ = self.shapes.of(everyone)
            rows_of_near = self.shapes.index(near_walls)
            near_rows = self.shapes.rows(self.bodies, everyone)[rows_of_near]
            held = np.array([ent in pressed for ent in near_walls.tolist()], dtype=np.bool_).reshape(-1)
            wall_rows = bodies_wall_contacts(
                table.pieces.verts, table.pieces.normals, table.pieces.first, table.pieces.reach, table.body_first,
                rows_of_near, state[near_rows][:, [X, Y, ANGLE, VX, VY, SPIN]],
                held, self.candidates.near_first, self.candidates.near_found, self.statics.arrays, dt,
                CONTACT_MARGIN)
            walls = (wall_rows, near_walls, near_rows, self.shapes.materials[rows_of_near])
        kept = [(ea, eb, a, b, rows, col_a, col_b) for (ea, eb, a, b, rows), gap, (col_a, col_b, _)
                in zip(pairs, gapped, near) if not gap]  # as for walls: bodies that will not meet do not touch
        pair_groups = _NO_PAIRS
        if kept:
            for _, _, a, b, *_ in kept:
                if a.asleep or b.asleep:
                    a.wake()
                    b.wake()
            store_rows = self.bodies.rows
            first = np.zeros(len(kept) + 1, dtype=np.int64)
            first[1:] = np.cumsum([len(rows) for *_, rows, _, _ in kept])
            pair_groups = (np.concatenate([rows for *_, rows, _, _ in kept]), first,
                        np.array([(ea, eb) for ea, eb, *_ in kept], dtype=np.int64),
                        np.array([(store_rows[ea], store_rows[eb]) for ea, eb, *_ in kept], dtype=np.int64),
                        np.array([(col_a.material.restitution, col_a.material.friction, col_b.material.restitution,
                                   col_b.material.friction) for *_, col_a, col_b in kept], dtype=np.float64))

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


def _arrays(col: Collider) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    shape = col.shape
    return shape.verts, shape.normals, shape.first, shape.reach


def _pose(body: Body) -> np.ndarray:
    return np.array((body.x, body.y, body.angle))


def _velocity(body: Body) -> np.ndarray:
    return np.array((body.vx, body.vy, body.spin))


def _body_rows(col_a: Collider, a: Body, col_b: Collider, b: Body) -> np.ndarray:
    """Contact rows between two bodies, A's pieces in the outer loop."""
    va, na = col_a.posed(a.x, a.y, a.angle)
    vb, nb = col_b.posed(b.x, b.y, b.angle)
    out = np.empty((2 * len(col_a.shape) * len(col_b.shape), ROW))
    count = collide_sets(va, na, col_a.shape.first, vb, nb, col_b.shape.first, col_b.shape.every_piece,
                         NO_SEAMS, NO_SEAMS, False, CONTACT_MARGIN, False, out)
    return out[:count]
