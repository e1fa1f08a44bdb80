"""Accuracy knobs and the named presets that set them.

Every preset keeps continuous collision on: a shot at full speed must never pass through a thin
wall, whatever the preset.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

PositionCorrection = Literal["split", "ngs", "none"]
POSITION_CORRECTIONS: tuple[str, ...] = ("split", "ngs", "none")


@dataclass(frozen=True, slots=True)
class Knobs:
    substeps: int = 4  # substeps per 1/60 s frame
    iterations: int = 8  # velocity iterations per substep
    position_iterations: int = 3  # split-impulse or NGS sweeps per substep
    ccd: bool = True  # continuous collision against walls
    position_correction: PositionCorrection = "split"
    warm_start: bool = True

    def __post_init__(self) -> None:
        if not 1 <= self.substeps <= 64:
            raise ValueError(f"substeps must be 1..64, got {self.substeps}")
        if not 1 <= self.iterations <= 100:
            raise ValueError(f"iterations must be 1..100, got {self.iterations}")
        if self.position_correction not in POSITION_CORRECTIONS:
            raise ValueError(f"position_correction must be one of {POSITION_CORRECTIONS}")


# Chosen from the Pareto front of docs/accuracy.md (`polygolf bench accuracy`): each is a point of
# that front. Substeps buy far more than iterations; NGS costs more than split impulses and bought
# nothing the cases could see, so no preset uses it (it stays a knob).
PRESETS: dict[str, Knobs] = {
    "fast": Knobs(substeps=2, iterations=4, position_iterations=3, ccd=True, position_correction="split"),
    "balanced": Knobs(substeps=4, iterations=4, position_iterations=3, ccd=True, position_correction="split"),
    "accurate": Knobs(substeps=16, iterations=4, position_iterations=3, ccd=True, position_correction="split"),
}
DEFAULT_PRESET = "balanced"


def preset(name: str) -> Knobs:
    try:
        return PRESETS[name]
    except KeyError:
        raise ValueError(f"unknown preset {name!r}; choose one of {', '.join(PRESETS)}") from None
