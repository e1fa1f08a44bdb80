from dataclasses import dataclass


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
    still_time: float = 0.0  # seconds spent below the rest thresholds
    # Pose at the start of the substep, for continuous collision.
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

    def __post_init__(self) -> None:
        self.x0, self.y0, self.angle0 = self.x, self.y, self.angle

    @classmethod
    def dynamic(cls, x: float, y: float, mass: float, inertia: float, **state: float) -> "Body":
        return cls(x=x, y=y, mass=mass, inertia=inertia, inv_mass=1.0 / mass,
                   inv_inertia=1.0 / inertia if inertia > 0.0 else 0.0, **state)

    @property
    def is_dynamic(self) -> bool:
        return self.inv_mass > 0.0

    def kinetic_energy(self) -> float:
        return 0.5 * (self.mass * (self.vx * self.vx + self.vy * self.vy) + self.inertia * self.spin * self.spin) \
            if self.inv_mass > 0.0 else 0.0

    def wake(self) -> None:
        self.asleep = False
        self.still_time = 0.0
