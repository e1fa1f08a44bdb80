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
            self.stats.bounces += bounce(table.store.state, self.statics.packed, table.arrays)


@inlined_kernel
def bounce(state: np.ndarray, walls: tuple, table: tuple) -> int:
    """The stage on a store's state (the static world's row from `StaticWorld.packed`); returns how
    many points bounced."""
    if not len(table[1]):
        return 0
    return solver.restitute(state, walls[4], table, RESTITUTION_THRESHOLD)
