from dataclasses import dataclass


@dataclass(slots=True)
class HoleState:
    """Strokes on the hole being played; the scoring system keeps it."""

    par: int
    max_strokes: int
    strokes: int = 0  # shots taken
    penalties: int = 0  # strokes added by hazards
    holed: bool = False
    picked_up: bool = False  # out of strokes: the ball is picked up

    @property
    def finished(self) -> bool:
        return self.holed or self.picked_up

    @property
    def score(self) -> int:
        """Strokes and penalties, at most `max_strokes`: a ball is picked up there, so a last stroke
        into the water (or a restart while it rolls) does not score beyond it."""
        return min(self.strokes + self.penalties, self.max_strokes)
