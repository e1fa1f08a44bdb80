import esper

from polygolf.engine.components.resources import Resources
from polygolf.engine.physics import solver
from polygolf.engine.physics.settings import RESTITUTION_THRESHOLD


class RestitutionProcessor(esper.Processor):
    """The restitution phase of every impact (Poisson): runs after `resolve` has stopped the
    approach. Without this processor every impact is perfectly plastic."""

    name = "restitution"

    def __init__(self, res: Resources) -> None:
        self.contacts, self.stats = res.contacts, res.stats

    def process(self) -> None:
        table = self.contacts.table
        if len(table):
            self.stats.bounces += solver.apply_restitution(table, RESTITUTION_THRESHOLD)
