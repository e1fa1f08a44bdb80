from collections import Counter

import esper

from polygolf.engine.components import Body, Collider, Wall
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.contact import Manifold, add_manifolds, collide_pieces, combine
from polygolf.engine.physics.settings import CONTACT_MARGIN, GAP_TOLERANCE
from polygolf.engine.physics.toi import pair_reaches, reaches


class NarrowphaseProcessor(esper.Processor):
    """Manifolds for the broadphase's candidates (see `physics.contact`): every pair of convex
    pieces, one manifold per normal between two bodies, impulses of persisting points carried over
    for warm starting. Reads the candidates; writes the contacts and the deepest overlap.

    A contact with a gap acts only if the bodies, moving on as they are, would close that gap within
    the substep (`toi.reaches`, `toi.pair_reaches`): a ball passing a corner or another ball it never
    touches is never hit, and a body above a floor or another body falls until it touches instead of
    hovering on the contact margin."""

    name = "narrowphase"

    def __init__(self, res: Resources) -> None:
        self.config, self.candidates, self.contacts = res.config, res.candidates, res.contacts
        self.statics, self.stats = res.statics, res.stats

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
            raw = collide_pieces(*col_a.world(a.x, a.y, a.angle), *col_b.world(b.x, b.y, b.angle), CONTACT_MARGIN,
                                 a, b, combine(col_a.material, col_b.material), ngs,
                                 lambda i, j, feature: (j, i, feature))
            if raw:
                pairs.append((ea, eb, a, b, raw))
                near.append((col_a, col_b, min(p.separation for _, _, p in raw)))
        # A body with something else near (a wall or another body) may be halted by it in the solve.
        busy = Counter(e for ea, eb, *_ in pairs for e in (ea, eb))
        if pairs:
            busy.update(self.candidates.walls.keys())
        for (ea, eb, a, b, _), (col_a, col_b, gap) in zip(pairs, near):
            gapped.append(gap > GAP_TOLERANCE
                          and not pair_reaches(col_a, a, col_b, b, dt, gap, busy[ea] > 1, busy[eb] > 1))
        pressed = {e for (ea, eb, *_), gap in zip(pairs, gapped) if not gap for e in (ea, eb)}
        grew = bool(pressed)
        while grew:  # through a chain of gaps, a push can reach: keep those contacts too
            grew = False
            for k, (ea, eb, *_) in enumerate(pairs):
                if gapped[k] and (ea in pressed or eb in pressed):
                    gapped[k], grew = False, True
                    pressed |= {ea, eb}

        for ent, found in self.candidates.walls.items():
            body, col = esper.component_for_entity(ent, Body), esper.component_for_entity(ent, Collider)
            pieces, normals = col.world(body.x, body.y, body.angle)
            raw = []
            for wall_ent, k in found:
                wall = esper.component_for_entity(wall_ent, Wall)
                hits = collide_pieces(pieces, normals, (wall.pieces[k],), (wall.normals[k],), CONTACT_MARGIN, body,
                                      static, combine(col.material, wall.material), ngs,
                                      lambda i, _j, feature, w=wall_ent, k=k: (w, k, i, feature),
                                      ((wall.internal[k], wall.hidden[k]),))
                if hits and ent not in pressed and min(p.separation for _, _, p in hits) > GAP_TOLERANCE \
                        and not reaches(col, body, wall.pieces[k], wall.normals[k], dt):
                    continue  # a gap this substep's motion will not close: nothing touches, nothing acts
                raw += hits
            if raw:
                deepest = max(deepest, add_manifolds(manifolds, raw, ent, -1, body, static, carried))

        for (ea, eb, a, b, raw), gap in zip(pairs, gapped):
            if gap:
                continue  # as for walls: two bodies that will not meet this substep do not touch
            if a.asleep or b.asleep:
                a.wake()
                b.wake()
            deepest = max(deepest, add_manifolds(manifolds, raw, ea, eb, a, b, carried))

        self.contacts.manifolds = manifolds
        self.contacts.touching = {m.entity_a for m in manifolds} | {m.entity_b for m in manifolds}
        self.stats.max_penetration = deepest
