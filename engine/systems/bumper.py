import esper
import numpy as np

from polygolf.engine.components import Bumper
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.contact import K_OTHER, M_NX, M_NY, P_APPROACH, P_RA_X, P_RA_Y
from polygolf.engine.physics.settings import RESTITUTION_THRESHOLD

LIT_SECONDS = 0.25


class BumperProcessor(esper.Processor):
    """After restitution: a ball that struck a bumper this substep gets its kick, an impulse at the
    centre of the struck points that adds `kick` m/s to the normal speed there (one kick per
    manifold, so a flat hit on two points is kicked once; an off-centre hit also turns the ball).
    Reads the contact table's struck points only (few, and in most substeps none)."""

    name = "bumper"

    def __init__(self, res: Resources) -> None:
        self.config, self.contacts = res.config, res.contacts

    def process(self) -> None:
        dt = self.config.dt
        for _, bumper in esper.get_component(Bumper):
            if bumper.lit:
                bumper.lit = max(0.0, bumper.lit - dt)
        table = self.contacts.table
        if not len(table):
            return
        points = table.points
        struck = points[:, P_APPROACH] < -RESTITUTION_THRESHOLD
        if not struck.any():
            return
        struck_rows = np.flatnonzero(struck)
        of = np.searchsorted(table.first, struck_rows, side="right") - 1  # each struck point's manifold
        for k in np.unique(of).tolist():
            if table.ents[k, 1] != -1:
                continue  # bumpers are walls: static manifolds only
            struck = struck_rows[of == k]
            bumper = esper.try_component(table.keys[struck[0], K_OTHER].item(), Bumper)
            if bumper is None:
                continue
            a = table.body(int(table.pair[k, 0]))
            rx = sum(points[struck, P_RA_X].tolist()) / len(struck)
            ry = sum(points[struck, P_RA_Y].tolist()) / len(struck)
            nx, ny = -table.normals[k, M_NX].item(), -table.normals[k, M_NY].item()  # away from the bumper
            rn = rx * ny - ry * nx
            k_ = a.inv_mass + a.inv_inertia * rn * rn
            lam = bumper.kick / k_
            a.vx += a.inv_mass * lam * nx
            a.vy += a.inv_mass * lam * ny
            a.spin += a.inv_inertia * lam * rn
            points[struck, P_APPROACH] = 0.0  # one kick per impact, even if the points linger
            bumper.lit = LIT_SECONDS
