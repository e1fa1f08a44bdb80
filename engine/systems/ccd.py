import math

import esper
import numpy as np

from polygolf.engine.components import Body, Collider
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.body import INV_MASS
from polygolf.engine.physics.collide import NO_SEAMS, max_separation
from polygolf.engine.physics.geometry import ShapeTable
from polygolf.engine.physics.grid import body_pairs
from polygolf.engine.physics.motion import rewind
from polygolf.engine.physics.settings import CONTACT_MARGIN, LINEAR_SLOP, TOI_TARGET
from polygolf.engine.physics.toi import body_pair_hits, first_wall_hits


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
        self.shapes, self.bodies, self.fat_boxes = res.shapes, res.bodies, res.fat_boxes
        self._hits = np.empty(0)  # each body's time of impact this substep, kept between substeps

    def process(self) -> None:
        bodies = esper.get_components(Body, Collider)
        state, table, rows = self.shapes.current(self.bodies, esper.get_component(Body), bodies)
        walls = self.statics.pieces
        if len(self._hits) != len(rows):
            self._hits = np.empty(len(rows))
        hits = self._hits
        longest, count = first_wall_hits(
            table.pieces.verts, table.pieces.normals, table.pieces.first, table.pieces.reach, table.body_first,
            state, rows, self.shapes.radius, LINEAR_SLOP, self.statics.grid.arrays,
            self.fat_boxes.of(state, len(self._seen)), self._seen, self._found,
            walls.verts, walls.normals, walls.first, TOI_TARGET, 0.25 * LINEAR_SLOP, LINEAR_SLOP, hits)
        # No pair can need sweeping while no body steps half the linear slop.
        if len(bodies) > 1 and longest >= 0.5 * LINEAR_SLOP:
            count += self._body_hits(table, rows, hits)
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

    def _body_hits(self, table: ShapeTable, rows: np.ndarray, hits: np.ndarray) -> int:
        """Pairs of bodies whose swept boxes overlap and that move fast relative to each other: each
        one's earliest impact goes into `hits` (by its index in `rows`); a windmill's arm that would
        crush the ball it meets stalls too. Returns how many pairs hit."""
        pairs = body_pairs(self.bodies.state, rows, self.shapes.radius, TOI_TARGET, True, self.config.collide_bodies,
                           True)
        arm_hits = np.empty(len(pairs))
        count = body_pair_hits(table.pieces.verts, table.pieces.normals, table.pieces.first, table.pieces.reach,
                               table.body_first, pairs, self.bodies.state, rows, self.shapes.radius,
                               self.shapes.thickness, self.config.collide_bodies, LINEAR_SLOP, TOI_TARGET,
                               0.25 * LINEAR_SLOP, LINEAR_SLOP, hits, arm_hits)
        for g in np.flatnonzero(arm_hits < 1.0).tolist() if count else ():
            hit = float(arm_hits[g])
            a, b = pairs[g].tolist()
            arm, ball = (a, b) if self.bodies.state[rows[a], INV_MASS] == 0.0 else (b, a)
            arm_ent, ball_ent = self.shapes.ents[arm], self.shapes.ents[ball]
            if self._pinched(esper.component_for_entity(ball_ent, Body), esper.component_for_entity(ball_ent, Collider),
                             esper.component_for_entity(arm_ent, Body), esper.component_for_entity(arm_ent, Collider),
                             hit):
                hits[arm] = min(hits[arm], hit)
        return count
