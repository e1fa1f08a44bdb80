"""Which area of a kind (sand, ice, a slope, water) each ball is on: the areas of an esper query packed
once for `geometry.first_area`, packed again only when esper's list changes."""

from __future__ import annotations

import numpy as np

from polygolf.engine.physics.geometry import Areas, first_area


class AreaIndex:
    """`under(state, rows, found)`: for `found` = esper.get_components(Region, Kind), the index in it of
    the first area under each awake body of `rows`, or -1."""

    def __init__(self) -> None:
        self._found: list | None = None
        self.areas = Areas.of([], [])

    def under(self, state: np.ndarray, rows: np.ndarray, found: list) -> np.ndarray:
        if found is not self._found:
            self.areas = Areas.of([region.outline for _, (region, _) in found],
                                  [region.aabb for _, (region, _) in found])
            self._found = found
        out = np.empty(len(rows), dtype=np.int64)
        if len(found):
            first_area(state, rows, self.areas.verts, self.areas.first, self.areas.boxes, out)
        else:
            out[:] = -1
        return out
