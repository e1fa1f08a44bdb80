"""Uniform grid of bounding boxes: the broadphase's spatial index.

Each item is filed under every cell its box touches; a query looks only at the cells its own box
touches, so the work grows with the neighbourhood, not with the number of items. Neither can blow
up: an item spanning more than MAX_CELLS cells is kept on a short list that every query checks, and a
query spanning more cells than there are items checks the items instead.
"""

from __future__ import annotations

import math
from collections import defaultdict
from collections.abc import Hashable, Iterator

AABB = tuple[float, float, float, float]  # min x, min y, max x, max y
MAX_CELLS = 256  # cells one item may be filed under


def overlaps(a: AABB, b: AABB) -> bool:
    return a[0] <= b[2] and b[0] <= a[2] and a[1] <= b[3] and b[1] <= a[3]


class SpatialGrid:
    def __init__(self, cell_size: float) -> None:
        if cell_size <= 0.0:
            raise ValueError("cell size must be positive")
        self.cell_size = cell_size
        self._cells: dict[tuple[int, int], list[tuple[Hashable, AABB]]] = defaultdict(list)
        self._large: list[tuple[Hashable, AABB]] = []  # items too big to file cell by cell
        self._items: list[tuple[Hashable, AABB]] = []  # every item once, for a query wider than the items

    def _cell_range(self, box: AABB) -> tuple[int, int, int, int]:
        inv = 1.0 / self.cell_size
        return (math.floor(box[0] * inv), math.floor(box[1] * inv),
                math.floor(box[2] * inv), math.floor(box[3] * inv))

    def insert(self, item: Hashable, box: AABB) -> None:
        self._items.append((item, box))
        x0, y0, x1, y1 = self._cell_range(box)
        if (x1 - x0 + 1) * (y1 - y0 + 1) > MAX_CELLS:
            self._large.append((item, box))
            return
        for cx in range(x0, x1 + 1):
            for cy in range(y0, y1 + 1):
                self._cells[cx, cy].append((item, box))

    def __len__(self) -> int:
        return len(self._items)

    def clear(self) -> None:
        self._cells.clear()
        self._large.clear()
        self._items.clear()

    def query(self, box: AABB) -> list[Hashable]:
        """Items whose boxes overlap `box`, each once."""
        x0, y0, x1, y1 = self._cell_range(box)
        cells = self._cells
        large = [item for item, other in self._large if overlaps(box, other)] if self._large else []
        if x0 == x1 and y0 == y1:
            found = [item for item, other in cells.get((x0, y0), ()) if overlaps(box, other)]
            return found + large if large else found
        if (x1 - x0 + 1) * (y1 - y0 + 1) > len(self._items):  # wider than there are items: each item once
            return [item for item, other in self._items if overlaps(box, other)]
        seen: dict[Hashable, None] = {}
        for cx in range(x0, x1 + 1):
            for cy in range(y0, y1 + 1):
                for item, other in cells.get((cx, cy), ()):
                    if item not in seen and overlaps(box, other):
                        seen[item] = None
        return list(seen) + large if large else list(seen)

    def pairs(self) -> Iterator[tuple[Hashable, Hashable]]:
        """Every pair of items whose boxes overlap, each once, in a stable order."""
        seen: set[tuple[Hashable, Hashable]] = set()
        for item_a, box_a in self._large:
            for item_b in self.query(box_a):
                key = (item_a, item_b) if item_a < item_b else (item_b, item_a)  # type: ignore[operator]
                if item_b != item_a and key not in seen:
                    seen.add(key)
                    yield key
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
