"""Real content files mutated at random, bytes and YAML structure alike (hypothesis): loading them
either works or is refused with a ContentError, never anything else, and promptly; what is accepted
also builds and plays a few seconds without an exception."""

from __future__ import annotations

import copy
import math
import os
import time
from pathlib import Path

import yaml
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from polygolf.engine.golf.holes import load_hole
from polygolf.engine.golf.play import HolePlay
from polygolf.engine.loading.course import load_library
from polygolf.engine.loading.paths import HOLES_DIR, SCENES_DIR, THEMES_DIR
from polygolf.engine.loading.scene import ShapeSpec, build_scene, load_scene
from polygolf.engine.loading.yamlsource import ContentError
from polygolf.game.theme import load_theme

SOURCES = {
    "hole": [HOLES_DIR / f"{name}.yaml" for name in ("straight", "dog-leg", "windmill", "gauntlet", "collision-test")],
    "scene": [SCENES_DIR / f"{name}.yaml" for name in ("flat-wall", "corner", "star-landing", "pile")],
    "theme": [THEMES_DIR / "night.yaml"],
    "library": [HOLES_DIR / "tiles.yaml"],
}
LIBRARY = load_library()
SECONDS_PER_CASE = 5.0

odd_values = st.one_of(
    st.none(), st.booleans(), st.integers(-10**20, 10**20), st.floats(allow_nan=True, allow_infinity=True),
    st.text(max_size=12), st.lists(st.integers(-5, 5), max_size=4), st.just({"box": {"center": [0, 0]}}),
    st.sampled_from([1e308, -1e308, 5e-324, 0, -1, 64, 65, 100000, "open", "wall", "empty", [0, 0], [[0, 0]]]),
)


def _paths(data, prefix=()):
    """Every path to a value in nested data."""
    yield prefix
    if isinstance(data, dict):
        for key, value in data.items():
            yield from _paths(value, (*prefix, key))
    elif isinstance(data, list):
        for i, value in enumerate(data):
            yield from _paths(value, (*prefix, i))


def _set(data, path, value):
    if not path:
        return value
    parent = data
    for part in path[:-1]:
        parent = parent[part]
    parent[path[-1]] = value
    return data


def _delete(data, path):
    if path:
        parent = data
        for part in path[:-1]:
            parent = parent[part]
        del parent[path[-1]]
    return data


@st.composite
def structural(draw, source: Path) -> str:
    data = yaml.safe_load(source.read_text())
    for _ in range(draw(st.integers(1, 3))):
        paths = list(_paths(data))
        path = draw(st.sampled_from(paths))
        action = draw(st.sampled_from(["set", "delete", "duplicate"]))
        if action == "set" or not path:
            data = _set(data, path, copy.deepcopy(draw(odd_values)))
        elif action == "delete":
            data = _delete(data, path)
        else:
            parent = data
            for part in path[:-1]:
                parent = parent[part]
            if isinstance(parent, list):
                parent.append(parent[path[-1]])
    return yaml.safe_dump(data, allow_unicode=True)


@st.composite
def byte_level(draw, source: Path) -> bytes:
    data = bytearray(source.read_bytes())
    for _ in range(draw(st.integers(1, 4))):
        at = draw(st.integers(0, max(0, len(data) - 1)))
        action = draw(st.sampled_from(["flip", "insert", "delete", "truncate"]))
        if action == "flip" and data:
            data[at] = draw(st.integers(0, 255))
        elif action == "insert":
            data[at:at] = draw(st.binary(min_size=1, max_size=8))
        elif action == "delete":
            del data[at:at + draw(st.integers(1, 20))]
        else:
            del data[at:]
    return bytes(data)


@st.composite
def mutated(draw):
    kind = draw(st.sampled_from(sorted(SOURCES)))
    source = draw(st.sampled_from(SOURCES[kind]))
    content = draw(st.one_of(structural(source), byte_level(source)))
    return kind, source.name, content


def _load_and_play(kind: str, path: Path) -> None:
    if kind == "hole":
        hole = load_hole(path, LIBRARY)
        play = HolePlay(hole, ShapeSpec(regular=5, radius=1.0), "fast")
        try:
            play.shoot((play.ball.x + 0.1, play.ball.y), (3.0, 1.0))
            play.step(60)
            assert math.isfinite(play.ball.x) and math.isfinite(play.ball.y)
        finally:
            play.close()
    elif kind == "scene":
        with build_scene(load_scene(path), "fast") as sim:
            sim.run(0.5)
    elif kind == "theme":
        load_theme(path)
    else:
        load_library(path)


EXAMPLES = int(os.environ.get("POLYGOLF_FUZZ_EXAMPLES", "150"))  # CI's share; raise it for a long local run


@settings(max_examples=EXAMPLES, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(mutated())
def test_mutated_content_is_refused_cleanly_or_plays(tmp_path_factory, case):
    kind, name, content = case
    path = tmp_path_factory.mktemp(kind) / name
    if isinstance(content, bytes):
        path.write_bytes(content)
    else:
        path.write_text(content)
    started = time.perf_counter()
    try:
        _load_and_play(kind, path)
        event(f"{kind}: accepted and played")
    except ContentError as exc:
        event(f"{kind}: refused")
        assert str(exc).startswith(str(path) + ":"), str(exc)
        assert "\n" not in str(exc)
    assert time.perf_counter() - started < SECONDS_PER_CASE
