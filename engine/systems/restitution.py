import esper

from engine import solver
from engine.context import PhysicsContext
from engine.settings import RESTITUTION_THRESHOLD


class RestitutionProcessor(esper.Processor):
    """The restitution phase of every impact (Poisson): runs after `resolve` has stopped the
    approach. Without this processor every impact is perfectly plastic."""

    name = "restitution"

    def __init__(self, ctx: PhysicsContext) -> None:
        self.ctx = ctx

    def process(self) -> None:
        if self.ctx.manifolds:
            self.ctx.bounces += solver.apply_restitution(self.ctx.manifolds, RESTITUTION_THRESHOLD)
