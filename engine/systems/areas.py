"""Which area of a kind (sand, ice, a slope, water) each ball is on: the areas of an esper query packed
once for `geometry.first_area`, packed again only when esper's list changes."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from polygolf.engine.physics.geometry import Areas, first_area


class AreaIndex:
    """`under(state, rows, found)`: for `found` = esper.get_components(Region, Kind), the index in it of
    the first area under each awake body of `rows`, or -1; None when no body is on one (the usual
    case, told without looking at the answer)."""

    def __init__(self, value: Callable[[object], float | tuple[float, ...]] = lambda kind: 0.0) -> None:
        self._found: list | None = None
        self._value = value
        self.areas = Areas.of([], [])
        self.values = np.zeros(0)  # value(kind) of each area, packed with them: a slope's push, a surface's scale
        self._out = np.zeros(0, dtype=np.int64)

    def under(self, state: np.ndarray, rows: np.ndarray, found: list) -> np.ndarray | None:
        if found is not self._found:
            self.areas = Areas.of([region.outline for _, (region, _) in found],
                                  [region.aabb for _, (region, _) in found])
            self.values = np.array([self._value(kind) for _, (_, kind) in found], dtype=np.float64)
            self._found = found
        if len(self._out) != len(rows):
            self._out = np.empty(len(rows), dtype=np.int64)
        if not first_area(state, rows, self.areas.verts, self.areas.first, self.areas.boxes, self._out):
            return None
        return self._out
