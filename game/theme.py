"""Colour palettes (content/themes/*.yaml): plain data; the front end turns them into colours."""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path

from polygolf.engine.loading.limits import Colour, Name
from polygolf.engine.loading.paths import content_roots, misplaced_folders
from polygolf.engine.loading.scene import Strict_
from polygolf.engine.loading.yamlsource import ContentError, line_of, load_yaml, validate

RGBA = tuple[int, int, int, int]


class Theme(Strict_):
    name: Name
    background: Colour
    green: Colour
    green_alt: Colour
    wall: Colour
    wall_edge: Colour
    obstacle: Colour
    obstacle_edge: Colour
    cup: Colour
    cup_rim: Colour
    flag: Colour  # the pennant on the pin
    tee: Colour
    ball: Colour
    ball_edge: Colour
    arrow: Colour
    arrow_strong: Colour
    text: Colour
    panel: Colour
    button: Colour
    button_hover: Colour
    button_text: Colour
    sand_zone: Colour  # bunkers
    water: Colour
    ice: Colour
    slope: Colour  # the arrows drawn on a slope
    bumper: Colour
    bumper_lit: Colour  # a bumper just hit
    windmill: Colour

    def rgba(self, field: str) -> RGBA:
        """A colour as an (r, g, b, a) tuple of 0-255 ints."""
        value = getattr(self, field).lstrip("#")
        parts = [int(value[i:i + 2], 16) for i in range(0, len(value), 2)]
        return (*parts, 255) if len(parts) == 3 else tuple(parts)  # type: ignore[return-value]


# Colours that must tell apart for the game to be playable: what lies on the green against both of its
# checker's greens, the ball against the walls and the hazards it rolls over, the words against what
# they are written on.
MUST_DIFFER = (
    *((thing, green) for thing in ("ball", "cup", "wall", "obstacle", "tee", "flag", "arrow", "arrow_strong",
                                   "sand_zone", "water", "ice", "slope", "bumper", "windmill")
      for green in ("green", "green_alt")),
    ("ball", "wall"), ("ball", "ball_edge"), *(("ball", ground) for ground in ("sand_zone", "water", "ice")),
    ("cup", "cup_rim"), ("text", "background"), ("text", "panel"),
    ("button_text", "button"), ("button_text", "button_hover"),
)
MIN_CONTRAST = 50.0  # RGB distance; the shipped themes' least is 61 (Sand's obstacle on its green)
_SEE_THROUGH = " (drawn over it, as see-through as it is)"


def load_theme(path: str | Path) -> Theme:
    """A theme file, refused (every pair named) where two colours that must tell apart are too close."""
    data, lines = load_yaml(path)
    theme = validate(Theme, data, lines, path)
    problems = [ContentError(path, line_of((a,), lines), a, f"{getattr(theme, a)} is too close to {b} "
                                                             f"({getattr(theme, b)}) to tell apart: at least "
                                                             f"{MIN_CONTRAST:g} apart in RGB, {apart:.0f} here"
                                                             + (_SEE_THROUGH if theme.rgba(a)[3] < 255 else ""))
                for a, b in MUST_DIFFER if (apart := _contrast(theme.rgba(a), theme.rgba(b))) < MIN_CONTRAST]
    if problems:
        raise ContentError.of(problems)
    return theme


def _contrast(over: RGBA, under: RGBA) -> float:
    """RGB distance between `over` as it shows drawn on `under` (blended by its alpha: a colour with
    alpha 00 is invisible, however far its RGB) and `under`."""
    alpha = over[3] / 255.0
    return math.dist([alpha * o + (1.0 - alpha) * u for o, u in zip(over[:3], under[:3])], under[:3])


# Used only when no theme file can be read: plain, high-contrast, and obviously not a real theme.
FALLBACK = Theme(
    name="Fallback", background="#202020", green="#3c7a3c", green_alt="#377037", wall="#8a8a8a",
    wall_edge="#404040", obstacle="#9a9a9a", obstacle_edge="#404040", cup="#000000", cup_rim="#ffffff",
    flag="#ff8000", tee="#ffffff", ball="#ffd640", ball_edge="#202020", arrow="#ffffff", arrow_strong="#ff8000",
    text="#ffffff", panel="#303030", button="#505050", button_hover="#707070", button_text="#ffffff",
    sand_zone="#d8c080", water="#3060d0", ice="#c0e8ff", slope="#e0e0a0", bumper="#e04080", bumper_lit="#ff90c0",
    windmill="#c06020",
)


def load_themes(directories: list[Path] | None = None) -> tuple[list[Theme], list[ContentError]]:
    """Every theme that loads from the content folders' themes/, in name order (grass first: it is
    the default), and the problems of those that do not; a broken theme is left out, and so is one
    whose name an earlier one has (the shipped folder's come first); with none left the plain
    fallback is used."""
    themes, problems = [], misplaced_folders("themes") if directories is None else []
    taken: dict[str, Path] = {}
    for path in theme_files(directories):
        try:
            theme = load_theme(path)
            check_name_free(theme, path, taken)
        except ContentError as exc:
            problems.append(exc)
            continue
        taken[_key(theme.name)] = path
        themes.append(theme)
    return sorted(themes, key=lambda t: (t.name != "Grass", t.name)) or [FALLBACK], problems


def theme_files(directories: list[Path] | None = None) -> list[Path]:
    """The theme files, in the order the game loads them (the shipped folder's first)."""
    folders = directories if directories is not None else [root / "themes" for root in content_roots()]
    return [p for folder in folders for p in sorted(folder.glob("*.yaml"))]


def check_name_free(theme: Theme, path: Path, taken: dict[str, Path]) -> None:
    """Raise a ContentError at the theme's name if a theme loaded before it has that name (in any
    case, spaces about it aside: the command line finds a theme by it)."""
    if _key(theme.name) in taken:
        raise ContentError(path, line_of(("name",), load_yaml(path)[1]), "name",
                           f"theme name {theme.name!r} is taken by {taken[_key(theme.name)]}: give this theme "
                           "another name")


def _key(name: str) -> str:
    """What tells theme names apart: not case, nor spaces before or after (the menu shows them alike)."""
    return name.strip().casefold()


def themes_before(path: Path) -> dict[str, Path]:
    """The names of the themes the game loads before this file (every one, for a file it does not
    load), each with its file."""
    taken: dict[str, Path] = {}
    for file in theme_files():
        if file.resolve() == path.resolve():
            break
        try:
            theme = load_theme(file)
            check_name_free(theme, file, taken)
        except ContentError:
            continue  # (its own problems are its own)
        taken[_key(theme.name)] = file
    return taken


def find_theme(themes: list[Theme], name: str, unread: Sequence[object] = ()) -> Theme:
    """The theme of that name. `unread`: the problems of the theme files that could not be read
    (`load_themes`): the one asked for may be one of them, so the error says why (as `find_course`)."""
    for theme in themes:
        if _key(theme.name) == _key(name):
            return theme
    raise KeyError(f"no theme {name!r}; themes: {', '.join(t.name.lower() for t in themes)}"
                   + "".join(f"; not read: {problem}" for problem in unread))
