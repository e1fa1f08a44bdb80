"""Colour palettes (content/themes/*.yaml): plain data; the front end turns them into colours."""

from __future__ import annotations

from pathlib import Path

from polygolf.engine.loading.limits import Colour, Name
from polygolf.engine.loading.paths import content_roots
from polygolf.engine.loading.scene import Strict_
from polygolf.engine.loading.yamlsource import ContentError, load

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


def load_theme(path: str | Path) -> Theme:
    return load(Theme, path)


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
    the default), and the problems of those that do not; a broken theme is left out, and with none
    left the plain fallback is used."""
    themes, problems = [], []
    folders = directories if directories is not None else [root / "themes" for root in content_roots()]
    for path in (p for folder in folders for p in sorted(folder.glob("*.yaml"))):
        try:
            themes.append(load_theme(path))
        except ContentError as exc:
            problems.append(exc)
    return sorted(themes, key=lambda t: (t.name != "Grass", t.name)) or [FALLBACK], problems


def find_theme(themes: list[Theme], name: str) -> Theme:
    for theme in themes:
        if theme.name.lower() == name.lower():
            return theme
    raise KeyError(f"no theme {name!r}; themes: {', '.join(t.name.lower() for t in themes)}")
