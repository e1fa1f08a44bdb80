import esper

from polygolf.engine.components import Body
from polygolf.engine.components.resources import Resources


class SpinProcessor(esper.Processor):
    """Integrates orientation. Without the `spin` effect bodies keep their angle and the assembler
    gives them infinite inertia, so contacts cannot make them turn either."""

    name = "spin"

    def __init__(self, res: Resources) -> None:
        self.config = res.config

    def process(self) -> None:
        dt = self.config.dt
        for _, body in esper.get_component(Body):
            if body.spin and not body.asleep:
                body.angle += body.spin * dt
