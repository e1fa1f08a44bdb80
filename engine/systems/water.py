import esper
import numpy as np

from polygolf.engine.components import Ball, Body, Collider, Region, Water
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.body import Selection
from polygolf.engine.physics.settings import LINEAR_SLOP
from polygolf.engine.systems.areas import AreaIndex


class WaterProcessor(esper.Processor):
    """A ball whose centre goes in the water is taken out, a penalty stroke is added ("penalty"),
    and it is put back at rest where it last rested (or, if another ball lies there now, at the
    nearest free drop spot: see `Water.put_back`)."""

    name = "water"

    def __init__(self, res: Resources) -> None:
        self.events, self.config, self.bodies = res.events, res.config, res.bodies
        self._balls, self._areas = Selection(), AreaIndex()

    def process(self) -> None:
        state = self.bodies.gather(esper.get_component(Body))
        balls = esper.get_components(Body, Ball)
        zones = esper.get_components(Region, Water)
        on = self._areas.under(state, self._balls.of(self.bodies, balls), zones)
        for q in np.flatnonzero(on >= 0).tolist() if on is not None else ():
            ent, (body, ball) = balls[q]
            water = zones[on[q]][1][1]
            own = esper.try_component(ent, Collider)
            reach = own.radius if own is not None else 0.0
            others = tuple((b.x, b.y, reach + c.radius + LINEAR_SLOP)
                           for other, (b, c, _) in esper.get_components(Body, Collider, Ball)
                           if other != ent and self.config.collide_bodies)  # K shots: ghosts
            body.x, body.y = water.put_back(ball.rest_x, ball.rest_y, others)
            body.rest()
            self.events.emit("penalty", ent, water.penalty)
