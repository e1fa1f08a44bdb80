"""Golf content (content/holes/): the tile library, holes and courses, validated with file and line.

The original PolyGolf's design, as data: a hole is a grid of tiles; a tile is a *border set* (which of
its four sides are walled, open, or a gate) plus an *obstacle pattern* (named polygons in tile
coordinates, metres from the tile's centre). A few border sets and patterns make many holes. The
first tile of a hole holds the tee, the last the cup, both placed at the tile's centre.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Literal

from pydantic import Field, model_validator

from polygolf.engine.loading.limits import (
    MAX_CUP_SPEED,
    MAX_ENTRIES,
    MAX_ITEMS,
    MAX_KICK,
    MAX_LAUNCH_EVERY,
    MAX_PUSH,
    MAX_TILE,
    MAX_TILE_INDEX,
    MAX_TILES,
    MAX_WINDMILL,
    MIN_TILE,
    Density,
    FileName,
    Friction,
    Key,
    Name,
    Restitution,
    Speed,
    check_vertex_budget,
    count,
    finite,
)
from polygolf.engine.loading.paths import HOLES_DIR
from polygolf.engine.loading.scene import DragSpec, Strict_, WallSpec
from polygolf.engine.loading.yamlsource import ContentError, Loc, format_loc, line_of, load_yaml, validate

SIDES = ("n", "e", "s", "w")
STEP = {"n": (0, 1), "e": (1, 0), "s": (0, -1), "w": (-1, 0)}
OPPOSITE = {"n": "s", "e": "w", "s": "n", "w": "e"}


class Gate(Strict_):
    gate: finite(hi=MAX_TILE, gt=0.0)  # clear width of the opening, m, centred on the side


Side = Literal["open", "wall"] | Gate


class BorderSet(Strict_):
    """Each side is `wall` (the default), `open` to the neighbouring tile, or a `{gate: width}`."""

    n: Side = "wall"
    e: Side = "wall"
    s: Side = "wall"
    w: Side = "wall"


HAZARDS = ("sand", "water", "ice", "slope", "bumper", "windmill")
Hazard = Literal["wall", "sand", "water", "ice", "slope", "bumper", "windmill"]
# Effects a hole can list: the physics core's, the hazards', and the collision test's launcher.
HOLE_EFFECTS = ("drag", "spin", "friction", "restitution", "ccd", *HAZARDS, "launch")
HoleEffect = Literal["drag", "spin", "friction", "restitution", "ccd", "sand", "water", "ice", "slope", "bumper",
                     "windmill", "launch"]


class PatternItem(WallSpec):
    """One thing in a pattern: a wall (the default), an area of the green (sand, water, ice, slope)
    or a special obstacle (bumper, windmill), shaped by `box` or `polygon` in tile coordinates."""

    hazard: Hazard = "wall"
    push: tuple[finite(-MAX_PUSH, MAX_PUSH), finite(-MAX_PUSH, MAX_PUSH)] | None = None  # slope: m/s², in tile
    # coordinates (turns with the tile)
    kick: finite(hi=MAX_KICK, gt=0.0) | None = None  # bumper: m/s added to each rebound
    speed: finite(-MAX_WINDMILL, MAX_WINDMILL) | None = None  # windmill: rad/s, counter-clockwise, about its centroid

    @model_validator(mode="after")
    def _parameters(self) -> PatternItem:
        needs = {"slope": "push", "bumper": "kick", "windmill": "speed"}
        for hazard, key in needs.items():
            given = getattr(self, key) is not None
            if self.hazard == hazard and not given:
                raise ValueError(f"a {hazard} needs '{key}'")
            if self.hazard != hazard and given:
                raise ValueError(f"'{key}' is only for a {hazard}")
        return self


class BallSpec(Strict_):
    radius: finite(0.05, MAX_TILE / 4) = 0.35
    density: Density = 1.0
    restitution: Restitution = 0.6
    friction: Friction = 0.3


class CupSpec(Strict_):
    radius: finite(0.05, MAX_TILE / 4) = 0.45
    max_speed: finite(hi=MAX_CUP_SPEED, gt=0.0) = 4.0  # m/s at the centre, falling linearly to zero at the rim


class TileLibrary(Strict_):
    tile_size: finite(MIN_TILE, MAX_TILE) = 6.0
    wall_thickness: finite(0.01, MAX_TILE / 4) = 0.3
    max_strokes: count(1, 99) = 10
    ball: BallSpec = BallSpec()
    green: DragSpec = DragSpec(linear=0.4, angular=1.0, rolling=1.2, rolling_angular=2.0)
    cup: CupSpec = CupSpec()
    border_sets: Annotated[dict[Key, BorderSet], Field(max_length=MAX_ENTRIES)]
    patterns: Annotated[dict[Key, Annotated[list[PatternItem], Field(max_length=MAX_ITEMS)]],
                        Field(max_length=MAX_ENTRIES)]

    @model_validator(mode="after")
    def _vertex_budget(self) -> TileLibrary:
        check_vertex_budget(sum(item.vertex_count for items in self.patterns.values() for item in items))
        return self

    @model_validator(mode="after")
    def _sizes_fit_a_tile(self) -> TileLibrary:
        quarter = self.tile_size / 4
        for what, value in (("wall_thickness", self.wall_thickness), ("ball.radius", self.ball.radius),
                            ("cup.radius", self.cup.radius)):
            if value > quarter:
                raise ValueError(f"{what} {value:g} m is more than a quarter of the tile ({quarter:g} m)")
        return self

    def resolve(self, borders: str | BorderSet) -> BorderSet:
        """A tile's border set: by name from the library, or given inline."""
        return self.border_sets[borders] if isinstance(borders, str) else borders


TileIndex = count(-MAX_TILE_INDEX, MAX_TILE_INDEX)


class TilePlacement(Strict_):
    at: tuple[TileIndex, TileIndex]  # [column, row]; row grows upwards
    borders: Key | BorderSet | None = None  # a library name, inline sides, or omitted: open toward neighbours
    pattern: Key = "empty"
    rotate: Literal[0, 90, 180, 270] = 0  # turns the pattern (not the borders), degrees


class Launch(Strict_):
    """For the collision test level: the ball leaves the tee at this velocity, again every `every` s."""

    velocity: tuple[Speed, Speed]
    every: finite(0.1, MAX_LAUNCH_EVERY) = 5.0


class HoleSpec(Strict_):
    name: Name
    par: count(1, 20)
    max_strokes: count(1, 99) | None = None
    # Two or more (an editor is told so by the schema; one tile is refused with the hole, `golf.holes.load_hole`,
    # saying why): the first holds the tee and the last the cup, each at its centre.
    tiles: Annotated[list[TilePlacement], Field(min_length=1, max_length=MAX_TILES, json_schema_extra={"minItems": 2})]
    green: DragSpec | None = None  # overrides the library's
    launch: Launch | None = None
    effects: list[HoleEffect] | None = None  # omitted: what the hole's content needs


class CourseSpec(Strict_):
    name: Name
    holes: Annotated[list[FileName], Field(min_length=1, max_length=MAX_ENTRIES)]  # hole files beside courses.yaml


class CoursesFile(Strict_):
    courses: Annotated[list[CourseSpec], Field(min_length=1, max_length=MAX_ENTRIES)]


# --- loading ----------------------------------------------------------------------------------------

def load_library(path: str | Path | None = None) -> TileLibrary:
    path = path or HOLES_DIR / "tiles.yaml"
    data, lines = load_yaml(path)
    library = validate(TileLibrary, data, lines, path)
    if "empty" not in library.patterns:
        raise ContentError(path, line_of(("patterns",), lines), "patterns", "needs an 'empty' pattern")
    problems = [ContentError(path, line_of(loc, lines), format_loc(loc), message)
                for name, borders in library.border_sets.items()
                for loc, message in _wide_gates(borders, library.tile_size, ("border_sets", name))]
    if problems:
        raise ContentError.of(problems)
    return library


def _wide_gates(borders: BorderSet, size: float, loc: Loc) -> list[tuple[Loc, str]]:
    """A gate as wide as the tile's side or wider, where and why: it would leave no wall either side
    of it, an open side that says it is a gate."""
    return [((*loc, side, "gate"), f"a gate {gate.gate:g} m wide on a {size:g} m tile leaves no wall either side of "
                                   f"it: make it narrower than {size:g} m, or the side open")
            for side in SIDES if isinstance(gate := getattr(borders, side), Gate) and gate.gate >= size]


@dataclass(slots=True)
class ParsedHole:
    """A hole file checked against the library, with the lines its values came from."""

    path: Path
    spec: HoleSpec
    lines: dict[Loc, int]

    def error(self, loc: Loc, message: str) -> ContentError:
        return ContentError(self.path, line_of(loc, self.lines), format_loc(loc), message)


def parse_hole(path: str | Path, library: TileLibrary, text: str | None = None) -> ParsedHole:
    """Load a hole file (or `text` named `path`) and check it against the library: names exist,
    tiles do not overlap, open sides meet open sides; tiles without `borders` open toward their
    neighbours. Every problem is reported, not only the first. (Geometry — reachability, tee and
    cup — is golf's: `golf.holes`.)"""
    path = Path(path)
    data, lines = load_yaml(path, text)
    parsed = ParsedHole(path, validate(HoleSpec, data, lines, path), lines)
    spec, fail = parsed.spec, parsed.error
    problems: list[ContentError] = []

    placed: dict[tuple[int, int], int] = {}
    for i, tile in enumerate(spec.tiles):
        if isinstance(tile.borders, str) and tile.borders not in library.border_sets:
            problems.append(fail(("tiles", i, "borders"), f"unknown border set {tile.borders!r}"))
        if tile.pattern not in library.patterns:
            problems.append(fail(("tiles", i, "pattern"), f"unknown pattern {tile.pattern!r}"))
        if isinstance(tile.borders, BorderSet):
            problems += [fail(loc, message) for loc, message in _wide_gates(tile.borders, library.tile_size,
                                                                             ("tiles", i, "borders"))]
        if tile.at in placed:
            problems.append(fail(("tiles", i, "at"), f"tile {list(tile.at)} is already used by "
                                                     f"tiles[{placed[tile.at]}]"))
        else:
            placed[tile.at] = i
    if problems:
        raise ContentError.of(problems)

    parsed.spec = spec = spec.model_copy(update={"tiles": _derive_borders(spec, library, placed)})
    for i, tile in enumerate(spec.tiles):
        borders = library.resolve(tile.borders)
        for side in SIDES:
            if getattr(borders, side) == "wall":
                continue
            dx, dy = STEP[side]
            j = placed.get((tile.at[0] + dx, tile.at[1] + dy))
            if j is None:
                problems.append(fail(("tiles", i, "borders"), f"side {side} of {_name(tile.borders)} opens onto no "
                                                              "tile: the ball could leave the hole"))
            elif getattr(library.resolve(spec.tiles[j].borders), OPPOSITE[side]) == "wall":
                problems.append(fail(("tiles", i, "borders"), f"side {side} is open but tiles[{j}] walls its side "
                                                              f"{OPPOSITE[side]}"))
    if problems:
        raise ContentError.of(problems)
    return parsed


def _name(borders: str | BorderSet) -> str:
    return repr(borders) if isinstance(borders, str) else "the inline border set"


def _derive_borders(spec: HoleSpec, library: TileLibrary, placed: dict[tuple[int, int], int]) -> list[TilePlacement]:
    """Tiles without `borders` get a side open toward each neighbour that does not wall it off."""
    tiles = list(spec.tiles)
    for i, tile in enumerate(tiles):
        if tile.borders is not None:
            continue
        sides = {}
        for side in SIDES:
            j = placed.get((tile.at[0] + STEP[side][0], tile.at[1] + STEP[side][1]))
            if j is None:
                continue
            theirs = spec.tiles[j].borders
            if theirs is None or getattr(library.resolve(theirs), OPPOSITE[side]) != "wall":
                sides[side] = "open"
        tiles[i] = tile.model_copy(update={"borders": BorderSet(**sides)})
    return tiles
