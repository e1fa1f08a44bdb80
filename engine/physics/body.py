"""A rigid body's simulated state, kept apart from the solver's scratch (as Box2D v3 keeps b2BodySim
apart from b2BodyState): what a body *is* and where it is on one side, what a substep leaves behind
for the next stage on the other.

The state lives in arrays, one row a body (structure of arrays, `COLUMNS`), so a kernel can step
every body of a world in one call. A `Body` is a handle on its row: `body.x` reads and writes the
array. A body made on its own has a row of its own; `BodyStore.gather` moves the bodies of a world
into one array, row for row, and points each handle at its new row.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

# The columns of a body row. The first thirteen are the contact solver's row (`solver.B_*`), in its
# order: pose, velocity, mass properties, split-impulse pseudo-velocity.
COLUMNS = ("x", "y", "angle", "vx", "vy", "spin", "mass", "inertia", "inv_mass", "inv_inertia",
           "push_x", "push_y", "push_spin", "asleep", "still_time", "x0", "y0", "angle0", "lag", "moved_for",
           "drag_scale", "energy0")
(X, Y, ANGLE, VX, VY, SPIN, MASS, INERTIA, INV_MASS, INV_INERTIA, PUSH_X, PUSH_Y, PUSH_SPIN, ASLEEP, STILL_TIME,
 X0, Y0, ANGLE0, LAG, MOVED_FOR, DRAG_SCALE, ENERGY0) = range(len(COLUMNS))
SOLVER_COLUMNS = PUSH_SPIN + 1


@dataclass(slots=True)
class Material:
    """Contact coefficients; a contact uses the product of both sides' values."""

    restitution: float = 1.0
    friction: float = 1.0


def _column(col: int, doc: str) -> property:
    def get(self: _Row) -> float:
        return self._row.item(col)

    def put(self: _Row, value: float) -> None:
        self._row[col] = value

    return property(get, put, doc=doc)


class _Row:
    __slots__ = ("_row",)

    def __init__(self, row: np.ndarray) -> None:
        self._row = row


class BodyScratch(_Row):
    """Working values of one substep's stages; never part of the body's physical state."""

    __slots__ = ()
    still_time = _column(STILL_TIME, "seconds spent below the rest thresholds")
    # Pose at the start of the substep, for continuous collision and rest detection.
    x0 = _column(X0, "x at the start of the substep")
    y0 = _column(Y0, "y at the start of the substep")
    angle0 = _column(ANGLE0, "angle at the start of the substep")
    lag = _column(LAG, "time continuous collision cut from the last substep's motion (s), made up in the next")
    moved_for = _column(MOVED_FOR, "how long the last substep's motion lasted (dt, plus any lag made up)")
    # Pseudo-velocities of split-impulse position correction; never part of the kinetic energy.
    push_x = _column(PUSH_X, "split-impulse pseudo-velocity, x")
    push_y = _column(PUSH_Y, "split-impulse pseudo-velocity, y")
    push_spin = _column(PUSH_SPIN, "split-impulse pseudo-velocity, angular")
    drag_scale = _column(DRAG_SCALE, "the surface under the body (sand, ice) scales its drag this substep by this")
    energy0 = _column(ENERGY0, "kinetic energy before this substep's contact solve (J): restitution may not exceed it "
                               "(inf until a solve says: no cap)")


class Body(_Row):
    """Rigid-body state about the centroid. Static and kinematic bodies have zero inverse mass."""

    __slots__ = ()
    x = _column(X, "m")
    y = _column(Y, "m")
    angle = _column(ANGLE, "radians, counter-clockwise")
    vx = _column(VX, "m/s")
    vy = _column(VY, "m/s")
    spin = _column(SPIN, "rad/s, counter-clockwise")
    mass = _column(MASS, "kg")
    inertia = _column(INERTIA, "kg m² about the centroid")
    inv_mass = _column(INV_MASS, "1/kg; zero: nothing moves it")
    inv_inertia = _column(INV_INERTIA, "zero: nothing turns it")

    def __init__(self, x: float, y: float, angle: float = 0.0, vx: float = 0.0, vy: float = 0.0, spin: float = 0.0,
                 mass: float = 0.0, inertia: float = 0.0, inv_mass: float = 0.0, inv_inertia: float = 0.0,
                 asleep: bool = False) -> None:
        self._point(np.array(self.row(x, y, angle, vx, vy, spin, mass, inertia, inv_mass, inv_inertia, asleep),
                             dtype=np.float64))

    @staticmethod
    def row(x: float, y: float, angle: float, vx: float, vy: float, spin: float, mass: float, inertia: float,
            inv_mass: float, inv_inertia: float, asleep: bool) -> list[float]:
        """A new body's row as a list (`Body()` converts one; `on_rows` many at once): the columns in
        order, the substep's start pose = the pose, drag scale 1."""
        return [x, y, angle, vx, vy, spin, mass, inertia, inv_mass, inv_inertia, 0.0, 0.0, 0.0, 1.0 if asleep else 0.0,
                0.0, x, y, angle, 0.0, 0.0, 1.0, math.inf]

    @classmethod
    def on_rows(cls, rows: list[list[float]]) -> list[Body]:
        """A body for each of these rows (`row`'s), made as one array: a search builds a thousand
        balls at once, and one conversion costs less than a thousand."""
        state = np.array(rows, dtype=np.float64).reshape(-1, len(COLUMNS))
        bodies = [cls.__new__(cls) for _ in rows]
        for body, row in zip(bodies, state):
            body._point(row)
        return bodies

    def _point(self, row: np.ndarray) -> None:
        """Make this handle read and write `row`."""
        self._row = row

    @property
    def scratch(self) -> BodyScratch:
        """The same row's working values (a handle made when asked: a world of a thousand bodies
        is built and gathered without one)."""
        return BodyScratch(self._row)

    @classmethod
    def dynamic(cls, x: float, y: float, mass: float, inertia: float, **state: float) -> Body:
        return cls(x=x, y=y, mass=mass, inertia=inertia, inv_mass=1.0 / mass,
                   inv_inertia=1.0 / inertia if inertia > 0.0 else 0.0, **state)

    @property
    def asleep(self) -> bool:
        return self._row.item(ASLEEP) != 0.0

    @asleep.setter
    def asleep(self, value: bool) -> None:
        self._row[ASLEEP] = bool(value)

    @property
    def is_dynamic(self) -> bool:
        return self.inv_mass > 0.0

    def motion(self) -> list[float]:
        """x, y, angle, vx, vy, spin, mass, inertia, inv_mass, inv_inertia: one read for a caller that
        wants several (a fan's shots read them for a thousand balls)."""
        return self._row[:INV_INERTIA + 1].tolist()

    def push(self, dvx: float, dvy: float, dspin: float) -> None:
        """Wake it and add this velocity (a shot)."""
        row = self._row
        vx, vy, spin = row[VX:SPIN + 1].tolist()
        row[VX:SPIN + 1] = vx + dvx, vy + dvy, spin + dspin
        self.wake()

    def kinetic_energy(self) -> float:
        x, y, angle, vx, vy, spin, mass, inertia, inv_mass = self._row[:INV_MASS + 1].tolist()
        return 0.5 * (mass * (vx * vx + vy * vy) + inertia * spin * spin) if inv_mass > 0.0 else 0.0

    def mark_start(self) -> None:
        """The pose now is where this substep's motion starts."""
        self._row[X0:ANGLE0 + 1] = self._row[X:ANGLE + 1]

    def wake(self) -> None:
        self._row[ASLEEP] = 0.0
        self._row[STILL_TIME] = 0.0

    def rest(self) -> None:
        """Put to rest where it is: no velocity, no motion owed."""
        self._row[ASLEEP] = 1.0
        self._row[VX:SPIN + 1] = 0.0
        self.mark_start()

    def __repr__(self) -> str:
        return f"Body({', '.join(f'{name}={value!r}' for name, value in zip(COLUMNS, self._row.tolist()))})"


class BodyStore:
    """The bodies of one world as one array (`state`, a row a body, `COLUMNS`), in the order of
    esper's list of bodies; gathered again only when that list changes (a body added or taken
    away). Handles of bodies that leave keep their last values in the array left behind."""

    __slots__ = ("_bodies", "state", "rows", "lookup")

    def __init__(self) -> None:
        self._bodies: list | None = None
        self.state = np.zeros((0, len(COLUMNS)))
        self.rows: dict[int, int] = {}  # entity -> row
        self.lookup = np.zeros(0, dtype=np.int64)  # the same as an array (-1: no row), for kernels

    def gather(self, bodies: Sequence[tuple[int, Body]]) -> np.ndarray:
        """The state array for `esper.get_component(Body)`, rows in that list's order."""
        if bodies is not self._bodies:
            state = np.array([body._row for _, body in bodies], dtype=np.float64).reshape(-1, len(COLUMNS))
            for k, (_, body) in enumerate(bodies):
                body._point(state[k])
            self.state, self.rows, self._bodies = state, {ent: k for k, (ent, _) in enumerate(bodies)}, bodies
            ents = np.array([ent for ent, _ in bodies], dtype=np.int64)
            self.lookup = np.full(int(ents.max(initial=-1)) + 1, -1, dtype=np.int64)
            self.lookup[ents] = np.arange(len(ents))
        return self.state

    def handle(self, row: int) -> Body:
        """The body whose row this is."""
        return self._bodies[row][1]

    @property
    def bodies(self) -> list[Body]:
        """Every body, row by row."""
        return [body for _, body in self._bodies or ()]


class Selection:
    """The rows (in a `BodyStore`) of the bodies an esper query found, e.g. those with a `Drag`;
    worked out again only when esper's list or the store's array changes."""

    __slots__ = ("_found", "_state", "rows")

    def __init__(self) -> None:
        self._found: list | None = None
        self._state: np.ndarray | None = None
        self.rows = np.zeros(0, dtype=np.int64)

    def of(self, store: BodyStore, found: Sequence[tuple[int, object]]) -> np.ndarray:
        if found is not self._found or store.state is not self._state:
            self.rows = np.array([store.rows[ent] for ent, _ in found], dtype=np.int64)
            self._found, self._state = found, store.state
        return self.rows
