from dataclasses import dataclass


@dataclass(slots=True)
class Ball:
    """Marks the player's ball; remembers where it last came to rest (for hazards that put it back)
    and whether it has dropped into the cup (then nothing touches it again)."""

    rest_x: float
    rest_y: float
    holed: bool = False
