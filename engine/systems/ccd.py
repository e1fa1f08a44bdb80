import math

import esper

from polygolf.engine.components import Body, Collider, Wall
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.settings import LINEAR_SLOP, TOI_TARGET
from polygolf.engine.physics.toi import time_of_impact


class CCDProcessor(esper.Processor):
    """Continuous collision against walls: a body whose motion this substep would carry it into or
    through a wall is moved back to its time of impact; the discrete contact that follows bounces it,
    and the time the motion lost is made up in the next substep (`BodyScratch.lag`), so a fast body
    that bounces ends up where it should rather than a substep behind."""

    name = "ccd"

    def __init__(self, res: Resources) -> None:
        self.statics, self.stats = res.statics, res.stats

    def process(self) -> None:
        grid = self.statics.grid
        for _, (body, col) in esper.get_components(Body, Collider):
            if body.asleep or body.inv_mass == 0.0:
                continue
            s = body.scratch
            dx, dy, da = body.x - s.x0, body.y - s.y0, body.angle - s.angle0
            if math.hypot(dx, dy) + abs(da) * col.radius < LINEAR_SLOP:
                continue  # small motions cannot skip anything: the discrete contact handles them
            r = col.radius + TOI_TARGET
            box = (min(s.x0, body.x) - r, min(s.y0, body.y) - r, max(s.x0, body.x) + r, max(s.y0, body.y) + r)
            found = grid.query(box)
            if not found:
                continue
            start, end = (s.x0, s.y0, s.angle0), (body.x, body.y, body.angle)
            first = 1.0
            for wall_ent, k in found:
                wall = esper.component_for_entity(wall_ent, Wall)
                for i, piece in enumerate(col.pieces):
                    t = time_of_impact(piece, col.normals[i], col.piece_reach[i], start, end,
                                       wall.pieces[k], wall.normals[k], TOI_TARGET, 0.25 * LINEAR_SLOP,
                                       LINEAR_SLOP)
                    if t is not None and t < first:
                        first = t
            if first < 1.0:
                body.x = s.x0 + first * dx
                body.y = s.y0 + first * dy
                body.angle = s.angle0 + first * da
                # The motion covered (dt + lag) this substep; the part after the impact is owed.
                s.lag = (1.0 - first) * s.moved_for
                self.stats.toi_hits += 1
