import math

import esper
import numpy as np

from polygolf.engine.components import Body, Collider
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.collide import NO_SEAMS, max_separation
from polygolf.engine.physics.grid import body_pairs
from polygolf.engine.physics.motion import rewind
from polygolf.engine.physics.settings import CONTACT_MARGIN, LINEAR_SLOP, TOI_TARGET
from polygolf.engine.physics.toi import first_pair_hit, first_wall_hits


class CCDProcessor(esper.Processor):
    """Continuous collision: a body whose motion this substep would carry it into or through a wall,
    or into or through another body, is moved back to its time of impact; the discrete contact that
    follows bounces it, and the time the motion lost is made up in the next substep
    (`BodyScratch.lag`), so a fast body that bounces ends up where it should rather than a substep
    behind. Of two bodies that meet, both go back to that time.

    A kinematic body (a windmill) goes back too when it would drive the body it meets into a wall that
    body lies against: it would crush it, so it stalls at the impact, standing still for the rest of
    the substep, and turns on once the ball has got out of the way (or been shot away)."""

    name = "ccd"

    def __init__(self, res: Resources) -> None:
        self.statics, self.stats, self.config = res.statics, res.stats, res.config
        walls = len(res.statics.grid)
        self._seen, self._found = np.zeros(walls, dtype=np.bool_), np.empty(walls, dtype=np.int64)
        self.shapes, self.bodies = res.shapes, res.bodies

    def process(self) -> None:
        bodies = esper.get_components(Body, Collider)
        table, _ = self.shapes.of(bodies)
        state = self.bodies.gather(esper.get_component(Body))
        rows = self.shapes.rows(self.bodies, bodies)
        walls = self.statics.pieces
        hits, longest, count = first_wall_hits(
            table.pieces.verts, table.pieces.normals, table.pieces.first, table.pieces.reach, table.body_first,
            state, rows, self.shapes.radius, LINEAR_SLOP, self.statics.grid.arrays, self._seen, self._found,
            walls.verts, walls.normals, walls.first, TOI_TARGET, 0.25 * LINEAR_SLOP, LINEAR_SLOP)
        # No pair can need sweeping while no body steps half the linear slop.
        if len(bodies) > 1 and longest >= 0.5 * LINEAR_SLOP:
            count += self._body_hits(rows, hits)
        if count:
            self.stats.toi_hits += rewind(state, rows, hits)

    def _pinched(self, body: Body, col: Collider, arm: Body, arm_col: Collider, t: float) -> bool:
        """Whether the arm, meeting the body at fraction `t` of the substep, drives it into a wall it
        lies against (within the contact margin): the push (the separating axis between arm and
        body at the impact) points at least 15° into that wall's face. A body it meets
        along the wall, or away from one, is pushed as usual."""
        sa = arm.scratch
        arm_verts, arm_normals = arm_col.posed(sa.x0 + t * (arm.x - sa.x0), sa.y0 + t * (arm.y - sa.y0),
                                               sa.angle0 + t * (arm.angle - sa.angle0))
        verts, normals = col.posed(body.x, body.y, body.angle)
        arm_first, first = arm_col.shape.first, col.shape.first
        best, push = -math.inf, (0.0, 0.0)
        for i in range(len(arm_col.shape)):
            for j in range(len(col.shape)):
                gap, face = max_separation(arm_verts, arm_normals, arm_first[i], arm_first[i + 1], verts, first[j],
                                           first[j + 1], NO_SEAMS, -1)
                if gap > best:
                    row = arm_first[i] + face
                    best, push = gap, (arm_normals[row, 0], arm_normals[row, 1])
                gap, face = max_separation(verts, normals, first[j], first[j + 1], arm_verts, arm_first[i],
                                           arm_first[i + 1], NO_SEAMS, -1)
                if gap > best:
                    row = first[j] + face
                    best, push = gap, (-normals[row, 0], -normals[row, 1])
        r = col.radius + CONTACT_MARGIN
        walls = self.statics.pieces
        for g in self.statics.grid.query((body.x - r, body.y - r, body.x + r, body.y + r)):
            for j in range(len(col.shape)):
                gap, face = max_separation(walls.verts, walls.normals, walls.first[g], walls.first[g + 1], verts,
                                           first[j], first[j + 1], NO_SEAMS, -1)
                row = walls.first[g] + face
                nx, ny = walls.normals[row, 0], walls.normals[row, 1]  # out of the wall, towards the body
                if gap < CONTACT_MARGIN and push[0] * nx + push[1] * ny < -0.25:
                    return True
        return False

    def _body_hits(self, rows: np.ndarray, hits: np.ndarray) -> int:
        """Pairs of bodies whose swept boxes overlap and that move fast relative to each other: each
        one's earliest impact goes into `hits` (by its index in `rows`). Returns how many pairs hit."""
        meet = self.config.collide_bodies
        index = self.shapes.of(esper.get_components(Body, Collider))[1]
        count = 0
        found = body_pairs(self.bodies.state, rows, self.shapes.radius, TOI_TARGET, True, meet, True)
        candidates = [(a, b) if a < b else (b, a) for a, b in self.shapes.ents[found].tolist()]
        for ea, eb in sorted(candidates):
            a, col_a = esper.component_for_entity(ea, Body), esper.component_for_entity(ea, Collider)
            b, col_b = esper.component_for_entity(eb, Body), esper.component_for_entity(eb, Collider)
            if not (a.inv_mass or b.inv_mass) or (a.inv_mass and b.inv_mass and not meet):
                continue
            if not (_moving(a) or _moving(b)):
                continue  # a resting ball is swept only against a turning windmill (which it may stall)
            # Against a kinematic body (a windmill's arm) any step beyond the slop is swept, as against
            # a wall; two dynamic bodies only when their steps could carry one half through the other
            # (cheaper in a crowd; the discrete contact then parts the overlap that is left).
            kinematic_pair = not (a.inv_mass and b.inv_mass)
            limit = LINEAR_SLOP if kinematic_pair else 0.5 * min(col_a.thickness, col_b.thickness)
            if _relative_travel(a, col_a, b, col_b) < limit:
                continue
            sa, sb = col_a.shape, col_b.shape
            hit = first_pair_hit(sa.verts, sa.normals, sa.first, sa.reach, _start(a), _end(a), sb.verts, sb.normals,
                                 sb.first, sb.reach, _start(b), _end(b), TOI_TARGET, 0.25 * LINEAR_SLOP, LINEAR_SLOP)
            if hit < 1.0:
                count += 1
                for ent, body in ((ea, a), (eb, b)):
                    if body.inv_mass and not body.asleep:
                        hits[index[ent]] = min(hits[index[ent]], hit)
                if kinematic_pair:
                    (arm, arm_ent, arm_col), (ball, col) = (((a, ea, col_a), (b, col_b)) if not a.inv_mass
                                                            else ((b, eb, col_b), (a, col_a)))
                    if self._pinched(ball, col, arm, arm_col, hit):
                        hits[index[arm_ent]] = min(hits[index[arm_ent]], hit)
        return count


def _start(body: Body) -> np.ndarray:
    s = body.scratch
    return np.array((s.x0, s.y0, s.angle0))


def _end(body: Body) -> np.ndarray:
    return np.array((body.x, body.y, body.angle))


def _moving(body: Body) -> bool:
    """Awake and dynamic, or kinematic and turning."""
    return (not body.asleep and body.inv_mass > 0.0) or (body.inv_mass == 0.0 and body.spin != 0.0)


def _relative_travel(a: Body, col_a: Collider, b: Body, col_b: Collider) -> float:
    sa, sb = a.scratch, b.scratch
    return (math.hypot(a.x - sa.x0 - b.x + sb.x0, a.y - sa.y0 - b.y + sb.y0)
            + abs(a.angle - sa.angle0) * col_a.radius + abs(b.angle - sb.angle0) * col_b.radius)
