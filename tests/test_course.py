"""Golf content: the shipped courses load and play, and broken content is refused in one line."""

from __future__ import annotations

import math
import shutil
import textwrap

import pytest

from polygolf.engine.golf.golfer import play_hole
from polygolf.engine.golf.holes import load_courses, load_hole
from polygolf.engine.golf.layout import layout_hole, point_clearance
from polygolf.engine.golf.play import HolePlay
from polygolf.engine.loading.course import load_library
from polygolf.engine.loading.paths import HOLES_DIR
from polygolf.engine.loading.scene import ShapeSpec
from polygolf.engine.loading.yamlsource import ContentError
from polygolf.game.tools.validate import validate_paths

PENTAGON = ShapeSpec(regular=5, radius=1.0)


@pytest.fixture(scope="module")
def library():
    return load_library()


@pytest.fixture(scope="module")
def courses():
    return load_courses()


def test_shipped_courses_load_without_errors(courses):
    names = [c.name for c in courses]
    assert names == ["Meadow", "Hazards", "Sandbox", "Collision Test"]
    assert [len(c.playable) for c in courses] == [9, 9, 3, 1]
    assert all(len(c.playable) == len(c.holes) for c in courses)
    assert validate_paths()[1] == []


def test_meadow_has_real_variety(courses):
    holes = courses[0].playable
    pars = [h.spec.par for h in holes]
    sizes = [len(h.spec.tiles) for h in holes]
    assert set(pars) >= {2, 3, 4, 5}
    assert max(sizes) >= 7  # a long hole
    turns = sum(1 for h in holes if len({t.at[1] for t in h.spec.tiles}) > 1)
    assert turns >= 4  # dog-legs and turns, not nine straight lanes
    gates = [h for h in holes if any("gate" in t.borders or "narrow" in t.borders for t in h.spec.tiles)]
    assert gates


@pytest.mark.parametrize("course_index", [0, 2])
def test_every_hole_can_be_holed_by_real_shots(courses, course_index):
    """The scripted golfer finishes every hole in the cup within the stroke limit: the holes are playable."""
    for hole in courses[course_index].playable:
        world = HolePlay(hole, PENTAGON)
        try:
            play_hole(world)
            assert world.state.holed, f"{hole.id}: not holed in {world.state.max_strokes} strokes"
        finally:
            world.close()


def test_layout_merges_walls_and_keeps_gates_open(library):
    hole = load_hole(HOLES_DIR / "narrow-gates.yaml", library)
    layout = layout_hole(hole.spec, hole.library)
    # One long box per straight run: 2 long sides + 2 ends + 2 boxes per gate boundary (4 of them).
    assert len(layout.borders) == 2 + 2 + 4 * 2
    # The gates are open: the line along the middle is clear.
    ty = layout.tee[1]
    assert all(point_clearance(layout, x, ty) > 0.3 for x in (6.0, 12.0, 18.0, 24.0))
    # The narrow gate between tiles 2 and 3 leaves 1.25 m between its posts.
    xs = sorted({round(x, 6) for b in layout.borders for x, _ in b})
    assert 12.0 - 0.15 in xs


def write_hole(tmp_path, body: str, name: str = "h.yaml"):
    shutil.copy(HOLES_DIR / "tiles.yaml", tmp_path / "tiles.yaml")
    path = tmp_path / name
    path.write_text(textwrap.dedent(body))
    return path


GOOD = """\
name: T
par: 3
tiles:
  - {at: [0, 0], borders: open-e}
  - {at: [1, 0], borders: open-w}
"""


@pytest.mark.parametrize(
    ("body", "line", "field", "message"),
    [
        (GOOD.replace("open-w}", "open-x}"), 5, "tiles[1].borders", "unknown border set 'open-x'"),
        (GOOD.replace("open-w}", "open-w, pattern: boulders}"), 5, "tiles[1].pattern", "unknown pattern"),
        (GOOD.replace("borders: open-w}", "borders: open-ew}"), 5, "tiles[1].borders", "opens onto no tile"),
        (GOOD.replace("borders: open-w}", "borders: open-n}"), 4, "tiles[0].borders", "walls its side w"),
        (GOOD.replace("{at: [1, 0], borders: open-w}", "{at: [2, 0], borders: open-w}"), 4, "tiles[0].borders",
         "opens onto no tile"),
        (GOOD.replace("par: 3", "par: three"), 2, "par", "valid integer"),
        (GOOD.replace("par: 3\n", ""), 1, "par", "missing"),
        (GOOD.replace("par: 3", "par: 3\nwind: 4"), 3, "wind", "unknown key"),
        (GOOD.replace("borders: open-e}", "borders: open-e, pattern: post}"), 4, "tiles[0].pattern",
         "tee at the tile's centre is blocked"),
        (GOOD.replace("{at: [1, 0], borders: open-w}", "{at: [0, 0], borders: open-w}"), 5, "tiles[1].at",
         "already used"),
    ],
)
def test_broken_hole_names_file_line_and_field(tmp_path, library, body, line, field, message):
    path = write_hole(tmp_path, body)
    with pytest.raises(ContentError) as info:
        load_hole(path, load_library(tmp_path / "tiles.yaml"))
    err = info.value
    assert (err.line, err.field) == (line, field), str(err)
    assert message in err.message
    assert str(err).startswith(f"{path}:{line}: {field}: ")


def test_unreachable_cup_is_refused(tmp_path):
    body = """\
    name: T
    par: 3
    tiles:
      - {at: [0, 0], borders: open-e}
      - {at: [1, 0], borders: open-w}
      - {at: [3, 0], borders: open-w}
      - {at: [2, 0], borders: open-e}
    """
    path = write_hole(tmp_path, body)
    with pytest.raises(ContentError, match="cup cannot be reached") as info:
        load_hole(path, load_library(tmp_path / "tiles.yaml"))
    assert (info.value.line, info.value.field) == (7, "tiles[3]")  # the cup tile


def test_a_windmill_turning_off_the_green_is_refused_in_one_line(tmp_path):
    path = write_hole(tmp_path, GOOD.replace("open-w}", "open-w, pattern: mill-out}"))
    with (tmp_path / "tiles.yaml").open("a") as tiles:
        tiles.write("  mill-out:\n    - {hazard: windmill, speed: 1.0, box: {center: [3.5, 0], half: [0.3, 0.1]}}\n")
    with pytest.raises(ContentError, match="windmill of pattern 'mill-out' turns about .* off the green") as info:
        load_hole(path, load_library(tmp_path / "tiles.yaml"))
    assert (info.value.line, info.value.field) == (5, "tiles[1].pattern")


def test_a_broken_hole_leaves_the_rest_of_the_course_playable(tmp_path):
    write_hole(tmp_path, GOOD, "good.yaml")
    write_hole(tmp_path, GOOD.replace("open-w}", "open-x}"), "bad.yaml")
    (tmp_path / "courses.yaml").write_text("courses:\n  - name: Mixed\n    holes: [good, bad, missing, good]\n")
    (course,) = load_courses(tmp_path / "courses.yaml")
    assert [type(h).__name__ for h in course.holes] == ["Hole", "ContentError", "ContentError", "Hole"]
    assert "no hole file missing.yaml" in str(course.holes[2]) and ":3: courses[0].holes[2]" in str(course.holes[2])
    count, problems = validate_paths([tmp_path])
    assert count == 4 and len(problems) == 2


def test_hole_world_holds_only_what_the_hole_needs(library, courses):
    straight = courses[0].playable[0]
    with_hole = HolePlay(straight, PENTAGON)
    try:
        assert with_hole.sim.system_names == ["shot", "integrate", "spin", "drag", "ccd", "broadphase", "narrowphase",
                                              "resolve", "impacts", "restitution", "cup", "scoring"]
        assert with_hole.sim.processors[7].friction is True
    finally:
        with_hole.close()
    test_level = next(c for c in courses if c.name == "Collision Test").playable[0]
    launcher = HolePlay(test_level, PENTAGON)
    try:
        assert "launch" in launcher.sim.system_names and "drag" not in launcher.sim.system_names
        launcher.step(30)
        speed = math.hypot(launcher.ball.vx, launcher.ball.vy)
        assert speed == pytest.approx(math.hypot(7.0, 2.5), rel=1e-9)  # constant velocity until it hits
    finally:
        launcher.close()


@pytest.mark.parametrize(("item", "message"), [
    ("{box: {center: [-5.0, 0], half: [1.0, 1.0]}}", "the tee at tiles[0]'s centre is blocked by an obstacle"),
    ("{polygon: [[-6.5, -0.2], [-3.5, -0.2], [-3.5, 0.2], [-6.5, 0.2]], hazard: windmill, speed: 1.0}",
     "the tee at tiles[0]'s centre is within a windmill's sweep"),
])
def test_a_pattern_reaching_into_another_tile_is_blamed_for_what_it_blocks(tmp_path, library, item, message):
    """QA8: an obstacle of tiles[1]'s pattern over the tee was blamed on tiles[0].pattern, which
    had none."""
    path = write_hole(tmp_path, GOOD.replace("open-w}", "open-w, pattern: reach}"))
    text = (tmp_path / "tiles.yaml").read_text().replace("\npatterns:\n", f"\npatterns:\n  reach:\n    - {item}\n", 1)
    (tmp_path / "tiles.yaml").write_text(text)
    with pytest.raises(ContentError) as info:
        load_hole(path, load_library(tmp_path / "tiles.yaml"))
    assert (info.value.line, info.value.field, info.value.message) == (5, "tiles[1].pattern", message), str(info.value)
