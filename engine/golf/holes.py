"""Holes and courses as the game plays them: a hole file parsed, its geometry laid out once and
checked (reachable cup, clear tee and cup), and courses of such holes with broken ones kept as errors."""

from __future__ import annotations

import math
import re
from collections.abc import Collection, Sequence
from dataclasses import dataclass, field
from pathlib import Path

from polygolf.engine.golf.layout import HoleLayout, layout_hole, pattern_items, point_clearance, tile_path
from polygolf.engine.loading.course import (
    HAZARDS,
    CoursesFile,
    HoleSpec,
    ParsedHole,
    TileLibrary,
    load_library,
    parse_hole,
)
from polygolf.engine.loading.paths import HOLES_DIR, content_roots, misplaced_folders
from polygolf.engine.loading.yamlsource import ContentError, format_loc, line_of, load_yaml, validate
from polygolf.engine.physics.polygon import about_centroid, bounding_radius, centroid
from polygolf.engine.physics.settings import LINEAR_SLOP

RANDOM_NINE_ID = "random-nine"  # the course the game builds from a seed (`golf.nine`): no content's


@dataclass(slots=True)
class Hole:
    """A validated hole: its spec, where it came from, the library it uses and its layout."""

    id: str
    path: Path
    spec: HoleSpec
    library: TileLibrary
    layout: HoleLayout


def load_hole(path: str | Path, library: TileLibrary, text: str | None = None) -> Hole:
    """Load a hole (its file, or `text` named `path`), lay it out and check it: the cup can be
    reached from the tee through open borders, and neither the tee nor the cup is blocked, in water
    or in a windmill's sweep."""
    parsed = parse_hole(path, library, text)
    spec = parsed.spec
    if len(spec.tiles) == 1:
        raise parsed.error(("tiles",), "a hole needs two tiles or more: the first holds the tee and the last the "
                                       "cup, each at its centre (one tile puts the tee in the cup)")
    if tile_path(spec, library) is None:
        raise parsed.error(("tiles", len(spec.tiles) - 1),
                           "the cup cannot be reached from the tee through open borders")
    layout = layout_hole(spec, library)
    _check_tee_and_cup(parsed, layout, library)
    _check_windmill_room(parsed, layout, library)
    _check_listed_effects(parsed, layout)
    return Hole(id=parsed.path.stem, path=parsed.path, spec=spec, library=library, layout=layout)


def _check_tee_and_cup(parsed: ParsedHole, layout: HoleLayout, library: TileLibrary) -> None:
    water = layout.zone_outlines("water")
    last = len(parsed.spec.tiles) - 1
    for (x, y), what, i in ((layout.tee, "tee", 0), (layout.cup, "cup", last)):
        need = library.ball.radius if what == "tee" else library.cup.radius
        if point_clearance(layout, x, y) < need:
            k = _pattern_reaching(parsed, library, layout, "wall", x, y, need, i)
            raise parsed.error(("tiles", k, "pattern"), f"the {what} at {_tile_centre(k, i)} is blocked by an obstacle")
        if water and point_clearance(layout, x, y, water) < need:
            k = _pattern_reaching(parsed, library, layout, "water", x, y, need, i)
            raise parsed.error(("tiles", k, "pattern"), f"the {what} at {_tile_centre(k, i)} is in or at the edge of "
                                                        "water")
        for outline, (px, py), _ in layout.windmills:
            if math.hypot(x - px, y - py) < bounding_radius(outline) + need:
                k = _pattern_reaching(parsed, library, layout, "windmill", x, y, need, i)
                raise parsed.error(("tiles", k, "pattern"), f"the {what} at {_tile_centre(k, i)} is within a "
                                                            "windmill's sweep")


def _tile_centre(k: int, i: int) -> str:
    """Where the tee or cup of tile i is, said from tile k's pattern that reaches it."""
    return "the tile's centre" if k == i else f"tiles[{i}]'s centre"


def _pattern_reaching(parsed: ParsedHole, library: TileLibrary, layout: HoleLayout, hazard: str, x: float, y: float,
                      need: float, default: int) -> int:
    """The first tile whose pattern puts a `hazard` item within `need` of (x, y) (a windmill: its
    sweep), else `default`: a pattern's item may reach far past its tile (QA8: a box 2 km wide on
    tiles[1] blocked the tee and was blamed on tiles[0], which has no pattern)."""
    for k, tile in enumerate(parsed.spec.tiles):
        items = [outline for item, outline in pattern_items(tile, library) if item.hazard == hazard]
        if hazard == "windmill":
            if any(math.dist((x, y), centroid(o)) < bounding_radius(about_centroid(o)[0]) + need for o in items):
                return k
        elif items and point_clearance(layout, x, y, items) < need:
            return k
    return default


# The effects a hole's own content brings (its tiles' hazards, its launcher): a list of effects must
# name those it has, and only those (the physics effects it may choose freely).
CONTENT_EFFECTS = (*HAZARDS, "launch")


def _check_listed_effects(parsed: ParsedHole, layout: HoleLayout) -> None:
    """A hole that lists its effects keeps every hazard it holds working: left off the list, a pond
    would be drawn but never take a ball, a windmill drawn but never turn. A hazard listed with
    nothing of it in the hole is refused too (it says the hole has what it has not)."""
    listed = parsed.spec.effects
    if listed is None:
        return
    present = {kind for kind, _, _ in layout.zones}
    present |= {"bumper"} if layout.bumpers else set()
    present |= {"windmill"} if layout.windmills else set()
    present |= {"launch"} if parsed.spec.launch is not None else set()
    missing = [e for e in CONTENT_EFFECTS if e in present and e not in listed]
    if missing:
        raise parsed.error(("effects",), f"leaves out {', '.join(missing)}, which the hole holds (left out, it would "
                                         "be there but do nothing): list them, or leave effects out for what the "
                                         "hole needs")
    extra = [e for e in CONTENT_EFFECTS if e in listed and e not in present]
    if extra:
        why = f"the hole holds no {extra[0]} (no tile's pattern has it)" if extra[0] != "launch" \
            else "the hole has no launch (its `launch:` key)"
        raise parsed.error(("effects", listed.index(extra[0])), why)


def _check_windmill_room(parsed: ParsedHole, layout: HoleLayout, library: TileLibrary) -> None:
    """A windmill must turn about a point on the green, and its sweep must leave the ball room to pass
    every wall: a narrower gap would crush a ball between arm and wall (a kinematic arm cannot be pushed
    back)."""
    room = 2.0 * library.ball.radius + 2.0 * LINEAR_SLOP
    tiles = parsed.spec.tiles
    # The tile each windmill came from: `layout_hole` lays them out tile by tile, pattern item by item.
    owners = [i for i, tile in enumerate(tiles) for item in library.patterns[tile.pattern] if item.hazard == "windmill"]
    for owner, (outline, (px, py), _) in zip(owners, layout.windmills, strict=True):
        loc = ("tiles", owner, "pattern")
        if not any(x0 <= px <= x1 and y0 <= py <= y1 for x0, y0, x1, y1 in layout.floor):
            raise parsed.error(loc, f"a windmill of pattern '{tiles[owner].pattern}' turns about "
                                    f"({px:.2f}, {py:.2f}) m, off the green: its centre must be on a tile")
        gap = point_clearance(layout, px, py) - bounding_radius(outline)
        if gap < room:
            raise parsed.error(loc, f"a windmill's sweep comes within {max(gap, 0.0):.2f} m of a wall: the ball "
                                    f"({2 * library.ball.radius:g} m across) needs {room:.2f} m to pass, not to be "
                                    "crushed")


@dataclass(slots=True)
class Course:
    """A course as it will be played: its holes in order, each loaded or the error that broke it."""

    id: str
    name: str
    holes: list[Hole | ContentError] = field(default_factory=list)

    @property
    def playable(self) -> list[Hole]:
        return [h for h in self.holes if isinstance(h, Hole)]


def library_beside(path: Path) -> TileLibrary:
    """The tile library a content file uses: `tiles.yaml` beside it, else the shipped one."""
    beside = Path(path).parent / "tiles.yaml"
    return load_library(beside if beside.exists() else None)


def load_hole_file(path: str | Path) -> Hole:
    """A hole file on its own (to play or check it), with the library beside it or the shipped one."""
    return load_hole(path, library_beside(Path(path)))


def load_courses(path: str | Path | None = None, library: TileLibrary | None = None,
                 taken: Collection[str] = ()) -> list[Course]:
    """Every course of a courses file with its holes. A broken hole is kept as its ContentError so
    the rest of the course plays; an unknown hole name is such an error too. Holes are files beside
    the courses file; the library is the one beside it too, else the shipped one. A course's id (its
    name in lower case, spaces as dashes) names its bests and replays, so it may not repeat one in
    the file, one of `taken` (other content folders') or Random nine's: a name that breaks these rules
    refuses the whole file, with every such problem and every unknown hole name of it."""
    path = Path(path or HOLES_DIR / "courses.yaml")
    library = library or library_beside(path)
    data, lines = load_yaml(path)
    spec = validate(CoursesFile, data, lines, path)
    courses = []
    seen = {RANDOM_NINE_ID: "Random nine", **{taken_id: "a course of another content folder" for taken_id in taken}}
    read: dict[str, Hole | ContentError] = {}  # each hole file once, however many times the courses list it
    named: list[ContentError] = []  # the names that break the rules
    for c, course in enumerate(spec.courses):
        loaded = Course(id=course.name.lower().replace(" ", "-"), name=course.name)
        loc = ("courses", c, "name")
        if any(mark in course.name for mark in ":/\\"):
            named.append(ContentError(path, line_of(loc, lines), format_loc(loc), "a course's name may not hold ':', "
                                      "'/' or '\\' (COURSE:HOLE and file paths use them)"))
        elif loaded.id in seen or re.fullmatch(rf"{RANDOM_NINE_ID}-[0-9]+", loaded.id):  # (a seed's nine's id)
            owner = seen.get(loaded.id, "Random nine's seeds")
            named.append(ContentError(path, line_of(loc, lines), format_loc(loc), f"course id {loaded.id!r} (from its "
                                      f"name) is taken by {owner}: give the course another name"))
        else:
            seen[loaded.id] = f"courses[{c}] {course.name!r}"
        for h, hole_id in enumerate(course.holes):
            hole_path = path.parent / f"{hole_id}.yaml"
            if not hole_path.exists() and not hole_path.is_symlink():  # (a broken link: its loader says why)
                loc = ("courses", c, "holes", h)
                loaded.holes.append(ContentError(path, line_of(loc, lines), format_loc(loc),
                                                 f"no hole file {hole_path.name}"))
                continue
            if hole_id not in read:
                try:
                    read[hole_id] = load_hole(hole_path, library)
                except ContentError as exc:
                    read[hole_id] = exc
            loaded.holes.append(read[hole_id])
        courses.append(loaded)
    if named:
        raise ContentError.of(named + [hole for course in courses for hole in course.holes
                                       if isinstance(hole, ContentError) and hole.file == str(path)])
    return courses


def load_all_courses() -> tuple[list[Course], list[ContentError]]:
    """The courses of every content folder (shipped, then the player's), and the problems of any
    courses or library file that could not be read at all (their courses are left out)."""
    courses: list[Course] = []
    problems = misplaced_folders("", "holes")
    for root in content_roots():
        path = root / "holes" / "courses.yaml"
        if path.exists():
            try:
                courses += load_courses(path, taken=[c.id for c in courses])
            except ContentError as exc:
                problems.append(exc)
    return courses, problems


def find_course(courses: list[Course], name: str, unread: Sequence[object] = ()) -> Course:
    """The course of that id or name. `unread`: the problems of the courses files that could not be
    read (`load_all_courses`): the one asked for may be in one, so the error says why."""
    for course in courses:
        if name in (course.id, course.name):
            return course
    raise KeyError(f"no course {name!r}; courses: {', '.join(c.id for c in courses)}"
                   + "".join(f"; not read: {problem}" for problem in unread))
