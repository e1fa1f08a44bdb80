import esper

from polygolf.engine.components.resources import Resources
from polygolf.engine.physics import solver


class ResolveProcessor(esper.Processor):
    """Sequential impulses on this substep's contacts, then position correction that adds no energy
    (`physics.solver.solve`). Friction runs only if the world has the `friction` effect."""

    name = "resolve"

    def __init__(self, res: Resources) -> None:
        self.config, self.contacts, self.stats = res.config, res.contacts, res.stats
        self.friction = "friction" in res.config.effects

    def process(self) -> None:
        table = self.contacts.table
        if len(table):
            self.stats.cold_restarts += solver.solve(table, self.config.knobs, self.config.dt, self.friction)
