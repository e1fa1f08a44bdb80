"""`polygolf validate`: check content files of every kind and report each problem in one line."""

from __future__ import annotations

import math
from collections.abc import Iterable
from pathlib import Path

from polygolf.engine.golf.holes import Hole, load_courses, load_hole_file
from polygolf.engine.golf.scenes import scene_hole
from polygolf.engine.golf.world import MAX_PLAYERS, start_problem
from polygolf.engine.loading.course import load_library
from polygolf.engine.loading.paths import content_roots
from polygolf.engine.loading.scene import load_scene
from polygolf.engine.loading.yamlsource import ContentError, format_loc, line_of, load_yaml
from polygolf.game.theme import check_name_free, load_theme, themes_before


def check_file(path: Path) -> list[ContentError]:
    """Every problem in one content file (empty if it is fine). The kind of file is told by its folder
    (scenes/, themes/), its name (tiles.yaml, courses.yaml) or its keys."""
    kind = _kind(path)
    try:
        if kind == "library":
            load_library(path)
        elif kind == "courses":
            return [p for c in load_courses(path, taken=_taken_before(path)) for h in c.holes
                    if isinstance(h, ContentError) for p in h.problems]
        elif kind == "hole":
            hole = load_hole_file(path)
            return _unreachable(path, hole) + _crowded_tee(path, hole)
        elif kind == "scene":
            scene_hole(load_scene(path), path)
        elif kind == "theme":
            check_name_free(load_theme(path), path, themes_before(path))
        else:
            load_yaml(path)
            return [ContentError(path, 1, "(file)", "not a known kind of content (tiles, courses, hole, scene, theme)")]
    except ContentError as exc:
        return exc.problems
    return []


def _unreachable(path: Path, hole: Hole) -> list[ContentError]:
    """The hole's cup out of a ball's reach from its tee along the green (the search golfer's route
    map: where the ball fits between walls, out of water), for all its open borders: an obstacle
    or a gate narrower than the ball closing the way. (Validation's own, not loading's: the
    game's start does not pay for a route map of every hole.)"""
    from polygolf.engine.golf.search import ROUTE_STEP, RouteMap

    layout = hole.layout
    route = RouteMap(layout, hole.library.ball.radius)
    # (A hole too large for the map's usual step gets a coarser map, which may miss a narrow way: no
    # claim is made from it.)
    if hole.spec.launch is not None or route.step > ROUTE_STEP or math.isfinite(route(*layout.tee)):
        return []
    _, lines = load_yaml(path)
    loc = ("tiles", len(hole.spec.tiles) - 1)
    return [ContentError(path, line_of(loc, lines), format_loc(loc),
                         f"the cup cannot be reached from the tee: walls, gates or water close every way for a ball "
                         f"{2 * hole.library.ball.radius:g} m across")]


def _crowded_tee(path: Path, hole: Hole) -> list[ContentError]:
    """Hot seat on this hole: up to four balls must start apart and clear of the cup (a library's ball
    too large for the tee's tile has nowhere to put them)."""
    if hole.spec.launch is not None:
        return []
    problem = next((p for n in range(2, MAX_PLAYERS + 1)
                    if (p := start_problem(hole.layout, hole.library.ball.radius, n)) is not None), None)
    if problem is None:
        return []
    _, lines = load_yaml(path)
    return [ContentError(path, line_of(("tiles", 0), lines), format_loc(("tiles", 0)), problem)]


def _taken_before(path: Path) -> list[str]:
    """The course ids of the content folders the game loads before this courses file's (the shipped
    content's, for the player's own): the file may not name a course as one of them."""
    files = [root / "holes" / "courses.yaml" for root in content_roots()]
    mine = next((k for k, file in enumerate(files) if file.resolve() == path.resolve()), len(files))
    taken: list[str] = []
    for file in files[:mine]:
        try:
            taken += [c.id for c in load_courses(file, taken=taken)] if file.exists() else []
        except ContentError:
            continue  # (its own problems are its own)
    return taken


_KEYS = {"border_sets": "library", "courses": "courses", "tiles": "hole", "bodies": "scene", "background": "theme"}


def _kind(path: Path) -> str:
    """What a file is: by its name or folder, else by the keys it has."""
    if path.name == "tiles.yaml":
        return "library"
    if path.name == "courses.yaml":
        return "courses"
    folder = {"scenes": "scene", "themes": "theme"}.get(path.parent.name)
    if folder:
        return folder
    try:
        data, _ = load_yaml(path)
    except ContentError:
        return "hole" if path.parent.name == "holes" else "unknown"  # the loader will report it
    if isinstance(data, dict):
        for key, kind in _KEYS.items():
            if key in data:
                return kind
    return "hole" if path.parent.name == "holes" else "unknown"


def content_files(paths: Iterable[str | Path]) -> list[Path]:
    out: list[Path] = []
    for p in map(Path, paths):
        out += sorted(p.rglob("*.yaml")) if p.is_dir() else [p]
    return out


def validate_paths(paths: Iterable[str | Path] | None = None) -> tuple[int, list[ContentError]]:
    """(files checked, problems). A hole's problems are reported once, not again through its course."""
    files = content_files(content_roots() if paths is None else paths)
    problems: list[ContentError] = []
    seen: set[str] = set()
    for path in files:
        for problem in check_file(path):
            if str(problem) not in seen:
                seen.add(str(problem))
                problems.append(problem)
    return len(files), problems
