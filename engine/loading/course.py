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

from pydantic import Field, Strict, model_validator

from polygolf.engine.loading.paths import HOLES_DIR
from polygolf.engine.loading.scene import Count, DragSpec, NonNegative, Number, Point, Positive, Strict_, WallSpec
from polygolf.engine.loading.yamlsource import ContentError, Loc, format_loc, line_of, load_yaml, validate

SIDES = ("n", "e", "s", "w")
STEP = {"n": (0, 1), "e": (1, 0), "s": (0, -1), "w": (-1, 0)}
OPPOSITE = {"n": "s", "e": "w", "s": "n", "w": "e"}


class Gate(Strict_):
    gate: Positive  # clear width of the opening, m, centred on the side


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
    push: Point | None = None  # slope: m/s², in tile coordinates (turns with the tile)
    kick: Positive | None = None  # bumper: m/s added to each rebound
    speed: Number | None = None  # windmill: rad/s, counter-clockwise; it turns about its centroid

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
    radius: Positive = 0.35
    density: Positive = 1.0
    restitution: NonNegative = 0.6
    friction: NonNegative = 0.3


class CupSpec(Strict_):
    radius: Positive = 0.45
    max_speed: Positive = 4.0  # m/s at the centre, falling linearly to zero at the rim


class TileLibrary(Strict_):
    tile_size: Positive = 6.0
    wall_thickness: Positive = 0.3
    max_strokes: Annotated[int, Strict(), Field(ge=1, le=99)] = 10
    ball: BallSpec = BallSpec()
    green: DragSpec = DragSpec(linear=0.4, angular=1.0, rolling=1.2, rolling_angular=2.0)
    cup: CupSpec = CupSpec()
    border_sets: dict[str, BorderSet]
    patterns: dict[str, list[PatternItem]]


class TilePlacement(Strict_):
    at: tuple[Count, Count]  # [column, row]; row grows upwards
    borders: str
    pattern: str = "empty"
    rotate: Literal[0, 90, 180, 270] = 0  # turns the pattern (not the borders), degrees


class Launch(Strict_):
    """For the collision test level: the ball leaves the tee at this velocity, again every `every` s."""

    velocity: Point
    every: Positive = 5.0


class HoleSpec(Strict_):
    name: str
    par: Annotated[int, Strict(), Field(ge=1, le=20)]
    max_strokes: Annotated[int, Strict(), Field(ge=1, le=99)] | None = None
    tiles: Annotated[list[TilePlacement], Field(min_length=1)]
    green: DragSpec | None = None  # overrides the library's
    launch: Launch | None = None
    effects: list[HoleEffect] | None = None  # omitted: what the hole's content needs


class CourseSpec(Strict_):
    name: str
    holes: Annotated[list[str], Field(min_length=1)]


class CoursesFile(Strict_):
    courses: Annotated[list[CourseSpec], Field(min_length=1)]


# --- loading ----------------------------------------------------------------------------------------

def load_library(path: str | Path | None = None) -> TileLibrary:
    path = path or HOLES_DIR / "tiles.yaml"
    data, lines = load_yaml(path)
    library = validate(TileLibrary, data, lines, path)
    if "empty" not in library.patterns:
        raise ContentError(path, line_of(("patterns",), lines), "patterns", "needs an 'empty' pattern")
    return library


@dataclass(slots=True)
class ParsedHole:
    """A hole file checked against the library, with the lines its values came from."""

    path: Path
    spec: HoleSpec
    lines: dict[Loc, int]

    def error(self, loc: Loc, message: str) -> ContentError:
        return ContentError(self.path, line_of(loc, self.lines), format_loc(loc), message)


def parse_hole(path: str | Path, library: TileLibrary) -> ParsedHole:
    """Load a hole file and check it against the library: names exist, tiles do not overlap, open
    sides meet open sides. (Geometry — reachability, tee and cup — is golf's: `golf.holes`.)"""
    path = Path(path)
    data, lines = load_yaml(path)
    parsed = ParsedHole(path, validate(HoleSpec, data, lines, path), lines)
    spec, fail = parsed.spec, parsed.error

    placed: dict[tuple[int, int], int] = {}
    for i, tile in enumerate(spec.tiles):
        if tile.borders not in library.border_sets:
            raise fail(("tiles", i, "borders"), f"unknown border set {tile.borders!r}")
        if tile.pattern not in library.patterns:
            raise fail(("tiles", i, "pattern"), f"unknown pattern {tile.pattern!r}")
        if tile.at in placed:
            raise fail(("tiles", i, "at"), f"tile {list(tile.at)} is already used by tiles[{placed[tile.at]}]")
        placed[tile.at] = i

    for i, tile in enumerate(spec.tiles):
        borders = library.border_sets[tile.borders]
        for side in SIDES:
            mine = getattr(borders, side)
            if mine == "wall":
                continue
            dx, dy = STEP[side]
            j = placed.get((tile.at[0] + dx, tile.at[1] + dy))
            if j is None:
                raise fail(("tiles", i, "borders"), f"side {side} of {tile.borders!r} opens onto no tile: "
                                                    "the ball could leave the hole")
            theirs = getattr(library.border_sets[spec.tiles[j].borders], OPPOSITE[side])
            if theirs == "wall":
                raise fail(("tiles", i, "borders"), f"side {side} is open but tiles[{j}] walls its side "
                                                    f"{OPPOSITE[side]}")
    return parsed
