import esper

from engine import solver
from engine.context import PhysicsContext
from engine.settings import LINEAR_SLOP, MAX_CORRECTION, POSITION_BETA


class ResolveProcessor(esper.Processor):
    """Sequential impulses on this substep's manifolds, then position correction that adds no energy.

    `friction` is decided when the world is built: a scene whose contacts have no friction never
    runs the friction code."""

    name = "resolve"

    def __init__(self, ctx: PhysicsContext, friction: bool) -> None:
        self.ctx = ctx
        self.friction = friction

    def process(self) -> None:
        ctx = self.ctx
        manifolds = ctx.manifolds
        if not manifolds:
            return
        knobs = ctx.knobs
        solver.prepare(manifolds)
        bodies = {id(b): b for m in manifolds for b in (m.body_a, m.body_b) if b.inv_mass > 0.0}.values()
        if knobs.warm_start:
            saved = [(b, b.vx, b.vy, b.spin) for b in bodies]
            before = sum(b.kinetic_energy() for b in bodies)
            solver.warm_start(manifolds)
            self._iterate(manifolds, knobs.iterations)
            if sum(b.kinetic_energy() for b in bodies) > before * (1.0 + 1e-12):
                # A contact solve without restitution can only take energy away; a cold Gauss-Seidel
                # sweep never adds any, but last substep's impulses re-applied to contacts that are
                # now opening can. Fall back to the cold solve.
                ctx.cold_restarts += 1
                for b, vx, vy, spin in saved:
                    b.vx, b.vy, b.spin = vx, vy, spin
                for m in manifolds:
                    for p in m.points:
                        p.normal_impulse = p.tangent_impulse = 0.0
                self._iterate(manifolds, knobs.iterations)
        else:
            self._iterate(manifolds, knobs.iterations)

        if knobs.position_correction == "split":
            dt = ctx.dt
            for _ in range(knobs.position_iterations):
                solver.solve_split(manifolds, dt, POSITION_BETA, LINEAR_SLOP, MAX_CORRECTION)
            moved = set()
            for m in manifolds:
                for body in (m.body_a, m.body_b):
                    if body.inv_mass > 0.0 and id(body) not in moved:
                        moved.add(id(body))
                        body.x += body.push_x * dt
                        body.y += body.push_y * dt
                        body.angle += body.push_spin * dt
                        body.push_x = body.push_y = body.push_spin = 0.0
        elif knobs.position_correction == "ngs":
            for _ in range(knobs.position_iterations):
                solver.solve_ngs(manifolds, POSITION_BETA, LINEAR_SLOP, MAX_CORRECTION)

    def _iterate(self, manifolds: list, iterations: int) -> None:
        for _ in range(iterations):
            solver.solve_velocities(manifolds, self.friction)
