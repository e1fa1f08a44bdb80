"""Game time at any frame rate (Fiedler, "Fix Your Timestep!"): the physics always advances whole fixed
frames; the time left over between them decides how far between the last two poses a body is drawn.

Plain Python, no arcade: the play view owns one `FixedStep` and one `Poses` per drawn body.
"""

from __future__ import annotations

import math

from polygolf.engine.physics.settings import FRAME_DT

MAX_CATCH_UP = 0.25  # seconds: a longer frame (a stall, a dragged window) is cut to this; the game slows
# rather than spiralling into ever longer catch-ups
TELEPORT = 1.0  # metres in one frame: faster than any shot, so it was put there (water), not moved
Pose = tuple[float, float, float]  # x, y, angle


class FixedStep:
    """The accumulator: real seconds in, whole physics frames out."""

    def __init__(self, frame: float = FRAME_DT, max_catch_up: float = MAX_CATCH_UP) -> None:
        self.frame = frame
        self.max_catch_up = max_catch_up
        self.accumulator = 0.0
        self.frames = 0  # stepped so far

    def advance(self, seconds: float) -> int:
        """Add a frame's real time; how many physics frames to step now."""
        self.accumulator += min(max(seconds, 0.0), self.max_catch_up)
        due = 0
        # A hair of slack so 1/20 + 1/20 + 1/20 is three 1/60 frames despite rounding.
        while self.accumulator >= self.frame - 1e-9:
            self.accumulator = max(0.0, self.accumulator - self.frame)
            due += 1
        self.frames += due
        return due

    @property
    def alpha(self) -> float:
        """How far the present is between the last physics frame and the next: 0 to 1."""
        return min(1.0, self.accumulator / self.frame)


def blend(before: Pose, after: Pose, alpha: float) -> Pose:
    """The pose `alpha` of the way from `before` to `after`; the turn takes the short way round, and
    a jump (the ball put back after water) is not smeared across the course."""
    if math.hypot(after[0] - before[0], after[1] - before[1]) > TELEPORT:
        return after
    turn = math.remainder(after[2] - before[2], math.tau)
    return (before[0] + (after[0] - before[0]) * alpha, before[1] + (after[1] - before[1]) * alpha,
            before[2] + turn * alpha)


class Poses:
    """The previous and the current pose of one drawn body."""

    def __init__(self, pose: Pose) -> None:
        self.previous = self.current = pose

    def moved_to(self, pose: Pose) -> None:
        self.previous, self.current = self.current, pose

    def at(self, alpha: float) -> Pose:
        return blend(self.previous, self.current, alpha)
