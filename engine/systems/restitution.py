import math

import esper
import numpy as np

from polygolf.engine.components import Slope
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics import solver
from polygolf.engine.physics.jit import leaf_kernel
from polygolf.engine.physics.settings import RESTITUTION_THRESHOLD

STEADY_MARGIN = 1.05  # approaches up to this many substeps' worth of the steadiest push are resting, not impacts


class RestitutionProcessor(esper.Processor):
    """The restitution phase of every impact (Poisson): runs after `resolve` has stopped the
    approach. Without this processor every impact is perfectly plastic.

    A contact held by a steady push (gravity, a slope) closes by that push times the substep every
    substep: that is resting, not an impact, and bouncing it (a box on a box at fast, where g·dt
    is 0.08 m/s) lifted the pair off the floor and walked it sideways. So the slowest approach
    that bounces is RESTITUTION_THRESHOLD, or STEADY_MARGIN substeps of the world's steadiest push
    if that is more."""

    name = "restitution"

    def __init__(self, res: Resources) -> None:
        self.contacts, self.stats, self.statics, self.config = res.contacts, res.stats, res.statics, res.config

    def inputs(self) -> float:
        """The slowest approach that bounces (m/s), for this world's pushes and substep."""
        pushes = [self.config.gravity, *(slope.push for _, slope in esper.get_component(Slope))]
        steadiest = max(math.hypot(*push) for push in pushes)
        return max(RESTITUTION_THRESHOLD, STEADY_MARGIN * steadiest * self.config.dt)

    def process(self) -> None:
        table = self.contacts.table
        if len(table):
            self.stats.bounces += bounce(table.store.state, self.statics.row, table.arrays, self.inputs())


@leaf_kernel
def bounce(state: np.ndarray, static: np.ndarray, table: tuple, threshold: float) -> int:
    """The stage on a store's state and a table with contacts (the caller looks first, as for
    `resolve`); `static` is the static world's row. Returns how many points bounced."""
    return solver.restitute(state, static, table, threshold)
