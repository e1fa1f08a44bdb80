from dataclasses import dataclass


@dataclass(slots=True)
class Drag:
    """Resistance to motion.

    `linear` and `angular` are exponential damping rates in 1/s: v(t) = v0·exp(-linear·t).
    `rolling` (m/s²) and `rolling_angular` (rad/s²) are constant decelerations, like a ball rolling
    on a green: they stop a body in finite time, which pure exponential drag never does.
    """

    linear: float = 0.0
    angular: float = 0.0
    rolling: float = 0.0
    rolling_angular: float = 0.0
