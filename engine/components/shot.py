from dataclasses import dataclass
from typing import ClassVar


@dataclass(slots=True)
class ShotInput:
    """A shot asked for by the player: a push at `origin` (a world point on the ball) along `vector`
    (the arrow, in metres). The shot system takes it only while the ball is at rest.

    `ShotInput.requests` counts every shot asked for anywhere, so the shot stage can tell in one
    comparison that nothing new is pending (K balls, no loop)."""

    requests: ClassVar[int] = 0
    origin: tuple[float, float] = (0.0, 0.0)
    vector: tuple[float, float] = (0.0, 0.0)
    pending: bool = False
    accepted: int = 0
    rejected: int = 0

    def __post_init__(self) -> None:
        if self.pending:
            ShotInput.requests += 1

    def request(self, origin: tuple[float, float], vector: tuple[float, float]) -> None:
        self.origin, self.vector, self.pending = origin, vector, True
        ShotInput.requests += 1

    def withdraw(self) -> None:
        """Forget a shot not yet taken (a restart in the same frame: the ball is back on its tee)."""
        self.pending = False
