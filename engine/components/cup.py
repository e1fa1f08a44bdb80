from dataclasses import dataclass


@dataclass(slots=True)
class Cup:
    """The hole in the green. A ball drops only if slower than `max_speed` at the centre, a cap that
    falls linearly to zero at the rim: faster balls roll over or lip out."""

    x: float
    y: float
    radius: float
    max_speed: float

    def capture_speed(self, distance: float) -> float:
        """The fastest a ball whose centre is `distance` from the cup's can be and still drop."""
        return self.max_speed * max(0.0, 1.0 - distance / self.radius)
