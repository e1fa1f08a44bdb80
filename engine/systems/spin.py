import esper

from engine.components import Body
from engine.context import PhysicsContext


class SpinProcessor(esper.Processor):
    """Integrates orientation. Without the `spin` effect bodies keep their angle and the pipeline
    gives them infinite inertia, so contacts cannot make them turn either."""

    name = "spin"

    def __init__(self, ctx: PhysicsContext) -> None:
        self.ctx = ctx

    def process(self) -> None:
        dt = self.ctx.dt
        for _, body in esper.get_component(Body):
            if body.spin and not body.asleep:
                body.angle += body.spin * dt
