import esper
import numpy as np

from polygolf.engine.components.resources import Resources
from polygolf.engine.physics import solver
from polygolf.engine.physics.jit import leaf_kernel


class ResolveProcessor(esper.Processor):
    """Sequential impulses on this substep's contacts, then position correction that adds no energy
    (`physics.solver.solve`). Friction runs only if the world has the `friction` effect."""

    name = "resolve"

    def __init__(self, res: Resources) -> None:
        self.config, self.contacts, self.stats, self.statics = res.config, res.contacts, res.stats, res.statics
        self.friction = "friction" in res.config.effects

    def inputs(self) -> tuple[bool, int, int, int, bool]:
        """What `resolve` reads besides the state, the walls, the table and dt: the knobs, friction."""
        return *solver.solve_knobs(self.config.knobs), self.friction

    def process(self) -> None:
        table = self.contacts.table
        if len(table):
            self.stats.cold_restarts += resolve(table.store.state, self.statics.row, self.inputs(),
                                                table.arrays, self.config.dt)


@leaf_kernel
def resolve(state: np.ndarray, static: np.ndarray, inputs: tuple, table: tuple, dt: float) -> int:
    """The stage on a store's state and a table with contacts (the caller looks first: the solve
    would still count a reference to each array it is handed); `static` is the static world's row.
    Returns how many islands were solved cold. (A leaf, calling the counted `solver.solve_table`: a
    run of stages hands it the table without counting references to its arrays.)"""
    warm, iterations, position_iterations, correction, friction = inputs
    return solver.solve_table(state, static, table, warm, iterations, position_iterations, correction, dt, friction)
