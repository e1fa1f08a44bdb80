import esper

from polygolf.engine.components import Ball, Body, Launcher
from polygolf.engine.components.resources import Resources


class LaunchProcessor(esper.Processor):
    """The collision test level's launcher: puts each ball back where it started (the tee, or its own
    spot beside it when several play) and sends it off at a fixed velocity every `every` seconds, for
    watching collisions."""

    name = "launch"

    def __init__(self, res: Resources) -> None:
        self.config = res.config

    def process(self) -> None:
        for _, launcher in esper.get_component(Launcher):
            launcher.clock += self.config.dt
            if launcher.clock < launcher.every - 1e-9:  # substeps add up to `every` only to rounding
                continue
            launcher.clock = 0.0
            for k, (_, (body, _)) in enumerate(sorted(esper.get_components(Body, Ball))):
                body.x, body.y = launcher.spots[k] if k < len(launcher.spots) else launcher.tee
                body.angle = 0.0
                body.vx, body.vy = launcher.velocity
                body.spin = 0.0
                body.wake()
