from collections import Counter
from itertools import groupby

import esper
import numpy as np

from polygolf.engine.components import Body, Collider, Wall
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.body import ANGLE, SPIN, VX, VY, X, Y
from polygolf.engine.physics.collide import (
    BODY,
    FEATURE,
    NO_SEAMS,
    NX,
    NY,
    PIECE_A,
    PIECE_B,
    ROW,
    SEP,
    bodies_wall_contacts,
    collide_sets,
)
from polygolf.engine.physics.contact import Manifold, add_manifolds, combine, contact_points, make_point
from polygolf.engine.physics.settings import CONTACT_MARGIN, GAP_TOLERANCE
from polygolf.engine.physics.toi import pair_reaches


class NarrowphaseProcessor(esper.Processor):
    """Manifolds for the broadphase's candidates (see `physics.contact`): every pair of convex
    pieces, one manifold per normal between two bodies, impulses of persisting points carried over
    for warm starting. Reads the candidates; writes the contacts and the deepest overlap.

    A contact with a gap acts only if the bodies, moving on as they are, would close that gap within
    the substep (`collide.wall_contacts`, `toi.pair_reaches`): a ball passing a corner or another ball it never
    touches is never hit, and a body above a floor or another body falls until it touches instead of
    hovering on the contact margin."""

    name = "narrowphase"

    def __init__(self, res: Resources) -> None:
        self.config, self.candidates, self.contacts = res.config, res.candidates, res.contacts
        self.statics, self.stats = res.statics, res.stats
        self.shapes, self.bodies = res.shapes, res.bodies
        self._owner, self._index = res.statics.owner.tolist(), res.statics.index.tolist()  # fixed once built

    def process(self) -> None:
        carried = self.contacts.carried() if self.config.knobs.warm_start else {}
        dt = self.config.dt
        ngs = self.config.knobs.position_correction == "ngs"
        static = self.statics.body
        manifolds: list[Manifold] = []
        deepest = self.stats.max_penetration

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
            if rows:
                pairs.append((ea, eb, a, b, rows))
                near.append((col_a, col_b, min(row[SEP] for row in rows)))
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

        near_walls = self.candidates.near
        if len(near_walls):
            everyone = esper.get_components(Body, Collider)
            table, _ = self.shapes.of(everyone)
            state = self.bodies.gather(esper.get_component(Body))[self.shapes.rows(self.bodies, everyone)]
            rows_of_near = self.shapes.index(near_walls)
            ents = near_walls.tolist()
            held = np.array([ent in pressed for ent in ents], dtype=np.bool_).reshape(-1)
            rows = bodies_wall_contacts(
                table.pieces.verts, table.pieces.normals, table.pieces.first, table.pieces.reach, table.body_first,
                rows_of_near, state[rows_of_near][:, [X, Y, ANGLE, VX, VY, SPIN]],
                held, self.candidates.near_first, self.candidates.near_found, self.statics.arrays, dt,
                CONTACT_MARGIN).tolist()
            owner, index = self._owner, self._index
            for q, kept in groupby(rows, key=lambda row: int(row[BODY])):  # body by body
                ent = ents[q]
                body, col = esper.component_for_entity(ent, Body), esper.component_for_entity(ent, Collider)
                materials = {}
                raw = []
                for row in kept:
                    g = int(row[PIECE_B])
                    wall_ent = owner[g]
                    if wall_ent not in materials:
                        materials[wall_ent] = combine(col.material, esper.component_for_entity(wall_ent, Wall).material)
                    key = (wall_ent, index[g], int(row[PIECE_A]), int(row[FEATURE]))
                    raw.append((row[NX], row[NY], make_point(row, key, body, static, materials[wall_ent], ngs)))
                deepest = max(deepest, add_manifolds(manifolds, raw, ent, -1, body, static, carried))

        for (ea, eb, a, b, rows), gap, (col_a, col_b, _) in zip(pairs, gapped, near):
            if gap:
                continue  # as for walls: two bodies that will not meet this substep do not touch
            raw = contact_points(rows, a, b, combine(col_a.material, col_b.material), ngs,
                                 lambda row: (int(row[PIECE_B]), int(row[PIECE_A]), int(row[FEATURE])))
            if a.asleep or b.asleep:
                a.wake()
                b.wake()
            deepest = max(deepest, add_manifolds(manifolds, raw, ea, eb, a, b, carried))

        self.contacts.manifolds = manifolds
        self.contacts.touching = {m.entity_a for m in manifolds} | {m.entity_b for m in manifolds}
        self.stats.max_penetration = deepest


def _arrays(col: Collider) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    shape = col.shape
    return shape.verts, shape.normals, shape.first, shape.reach


def _pose(body: Body) -> np.ndarray:
    return np.array((body.x, body.y, body.angle))


def _velocity(body: Body) -> np.ndarray:
    return np.array((body.vx, body.vy, body.spin))


def _body_rows(col_a: Collider, a: Body, col_b: Collider, b: Body) -> list[list[float]]:
    """Contact rows between two bodies, A's pieces in the outer loop."""
    va, na = col_a.posed(a.x, a.y, a.angle)
    vb, nb = col_b.posed(b.x, b.y, b.angle)
    out = np.empty((2 * len(col_a.shape) * len(col_b.shape), ROW))
    count = collide_sets(va, na, col_a.shape.first, vb, nb, col_b.shape.first, col_b.shape.every_piece,
                         NO_SEAMS, NO_SEAMS, False, CONTACT_MARGIN, False, out)
    return out[:count].tolist()
