import esper

from polygolf.engine.components import Bumper
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.settings import RESTITUTION_THRESHOLD

LIT_SECONDS = 0.25


class BumperProcessor(esper.Processor):
    """After restitution: a ball that struck a bumper this substep gets its kick, an impulse at the
    centre of the struck points that adds `kick` m/s to the normal speed there (one kick per
    manifold, so a flat hit on two points is kicked once; an off-centre hit also turns the ball)."""

    name = "bumper"

    def __init__(self, res: Resources) -> None:
        self.config, self.contacts = res.config, res.contacts

    def process(self) -> None:
        dt = self.config.dt
        for _, bumper in esper.get_component(Bumper):
            bumper.lit = max(0.0, bumper.lit - dt)
        for m in self.contacts.manifolds:
            if m.entity_b != -1:
                continue  # bumpers are walls: static manifolds only
            struck = [p for p in m.points if p.approach_speed < -RESTITUTION_THRESHOLD]
            bumper = esper.try_component(struck[0].key[0], Bumper) if struck else None
            if bumper is None:
                continue
            a = m.body_a
            rx = sum(p.ra_x for p in struck) / len(struck)
            ry = sum(p.ra_y for p in struck) / len(struck)
            nx, ny = -m.nx, -m.ny  # away from the bumper
            rn = rx * ny - ry * nx
            k = a.inv_mass + a.inv_inertia * rn * rn
            lam = bumper.kick / k
            a.vx += a.inv_mass * lam * nx
            a.vy += a.inv_mass * lam * ny
            a.spin += a.inv_inertia * lam * rn
            for p in struck:
                p.approach_speed = 0.0  # one kick per impact, even if the points linger
            bumper.lit = LIT_SECONDS
