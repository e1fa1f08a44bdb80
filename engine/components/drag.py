from dataclasses import dataclass


@dataclass(slots=True)
class Drag:
    """Exponential damping rates in 1/s: v(t) = v0·exp(-linear·t), ω(t) = ω0·exp(-angular·t)."""

    linear: float = 0.0
    angular: float = 0.0
