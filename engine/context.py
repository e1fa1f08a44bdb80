"""State shared by the processors of one simulation: the knobs, the static index and the contacts
handed from one stage of the substep to the next."""

from __future__ import annotations

from dataclasses import dataclass, field

from engine.components.body import Body
from engine.contact import Manifold
from engine.grid import SpatialGrid
from engine.presets import Knobs
from engine.settings import FRAME_DT


@dataclass(slots=True)
class PhysicsContext:
    knobs: Knobs
    effects: frozenset[str]
    static_grid: SpatialGrid
    gravity: tuple[float, float] = (0.0, 0.0)  # m/s²
    static_body: Body = field(default_factory=lambda: Body(x=0.0, y=0.0))
    # body entity -> candidate (wall entity, piece index) pairs, from the broadphase
    wall_candidates: dict[int, list[tuple[int, int]]] = field(default_factory=dict)
    body_pairs: list[tuple[int, int]] = field(default_factory=list)
    manifolds: list[Manifold] = field(default_factory=list)
    touching: set[int] = field(default_factory=set)  # entities in this substep's manifolds
    # Measurements, reset by whoever reads them.
    max_penetration: float = 0.0
    bounces: int = 0
    toi_hits: int = 0
    cold_restarts: int = 0  # substeps whose warm start would have added energy

    @property
    def dt(self) -> float:
        return FRAME_DT / self.knobs.substeps

    @property
    def contact_count(self) -> int:
        return sum(len(m.points) for m in self.manifolds)
