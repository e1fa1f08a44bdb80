"""A simulation's resources (Bevy's word): plain data that belongs to the world, not to an entity, split
by who writes it, so a processor's constructor shows what it reads and writes."""

from __future__ import annotations

from collections import deque
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from polygolf.engine.components.wall import Wall
from polygolf.engine.physics.body import Body, BodyStore, Selection
from polygolf.engine.physics.contact import ContactTable, Manifold
from polygolf.engine.physics.geometry import ConvexSet, ShapeTable
from polygolf.engine.physics.grid import BoxGrid, FatBoxes
from polygolf.engine.physics.presets import Knobs
from polygolf.engine.physics.seams import HIDDEN, REFLEX
from polygolf.engine.physics.settings import FRAME_DT


@dataclass(slots=True)
class StepConfig:
    """Set when the world is built (knobs may be switched live); read by every stage."""

    knobs: Knobs
    effects: frozenset[str]
    gravity: tuple[float, float] = (0.0, 0.0)  # m/s²
    collide_bodies: bool = True  # False: dynamic bodies meet walls and kinematic bodies, not each other
    # True: continuous collision sweeps every two dynamic bodies that step past each other by more than
    # the slop (a game's few balls); False: only by half the thinner's width (a crowd, where the sweeps
    # would cost more than the rest of the step: the discrete contact parts the others a substep later).
    sweep_bodies: bool = False

    @property
    def dt(self) -> float:
        return FRAME_DT / self.knobs.substeps


@dataclass(slots=True)
class StaticWorld:
    """The walls as one set of convex pieces in world coordinates, filed once at assembly: row for
    row with the vertices, the seams (physics.seams: `internal` edges, `hidden` vertices); per piece,
    the wall entity it belongs to, its index there and that wall's material; a grid of the pieces'
    boxes. And the stand-in body a wall contact pushes against."""

    pieces: ConvexSet
    internal: np.ndarray  # bool per vertex row: the edge starting there is covered
    hidden: np.ndarray  # int8 per vertex row: 0 a corner, HIDDEN on a flat stretch, REFLEX an inside corner
    owner: np.ndarray  # int64 per piece: its wall entity
    index: np.ndarray  # int64 per piece: its index among that wall's pieces
    materials: np.ndarray  # (pieces, 2) float64: its wall's restitution and friction
    grid: BoxGrid
    body: Body = field(default_factory=lambda: Body(x=0.0, y=0.0))

    @property
    def arrays(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """What a kernel reads of the walls: vertices, normals, piece rows, internal edges, hidden vertices."""
        return self.pieces.verts, self.pieces.normals, self.pieces.first, self.internal, self.hidden

    @property
    def row(self) -> np.ndarray:
        """The stand-in body's row: all the solver reads of the walls."""
        return self.body._row

    @property
    def packed(self) -> tuple:
        """Everything a stage's kernel reads of the walls, in one tuple: `arrays`, the pieces'
        materials, owners and indices, the stand-in body's row, the grid's `arrays`."""
        return (self.arrays, self.materials, self.owner, self.index, self.row, self.grid.arrays)

    @classmethod
    def of(cls, walls: Sequence[tuple[int, Wall]], cell_size: float) -> StaticWorld:
        """From (entity, wall) pairs, their seams already marked (assemble.mark_seams)."""
        found = [(ent, wall, k) for ent, wall in walls for k in range(len(wall.pieces))]
        pieces = ConvexSet.of([w.pieces[k] for _, w, k in found], [w.normals[k] for _, w, k in found])

        def rows(marks: str) -> np.ndarray:
            return np.array([v in getattr(w, marks)[k] if getattr(w, marks) else False
                             for _, w, k in found for v in range(len(w.pieces[k]))], dtype=np.bool_)

        hidden = np.where(rows("reflex"), REFLEX, np.where(rows("hidden"), HIDDEN, 0)).astype(np.int8)

        boxes = np.array([w.piece_aabbs[k] for _, w, k in found], dtype=np.float64).reshape(-1, 4)
        return cls(pieces=pieces, internal=rows("internal"), hidden=hidden,
                   owner=np.array([e for e, _, _ in found], dtype=np.int64),
                   index=np.array([k for _, _, k in found], dtype=np.int64),
                   materials=np.array([(w.material.restitution, w.material.friction) for _, w, _ in found],
                                      dtype=np.float64).reshape(-1, 2),
                   grid=BoxGrid(boxes, cell_size))


@dataclass(slots=True)
class Shapes:
    """Every body's convex pieces in one table (`geometry.ShapeTable`), so a stage can hand all
    bodies to one kernel call, with each one's entity, bounding radius, thinnest width and material; built
    again only when esper's list of bodies changes (a body or a collider added or taken away)."""

    _bodies: list | None = None
    _table: ShapeTable | None = None
    _rows: dict[int, int] = field(default_factory=dict)
    ents: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))
    radius: np.ndarray = field(default_factory=lambda: np.zeros(0))
    thickness: np.ndarray = field(default_factory=lambda: np.zeros(0))
    materials: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))  # restitution, friction
    _selection: Selection = field(default_factory=Selection)
    lookup: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))  # entity -> row (-1: none)
    _everyone: list | None = None  # esper's list of bodies when `current` last answered
    _current: tuple = ()
    packed: tuple = ()  # what a stage's kernel reads of the shapes, as `current` last gave them

    def index(self, ents: np.ndarray) -> np.ndarray:
        """The rows (as `of` gives them) of these entities, each of which has a body and a collider."""
        return self.lookup[ents]

    def of(self, bodies: list) -> tuple[ShapeTable, dict[int, int]]:
        """The table for `esper.get_components(Body, Collider)`, and each entity's row in it."""
        if self._bodies is not bodies or self._table is None:
            self._table = ShapeTable.of([col.shape for _, (_, col) in bodies])
            self._rows = {ent: k for k, (ent, _) in enumerate(bodies)}
            self.ents = np.array([ent for ent, _ in bodies], dtype=np.int64)
            self.radius = np.array([col.radius for _, (_, col) in bodies], dtype=np.float64)
            self.thickness = np.array([col.thickness for _, (_, col) in bodies], dtype=np.float64)
            self.materials = np.array([(col.material.restitution, col.material.friction) for _, (_, col) in bodies],
                                      dtype=np.float64).reshape(-1, 2)
            self.lookup = np.full(int(self.ents.max(initial=-1)) + 1, -1, dtype=np.int64)
            self.lookup[self.ents] = np.arange(len(self.ents))
            self._bodies = bodies
        return self._table, self._rows

    def current(self, store: BodyStore, everyone: list, bodies: list) -> tuple[np.ndarray, ShapeTable, np.ndarray]:
        """The store's state gathered for `esper.get_component(Body)` (`everyone`), the shape table
        for `esper.get_components(Body, Collider)` (`bodies`) and each of those bodies' rows in the
        state: what a contact stage reads each substep, worked out again only when either list
        changes (two identity tests while nothing is added or taken away). Also sets `packed`: all
        of that a kernel reads, in one tuple (the table's vertices, normals, piece rows, reaches and
        body rows; the bodies' rows, radii, widths, materials and entities; the entities' shapes)."""
        if everyone is not self._everyone or bodies is not self._bodies:
            state = store.gather(everyone)
            table, _ = self.of(bodies)
            rows = self._selection.of(store, bodies)
            self._current = (state, table, rows)
            self._everyone = everyone
            pieces = table.pieces
            self.packed = (pieces.verts, pieces.normals, pieces.first, pieces.reach, table.body_first, rows,
                           self.radius, self.thickness, self.materials, self.ents, self.lookup)
        return self._current


@dataclass(slots=True)
class Candidates:
    """Broadphase -> narrowphase: the bodies with wall pieces near them (`near`: entities) and those
    pieces (rows of the static world's pieces, ascending; body k's are
    `near_found[near_first[k]:near_first[k + 1]]`), and body pairs. `walls` gives the same as a
    dict, entity -> pieces."""

    near: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))
    near_first: np.ndarray = field(default_factory=lambda: np.zeros(1, dtype=np.int64))
    near_found: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))
    pair_ents: np.ndarray = field(default_factory=lambda: np.zeros((0, 2), dtype=np.int64))  # (a, b), a < b, sorted

    @property
    def arrays(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """As a kernel takes them: near, near_first, near_found, pair_ents."""
        return self.near, self.near_first, self.near_found, self.pair_ents

    @property
    def pairs(self) -> list[tuple[int, int]]:
        return [(a, b) for a, b in self.pair_ents.tolist()]

    @property
    def walls(self) -> dict[int, np.ndarray]:
        first = self.near_first.tolist()
        return {ent: self.near_found[first[k]:first[k + 1]] for k, ent in enumerate(self.near.tolist())}

    @walls.setter
    def walls(self, walls: dict[int, np.ndarray]) -> None:
        self.near = np.array(list(walls), dtype=np.int64)
        self.near_first = np.zeros(len(walls) + 1, dtype=np.int64)
        self.near_first[1:] = np.cumsum([len(found) for found in walls.values()])
        self.near_found = (np.concatenate([np.asarray(f, dtype=np.int64) for f in walls.values()]) if walls
                           else np.zeros(0, dtype=np.int64))


NO_CONTACTS = ContactTable.empty()  # the table of a substep where nothing touches (shared: never written)


class Contacts:
    """Narrowphase -> resolve, impacts, restitution, bumper and rest detection: this substep's
    contacts (`contact.ContactTable`), left for the next substep's warm start.

    A run of compiled stages (`systems.run.StageRun`) keeps the table it makes inside the run
    (`keeper`), and says how many manifolds it has (`size`); `table` fetches it from there only
    when someone asks and there is something to fetch."""

    __slots__ = ("_table", "keeper", "_stale", "size")

    def __init__(self, table: ContactTable | None = None) -> None:
        self._table = table if table is not None else ContactTable.empty()
        self.keeper = None  # the run holding the newest table, which `table` then shares or fetches
        self._stale = False
        self.size = len(self._table)  # manifolds in the newest table

    @property
    def table(self) -> ContactTable:
        if self._stale:
            self._table = self.keeper.table() if self.size else NO_CONTACTS
            self._stale = False
        return self._table

    @table.setter
    def table(self, table: ContactTable) -> None:
        self._table, self.keeper, self._stale, self.size = table, None, False, len(table)

    def let_go(self) -> None:
        """Take the newest table out of the run that holds it and forget the run: a closing world's run
        and resources would otherwise hold each other, and everything they reach (a thousand balls'
        handles), until the garbage collector's slowest pass."""
        self.table = self.table

    def keep(self, run: object, size: int, fresh: bool = False) -> None:
        """`run` holds the newest table, of `size` manifolds: a new one (`fresh`: fetched when asked
        for), or the one here."""
        self.keeper, self.size = run, size
        self._stale = self._stale or fresh

    @property
    def manifolds(self) -> list[Manifold]:
        """The table as objects, built on demand (tests and tools; the stages read the table)."""
        return self.table.manifolds()

    @property
    def touching(self) -> set[int]:
        """The entities in this substep's manifolds (-1: the static world)."""
        return set(self.table.ents.ravel().tolist())

    @property
    def count(self) -> int:
        return len(self.table.points)


# Columns of `Stats.values`: what the stages add to, in one array a compiled run of stages can write.
PENETRATION, BOUNCES, TOI_HITS, COLD_RESTARTS = range(4)


class Stats:
    """Measurements the stages add to; whoever reads one resets it. Kept in one float array
    (`values`, the columns above) so a compiled run of stages adds to them in place."""

    __slots__ = ("values",)

    def __init__(self) -> None:
        self.values = np.zeros(4)

    def _column(column: int, cast: type) -> property:  # noqa: N805 (a property factory for this class body)
        def get(self: Stats) -> float | int:
            return cast(self.values[column])

        def put(self: Stats, value: float) -> None:
            self.values[column] = value
        return property(get, put)

    max_penetration = _column(PENETRATION, float)
    bounces = _column(BOUNCES, int)
    toi_hits = _column(TOI_HITS, int)
    cold_restarts = _column(COLD_RESTARTS, int)  # substeps whose warm start would have added energy
    del _column


HEARD_LIMIT = 256  # events and impacts kept for a listener that has not drained them (a bound, not a budget)


@dataclass(frozen=True, slots=True)
class Impact:
    """Something struck a body hard enough to hear: `kind` is "shot" (the club), "wall", "bumper" or
    "body" (another body, a windmill); `speed` is the approach speed along the normal, m/s (a shot:
    the speed it gave the ball); (x, y) where; `bodies` the two entities that met (-1: a wall), so a
    listener can tell whose ball it was (the shot preview's first bounce)."""

    kind: str
    speed: float
    x: float
    y: float
    bodies: tuple[int, int] = (-1, -1)


@dataclass(slots=True)
class Events:
    """Golf events of this substep, in the order they happened, each naming the ball it happened to:
    ("shot", ball, 1), ("holed", ball, 1), ("penalty", ball, strokes) (water), ("restart", ball, strokes)
    (back to the tee: a penalty too, but no splash). The scoring stage, last in the
    table, reads `fired` and clears it; a ball's own `HoleState` keeps its score (one per player).

    A listener outside the world (the front end's sound and drawing) reads `heard` and `impacts`
    instead: everything since it last called `drain()`, bounded so nobody has to listen."""

    fired: list[tuple[str, int, int]] = field(default_factory=list)
    heard: deque[tuple[str, int, int]] = field(default_factory=lambda: deque(maxlen=HEARD_LIMIT))
    impacts: deque[Impact] = field(default_factory=lambda: deque(maxlen=HEARD_LIMIT))

    def emit(self, kind: str, ball: int, amount: int = 1) -> None:
        self.fired.append((kind, ball, amount))
        self.heard.append((kind, ball, amount))

    def strike(self, kind: str, speed: float, x: float, y: float, bodies: tuple[int, int] = (-1, -1)) -> None:
        self.impacts.append(Impact(kind, speed, x, y, bodies))

    def drain(self) -> tuple[list[tuple[str, int, int]], list[Impact]]:
        """The golf events and impacts since the last drain, oldest first."""
        heard, impacts = list(self.heard), list(self.impacts)
        self.heard.clear()
        self.impacts.clear()
        return heard, impacts


@dataclass(slots=True)
class Resources:
    config: StepConfig
    statics: StaticWorld
    bodies: BodyStore = field(default_factory=BodyStore)
    shapes: Shapes = field(default_factory=Shapes)
    candidates: Candidates = field(default_factory=Candidates)
    fat_boxes: FatBoxes = field(default_factory=FatBoxes)  # each body's walls near, for ccd and the broadphase
    contacts: Contacts = field(default_factory=Contacts)
    stats: Stats = field(default_factory=Stats)
    events: Events = field(default_factory=Events)
