import esper
import numpy as np

from polygolf.engine.components.resources import Resources
from polygolf.engine.physics import solver
from polygolf.engine.physics.jit import inlined_kernel
from polygolf.engine.physics.settings import RESTITUTION_THRESHOLD


class RestitutionProcessor(esper.Processor):
    """The restitution phase of every impact (Poisson): runs after `resolve` has stopped the
    approach. Without this processor every impact is perfectly plastic."""

    name = "restitution"

    def __init__(self, res: Resources) -> None:
        self.contacts, self.stats, self.statics = res.contacts, res.stats, res.statics

    def process(self) -> None:
        table = self.contacts.table
        if len(table):
            self.stats.bounces += bounce(table.store.state, self.statics.row, table.arrays)


@inlined_kernel
def bounce(state: np.ndarray, static: np.ndarray, table: tuple) -> int:
    """The stage on a store's state and a table with contacts (the caller looks first, as for
    `resolve`); `static` is the static world's row. Returns how many points bounced."""
    return solver.restitute(state, static, table, RESTITUTION_THRESHOLD)
