import esper

from engine.components import Body, Collider
from engine.context import PhysicsContext
from engine.grid import SpatialGrid
from engine.settings import CONTACT_MARGIN


class BroadphaseProcessor(esper.Processor):
    """Candidate pairs from bounding boxes on a uniform grid: moving bodies against the static grid
    of wall pieces, and bodies against each other. Resting bodies are not looked up at all."""

    name = "broadphase"

    def __init__(self, ctx: PhysicsContext, cell_size: float) -> None:
        self.ctx = ctx
        self._dynamic_grid = SpatialGrid(cell_size)

    def process(self) -> None:
        ctx = self.ctx
        candidates: dict[int, list] = {}
        bodies = esper.get_components(Body, Collider)
        static_grid = ctx.static_grid
        for ent, (body, col) in bodies:
            if body.asleep or body.inv_mass == 0.0:
                continue
            r = col.radius + CONTACT_MARGIN
            found = static_grid.query((body.x - r, body.y - r, body.x + r, body.y + r))
            if found:
                candidates[ent] = found
        ctx.wall_candidates = candidates

        pairs: list[tuple[int, int]] = []
        if len(bodies) > 1:
            grid = self._dynamic_grid
            grid.clear()
            for ent, (body, col) in bodies:
                r = col.radius + CONTACT_MARGIN
                grid.insert(ent, (body.x - r, body.y - r, body.x + r, body.y + r))
            for ea, eb in grid.pairs():
                if not (_moving(esper.component_for_entity(ea, Body))
                        or _moving(esper.component_for_entity(eb, Body))):
                    continue
                pairs.append((ea, eb))
        ctx.body_pairs = pairs


def _moving(body: Body) -> bool:
    """Awake and able to move: a dynamic body, or a kinematic one with a velocity."""
    return not body.asleep and bool(body.inv_mass or body.vx or body.vy or body.spin)
