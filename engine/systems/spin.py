import esper

from polygolf.engine.components import Body
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.motion import turn


class SpinProcessor(esper.Processor):
    """Integrates orientation. Without the `spin` effect bodies keep their angle and the assembler
    gives them infinite inertia, so contacts cannot make them turn either."""

    name = "spin"

    def __init__(self, res: Resources) -> None:
        self.config, self.bodies = res.config, res.bodies

    def process(self) -> None:
        turn(self.bodies.gather(esper.get_component(Body)), self.config.dt)
