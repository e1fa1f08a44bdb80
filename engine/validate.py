"""`polygolf validate`: check content files of every kind and report each problem in one line."""

from __future__ import annotations

from collections.abc import Callable, Iterable
from pathlib import Path

from engine.course import CONTENT_DIR, load_courses, load_hole, load_library
from engine.scene import load_scene
from engine.yamlsource import ContentError, load_yaml

Checker = Callable[[Path], list[ContentError]]


def _library_for(path: Path):
    return load_library(path.parent / "tiles.yaml")


def check_file(path: Path, extra: dict[str, Checker] | None = None) -> list[ContentError]:
    """Every problem in one content file (empty if it is fine). The kind of file is told by its folder
    (holes/, scenes/, themes/) or its name (tiles.yaml, courses.yaml)."""
    kind = _kind(path)
    try:
        if kind == "library":
            load_library(path)
        elif kind == "courses":
            return [h for c in load_courses(path) for h in c.holes if isinstance(h, ContentError)]
        elif kind == "hole":
            load_hole(path, _library_for(path))
        elif kind == "scene":
            load_scene(path)
        elif extra and kind in extra:
            return extra[kind](path)
        else:
            load_yaml(path)
            return [ContentError(path, 1, "(file)", "not a known kind of content (tiles, courses, hole, scene, theme)")]
    except ContentError as exc:
        return [exc]
    return []


def _kind(path: Path) -> str:
    if path.name == "tiles.yaml":
        return "library"
    if path.name == "courses.yaml":
        return "courses"
    folder = path.parent.name
    return {"holes": "hole", "scenes": "scene", "themes": "theme"}.get(folder, "unknown")


def content_files(paths: Iterable[str | Path]) -> list[Path]:
    out: list[Path] = []
    for p in map(Path, paths):
        out += sorted(p.rglob("*.yaml")) if p.is_dir() else [p]
    return out


def validate_paths(paths: Iterable[str | Path] = (CONTENT_DIR,), extra: dict[str, Checker] | None = None
                   ) -> tuple[int, list[ContentError]]:
    """(files checked, problems). A hole's problems are reported once, not again through its course."""
    files = content_files(paths)
    problems: list[ContentError] = []
    seen: set[str] = set()
    for path in files:
        for problem in check_file(path, extra):
            if str(problem) not in seen:
                seen.add(str(problem))
                problems.append(problem)
    return len(files), problems
