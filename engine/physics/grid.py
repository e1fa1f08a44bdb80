"""Uniform grid of bounding boxes: the broadphase's spatial index.

Each item is filed under every cell its box touches; a query looks only at the cells its own box
touches, so the work grows with the neighbourhood, not with the number of items.
"""

from __future__ import annotations

import math
from collections import defaultdict
from collections.abc import Hashable, Iterator

AABB = tuple[float, float, float, float]  # min x, min y, max x, max y


def overlaps(a: AABB, b: AABB) -> bool:
    return a[0] <= b[2] and b[0] <= a[2] and a[1] <= b[3] and b[1] <= a[3]


class SpatialGrid:
    def __init__(self, cell_size: float) -> None:
        if cell_size <= 0.0:
            raise ValueError("cell size must be positive")
        self.cell_size = cell_size
        self._cells: dict[tuple[int, int], list[tuple[Hashable, AABB]]] = defaultdict(list)

    def _cell_range(self, box: AABB) -> tuple[int, int, int, int]:
        inv = 1.0 / self.cell_size
        return (math.floor(box[0] * inv), math.floor(box[1] * inv),
                math.floor(box[2] * inv), math.floor(box[3] * inv))

    def insert(self, item: Hashable, box: AABB) -> None:
        x0, y0, x1, y1 = self._cell_range(box)
        for cx in range(x0, x1 + 1):
            for cy in range(y0, y1 + 1):
                self._cells[cx, cy].append((item, box))

    def clear(self) -> None:
        self._cells.clear()

    def query(self, box: AABB) -> list[Hashable]:
        """Items whose boxes overlap `box`, each once."""
        x0, y0, x1, y1 = self._cell_range(box)
        cells = self._cells
        if x0 == x1 and y0 == y1:
            return [item for item, other in cells.get((x0, y0), ()) if overlaps(box, other)]
        seen: dict[Hashable, None] = {}
        for cx in range(x0, x1 + 1):
            for cy in range(y0, y1 + 1):
                for item, other in cells.get((cx, cy), ()):
                    if item not in seen and overlaps(box, other):
                        seen[item] = None
        return list(seen)

    def pairs(self) -> Iterator[tuple[Hashable, Hashable]]:
        """Every pair of items whose boxes overlap, each once, in a stable order."""
        seen: set[tuple[Hashable, Hashable]] = set()
        for members in self._cells.values():
            count = len(members)
            for i in range(count):
                item_a, box_a = members[i]
                for j in range(i + 1, count):
                    item_b, box_b = members[j]
                    if not overlaps(box_a, box_b):
                        continue
                    key = (item_a, item_b) if item_a < item_b else (item_b, item_a)  # type: ignore[operator]
                    if key not in seen:
                        seen.add(key)
                        yield key
