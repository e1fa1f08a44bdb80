"""A hole, built: tile layout -> wall geometry -> an esper world with the ball, the cup and the rules."""

from __future__ import annotations

import math
from collections import defaultdict, deque
from dataclasses import dataclass, field

import esper

from engine import polygon
from engine.components import (
    Ball,
    Body,
    Bumper,
    Collider,
    Cup,
    Drag,
    HoleState,
    Ice,
    Material,
    Name,
    Region,
    Sand,
    ShotInput,
    Slope,
    Water,
    Windmill,
)
from engine.context import PhysicsContext
from engine.course import OPPOSITE, SIDES, STEP, Gate, Hole
from engine.grid import SpatialGrid
from engine.pipeline import make_body, make_collider, make_wall, new_world, processors_for
from engine.presets import Knobs, preset
from engine.settings import FRAME_DT, MAX_SHOT_SPEED
from engine.simulation import Simulation
from engine.systems.cup import CupProcessor
from engine.systems.launch import LaunchProcessor
from engine.systems.scoring import ScoringProcessor
from engine.systems.shot import ShotProcessor

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


def layout_hole(hole: Hole) -> HoleLayout:
    lib, spec = hole.library, hole.spec
    size, thick = lib.tile_size, lib.wall_thickness
    placed = {t.at: t for t in spec.tiles}
    floor = [(c * size, r * size, (c + 1) * size, (r + 1) * size) for c, r in (t.at for t in spec.tiles)]

    # Walled stretches per grid line: ("v", x index) or ("h", y index) -> intervals along the line.
    lines: dict[tuple[str, int], list[tuple[float, float]]] = defaultdict(list)
    for tile in spec.tiles:
        c, r = tile.at
        borders = lib.border_sets[tile.borders]
        for side in SIDES:
            dx, dy = STEP[side]
            neighbour = placed.get((c + dx, r + dy))
            if neighbour is not None and side in ("w", "s"):
                continue  # a shared side is laid out once, from the tile to its west or south
            kind = getattr(borders, side)
            if neighbour is not None:
                kind = _narrower(kind, getattr(lib.border_sets[neighbour.borders], OPPOSITE[side]))
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
        cx, cy = (tile.at[0] + 0.5) * size, (tile.at[1] + 0.5) * size
        turn = math.radians(tile.rotate)
        c, s = math.cos(turn), math.sin(turn)
        for item in lib.patterns[tile.pattern]:
            outline = tuple((cx + c * x - s * y, cy + s * x + c * y) for x, y in item.outline())
            material = Material(item.restitution, item.friction)
            if item.hazard == "wall":
                obstacles.append((outline, material))
            elif item.hazard == "bumper":
                bumpers.append((outline, material, item.kick))
            elif item.hazard == "windmill":
                local, pivot = polygon.normalise(outline)
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
    layout.route = _route(hole, tee, cup)
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


def _route(hole: Hole, tee: tuple[float, float], cup: tuple[float, float]) -> list[tuple[float, float]]:
    """Shortest way through the tiles: tee, then each opening crossed and tile centre, then cup."""
    lib, spec = hole.library, hole.spec
    size = lib.tile_size
    index = {t.at: t for t in spec.tiles}
    start, goal = spec.tiles[0].at, spec.tiles[-1].at
    came: dict[tuple[int, int], tuple[tuple[int, int], str] | None] = {start: None}
    queue = deque([start])
    while queue:
        at = queue.popleft()
        if at == goal:
            break
        for side in SIDES:
            if getattr(lib.border_sets[index[at].borders], side) == "wall":
                continue
            nxt = (at[0] + STEP[side][0], at[1] + STEP[side][1])
            if nxt in index and nxt not in came:
                came[nxt] = (at, side)
                queue.append(nxt)
    if goal not in came:
        return [tee, cup]
    steps = []
    at = goal
    while came[at] is not None:
        prev, side = came[at]
        steps.append((prev, side, at))
        at = prev
    points = [tee]
    for prev, side, nxt in reversed(steps):
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


def ball_outline(shape, radius: float) -> polygon.Outline:
    """The player's chosen shape (a scene ShapeSpec) scaled so its farthest vertex is at `radius`."""
    outline = shape.outline()
    scale = radius / polygon.bounding_radius(outline)
    return tuple((x * scale, y * scale) for x, y in outline)


def hole_effects(hole: Hole, layout: HoleLayout | None = None) -> dict[str, str]:
    """Effect -> why the hole needs it. The game's own (shot, cup, scoring) are always there; the
    rest are the hole's `effects` list if it has one, else what its content needs."""
    lib, spec = hole.library, hole.spec
    layout = layout or layout_hole(hole)
    green = spec.green or lib.green
    reasons = {"shot": "the player shoots", "cup": "the ball can drop into the cup",
               "scoring": f"par {spec.par}, picked up after {spec.max_strokes or lib.max_strokes} strokes"}
    derived: dict[str, str] = {}
    if green.any:
        derived["drag"] = f"the green slows the ball (linear {green.linear:g}/s, rolling {green.rolling:g} m/s²)"
    derived["spin"] = "a contact off the centre of mass turns a polygon"
    walls = [Material()] + [m for _, m in layout.obstacles] + [m for _, m, _ in layout.bumpers]
    best_e = max(lib.ball.restitution * m.restitution for m in walls)
    if best_e > 0:
        derived["restitution"] = (f"ball restitution {lib.ball.restitution:g} x walls up to "
                                  f"{best_e / lib.ball.restitution:g}")
    best_f = max(lib.ball.friction * m.friction for m in walls)
    if best_f > 0:
        derived["friction"] = f"ball friction {lib.ball.friction:g} x walls up to {best_f / lib.ball.friction:g}"
    derived["ccd"] = (f"a shot moves up to {MAX_SHOT_SPEED * FRAME_DT / 4:.2g} m a substep; "
                      f"walls are {lib.wall_thickness:g} m thick")
    counts = {kind: sum(1 for k, _, _ in layout.zones if k == kind) for kind in ("sand", "water", "ice", "slope")}
    words = {"sand": "bunker", "water": "pond", "ice": "ice sheet", "slope": "slope"}
    for kind, count in counts.items():
        if count:
            derived[kind] = f"{count} {words[kind]}{'s' if count > 1 else ''}"
    if layout.bumpers:
        derived["bumper"] = f"{len(layout.bumpers)} bumper{'s' if len(layout.bumpers) > 1 else ''}"
    if layout.windmills:
        derived["windmill"] = f"{len(layout.windmills)} windmill{'s' if len(layout.windmills) > 1 else ''}"
    if spec.launch is not None:
        derived["launch"] = f"collision test: the ball is launched every {spec.launch.every:g} s"
    if spec.effects is not None:
        derived = {e: "listed by the hole" + (f" ({derived[e]})" if e in derived else "") for e in spec.effects}
    return {**reasons, **derived}


class HoleWorld:
    """One hole being played: an esper world holding the ball, walls, hazards, cup and the hole's
    state, with only the processors the hole needs. The front end writes `shoot()` and reads the rest."""

    def __init__(self, hole: Hole, shape, knobs: Knobs | str = "balanced") -> None:
        lib, spec = hole.library, hole.spec
        knobs = preset(knobs) if isinstance(knobs, str) else knobs
        self.hole = hole
        self.layout = layout = layout_hole(hole)
        self.reasons = hole_effects(hole, layout)
        rotates = "spin" in self.reasons

        world = new_world(f"hole-{hole.id}")
        self.outline = ball_outline(shape, lib.ball.radius)
        self.ball = make_body(self.outline, layout.tee, lib.ball.density, rotates=rotates)
        self.ball.asleep = spec.launch is None
        self.collider: Collider = make_collider(self.outline, Material(lib.ball.restitution, lib.ball.friction))
        self.shot = ShotInput()
        green = spec.green or lib.green
        components: list[object] = [self.ball, self.collider, Ball(*layout.tee), self.shot, Name("ball")]
        if green.any:
            components.append(Drag(**green.model_dump()))
        self.ball_entity = esper.create_entity(*components)
        self.cup = Cup(layout.cup[0], layout.cup[1], lib.cup.radius, lib.cup.max_speed)
        esper.create_entity(self.cup)
        self.state = HoleState(par=spec.par, max_strokes=spec.max_strokes or lib.max_strokes)
        esper.create_entity(self.state)

        grid = SpatialGrid(lib.tile_size / 2.0)
        self.bumpers: list[Bumper] = []
        solids = [(b, Material(), None) for b in layout.borders] + [(o, m, None) for o, m in layout.obstacles]
        solids += layout.bumpers
        for outline, material, kick in solids:
            wall = make_wall(outline, material)
            parts: list[object] = [wall]
            if kick is not None:
                self.bumpers.append(Bumper(kick))
                parts.append(self.bumpers[-1])
            ent = esper.create_entity(*parts)
            for k, box in enumerate(wall.piece_aabbs):
                grid.insert((ent, k), box)
        marker = {"sand": Sand, "ice": Ice, "water": Water}
        for kind, outline, push in layout.zones:
            xs, ys = zip(*outline)
            region = Region(outline, (min(xs), min(ys), max(xs), max(ys)))
            esper.create_entity(region, Slope(push) if kind == "slope" else marker[kind]())
        self.windmills: list[Body] = []
        for outline, pivot, speed in layout.windmills:
            body = Body(x=pivot[0], y=pivot[1], spin=speed)  # kinematic: no inverse mass or inertia
            self.windmills.append(body)
            esper.create_entity(body, make_collider(outline, Material()), Windmill(speed), Name("windmill"))

        ctx = PhysicsContext(knobs=knobs, effects=frozenset(self.reasons), static_grid=grid)
        procs: list[esper.Processor] = [ShotProcessor(ctx)]
        if "launch" in self.reasons and spec.launch is not None:
            procs.append(LaunchProcessor(ctx, spec.launch.velocity, spec.launch.every, layout.tee))
        procs += processors_for(ctx, self.reasons, contacts=True, has_walls=True, cell_size=lib.tile_size / 2.0)
        procs += [CupProcessor(ctx), ScoringProcessor(ctx)]
        self.sim = Simulation(world, ctx, procs, {self.ball_entity: "ball"}, preset_name=knobs_name(knobs),
                              reasons=self.reasons, scene_name=hole.id)

    # The front end's verbs.
    def shoot(self, origin: tuple[float, float], vector: tuple[float, float]) -> None:
        self.shot.request(origin, vector)

    @property
    def ball_at_rest(self) -> bool:
        return self.ball.asleep

    def step(self, frames: int = 1, profile: bool = False) -> None:
        self.sim.step(frames, measure=False, profile=profile)

    def set_knobs(self, knobs: Knobs) -> None:
        self.sim.ctx.knobs = knobs
        self.sim.preset_name = knobs_name(knobs)

    def close(self) -> None:
        self.sim.close()


def knobs_name(knobs: Knobs) -> str:
    from engine.presets import PRESETS

    return next((name for name, k in PRESETS.items() if k == knobs), "custom")
