"""Colour palettes (content/themes/*.yaml): plain data; the front end turns them into colours."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

from pydantic import StringConstraints

from polygolf.engine.loading.paths import THEMES_DIR
from polygolf.engine.loading.scene import Strict_
from polygolf.engine.loading.yamlsource import load

Colour = Annotated[str, StringConstraints(pattern=r"^#([0-9a-fA-F]{6}|[0-9a-fA-F]{8})$")]
RGBA = tuple[int, int, int, int]


class Theme(Strict_):
    name: str
    background: Colour
    green: Colour
    green_alt: Colour
    wall: Colour
    wall_edge: Colour
    obstacle: Colour
    obstacle_edge: Colour
    cup: Colour
    cup_rim: Colour
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


def load_themes(directory: Path = THEMES_DIR) -> list[Theme]:
    """Every theme, in name order; grass first because it is the default."""
    themes = [load_theme(p) for p in sorted(directory.glob("*.yaml"))]
    return sorted(themes, key=lambda t: (t.name != "Grass", t.name))


def find_theme(themes: list[Theme], name: str) -> Theme:
    for theme in themes:
        if theme.name.lower() == name.lower():
            return theme
    raise KeyError(f"no theme {name!r}; themes: {', '.join(t.name.lower() for t in themes)}")
