"""A hole's geometry from its tiles: walls, obstacles and hazards in metres, the tee, the cup, and the
way through the tiles. Computed once per hole (`golf.holes.Hole.layout`) and kept."""

from __future__ import annotations

import math
from collections import defaultdict, deque
from dataclasses import dataclass, field

from polygolf.engine.components import Material
from polygolf.engine.loading.course import OPPOSITE, SIDES, STEP, Gate, HoleSpec, TileLibrary, TilePlacement
from polygolf.engine.physics import polygon

Rect = tuple[float, float, float, float]


@dataclass(slots=True)
class HoleLayout:
    """World geometry of a hole, in metres: what the renderer draws and the physics collides with."""

    tile_size: float
    floor: list[Rect]  # one square per tile
    borders: list[polygon.Outline]  # merged wall boxes along tile sides
    obstacles: list[tuple[polygon.Outline, Material]]  # pattern walls
    tee: tuple[float, float]
    cup: tuple[float, float]
    cup_radius: float
    route: list[tuple[float, float]] = field(default_factory=list)  # tee, openings and tile centres, cup
    bumpers: list[tuple[polygon.Outline, Material, float]] = field(default_factory=list)  # outline, material, kick
    zones: list[tuple[str, polygon.Outline, tuple[float, float]]] = field(default_factory=list)  # kind, outline, push
    windmills: list[tuple[polygon.Outline, tuple[float, float], float]] = field(default_factory=list)
    # windmills: outline about the pivot, pivot, speed (rad/s)
    drops: dict[float, tuple[tuple[float, float], ...]] = field(default_factory=dict, repr=False, compare=False)
    # water's drop spots by ball radius, once worked out (`world.drop_spots`)

    @property
    def bounds(self) -> Rect:
        xs = [r[0] for r in self.floor] + [r[2] for r in self.floor]
        ys = [r[1] for r in self.floor] + [r[3] for r in self.floor]
        return min(xs), min(ys), max(xs), max(ys)

    def wall_outlines(self) -> list[polygon.Outline]:
        """Everything solid that does not move."""
        return self.borders + [o for o, _ in self.obstacles] + [o for o, _, _ in self.bumpers]

    def zone_outlines(self, kind: str) -> list[polygon.Outline]:
        return [outline for k, outline, _ in self.zones if k == kind]


def _segments(side, length: float) -> list[tuple[float, float]]:
    """Walled stretches along a side of the given length."""
    if side == "wall":
        return [(0.0, length)]
    if isinstance(side, Gate):
        edge = max(0.0, (length - side.gate) / 2.0)
        return [(0.0, edge), (length - edge, length)] if edge > 0.0 else []
    return []


def _narrower(a, b):
    if a == "wall" or b == "wall":
        return "wall"
    if isinstance(a, Gate) and isinstance(b, Gate):
        return a if a.gate <= b.gate else b
    return a if isinstance(a, Gate) else b


def pattern_items(tile: TilePlacement, lib: TileLibrary) -> list[tuple]:
    """Each item of the tile's pattern with its outline where the tile puts it (world coordinates)."""
    size = lib.tile_size
    cx, cy = (tile.at[0] + 0.5) * size, (tile.at[1] + 0.5) * size
    turn = math.radians(tile.rotate)
    return [(item, polygon.placed(item.outline(), cx, cy, turn)) for item in lib.patterns[tile.pattern]]


def layout_hole(spec: HoleSpec, lib: TileLibrary) -> HoleLayout:
    size, thick = lib.tile_size, lib.wall_thickness
    placed = {t.at: t for t in spec.tiles}
    floor = [(c * size, r * size, (c + 1) * size, (r + 1) * size) for c, r in (t.at for t in spec.tiles)]

    # Walled stretches per grid line: ("v", x index) or ("h", y index) -> intervals along the line.
    lines: dict[tuple[str, int], list[tuple[float, float]]] = defaultdict(list)
    for tile in spec.tiles:
        c, r = tile.at
        borders = lib.resolve(tile.borders)
        for side in SIDES:
            dx, dy = STEP[side]
            neighbour = placed.get((c + dx, r + dy))
            if neighbour is not None and side in ("w", "s"):
                continue  # a shared side is laid out once, from the tile to its west or south
            kind = getattr(borders, side)
            if neighbour is not None:
                kind = _narrower(kind, getattr(lib.resolve(neighbour.borders), OPPOSITE[side]))
            if side in ("e", "w"):
                key, start = ("v", c + (1 if side == "e" else 0)), r * size
            else:
                key, start = ("h", r + (1 if side == "n" else 0)), c * size
            lines[key].extend((start + a, start + b) for a, b in _segments(kind, size))

    borders: list[polygon.Outline] = []
    half = thick / 2.0
    for (orientation, index), intervals in sorted(lines.items()):
        for a, b in _merge(intervals):
            # Ends on a tile corner reach past it so walls meeting there close the corner; the ends
            # at a gate stay put so the gate keeps its width.
            a -= half if _on_grid(a, size) else 0.0
            b += half if _on_grid(b, size) else 0.0
            at = index * size
            if orientation == "v":
                box = ((at - half, a), (at + half, a), (at + half, b), (at - half, b))
            else:
                box = ((a, at - half), (b, at - half), (b, at + half), (a, at + half))
            borders.append(box)

    obstacles, bumpers, zones, windmills = [], [], [], []
    for tile in spec.tiles:
        turn = math.radians(tile.rotate)
        c, s = math.cos(turn), math.sin(turn)
        for item, outline in pattern_items(tile, lib):
            material = Material(item.restitution, item.friction)
            if item.hazard == "wall":
                obstacles.append((outline, material))
            elif item.hazard == "bumper":
                bumpers.append((outline, material, item.kick))
            elif item.hazard == "windmill":
                local, pivot = polygon.about_centroid(outline)  # (checked on its tile by the library)
                windmills.append((local, pivot, item.speed))
            else:
                push = (0.0, 0.0)
                if item.push is not None:
                    push = (c * item.push[0] - s * item.push[1], s * item.push[0] + c * item.push[1])
                zones.append((item.hazard, outline, push))

    first, last = spec.tiles[0].at, spec.tiles[-1].at
    tee = ((first[0] + 0.5) * size, (first[1] + 0.5) * size)
    cup = ((last[0] + 0.5) * size, (last[1] + 0.5) * size)
    layout = HoleLayout(tile_size=size, floor=floor, borders=borders, obstacles=obstacles, tee=tee, cup=cup,
                        cup_radius=lib.cup.radius, bumpers=bumpers, zones=zones, windmills=windmills)
    layout.route = _route(spec, lib, tee, cup)
    return layout


def _merge(intervals: list[tuple[float, float]]) -> list[tuple[float, float]]:
    out: list[list[float]] = []
    for a, b in sorted(intervals):
        if out and a <= out[-1][1] + 1e-9:
            out[-1][1] = max(out[-1][1], b)
        else:
            out.append([a, b])
    return [(a, b) for a, b in out if b - a > 1e-9]


def _on_grid(value: float, size: float) -> bool:
    return abs(value / size - round(value / size)) < 1e-9


TileStep = tuple[tuple[int, int], str, tuple[int, int]]  # (tile, side crossed, next tile)


def tile_path(spec: HoleSpec, lib: TileLibrary) -> list[TileStep] | None:
    """Fewest tiles from the tee's to the cup's through open borders (breadth first), or None."""
    index = {t.at: t for t in spec.tiles}
    start, goal = spec.tiles[0].at, spec.tiles[-1].at
    came: dict[tuple[int, int], tuple[tuple[int, int], str] | None] = {start: None}
    queue = deque([start])
    while queue:
        at = queue.popleft()
        if at == goal:
            break
        for side in SIDES:
            if getattr(lib.resolve(index[at].borders), side) == "wall":
                continue
            nxt = (at[0] + STEP[side][0], at[1] + STEP[side][1])
            if nxt in index and nxt not in came:
                came[nxt] = (at, side)
                queue.append(nxt)
    if goal not in came:
        return None
    steps: list[TileStep] = []
    at = goal
    while came[at] is not None:
        prev, side = came[at]
        steps.append((prev, side, at))
        at = prev
    return steps[::-1]


def _route(spec: HoleSpec, lib: TileLibrary, tee: tuple[float, float],
           cup: tuple[float, float]) -> list[tuple[float, float]]:
    """The way through the tiles: tee, then each opening crossed and tile centre, then cup."""
    steps = tile_path(spec, lib)
    if steps is None:
        return [tee, cup]
    size = lib.tile_size
    points = [tee]
    for prev, side, nxt in steps:
        dx, dy = STEP[side]
        points.append(((prev[0] + 0.5 + 0.5 * dx) * size, (prev[1] + 0.5 + 0.5 * dy) * size))  # the opening
        points.append(((nxt[0] + 0.5) * size, (nxt[1] + 0.5) * size))
    points[-1] = cup
    return points


def point_clearance(layout: HoleLayout, x: float, y: float, outlines: list | None = None) -> float:
    """Distance from a point to the nearest wall or obstacle (0 if inside one)."""
    best = math.inf
    for outline in layout.wall_outlines() if outlines is None else outlines:
        if polygon.contains(outline, x, y):
            return 0.0
        n = len(outline)
        for i in range(n):
            (ax, ay), (bx, by) = outline[i], outline[(i + 1) % n]
            ex, ey = bx - ax, by - ay
            t = max(0.0, min(1.0, ((x - ax) * ex + (y - ay) * ey) / (ex * ex + ey * ey)))
            best = min(best, math.hypot(x - ax - t * ex, y - ay - t * ey))
    return best


def ball_fits(layout: HoleLayout, x: float, y: float, radius: float) -> bool:
    """Whether a ball of `radius` can rest at (x, y): on the green, clear of every wall and obstacle,
    out of the water and out of every windmill's sweep."""
    on_green = any(x0 <= x <= x1 and y0 <= y <= y1 for x0, y0, x1, y1 in layout.floor)
    if not on_green or point_clearance(layout, x, y) < radius:
        return False
    water = layout.zone_outlines("water")
    if water and point_clearance(layout, x, y, water) < radius:
        return False
    return all(math.hypot(x - px, y - py) >= polygon.bounding_radius(outline) + radius
               for outline, (px, py), _ in layout.windmills)


def ball_outline(shape, radius: float) -> polygon.Outline:
    """The player's chosen shape (a scene ShapeSpec) scaled so its farthest vertex is at `radius`."""
    outline = shape.outline()
    scale = radius / polygon.bounding_radius(outline)
    return tuple((x * scale, y * scale) for x, y in outline)
