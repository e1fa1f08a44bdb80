"""Which area of a kind (sand, ice, a slope, water) each ball is on: the areas of an esper query packed
once for `geometry.first_area`, packed again only when esper's list changes."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from polygolf.engine.physics.geometry import Areas, first_area


class AreaIndex:
    """For `found` = esper.get_components(Region, Kind): the areas packed for `geometry.first_area`,
    with value(kind) of each (a slope's push: `columns` 2; a surface's scale), and the answer's
    array. `inputs` hands these to a stage's kernel; `under` asks here: the index in `found` of
    the first area under each awake body of `rows`, or -1; None when no body is on one (the usual
    case, told without looking at the answer)."""

    def __init__(self, value: Callable[[object], float | tuple[float, ...]] = lambda kind: 0.0,
                 columns: int = 0) -> None:
        self._found: list | None = None
        self._value, self._columns = value, columns
        self.areas = Areas.of([], [])
        self.values = np.zeros((0, columns) if columns else 0)
        self._out = np.zeros(0, dtype=np.int64)

    def inputs(self, rows: np.ndarray, found: list) -> tuple:
        """(rows, the areas' vertices, rows and boxes, their values, the answer's array)."""
        if found is not self._found:
            self.areas = Areas.of([region.outline for _, (region, _) in found],
                                  [region.aabb for _, (region, _) in found])
            values = np.array([self._value(kind) for _, (_, kind) in found], dtype=np.float64)
            self.values = values.reshape(-1, self._columns) if self._columns else values
            self._found = found
        if len(self._out) != len(rows):
            self._out = np.empty(len(rows), dtype=np.int64)
        return rows, self.areas.verts, self.areas.first, self.areas.boxes, self.values, self._out

    def under(self, state: np.ndarray, rows: np.ndarray, found: list) -> np.ndarray | None:
        rows, verts, first, boxes, _, out = self.inputs(rows, found)
        return out if first_area(state, rows, verts, first, boxes, out) else None
