"""A rigid body's simulated state, kept apart from the solver's scratch (as Box2D v3 keeps b2BodySim
apart from b2BodyState): what a body *is* and where it is on one side, what a substep leaves behind
for the next stage on the other."""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(slots=True)
class Material:
    """Contact coefficients; a contact uses the product of both sides' values."""

    restitution: float = 1.0
    friction: float = 1.0


@dataclass(slots=True)
class BodyScratch:
    """Working values of one substep's stages; never part of the body's physical state."""

    still_time: float = 0.0  # seconds spent below the rest thresholds
    # Pose at the start of the substep, for continuous collision and rest detection.
    x0: float = 0.0
    y0: float = 0.0
    angle0: float = 0.0
    # Time continuous collision cut from the last substep's motion (s), made up in the next one;
    # and how long the last substep's motion lasted (dt, plus any lag made up).
    lag: float = 0.0
    moved_for: float = 0.0
    # Pseudo-velocities of split-impulse position correction; never part of the kinetic energy.
    push_x: float = 0.0
    push_y: float = 0.0
    push_spin: float = 0.0


@dataclass(slots=True)
class Body:
    """Rigid-body state about the centroid. Static and kinematic bodies have zero inverse mass."""

    x: float
    y: float
    angle: float = 0.0  # radians, counter-clockwise
    vx: float = 0.0
    vy: float = 0.0
    spin: float = 0.0  # rad/s, counter-clockwise
    mass: float = 0.0
    inertia: float = 0.0
    inv_mass: float = 0.0
    inv_inertia: float = 0.0
    asleep: bool = False
    scratch: BodyScratch = field(default_factory=BodyScratch)

    def __post_init__(self) -> None:
        self.mark_start()

    @classmethod
    def dynamic(cls, x: float, y: float, mass: float, inertia: float, **state: float) -> Body:
        return cls(x=x, y=y, mass=mass, inertia=inertia, inv_mass=1.0 / mass,
                   inv_inertia=1.0 / inertia if inertia > 0.0 else 0.0, **state)

    @property
    def is_dynamic(self) -> bool:
        return self.inv_mass > 0.0

    def kinetic_energy(self) -> float:
        return 0.5 * (self.mass * (self.vx * self.vx + self.vy * self.vy) + self.inertia * self.spin * self.spin) \
            if self.inv_mass > 0.0 else 0.0

    def mark_start(self) -> None:
        """The pose now is where this substep's motion starts."""
        self.scratch.x0, self.scratch.y0, self.scratch.angle0 = self.x, self.y, self.angle

    def wake(self) -> None:
        self.asleep = False
        self.scratch.still_time = 0.0

    def rest(self) -> None:
        """Put to rest where it is: no velocity, no motion owed."""
        self.asleep = True
        self.vx = self.vy = self.spin = 0.0
        self.mark_start()
