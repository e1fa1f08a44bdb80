import esper

from polygolf.engine.components import Body, Windmill
from polygolf.engine.components.resources import Resources


class WindmillProcessor(esper.Processor):
    """Drives each windmill at its set speed. It is kinematic (no inverse mass or inertia), so no
    contact can slow it; the contact solver sees its surface velocity, ω × r, like any body's."""

    name = "windmill"

    def __init__(self, res: Resources) -> None:
        pass  # reads components only

    def process(self) -> None:
        for _, (body, windmill) in esper.get_components(Body, Windmill):
            body.spin = windmill.speed
