import esper

from polygolf.engine.components import Ball, Body, Collider, Region, Water
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.settings import LINEAR_SLOP


class WaterProcessor(esper.Processor):
    """A ball whose centre goes in the water is taken out, a penalty stroke is added ("penalty"),
    and it is put back at rest where it last rested (or, if another ball lies there now, at the
    nearest free drop spot: see `Water.put_back`)."""

    name = "water"

    def __init__(self, res: Resources) -> None:
        self.events, self.config = res.events, res.config

    def process(self) -> None:
        zones = esper.get_components(Region, Water)
        for ent, (body, ball) in esper.get_components(Body, Ball):
            if body.asleep:
                continue
            for _, (region, water) in zones:
                if region.contains(body.x, body.y):
                    own = esper.try_component(ent, Collider)
                    reach = own.radius if own is not None else 0.0
                    others = tuple((b.x, b.y, reach + c.radius + LINEAR_SLOP)
                                   for other, (b, c, _) in esper.get_components(Body, Collider, Ball)
                                   if other != ent and self.config.collide_bodies)  # K shots: ghosts
                    body.x, body.y = water.put_back(ball.rest_x, ball.rest_y, others)
                    body.rest()
                    self.events.emit("penalty", ent, water.penalty)
                    break
