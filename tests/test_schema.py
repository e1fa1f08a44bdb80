"""`polygolf schema`: the shipped schemas are the models' own, every shipped file names its schema
for editors and passes it, and the schema catches what the loader catches."""

from __future__ import annotations

import json

import jsonschema
import pytest
import yaml

from polygolf.engine.loading.paths import CONTENT_DIR
from polygolf.game.cli import main
from polygolf.game.tools.schema import schema_for, schemas

SHIPPED = sorted(CONTENT_DIR.rglob("*.yaml"))
SCHEMAS = schemas()


def test_shipped_schemas_are_up_to_date(tmp_path, capsys):
    assert main(["schema", "--out", str(tmp_path)]) == 0
    for kind in SCHEMAS:
        written = (tmp_path / f"{kind}.schema.json").read_text()
        assert written == (CONTENT_DIR / "schemas" / f"{kind}.schema.json").read_text(), \
            f"run `polygolf schema --out content/schemas`: {kind} changed"
    capsys.readouterr()
    assert main(["schema"]) == 0
    assert set(json.loads(capsys.readouterr().out)) == set(SCHEMAS)


@pytest.mark.parametrize("path", SHIPPED, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_every_shipped_file_names_and_passes_its_schema(path):
    kind = schema_for(path)
    first = path.read_text().splitlines()[0]
    assert first == f"# yaml-language-server: $schema=../schemas/{kind}.schema.json"
    jsonschema.validate(yaml.safe_load(path.read_text()), SCHEMAS[kind])


def test_the_hole_schema_offers_the_librarys_names():
    tile = SCHEMAS["hole"]["$defs"]["TilePlacement"]["properties"]
    assert "open-ew" in tile["borders"]["anyOf"][0]["enum"] and "diamond" in tile["pattern"]["enum"]
    bad = {"name": "x", "par": 3, "tiles": [{"at": [0, 0], "borders": "open-x"}]}
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(bad, SCHEMAS["hole"])
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate({"name": "x", "bodies": [{"name": "b", "shape": {"regular": 4, "radius": 0.5},
                                                      "position": [0, 0], "restitution": 5}]}, SCHEMAS["scene"])


def test_the_readme_lists_the_limits_that_are_enforced():
    from polygolf.engine.loading.limits import LIMITS

    readme = (CONTENT_DIR.parent / "README.md").read_text() if (CONTENT_DIR.parent / "README.md").exists() else ""
    if not readme:
        pytest.skip("no README beside the content (an installed package)")
    for what, limit in LIMITS:
        assert f"| {what} | {limit} |" in readme, what
