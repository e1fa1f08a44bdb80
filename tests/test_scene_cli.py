"""Scene loading, one-line errors for malformed scenes, and `polygolf simulate` / `explain`."""

from __future__ import annotations

import json
import re
import subprocess
import sys
import textwrap

import pytest

from polygolf.engine.golf.scenes import build_scene_file
from polygolf.engine.loading.scene import build_scene, load_scene
from polygolf.engine.loading.yamlsource import ContentError
from polygolf.game.cli import main

from .conftest import SCENES

GOOD = """\
name: t
bodies:
  - name: ball
    shape: {regular: 4, radius: 0.5}
    position: [3.0, 0.0]
    velocity: [-10.0, 0.0]
walls:
  - box: {center: [-1.0, 0.0], half: [1.0, 5.0]}
"""


def write(tmp_path, text, name="scene.yaml"):
    path = tmp_path / name
    path.write_text(textwrap.dedent(text))
    return path


@pytest.mark.parametrize("path", sorted(SCENES.glob("*.yaml")), ids=lambda p: p.stem)
def test_every_shipped_scene_loads_and_runs(path):
    with build_scene_file(path) as sim:
        sim.run(0.5)
        assert not sim.metrics.nan


@pytest.mark.parametrize(
    ("text", "line", "field", "message"),
    [
        (GOOD.replace("velocity: [-10.0, 0.0]", "velocity: [-10.0, fast]"), 6, "bodies[0].velocity[1]", "valid number"),
        (GOOD.replace("    position: [3.0, 0.0]\n", ""), 3, "bodies[0].position", "missing"),
        (GOOD.replace("    velocity:", "    colour: red\n    velocity:"), 6, "bodies[0].colour", "unknown key"),
        (GOOD.replace("{regular: 4, radius: 0.5}", "{vertices: [[0, 0], [4, 0], [0, 3], [3, 3]]}"), 4,
         "bodies[0].shape", "cross"),
        (GOOD.replace("{regular: 4, radius: 0.5}", "{regular: 4}"), 4, "bodies[0].shape", "needs a radius"),
        (GOOD.replace("{regular: 4, radius: 0.5}", "{regular: 2, radius: 0.5}"), 4, "bodies[0].shape.regular",
         "greater than or equal to 3"),
        (GOOD.replace("name: t", "name: t\npreset: turbo"), 2, "preset", "Input should be"),
        (GOOD.replace("name: t", "name: t\neffects: [wind]"), 2, "effects[0]", "Input should be"),
        (GOOD.replace("half: [1.0, 5.0]", "half: [1.0, -5.0]"), 8, "walls[0].box.half[1]", "greater than 0"),
        (GOOD.replace("    position: [3.0, 0.0]", "    position: [3.0, 0.0]\n    position: [1.0, 0.0]"), 6,
         "bodies[0].position", "duplicate key"),
        (GOOD.replace("bodies:", "bodies: [oops"), 3, "(yaml)", "expected"),
    ],
)
def test_malformed_scene_names_file_line_and_field(tmp_path, text, line, field, message):
    path = write(tmp_path, text)
    with pytest.raises(ContentError) as info:
        load_scene(path)
    err = info.value
    assert (err.file, err.line, err.field) == (str(path), line, field)
    assert message in err.message
    assert str(err).startswith(f"{path}:{line}: {field}: ")
    assert "\n" not in str(err)


def test_simulate_json_follows_the_contract(capsys):
    assert main(["simulate", str(SCENES / "flat-wall.yaml"), "--seconds", "1", "--preset", "fast", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert set(report) >= {"scene", "preset", "steps", "systems", "bodies", "metrics"}
    assert (report["scene"], report["preset"], report["steps"]) == ("flat-wall", "fast", 60)
    (body,) = report["bodies"]
    assert set(body) >= {"name", "position", "angle", "velocity", "spin", "at_rest"}
    assert body["velocity"][0] == pytest.approx(5.0, rel=0.01)
    assert body["angle"] == pytest.approx(45.0)
    metrics = report["metrics"]
    assert set(metrics) >= {"max_penetration", "max_energy_ratio", "final_energy_ratio", "nan", "wall_ms"}
    assert metrics["max_energy_ratio"] == pytest.approx(1.0)
    assert metrics["final_energy_ratio"] == pytest.approx(0.25, rel=0.02)
    assert metrics["nan"] is False


def test_simulate_malformed_scene_exits_2_with_one_line(tmp_path, capsys):
    path = write(tmp_path, GOOD.replace("velocity: [-10.0, 0.0]", "velocity: fast"))
    assert main(["simulate", str(path), "--json"]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    lines = captured.err.strip().splitlines()
    assert len(lines) == 1 and f"{path}:6: bodies[0].velocity:" in lines[0]


def test_missing_scene_file_exits_2(tmp_path, capsys):
    assert main(["simulate", str(tmp_path / "nope.yaml")]) == 2
    assert "nope.yaml" in capsys.readouterr().err


def test_an_unknown_scene_name_lists_the_scenes_and_the_text_report_reads_as_text(capsys):
    assert main(["simulate", "nosuch"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("polygolf: no scene 'nosuch': give a scene file, or one of ") \
        and "pile" in err[0] and "flat-wall" in err[0]
    assert main(["simulate", "stack-drop", "--seconds", "1"]) == 0  # starts at rest: no ratio to give
    last = capsys.readouterr().out.strip().splitlines()[-1]
    assert "max energy ratio n/a (started at rest)" in last and "None" not in last
    assert main(["simulate", "flat-wall", "--seconds", "1"]) == 0
    last = capsys.readouterr().out.strip().splitlines()[-1]
    assert re.search(r"max energy ratio 1(\.\d{1,3})?, final 0\.2\d{0,3},", last), last


def test_listed_effects_decide_the_pipeline(tmp_path):
    path = write(tmp_path, GOOD.replace("name: t", "name: t\neffects: [restitution]"))
    with build_scene(load_scene(path)) as sim:
        assert sim.system_names == ["integrate", "broadphase", "narrowphase", "resolve", "restitution"]
    with build_scene(load_scene(write(tmp_path, GOOD, "derived.yaml"))) as sim:
        assert sim.system_names == ["integrate", "spin", "ccd", "broadphase", "narrowphase", "resolve",
                                    "restitution"]


def test_explain_says_why(capsys):
    assert main(["explain", str(SCENES / "corner.yaml")]) == 0
    out = capsys.readouterr().out
    assert "drag" in out and "ball has drag" in out
    assert "friction on" in out


def _first_best_pair(spec, key: str) -> str | None:
    """The reason's definition, pair by pair: each body against the walls, the kinematic bodies,
    then the other bodies (where bodies meet); the first largest product above zero."""
    best, text = 0.0, None
    others = [(getattr(w.material, key), "wall") for w in spec.walls]
    others += [(getattr(k.material, key), k.name) for k in spec.kinematic]
    for i, body in enumerate(spec.bodies):
        own = getattr(body.material, key)
        bodies = [(getattr(o.material, key), o.name) for j, o in enumerate(spec.bodies) if j != i] \
            if spec.collide_bodies else []
        for value, name in others + bodies:
            if own * value > best:
                best, text = own * value, f"{body.name} {key} {own:g} x {name} {value:g}"
    return text


def test_the_coefficient_reason_names_the_first_largest_pair():
    """`explain`'s restitution and friction reasons, found in one pass, name the same pair as the
    pair-by-pair definition, ties and zeros included, with and without bodies meeting."""
    import random
    from types import SimpleNamespace as Part

    from polygolf.engine.assembly.effects import _best_product

    rng = random.Random(5)
    values = [0.0, 0.0, 0.3, 0.5, 0.5, 0.7, 1.0]
    for _ in range(400):
        def part(name: str) -> Part:
            return Part(name=name, material=Part(restitution=rng.choice(values), friction=rng.choice(values)))
        spec = Part(walls=[part("w") for _ in range(rng.randint(0, 3))],
                    kinematic=[part(f"arm{k}") for k in range(rng.randint(0, 2))],
                    bodies=[part(f"b{k}") for k in range(rng.randint(0, 6))], collide_bodies=rng.random() < 0.5)
        for key in ("restitution", "friction"):
            assert _best_product(spec, key) == _first_best_pair(spec, key)


def test_installed_command_runs():
    out = subprocess.run([sys.executable, "-m", "polygolf.game.cli", "simulate", str(SCENES / "long-roll.yaml"),
                          "--seconds", "1", "--json"], capture_output=True, text=True, check=True).stdout
    assert json.loads(out)["systems"] == ["integrate", "spin", "drag"]


CONTACT = ["broadphase", "narrowphase", "resolve"]
SCENE_PIPELINES = {
    "corner": ["integrate", "spin", "drag", "ccd", *CONTACT, "restitution"],
    "deep-overlap": ["integrate", "spin", *CONTACT, "restitution"],
    "far-from-origin": ["integrate", "spin", "ccd", *CONTACT, "restitution"],
    "fast-spin": ["integrate", "spin", "ccd", *CONTACT, "restitution"],
    "flat-wall": ["integrate", "spin", "ccd", *CONTACT, "restitution"],
    "long-roll": ["integrate", "spin", "drag"],
    "mass-ratio": ["integrate", "spin", "ccd", *CONTACT, "restitution"],  # bodies, too, are not skipped
    "pile": ["integrate", "spin", "gravity", "ccd", *CONTACT, "restitution"],
    "resting-contact": ["integrate", "spin", "gravity", "drag", "ccd", *CONTACT, "restitution"],
    "star-landing": ["integrate", "spin", "ccd", *CONTACT, "restitution"],
    "thin-wall": ["integrate", "spin", "ccd", *CONTACT, "restitution"],
    "vertex-hit": ["integrate", "spin", "ccd", *CONTACT, "restitution"],
    "ghost-corner": ["integrate", "spin", "ccd", *CONTACT, "restitution"],
    "seam-slide": ["integrate", "spin", "gravity", "ccd", *CONTACT],
    "hover-drop": ["integrate", "spin", "gravity", "ccd", *CONTACT],
    "body-tunnel": ["integrate", "spin", "ccd", *CONTACT, "restitution"],
    "plate-tunnel": ["integrate", "spin", "ccd", *CONTACT, "restitution"],
    "heavy-crush": ["integrate", "spin", "ccd", *CONTACT],
    "ghost-pass": ["integrate", "spin", "ccd", *CONTACT, "restitution"],
    "stack-drop": ["integrate", "spin", "gravity", "ccd", *CONTACT],
    "piston-crush": ["integrate", "spin", "ccd", *CONTACT],
    "v-groove": ["integrate", "spin", "gravity", "ccd", *CONTACT, "restitution"],
    "dog-leg-rail": ["integrate", "spin", "drag", "ccd", *CONTACT, "restitution", "cup"],
    "elastic-pinch": ["integrate", "spin", "ccd", *CONTACT, "restitution"],  # frictionless everywhere
}
FRICTION = {"v-groove", "corner", "deep-overlap", "fast-spin", "pile", "resting-contact", "ghost-corner", "hover-drop",
            "dog-leg-rail", "heavy-crush", "piston-crush", "ghost-pass", "stack-drop"}


@pytest.mark.parametrize("name", sorted(SCENE_PIPELINES))
def test_each_scene_runs_only_the_systems_its_content_needs(name):
    with build_scene_file(SCENES / f"{name}.yaml") as sim:
        assert sim.system_names == SCENE_PIPELINES[name]
        resolve = [p for p in sim.processors if p.name == "resolve"]
        assert [p.friction for p in resolve] == ([name in FRICTION] if resolve else [])


def test_every_shipped_scene_has_its_pipeline_asserted():
    assert {p.stem for p in SCENES.glob("*.yaml")} == set(SCENE_PIPELINES)
