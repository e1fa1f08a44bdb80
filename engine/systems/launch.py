import esper

from engine.components import Ball, Body
from engine.context import PhysicsContext


class LaunchProcessor(esper.Processor):
    """The collision test level's launcher: puts the ball back on the tee and sends it off at a
    fixed velocity every `every` seconds, for watching collisions."""

    name = "launch"

    def __init__(self, ctx: PhysicsContext, velocity: tuple[float, float], every: float,
                 tee: tuple[float, float]) -> None:
        self.ctx = ctx
        self.velocity, self.every, self.tee = velocity, every, tee
        self.clock = every  # launch on the first substep

    def process(self) -> None:
        self.clock += self.ctx.dt
        if self.clock < self.every - 1e-9:  # substeps add up to `every` only to rounding
            return
        self.clock = 0.0
        for _, (body, _) in esper.get_components(Body, Ball):
            body.x, body.y = self.tee
            body.angle = 0.0
            body.vx, body.vy = self.velocity
            body.spin = 0.0
            body.wake()
