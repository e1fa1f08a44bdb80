"""`polygolf schema`: a JSON Schema for every kind of content file, made from the models that load
them, so an editor (with the YAML language server) completes and checks a file as it is typed. The
hole schema offers the tile library's border-set and pattern names as choices."""

from __future__ import annotations

import json
from pathlib import Path

from pydantic import BaseModel

from polygolf.engine.loading.course import CoursesFile, HoleSpec, TileLibrary, load_library
from polygolf.engine.loading.scene import Scene
from polygolf.game.theme import Theme

KINDS: dict[str, type[BaseModel]] = {"hole": HoleSpec, "tiles": TileLibrary, "courses": CoursesFile,
                                     "theme": Theme, "scene": Scene}
TITLES = {"hole": "PolyGolf hole", "tiles": "PolyGolf tile library", "courses": "PolyGolf courses",
          "theme": "PolyGolf theme", "scene": "PolyGolf physics scene"}


def schemas(library: TileLibrary | None = None) -> dict[str, dict]:
    """Kind -> JSON Schema. The hole's `borders` and `pattern` list the library's names."""
    library = library or load_library()
    out = {}
    for kind, model in KINDS.items():
        schema = model.model_json_schema()
        schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
        schema["title"] = TITLES[kind]
        out[kind] = schema
    tile = out["hole"]["$defs"]["TilePlacement"]["properties"]
    tile["borders"]["anyOf"][0] = {"enum": sorted(library.border_sets), "description": "a border set of the library"}
    tile["pattern"] = {"enum": sorted(library.patterns), "default": "empty", "description": "a pattern of the library"}
    return out


def write_schemas(folder: Path, library: TileLibrary | None = None) -> list[Path]:
    folder.mkdir(parents=True, exist_ok=True)
    written = []
    for kind, schema in schemas(library).items():
        path = folder / f"{kind}.schema.json"
        path.write_text(json.dumps(schema, indent=2, sort_keys=True) + "\n")
        written.append(path)
    return written


def schema_for(path: Path) -> str:
    """Which schema a content file follows, by where it lives (as `validate` tells kinds)."""
    if path.name == "tiles.yaml":
        return "tiles"
    if path.name == "courses.yaml":
        return "courses"
    return {"themes": "theme", "scenes": "scene"}.get(path.parent.name, "hole")
