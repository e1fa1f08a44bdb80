from dataclasses import dataclass


@dataclass(slots=True)
class Launcher:
    """The collision test's launcher: the ball leaves `tee` at `velocity` every `every` seconds.
    `clock` starts full, so the first launch is on the first substep."""

    velocity: tuple[float, float]
    every: float
    tee: tuple[float, float]
    clock: float = 0.0
    spots: tuple[tuple[float, float], ...] = ()  # each player's own spot beside the tee, in ball order

    def __post_init__(self) -> None:
        self.clock = self.every
