import esper

from engine.components import Body
from engine.context import PhysicsContext
from engine.settings import REST_ANGULAR, REST_LINEAR, TIME_TO_REST


class IntegrateProcessor(esper.Processor):
    """Semi-implicit Euler for position (velocities were already updated this substep), and rest
    detection: a dynamic body slower than the rest thresholds for TIME_TO_REST is put to rest and
    skipped by every system until something wakes it."""

    name = "integrate"

    def __init__(self, ctx: PhysicsContext) -> None:
        self.ctx = ctx

    def process(self) -> None:
        dt = self.ctx.dt
        for _, body in esper.get_component(Body):
            if body.asleep:
                continue
            if body.inv_mass > 0.0:
                if (body.vx * body.vx + body.vy * body.vy < REST_LINEAR * REST_LINEAR
                        and abs(body.spin) < REST_ANGULAR):
                    body.still_time += dt
                    if body.still_time >= TIME_TO_REST:
                        body.asleep = True
                        body.vx = body.vy = body.spin = 0.0
                        body.x0, body.y0, body.angle0 = body.x, body.y, body.angle
                        continue
                else:
                    body.still_time = 0.0
            body.x0, body.y0, body.angle0 = body.x, body.y, body.angle
            body.x += body.vx * dt
            body.y += body.vy * dt
