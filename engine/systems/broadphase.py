import esper

from polygolf.engine.components import Body, Collider
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.grid import SpatialGrid
from polygolf.engine.physics.settings import CONTACT_MARGIN


class BroadphaseProcessor(esper.Processor):
    """Candidate pairs from bounding boxes on a uniform grid: moving bodies against the static grid
    of wall pieces, and bodies against each other. Resting bodies are not looked up at all.
    Reads the static index; writes the candidates."""

    name = "broadphase"

    def __init__(self, res: Resources) -> None:
        self.statics, self.candidates, self.config = res.statics, res.candidates, res.config
        self._dynamic_grid = SpatialGrid(res.statics.grid.cell_size)

    def process(self) -> None:
        bodies = esper.get_components(Body, Collider)
        static_grid = self.statics.grid
        walls: dict[int, list] = {}
        for ent, (body, col) in bodies:
            if body.asleep or body.inv_mass == 0.0:
                continue
            r = col.radius + CONTACT_MARGIN
            found = static_grid.query((body.x - r, body.y - r, body.x + r, body.y + r))
            if found:
                walls[ent] = found
        self.candidates.walls = walls

        pairs: list[tuple[int, int]] = []
        if len(bodies) > 1:
            grid = self._dynamic_grid
            grid.clear()
            if self.config.collide_bodies:
                for ent, (body, col) in bodies:
                    r = col.radius + CONTACT_MARGIN
                    grid.insert(ent, (body.x - r, body.y - r, body.x + r, body.y + r))
                for ea, eb in grid.pairs():
                    if _moving(esper.component_for_entity(ea, Body)) or _moving(esper.component_for_entity(eb, Body)):
                        pairs.append((ea, eb))
            else:  # bodies meet kinematic ones only: index those, look each moving body up (K shots: no K²)
                for ent, (body, col) in bodies:
                    if body.inv_mass == 0.0:
                        r = col.radius + CONTACT_MARGIN
                        grid.insert(ent, (body.x - r, body.y - r, body.x + r, body.y + r))
                if grid:
                    for ent, (body, col) in bodies:
                        if body.inv_mass and not body.asleep:
                            r = col.radius + CONTACT_MARGIN
                            pairs += [(min(ent, k), max(ent, k))
                                      for k in grid.query((body.x - r, body.y - r, body.x + r, body.y + r))]
        self.candidates.pairs = sorted(pairs)  # one order whichever way they were found


def _moving(body: Body) -> bool:
    """Awake and able to move: a dynamic body, or a kinematic one with a velocity."""
    return not body.asleep and bool(body.inv_mass or body.vx or body.vy or body.spin)
