import math

import esper

from engine.components import Body, Collider, Wall
from engine.context import PhysicsContext
from engine.settings import LINEAR_SLOP, TOI_TARGET
from engine.toi import time_of_impact


class CCDProcessor(esper.Processor):
    """Continuous collision against walls: a body whose motion this substep would carry it into or
    through a wall is moved back to its time of impact; the discrete contact that follows bounces it,
    and the time the motion lost is made up in the next substep (`Body.lag`), so a fast body that
    bounces ends up where it should rather than a substep behind."""

    name = "ccd"

    def __init__(self, ctx: PhysicsContext) -> None:
        self.ctx = ctx

    def process(self) -> None:
        ctx = self.ctx
        grid = ctx.static_grid
        for _, (body, col) in esper.get_components(Body, Collider):
            if body.asleep or body.inv_mass == 0.0:
                continue
            dx, dy, da = body.x - body.x0, body.y - body.y0, body.angle - body.angle0
            if math.hypot(dx, dy) + abs(da) * col.radius < LINEAR_SLOP:
                continue  # small motions cannot skip anything: the discrete contact handles them
            r = col.radius + TOI_TARGET
            box = (min(body.x0, body.x) - r, min(body.y0, body.y) - r,
                   max(body.x0, body.x) + r, max(body.y0, body.y) + r)
            found = grid.query(box)
            if not found:
                continue
            start, end = (body.x0, body.y0, body.angle0), (body.x, body.y, body.angle)
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
                body.x = body.x0 + first * dx
                body.y = body.y0 + first * dy
                body.angle = body.angle0 + first * da
                # The motion covered (dt + lag) this substep; the part after the impact is owed.
                body.lag = (1.0 - first) * body.moved_for
                ctx.toi_hits += 1
