from dataclasses import dataclass


@dataclass(slots=True)
class ShotInput:
    """A shot asked for by the player: a push at `origin` (a world point on the ball) along `vector`
    (the arrow, in metres). The shot system takes it only while the ball is at rest."""

    origin: tuple[float, float] = (0.0, 0.0)
    vector: tuple[float, float] = (0.0, 0.0)
    pending: bool = False
    accepted: int = 0
    rejected: int = 0

    def request(self, origin: tuple[float, float], vector: tuple[float, float]) -> None:
        self.origin, self.vector, self.pending = origin, vector, True
