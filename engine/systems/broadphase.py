import esper
import numpy as np

from polygolf.engine.components import Body, Collider
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.grid import BoxGrid, box_pairs
from polygolf.engine.physics.settings import CONTACT_MARGIN


class BroadphaseProcessor(esper.Processor):
    """Candidate pairs from bounding boxes (`physics.grid`): moving bodies against the walls' grid,
    and bodies against each other. Resting bodies are not looked up at all. Reads the static index;
    writes the candidates."""

    name = "broadphase"

    def __init__(self, res: Resources) -> None:
        self.statics, self.candidates, self.config = res.statics, res.candidates, res.config

    def process(self) -> None:
        bodies = esper.get_components(Body, Collider)
        moving = [(ent, body, col) for ent, (body, col) in bodies if not body.asleep and body.inv_mass]
        walls: dict[int, np.ndarray] = {}
        if moving and len(self.statics.grid):
            first, found = self.statics.grid.query_many(boxes(moving))
            first = first.tolist()
            walls = {ent: found[first[q]:first[q + 1]] for q, (ent, _, _) in enumerate(moving)
                     if first[q + 1] > first[q]}
        self.candidates.walls = walls

        pairs: list[tuple[int, int]] = []
        if len(bodies) > 1:
            if self.config.collide_bodies:
                everyone = [(ent, body, col) for ent, (body, col) in bodies]
                active = np.array([_moving(body) for _, body, _ in everyone], dtype=np.bool_)
                ents = [ent for ent, _, _ in everyone]
                pairs = [(min(ents[i], ents[j]), max(ents[i], ents[j]))
                         for i, j in box_pairs(boxes(everyone), active).tolist()]
            else:  # bodies meet kinematic ones only: index those, look each moving body up (K shots: no K²)
                kinematic = [(ent, body, col) for ent, (body, col) in bodies if body.inv_mass == 0.0]
                if kinematic and moving:
                    first, found = BoxGrid(boxes(kinematic), self.statics.grid.cell_size).query_many(boxes(moving))
                    found = found.tolist()
                    pairs = [(min(ent, kinematic[k][0]), max(ent, kinematic[k][0]))
                             for q, (ent, _, _) in enumerate(moving) for k in found[first[q]:first[q + 1]]]
        self.candidates.pairs = sorted(pairs)  # one order whichever way they were found


def boxes(bodies: list[tuple[int, Body, Collider]], margin: float = CONTACT_MARGIN) -> np.ndarray:
    """Each body's bounding box, grown by the contact margin."""
    return np.array([(body.x - r, body.y - r, body.x + r, body.y + r)
                     for _, body, col in bodies for r in (col.radius + margin,)], dtype=np.float64).reshape(-1, 4)


def _moving(body: Body) -> bool:
    """Awake and able to move: a dynamic body, or a kinematic one with a velocity."""
    return not body.asleep and bool(body.inv_mass or body.vx or body.vy or body.spin)
