"""Procedural holes: a self-avoiding walk of tiles from the tee to the cup, patterns placed by rules,
each candidate written and loaded like any hole file, then (for `polygolf generate` and Random nine)
proven by the search golfer.

Why rules and checks rather than free choice: a random hole is only fun if it is fair. So the tee and
cup tiles get nothing or something light that keeps their centre clear; obstacles and hazards go on
the tiles between; a hole has at most one windmill and a few of each other hazard; slopes point along
the walk or across it; and every tile must leave the ball a dry way from where it comes in to where it
goes out (checked on a grid against the walls and water, windmills left out since the ball can time
them), which is what "water only where the ball can get round it" means. Borders are written out from
the walk, so two tiles that happen to touch without being neighbours on the walk stay walled off: the
walk is the way.

Determinism: every choice comes from `random.Random` seeded with the text "seed:number:draw" (a text
seed is hashed with SHA-512, not Python's salted hash), so a seed names a hole on any machine: the same
seed gives byte-identical text. A draw that fails a check (or that the golfer cannot sink) is followed
by the next draw, a bounded number of times, then `GenerateError`.
"""

from __future__ import annotations

import math
import os
import random
import time
from collections import Counter, deque
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from polygolf.engine.golf.holes import Hole, load_hole
from polygolf.engine.golf.layout import HoleLayout, layout_hole
from polygolf.engine.golf.search import HoleProof, prove_hole
from polygolf.engine.loading.course import (
    OPPOSITE,
    SIDES,
    STEP,
    BorderSet,
    Gate,
    HoleSpec,
    PatternItem,
    TileLibrary,
    TilePlacement,
)
from polygolf.engine.loading.paths import CONTENT_DIR
from polygolf.engine.loading.yamlsource import ContentError
from polygolf.engine.physics import polygon

SCHEMA_REF = "../schemas/hole.schema.json"  # as the shipped holes have it
TILE_COUNTS = (3, 4, 5, 6, 7)
TILE_COUNT_WEIGHTS = (2, 3, 3, 2, 1)  # walks of 4 and 5 tiles most often
MAX_DRAWS = 40  # candidates drawn (each cheap) before giving up on a seed
MAX_PROOFS = 6  # of those, how many the golfer may try (each costs seconds)
TILE_TRIES = 8  # pattern draws for one tile before it is left empty
LIGHT_CLEARANCE = 1.2  # m from the tile's centre to anything in a "light" pattern (tee and cup tiles)
GATE_CHANCE = 0.2  # a middle tile of walls, sand or nothing gets gated borders this often
STRAIGHT_ON = 2.0  # the walk's weight for going on straight, against 1 for each turn
GRID = 0.2  # m between the dry-route check's sample points
# Middle tiles: how often each kind of pattern is drawn, and how many tiles of a kind a hole may have.
CATEGORY_WEIGHTS = {"empty": 1.0, "walls": 3.0, "sand": 1.2, "water": 1.0, "ice": 0.6, "slope": 1.0,
                    "bumper": 0.8, "windmill": 0.8}
CATEGORY_LIMITS = {"walls": 7, "empty": 7, "sand": 2, "water": 2, "ice": 2, "slope": 2, "bumper": 2, "windmill": 1}
HARD = ("water", "windmill")  # a hole with one of these gets a stroke more of placeholder par
SLOPE_AIMS = {"down": 3.0, "across": 2.0, "up": 1.0}  # down: the way the ball goes; up: back toward the tee


class GenerateError(ValueError):
    """No acceptable hole came of a seed within the bounded draws; str() says why in one line."""


# --- the library, sorted into kinds -----------------------------------------------------------------

@dataclass(frozen=True, slots=True)
class PatternInfo:
    """What a pattern holds, for the placing rules."""

    name: str
    kinds: frozenset[str]  # the hazards in it ("sand", "water", ...), "wall" for plain walls
    clearance: float  # m from the tile's centre to its nearest item (inf: empty)
    push: tuple[float, float] | None  # a slope's push in tile coordinates

    @property
    def category(self) -> str:
        """The one kind a pattern counts as: its most demanding hazard, else walls, else empty."""
        for kind in ("windmill", "water", "slope", "ice", "bumper", "sand"):
            if kind in self.kinds:
                return kind
        return "walls" if self.kinds else "empty"

    @property
    def light(self) -> bool:
        """Fit for the tee's or the cup's tile: only walls or sand, all well clear of the centre."""
        return self.kinds <= {"wall", "sand"} and self.clearance >= LIGHT_CLEARANCE


def _clearance(outline: list[tuple[float, float]], x: float = 0.0, y: float = 0.0) -> float:
    if polygon.contains(outline, x, y):
        return 0.0
    best = math.inf
    for i in range(len(outline)):
        (ax, ay), (bx, by) = outline[i], outline[(i + 1) % len(outline)]
        ex, ey = bx - ax, by - ay
        t = max(0.0, min(1.0, ((x - ax) * ex + (y - ay) * ey) / (ex * ex + ey * ey)))
        best = min(best, math.hypot(x - ax - t * ex, y - ay - t * ey))
    return best


def pattern_info(name: str, items: list[PatternItem]) -> PatternInfo:
    push = next((item.push for item in items if item.hazard == "slope"), None)
    return PatternInfo(name, frozenset(item.hazard for item in items),
                       min((_clearance(item.outline()) for item in items), default=math.inf), push)


def sort_patterns(library: TileLibrary) -> dict[str, list[PatternInfo]]:
    """The library's patterns by category, in the library's order (so draws do not depend on hashing)."""
    out: dict[str, list[PatternInfo]] = {}
    for name, items in library.patterns.items():
        info = pattern_info(name, items)
        out.setdefault(info.category, []).append(info)
    return out


# --- a drawn hole -----------------------------------------------------------------------------------

@dataclass(slots=True)
class PlannedTile:
    at: tuple[int, int]
    sides: tuple[str, ...]  # the sides the walk crosses, in n, e, s, w order
    borders: str | BorderSet  # a library border set's name, or inline sides
    pattern: str = "empty"
    rotate: int = 0
    category: str = "empty"


@dataclass(slots=True)
class HolePlan:
    """One draw: the tiles in walk order (tee first, cup last), and a par to write until one is proven."""

    seed: int
    number: int
    draw: int
    tiles: list[PlannedTile]
    par: int

    @property
    def name(self) -> str:
        return f"Random {self.seed}-{self.number}"

    def text(self, par: int | None = None, schema: str = SCHEMA_REF, proven: bool = False) -> str:
        """The hole file, in the shipped holes' style (defaults left out, one tile a line)."""
        par = self.par if par is None else par
        how = "par estimated by the search golfer" if proven else "par a placeholder (not proven)"
        lines = [f"# yaml-language-server: $schema={schema}",
                 f"# Generated: seed {self.seed}, hole {self.number}, draw {self.draw}; {how}.",
                 "# Borders follow the walk from tee to cup; tiles that merely touch stay walled off.",
                 f"name: {self.name}",
                 f"par: {par}",
                 "tiles:                 # [column, row]; the first tile holds the tee, the last the cup"]
        for tile in self.tiles:
            parts = [f"at: [{tile.at[0]}, {tile.at[1]}]", f"borders: {_borders_text(tile.borders)}"]
            if tile.pattern != "empty":
                parts.append(f"pattern: {tile.pattern}")
            if tile.rotate:
                parts.append(f"rotate: {tile.rotate}")
            lines.append(f"  - {{{', '.join(parts)}}}")
        return "\n".join(lines) + "\n"


def _borders_text(borders: str | BorderSet) -> str:
    if isinstance(borders, str):
        return borders
    sides = []
    for side in SIDES:
        value = getattr(borders, side)
        if value != "wall":
            sides.append(f"{side}: {{gate: {value.gate:g}}}" if isinstance(value, Gate) else f"{side}: open")
    return "{" + ", ".join(sides) + "}"


def _weighted(rng: random.Random, options: list, weights: list[float]):
    return rng.choices(options, weights=weights, k=1)[0]


def random_walk(rng: random.Random, length: int) -> list[tuple[int, int]]:
    """A self-avoiding walk of `length` tiles that prefers going straight on, shifted so its columns
    and rows start at 0. (A walk this short cannot trap itself; a longer one that does starts over.)"""
    while True:
        path = [(0, 0)]
        heading = rng.choice(SIDES)
        while len(path) < length:
            options = [side for side in SIDES if _next(path[-1], side) not in path]
            if not options:
                break
            heading = _weighted(rng, options, [STRAIGHT_ON if side == heading else 1.0 for side in options])
            path.append(_next(path[-1], heading))
        if len(path) == length:
            c0, r0 = min(c for c, _ in path), min(r for _, r in path)
            return [(c - c0, r - r0) for c, r in path]


def _next(at: tuple[int, int], side: str) -> tuple[int, int]:
    return at[0] + STEP[side][0], at[1] + STEP[side][1]


def _side_towards(a: tuple[int, int], b: tuple[int, int]) -> str:
    return next(side for side in SIDES if _next(a, side) == b)


def _border_choices(library: TileLibrary, sides: tuple[str, ...]) -> tuple[str | BorderSet, list[str]]:
    """The plain border set for a tile the walk crosses at `sides` (by name if the library has it,
    else inline), and the library's gated sets for the same sides."""
    plain: str | BorderSet = BorderSet(**{side: "open" for side in sides})
    gated = []
    for name, borders in library.border_sets.items():
        values = {side: getattr(borders, side) for side in SIDES}
        if {side for side, v in values.items() if v != "wall"} != set(sides):
            continue
        if all(values[side] == "open" for side in sides):
            if not isinstance(plain, str):
                plain = name
        elif all(values[side] == "open" or isinstance(values[side], Gate) for side in sides):
            gated.append(name)
    return plain, gated


def _slope_rotation(rng: random.Random, push: tuple[float, float], entry: str | None, exit_: str | None) -> int:
    """A rotation that turns the slope's push down the walk (the way the ball travels), across it, or
    up it (back toward the tee)."""
    travel = [side for side in ((OPPOSITE[entry] if entry else None), exit_) if side]
    down = sorted(set(travel), key=SIDES.index)
    up = sorted({OPPOSITE[side] for side in travel}, key=SIDES.index)
    across = [side for side in SIDES if side not in down and side not in up]
    aims = [(kind, sides) for kind, sides in (("down", down), ("across", across), ("up", up)) if sides]
    _kind, sides = _weighted(rng, aims, [SLOPE_AIMS[k] for k, _ in aims])
    side = rng.choice(sides)
    target = math.degrees(math.atan2(STEP[side][1], STEP[side][0]))
    return round((target - math.degrees(math.atan2(push[1], push[0]))) / 90.0) % 4 * 90


def plan_hole(seed: int, library: TileLibrary, number: int = 1, draw: int = 0) -> HolePlan:
    """One draw of a hole: the walk, then each tile's pattern, rotation and borders by the rules."""
    rng = random.Random(f"polygolf-hole:{seed}:{number}:{draw}")
    kinds = sort_patterns(library)
    light = [info for infos in kinds.values() for info in infos if info.light and info.category != "empty"]
    cells = random_walk(rng, _weighted(rng, list(TILE_COUNTS), list(TILE_COUNT_WEIGHTS)))
    used: Counter[str] = Counter()
    tiles: list[PlannedTile] = []
    for i, at in enumerate(cells):
        entry = _side_towards(at, cells[i - 1]) if i > 0 else None
        exit_ = _side_towards(at, cells[i + 1]) if i < len(cells) - 1 else None
        sides = tuple(side for side in SIDES if side in (entry, exit_))
        plain, gated = _border_choices(library, sides)
        tile = PlannedTile(at, sides, plain)
        for _ in range(TILE_TRIES):
            if entry is None or exit_ is None:  # the tee's or the cup's tile: empty mostly, else light
                info = rng.choice(light) if light and rng.random() < 0.3 else None
            else:
                open_ = [c for c in CATEGORY_WEIGHTS if c in kinds and used[c] < CATEGORY_LIMITS[c]]
                info = rng.choice(kinds[_weighted(rng, open_, [CATEGORY_WEIGHTS[c] for c in open_])])
            if info is None or info.category == "empty":
                tile.pattern, tile.rotate, tile.category = "empty", 0, "empty"
            elif info.push is not None:
                tile.pattern, tile.category = info.name, info.category
                tile.rotate = _slope_rotation(rng, info.push, entry, exit_)
            else:
                tile.pattern, tile.category = info.name, info.category
                tile.rotate = rng.choice((0, 90, 180, 270))
            tile.borders = plain
            if gated and tile.category in ("empty", "walls", "sand") and rng.random() < GATE_CHANCE:
                tile.borders = rng.choice(gated)
            if tile_passable(tile, library, entry, exit_):
                break
        else:
            tile.pattern, tile.rotate, tile.category, tile.borders = "empty", 0, "empty", plain
        used[tile.category] += 1
        tiles.append(tile)
    hard = any(t.category in HARD for t in tiles)
    par = min(20, 1 + math.ceil(len(tiles) / 2) + hard)
    return HolePlan(seed, number, draw, tiles, par)


# --- the dry-route check ----------------------------------------------------------------------------

def _spec(tiles: list[PlannedTile]) -> HoleSpec:
    return HoleSpec(name="candidate", par=3, tiles=[TilePlacement(at=t.at, borders=t.borders, pattern=t.pattern,
                                                                  rotate=t.rotate) for t in tiles])


def tile_passable(tile: PlannedTile, library: TileLibrary, entry: str | None, exit_: str | None) -> bool:
    """Whether a ball can get through this tile alone, from where the walk comes in (or the tee) to
    where it goes out (or the cup), without touching a wall or water."""
    layout = layout_hole(_spec([PlannedTile((0, 0), tile.sides, tile.borders, tile.pattern, tile.rotate)]), library)
    size = library.tile_size
    inset = library.ball.radius + GRID

    def point(side: str | None) -> tuple[float, float]:
        if side is None:
            return size / 2, size / 2
        dx, dy = STEP[side]
        return size / 2 + dx * (size / 2 - inset), size / 2 + dy * (size / 2 - inset)

    return dry_route(layout, library.ball.radius, point(entry), point(exit_))


def dry_route(layout: HoleLayout, radius: float, start: tuple[float, float], goal: tuple[float, float],
              spacing: float = GRID) -> bool:
    """Whether a ball of `radius` can roll from `start` to `goal` on the green without touching a wall,
    a bumper or water (windmills are left out: the ball can time them). Sampled every `spacing` metres
    and searched breadth first; cheap next to one golfer's shot."""
    x0, y0, x1, y1 = layout.bounds
    xs = np.arange(x0 + spacing / 2, x1, spacing)
    ys = np.arange(y0 + spacing / 2, y1, spacing)
    px, py = np.meshgrid(xs, ys, indexing="ij")
    free = np.zeros(px.shape, dtype=bool)
    for fx0, fy0, fx1, fy1 in layout.floor:
        free |= (px >= fx0) & (px <= fx1) & (py >= fy0) & (py <= fy1)
    for outline in layout.wall_outlines() + layout.zone_outlines("water"):
        pts = np.asarray(outline, dtype=float)
        ax, ay = pts[:, 0], pts[:, 1]
        bx, by = np.roll(ax, -1), np.roll(ay, -1)
        near = np.zeros(px.shape, dtype=bool)
        inside = np.zeros(px.shape, dtype=bool)
        for k in range(len(pts)):
            ex, ey = bx[k] - ax[k], by[k] - ay[k]
            t = np.clip(((px - ax[k]) * ex + (py - ay[k]) * ey) / (ex * ex + ey * ey), 0.0, 1.0)
            near |= np.hypot(px - ax[k] - t * ex, py - ay[k] - t * ey) < radius
            if ay[k] != by[k]:
                crosses = (ay[k] > py) != (by[k] > py)
                inside ^= crosses & (px < ax[k] + (py - ay[k]) * ex / ey)
        free &= ~(near | inside)

    def cell(p: tuple[float, float]) -> tuple[int, int] | None:
        i = int(np.clip(round((p[0] - xs[0]) / spacing), 0, len(xs) - 1))
        j = int(np.clip(round((p[1] - ys[0]) / spacing), 0, len(ys) - 1))
        best = None
        for di in range(-2, 3):  # the nearest free sample within two steps
            for dj in range(-2, 3):
                a, b = i + di, j + dj
                if 0 <= a < len(xs) and 0 <= b < len(ys) and free[a, b]:
                    d = math.hypot(xs[a] - p[0], ys[b] - p[1])
                    if best is None or d < best[0]:
                        best = (d, (a, b))
        return None if best is None else best[1]

    begin, end = cell(start), cell(goal)
    if begin is None or end is None:
        return False
    seen = np.zeros(free.shape, dtype=bool)
    seen[begin] = True
    queue = deque([begin])
    while queue:
        i, j = queue.popleft()
        if (i, j) == end:
            return True
        for a, b in ((i + 1, j), (i - 1, j), (i, j + 1), (i, j - 1)):
            if 0 <= a < free.shape[0] and 0 <= b < free.shape[1] and free[a, b] and not seen[a, b]:
                seen[a, b] = True
                queue.append((a, b))
    return False


# --- drawing until one is good --------------------------------------------------------------------

Prove = Callable[[Hole], HoleProof]  # the golfer's proof: .sunk, .estimated_par, .best_strokes, .seconds


@dataclass(slots=True)
class Generated:
    """A hole that passed: its text (with the proven par when proven), the plan, the loaded hole, the
    golfer's proof if asked for, and what the refused draws were refused for."""

    text: str
    plan: HolePlan
    hole: Hole
    proof: HoleProof | None
    seconds: float
    refused: list[str] = field(default_factory=list)


def generate(seed: int, library: TileLibrary, *, number: int = 1, prove: Prove | None = None,
             schema: str = SCHEMA_REF, progress: Callable[[str], None] | None = None,
             max_draws: int = MAX_DRAWS, max_proofs: int = MAX_PROOFS) -> Generated:
    """Draw hole `number` of `seed` until a draw loads as a hole file (`golf.holes.load_hole`: cup
    reachable, tee and cup clear, windmill room), leaves a dry way from tee to cup and, with `prove`,
    is sunk by the golfer (its estimated par is then written). Raises GenerateError after
    `max_draws` draws or `max_proofs` proofs."""
    started = time.perf_counter()
    refused: list[str] = []
    proofs = 0
    # Each draw is loaded from its text, as a file of this name would be (no file: a worker stopped
    # mid-draw, as Esc during Random nine's build does, leaves nothing behind).
    path = Path(f"random-{seed}-{number}.yaml")
    for draw in range(max_draws):
        plan = plan_hole(seed, library, number, draw)
        text = plan.text(schema=schema)
        try:
            hole = load_hole(path, library, text)
        except ContentError as exc:
            refused.append(f"draw {draw}: {exc.field}: {exc.message}")
            continue
        if not dry_route(hole.layout, library.ball.radius, hole.layout.tee, hole.layout.cup):
            refused.append(f"draw {draw}: no dry way from the tee to the cup")
            continue
        if prove is None:
            return Generated(text, plan, hole, None, time.perf_counter() - started, refused)
        proofs += 1
        proof = prove(hole)
        if proof.sunk:
            par = max(1, min(20, int(proof.estimated_par)))
            return Generated(plan.text(par, schema, proven=True), plan, hole, proof,
                             time.perf_counter() - started, refused)
        refused.append(f"draw {draw}: the golfer did not sink it")
        if progress is not None:
            progress(f"hole {number}: the golfer did not sink draw {draw}; drawing again")
        if proofs >= max_proofs:
            break
    last = f" (last: {refused[-1]})" if refused else ""
    raise GenerateError(f"seed {seed}, hole {number}: no acceptable hole in {len(refused)} draws, "
                        f"{proofs} of them tried by the golfer{last}")


def generate_hole(seed: int, library: TileLibrary, *, number: int = 1, prove: Prove | None = None,
                  schema: str = SCHEMA_REF) -> str:
    """The YAML text of hole `number` of `seed` (see `generate`): without `prove`, its par is a
    placeholder from its length and hazards."""
    return generate(seed, library, number=number, prove=prove, schema=schema).text


def schema_ref(folder: Path) -> str:
    """The hole schema's path as seen from a hole file in `folder` (an editor finds it from there);
    the shipped holes' own reference in content/holes."""
    target = (CONTENT_DIR / "schemas" / "hole.schema.json").resolve()
    try:
        return Path(os.path.relpath(target, Path(folder).resolve())).as_posix()
    except ValueError:  # another drive (Windows): no relative path
        return target.as_uri()


def golfer_proof(knobs: str = "fast", effort: str = "quick") -> Prove:
    """The search golfer as a `prove` function: does it sink the hole (with every shape it tries),
    and in how many strokes."""

    def prove(hole: Hole) -> HoleProof:
        return prove_hole(hole, shapes=None, effort=effort, knobs=knobs)

    return prove
