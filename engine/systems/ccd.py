import math

import esper

from polygolf.engine.components import Body, Collider, Wall
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.collide import max_separation
from polygolf.engine.physics.grid import SpatialGrid
from polygolf.engine.physics.settings import CONTACT_MARGIN, LINEAR_SLOP, TOI_TARGET
from polygolf.engine.physics.toi import pair_time_of_impact, time_of_impact


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
        self._swept = SpatialGrid(res.statics.grid.cell_size)

    def process(self) -> None:
        bodies = esper.get_components(Body, Collider)
        first: dict[int, float] = {}
        longest = 0.0  # the longest step of an awake body
        for ent, (body, col) in bodies:
            if body.asleep:
                continue
            travel = _travel(body, col)
            longest = max(longest, travel)
            if body.inv_mass == 0.0 or travel < LINEAR_SLOP:
                continue  # small motions cannot skip anything: the discrete contact handles them
            t = self._first_wall_hit(body, col)
            if t < 1.0:
                first[ent] = t
        # No pair can need sweeping while no body steps half the linear slop.
        if len(bodies) > 1 and longest >= 0.5 * LINEAR_SLOP:
            self._body_hits(bodies, first)
        for ent, t in first.items():
            body = esper.component_for_entity(ent, Body)
            s = body.scratch
            body.x = s.x0 + t * (body.x - s.x0)
            body.y = s.y0 + t * (body.y - s.y0)
            body.angle = s.angle0 + t * (body.angle - s.angle0)
            if body.inv_mass:
                # The motion covered (dt + lag) this substep; the part after the impact is owed.
                s.lag = (1.0 - t) * s.moved_for
            else:
                body.spin = 0.0  # a stalled windmill: still, for the solve too; it owes nothing
            self.stats.toi_hits += 1

    def _first_wall_hit(self, body: Body, col: Collider) -> float:
        s = body.scratch
        r = col.radius + TOI_TARGET
        box = (min(s.x0, body.x) - r, min(s.y0, body.y) - r, max(s.x0, body.x) + r, max(s.y0, body.y) + r)
        start, end = (s.x0, s.y0, s.angle0), (body.x, body.y, body.angle)
        first = 1.0
        for wall_ent, k in self.statics.grid.query(box):
            wall = esper.component_for_entity(wall_ent, Wall)
            for i, piece in enumerate(col.pieces):
                t = time_of_impact(piece, col.normals[i], col.piece_reach[i], start, end,
                                   wall.pieces[k], wall.normals[k], TOI_TARGET, 0.25 * LINEAR_SLOP, LINEAR_SLOP)
                if t is not None and t < first:
                    first = t
        return first

    def _pinched(self, body: Body, col: Collider, arm: Body, arm_col: Collider, t: float) -> bool:
        """Whether the arm, meeting the body at fraction `t` of the substep, drives it into a wall it
        lies against (within the contact margin): the push (the separating axis between arm and
        body at the impact) points at least 15° into that wall's face. A body it meets
        along the wall, or away from one, is pushed as usual."""
        sa = arm.scratch
        arm_pieces, arm_normals = arm_col.world(sa.x0 + t * (arm.x - sa.x0), sa.y0 + t * (arm.y - sa.y0),
                                                sa.angle0 + t * (arm.angle - sa.angle0))
        pieces, normals = col.world(body.x, body.y, body.angle)
        best, push = -math.inf, (0.0, 0.0)
        for av, an in zip(arm_pieces, arm_normals):
            for bv, bn in zip(pieces, normals):
                gap, face = max_separation(av, an, bv)
                if gap > best:
                    best, push = gap, an[face]
                gap, face = max_separation(bv, bn, av)
                if gap > best:
                    best, push = gap, (-bn[face][0], -bn[face][1])
        r = col.radius + CONTACT_MARGIN
        for wall_ent, k in self.statics.grid.query((body.x - r, body.y - r, body.x + r, body.y + r)):
            wall = esper.component_for_entity(wall_ent, Wall)
            for verts in pieces:
                gap, face = max_separation(wall.pieces[k], wall.normals[k], verts)
                nx, ny = wall.normals[k][face]  # out of the wall, towards the body
                if gap < CONTACT_MARGIN and push[0] * nx + push[1] * ny < -0.25:
                    return True
        return False

    def _body_hits(self, bodies: list, first: dict[int, float]) -> None:
        """Pairs of bodies whose swept boxes overlap and that move fast relative to each other."""
        grid = self._swept
        grid.clear()
        meet = self.config.collide_bodies

        def swept(body: Body, col: Collider) -> tuple[float, float, float, float]:
            s, r = body.scratch, col.radius + TOI_TARGET
            return min(s.x0, body.x) - r, min(s.y0, body.y) - r, max(s.x0, body.x) + r, max(s.y0, body.y) + r

        if meet:
            for ent, (body, col) in bodies:
                grid.insert(ent, swept(body, col))
            candidates = grid.pairs()
        else:  # bodies meet kinematic ones only: index those, look each moving body up (K shots: no K²)
            for ent, (body, col) in bodies:
                if not body.inv_mass:
                    grid.insert(ent, swept(body, col))
            candidates = [(min(ent, k), max(ent, k)) for ent, (body, col) in bodies
                          if body.inv_mass and not body.asleep and grid for k in grid.query(swept(body, col))]
        for ea, eb in candidates:
            a, col_a = esper.component_for_entity(ea, Body), esper.component_for_entity(ea, Collider)
            b, col_b = esper.component_for_entity(eb, Body), esper.component_for_entity(eb, Collider)
            if not (a.inv_mass or b.inv_mass) or (a.inv_mass and b.inv_mass and not meet):
                continue
            if not (_moving(a) or _moving(b)):
                continue  # a resting ball is swept only against a turning windmill (which it may stall)
            # Against a kinematic body (a windmill's arm) any step beyond the slop is swept, as against
            # a wall; two dynamic bodies only when their steps could carry one half through the other
            # (cheaper in a crowd; the discrete contact then parts the overlap that is left).
            kinematic = not (a.inv_mass and b.inv_mass)
            limit = LINEAR_SLOP if kinematic else 0.5 * min(col_a.thickness, col_b.thickness)
            if _relative_travel(a, col_a, b, col_b) < limit:
                continue
            sa, sb = a.scratch, b.scratch
            start_a, end_a = (sa.x0, sa.y0, sa.angle0), (a.x, a.y, a.angle)
            start_b, end_b = (sb.x0, sb.y0, sb.angle0), (b.x, b.y, b.angle)
            hit = 1.0
            for i, piece_a in enumerate(col_a.pieces):
                for j, piece_b in enumerate(col_b.pieces):
                    t = pair_time_of_impact(piece_a, col_a.normals[i], col_a.piece_reach[i], start_a, end_a,
                                            piece_b, col_b.normals[j], col_b.piece_reach[j], start_b, end_b,
                                            TOI_TARGET, 0.25 * LINEAR_SLOP, LINEAR_SLOP)
                    if t is not None and t < hit:
                        hit = t
            if hit < 1.0:
                for ent, body in ((ea, a), (eb, b)):
                    if body.inv_mass and not body.asleep:
                        first[ent] = min(first.get(ent, 1.0), hit)
                if kinematic:
                    (arm, arm_ent, arm_col), (ball, col) = (((a, ea, col_a), (b, col_b)) if not a.inv_mass
                                                            else ((b, eb, col_b), (a, col_a)))
                    if self._pinched(ball, col, arm, arm_col, hit):
                        first[arm_ent] = min(first.get(arm_ent, 1.0), hit)


def _moving(body: Body) -> bool:
    """Awake and dynamic, or kinematic and turning."""
    return (not body.asleep and body.inv_mass > 0.0) or (body.inv_mass == 0.0 and body.spin != 0.0)


def _travel(body: Body, col: Collider) -> float:
    s = body.scratch
    return math.hypot(body.x - s.x0, body.y - s.y0) + abs(body.angle - s.angle0) * col.radius


def _relative_travel(a: Body, col_a: Collider, b: Body, col_b: Collider) -> float:
    sa, sb = a.scratch, b.scratch
    return (math.hypot(a.x - sa.x0 - b.x + sb.x0, a.y - sa.y0 - b.y + sb.y0)
            + abs(a.angle - sa.angle0) * col_a.radius + abs(b.angle - sb.angle0) * col_b.radius)
