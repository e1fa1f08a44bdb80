"""Where content lives: the shipped package data, unless `POLYGOLF_CONTENT` points elsewhere.

The shipped folder is found with importlib.resources, so a wheel installed anywhere finds it; the
game reads it as plain files (an installed package is a folder on disk, not a zip).
"""

from __future__ import annotations

import os
from importlib.resources import files
from pathlib import Path


def content_dir() -> Path:
    """The content root: `POLYGOLF_CONTENT` if set, else the installed `polygolf.content`."""
    override = os.environ.get("POLYGOLF_CONTENT")
    return Path(override) if override else Path(str(files("polygolf.content")))


CONTENT_DIR = content_dir()
HOLES_DIR = CONTENT_DIR / "holes"
THEMES_DIR = CONTENT_DIR / "themes"
SCENES_DIR = CONTENT_DIR / "scenes"
