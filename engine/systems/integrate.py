import esper

from polygolf.engine.components import Body, Drag
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.settings import REST_ANGULAR, REST_LINEAR, REST_SPEED_CAP, TIME_TO_REST


class IntegrateProcessor(esper.Processor):
    """Semi-implicit Euler, position half: x += v·dt with the velocity the contact solver left at
    the end of the last substep (forces then update velocities, and the solver constrains them
    before they move anything). Also rest detection.

    A body is put to rest when it is touching something or slowed by drag (a free body with no drag
    coasts for ever: sleeping it would steal its momentum) and has hardly *moved* for TIME_TO_REST.
    Judging by displacement (corrections included) rather than velocity lets a ball pressed into a
    corner by a slope fall asleep although the slope adds velocity every substep. A body at rest has
    its velocities zeroed and is skipped by every system until something wakes it."""

    name = "integrate"

    def __init__(self, res: Resources) -> None:
        self.config, self.contacts = res.config, res.contacts

    def process(self) -> None:
        dt = self.config.dt
        still_step = REST_LINEAR * dt
        still_turn = REST_ANGULAR * dt
        touching = self.contacts.touching
        for ent, body in esper.get_component(Body):
            if body.asleep:
                continue
            s = body.scratch
            if body.inv_mass > 0.0 and (ent in touching or esper.has_component(ent, Drag)):
                dx, dy = body.x - s.x0, body.y - s.y0
                if (dx * dx + dy * dy < still_step * still_step and abs(body.angle - s.angle0) < still_turn
                        and body.vx * body.vx + body.vy * body.vy < REST_SPEED_CAP * REST_SPEED_CAP):
                    s.still_time += dt
                    if s.still_time >= TIME_TO_REST:
                        body.rest()
                        continue
                else:
                    s.still_time = 0.0
            body.mark_start()
            step = dt
            if s.lag:
                # Continuous collision stopped the body early last substep; it now moves on with its
                # new velocity for the time it lost, so impacts do not slow the clock.
                step += s.lag
                body.angle += body.spin * s.lag
                s.lag = 0.0
            s.moved_for = step
            body.x += body.vx * step
            body.y += body.vy * step
