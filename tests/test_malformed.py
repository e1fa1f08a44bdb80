"""A corpus of malformed content, as a careless author or a hostile file would write it: every case
is refused in one line `file:line: field: message`, with no traceback, promptly; nothing is accepted
that should not be. Five kinds of file (hole, tile library, courses, theme, scene) and the arguments."""

from __future__ import annotations

import json
import math
import os
import re
import shutil
import signal
import textwrap
import time
from contextlib import contextmanager
from pathlib import Path

import pytest

from polygolf.engine.loading.paths import HOLES_DIR, SCENES_DIR, THEMES_DIR
from polygolf.game.cli import main

from .test_scene_cli import GOOD

HOLE = textwrap.dedent("""\
    name: Case
    par: 3
    tiles:
      - {at: [0, 0], borders: open-e}
      - {at: [1, 0], borders: open-w}
    """)
SCENE = GOOD  # the scene test's well-formed scene, broken below one way at a time
COURSES = "courses:\n  - name: Case\n    holes: [case]\n"
LIBRARY = (HOLES_DIR / "tiles.yaml").read_text()
THEME = (THEMES_DIR / "grass.yaml").read_text()
LINE = re.compile(r"^(?P<file>[^:]+):(?P<line>\d+): (?P<field>[^:]+): (?P<message>.+)$")


def _sub(text: str, old: str, new: str) -> str:
    assert old in text, old
    return text.replace(old, new, 1)


def _bomb(levels: int = 9) -> str:
    lines = ["a0: &a0 [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]"]
    for i in range(1, levels):
        lines.append(f"a{i}: &a{i} [" + ", ".join([f"*a{i - 1}"] * 10) + "]")
    return "\n".join(lines) + "\nname: bomb\npar: 3\ntiles: *a8\n"


# (id, kind, content, line, field, message fragment). Line None: any line.
CASES = [
    # --- holes -------------------------------------------------------------------------------
    ("hole-nul-byte", "hole", HOLE.encode().replace(b"Case", b"Ca\x00se"), 1, "(file)", "control character"),
    ("hole-latin1", "hole", HOLE.encode().replace(b"Case", "Café".encode("latin-1")), 1, "(file)", "not UTF-8"),
    ("hole-cyclic-anchor", "hole", "name: &n [a, *n]\npar: 3\ntiles: []\n", 1, "name[1]", "alias refers to the value"),
    ("hole-deep-nesting", "hole", "name: " + "[" * 200 + "]" * 200 + "\npar: 3\n", 1, "(yaml)", "nested more than"),
    ("hole-billion-laughs", "hole", _bomb(), None, None, "values"),
    ("hole-merge-of-a-list", "hole", "name: M\npar: 3\ntiles:\n  - {<<: [1, 2], at: [0, 0]}\n", 4, "tiles[0]",
     "<< merges mappings only"),
    ("hole-5000-digit-par", "hole", "name: M\npar: " + "9" * 5000 + "\ntiles: []\n", 2, "par", "5000 digits: too long"),
    # YAML's own tags on text they cannot read: PyYAML's constructors raised IndexError, KeyError or
    # AttributeError, a traceback (QA, stop 31)
    ("hole-int-tag-empty", "hole", _sub(HOLE, "par: 3", 'par: !!int ""'), 2, "par", "'' is not a YAML int"),
    ("hole-float-tag-empty", "hole", _sub(HOLE, "par: 3", 'par: !!float ""'), 2, "par", "not a YAML float"),
    ("hole-bool-tag-word", "hole", _sub(HOLE, "name: Case", "name: !!bool foo"), 1, "name", "foo is not a YAML bool"),
    ("hole-timestamp-tag-word", "hole", _sub(HOLE, "name: Case", "name: !!timestamp foo"), 1, "name",
     "not a YAML timestamp"),
    ("hole-int-tag-key", "hole", _sub(HOLE, "par: 3", 'par: 3\n? !!int ""\n: 1'), 3, "(top level)", "not a YAML int"),
    # A hex integer past Python's 4300 digits got past the digits check and the message could not be written.
    ("hole-hex-name", "hole", _sub(HOLE, "name: Case", "name: 0x" + "f" * 4000), 1, "name",
     "integer of about 4817 digits"),
    # YAML 1.1's base-60 integer: PyYAML's loop is quadratic (900 KB of it took 46 s), refused unread.
    ("hole-base-60-par", "hole", "name: M\npar: 1" + ":59" * 3000 + "\ntiles: []\n", 2, "par", "digits: too long"),
    ("hole-zero-width-name", "hole", _sub(HOLE, "name: Case", 'name: "Case\\u200b"'), 1, "name",
     "invisible character, got U+200B"),
    ("hole-huge-tile-index", "hole", _sub(HOLE, "[1, 0]", "[100000000000000000, 0]"), 5, "tiles[1].at[0]",
     "less than or equal to 100"),
    ("hole-python-name-tag", "hole", _sub(HOLE, "name: Case", "name: !!python/name:os.system x"), 1, "name",
     "not allowed"),
    ("hole-python-object-tag", "hole", _sub(HOLE, "name: Case", "name: !!python/object:os.system {}"), 1, "name",
     "not allowed"),
    ("hole-unknown-border", "hole", _sub(HOLE, "open-w}", "open-x}"), 5, "tiles[1].borders", "unknown border set"),
    ("hole-unknown-pattern", "hole", _sub(HOLE, "open-w}", "open-w, pattern: nope}"), 5, "tiles[1].pattern",
     "unknown pattern"),
    ("hole-open-to-nothing", "hole", _sub(HOLE, "borders: open-w}", "borders: open-ew}"), 5, "tiles[1].borders",
     "opens onto no tile"),
    ("hole-par-zero", "hole", _sub(HOLE, "par: 3", "par: 0"), 2, "par", "greater than or equal to 1"),
    ("hole-par-float", "hole", _sub(HOLE, "par: 3", "par: 3.5"), 2, "par", "valid integer"),
    ("hole-par-string", "hole", _sub(HOLE, "par: 3", "par: three"), 2, "par", "valid integer"),
    ("hole-no-tiles", "hole", _sub(HOLE, "tiles:", "tiles: []\nextra:"), 3, "tiles", "at least 1"),
    ("hole-rotate-45", "hole", _sub(HOLE, "open-w}", "open-w, rotate: 45}"), 5, "tiles[1].rotate", "90"),
    ("hole-unknown-key", "hole", _sub(HOLE, "par: 3", "par: 3\ncolour: red"), 3, "colour", "unknown key"),
    ("hole-green-inf", "hole", _sub(HOLE, "par: 3", "par: 3\ngreen: {linear: .inf}"), 3, "green.linear", "finite"),
    ("hole-green-negative", "hole", _sub(HOLE, "par: 3", "par: 3\ngreen: {rolling: -1}"), 3, "green.rolling",
     "greater than or equal to 0"),
    ("hole-launch-nan", "hole", _sub(HOLE, "par: 3", "par: 3\nlaunch: {velocity: [.nan, 0]}"), 3,
     "launch.velocity[0]", "finite"),
    ("hole-launch-every-zero", "hole", _sub(HOLE, "par: 3", "par: 3\nlaunch: {velocity: [1, 0], every: 0}"), 3,
     "launch.every", "greater than or equal to 0.1"),
    ("hole-effects-unknown", "hole", _sub(HOLE, "par: 3", "par: 3\neffects: [lava]"), 3, "effects[0]",
     "Input should be"),
    ("hole-effects-listed-absent", "hole", _sub(HOLE, "par: 3", "par: 3\neffects: [drag, sand]"), 3, "effects[1]",
     "the hole holds no sand"),
    ("hole-effects-leave-out-launch", "hole",
     _sub(HOLE, "par: 3", "par: 3\nlaunch: {velocity: [1, 0]}\neffects: [drag]"), 4, "effects",
     "leaves out launch, which the hole holds"),
    ("hole-effects-leave-out-hazards", "hole",
     "name: Eff\npar: 3\neffects: [sand]\ntiles:\n  - {at: [0, 0], borders: open-e}\n"
     "  - {at: [1, 0], borders: open-ew, pattern: windmill}\n  - {at: [2, 0], borders: open-ew, pattern: pond-middle}\n"
     "  - {at: [3, 0], borders: open-w}\n", 3, "effects", "leaves out water, windmill, which the hole holds"),
    ("hole-gate-wider-than-tile", "hole", _sub(HOLE, "borders: open-e}", "borders: {e: {gate: 100}}}"), 4,
     "tiles[0].borders.e.gate", "leaves no wall either side of it"),
    ("hole-duplicate-tile", "hole", _sub(HOLE, "[1, 0], borders: open-w}", "[0, 0], borders: open-w}"), 5,
     "tiles[1].at", "already used"),
    ("hole-list-top", "hole", "- just\n- a list\n", 1, "(top level)", "should be a mapping"),
    ("hole-yaml-syntax", "hole", _sub(HOLE, "tiles:", "tiles: [oops"), 4, "(yaml)", "expected"),
    ("hole-tab-indent", "hole", HOLE.replace("  - {at: [1, 0]", "\t- {at: [1, 0]"), 5, "(yaml)", ""),
    ("hole-bool-key", "hole", _sub(HOLE, "par: 3", "par: 3\ntrue: 1"), 3, "(top level)", "keys must be names"),
    # A pattern named `1e5` or `2024-01-01` is a number or a date to YAML: the line says so (QA, stop 31).
    ("library-number-named-pattern", "library", _sub(LIBRARY, "patterns:\n", "patterns:\n  1e5: []\n"), None,
     "patterns", "1e5 reads as a number in YAML (quote it)"),
    ("library-date-named-pattern", "library", _sub(LIBRARY, "patterns:\n", "patterns:\n  2024-01-01: []\n"), None,
     "patterns", "reads as a date in YAML"),
    ("hole-long-name", "hole", _sub(HOLE, "name: Case", "name: " + "x" * 200), 1, "name", "at most 100"),
    ("hole-inline-border-bad", "hole", _sub(HOLE, "borders: open-w}", "borders: {w: opn}}"), 5,
     "tiles[1].borders.w", "'open' or 'wall'"),
    # --- tile library ------------------------------------------------------------------------
    ("tiles-size-inf", "library", _sub(LIBRARY, "tile_size: 6.0", "tile_size: .inf"), 4, "tile_size", "finite"),
    ("tiles-size-huge", "library", _sub(LIBRARY, "tile_size: 6.0", "tile_size: 1.0e+9"), 4, "tile_size",
     "less than or equal to 100"),
    ("tiles-gate-wider-than-tile", "library", _sub(LIBRARY, "gate-e: {e: {gate: 1.6}}", "gate-e: {e: {gate: 6}}"), 40,
     "border_sets.gate-e.e.gate", "a gate 6 m wide on a 6 m tile"),
    ("tiles-thick-walls", "library", _sub(LIBRARY, "wall_thickness: 0.3", "wall_thickness: 2.5"), None, None,
     "quarter of the tile"),
    ("tiles-restitution-5", "library", _sub(LIBRARY, "restitution: 0.6", "restitution: 5"), None,
     "ball.restitution", "less than or equal to 1"),
    ("tiles-friction-negative", "library", _sub(LIBRARY, "friction: 0.3", "friction: -0.3"), None, "ball.friction",
     "greater than or equal to 0"),
    ("tiles-density-denormal", "library", _sub(LIBRARY, "density: 1.0", "density: 5.0e-324"), None, "ball.density",
     "greater than or equal to 0.001"),
    ("tiles-cup-speed-inf", "library", _sub(LIBRARY, "max_speed: 4.0", "max_speed: .inf"), None,
     "cup.max_speed", "finite"),
    ("tiles-kick-inf", "library", _sub(LIBRARY, "kick: 3.0", "kick: .inf"), None, None, "finite"),
    ("tiles-kick-zero", "library", _sub(LIBRARY, "kick: 3.0", "kick: 0"), None, None, "greater than 0"),
    ("tiles-windmill-nan", "library", _sub(LIBRARY, "speed: 1.2", "speed: .nan"), None, None, "finite"),
    ("tiles-windmill-fast", "library", _sub(LIBRARY, "speed: 1.2", "speed: 500"), None, None,
     "less than or equal to 20"),
    ("tiles-push-huge", "library", re.sub(r"push: \[[^]]*\]", "push: [1.0e+308, 0]", LIBRARY, count=1), None, None,
     "less than or equal to 100"),
    ("tiles-no-empty", "library", _sub(LIBRARY, "  empty: []\n", ""), None, "patterns", "needs an 'empty' pattern"),
    ("tiles-huge-box", "library", _sub(LIBRARY, "half: [0.5, 0.5]", "half: [1.0e+12, 1.0e+12]"), None, None,
     "less than or equal to 1000"),
    ("tiles-slope-no-push", "library", re.sub(r"push: \[[^]]*\], ", "", LIBRARY, count=1), None, None,
     "needs 'push'"),
    ("tiles-bad-name", "library", _sub(LIBRARY, "  open-n: {n: open}", "  ../evil: {n: open}"), None, None,
     "a name is letters"),
    # --- courses -----------------------------------------------------------------------------
    ("courses-dotdot", "courses", COURSES.replace("[case]", "[../../etc/passwd]"), 3, "courses[0].holes[0]",
     "a hole is named by its file in this folder"),
    ("courses-absolute", "courses", COURSES.replace("[case]", "[/tmp/case]"), 3, "courses[0].holes[0]",
     "a hole is named by its file in this folder"),
    ("courses-missing-hole", "courses", COURSES.replace("[case]", "[nowhere]"), 3, "courses[0].holes[0]",
     "no hole file"),
    ("courses-empty", "courses", "courses: []\n", 1, "courses", "at least 1"),
    ("courses-holes-not-list", "courses", COURSES.replace("[case]", "case"), 3, "courses[0].holes", "valid list"),
    ("courses-no-name", "courses", "courses:\n  - holes: [case]\n", 2, "courses[0].name", "missing"),
    ("courses-empty-name", "courses", "courses:\n  - name: ''\n    holes: [case]\n", 2, "courses[0].name",
     "at least 1"),
    ("courses-newline-name", "courses", COURSES.replace("Case", '"Line\\nBreak"'), 2, "courses[0].name",
     "control characters, got U+000A"),
    ("courses-nul", "courses", COURSES.encode().replace(b"Case", b"C\x00"), 2, "(file)", "control character"),
    # --- themes ------------------------------------------------------------------------------
    ("theme-bad-colour", "theme", _sub(THEME, '"#4f9d4a"', '"green"'), 5, "green", 'a colour is "#RRGGBB"'),
    ("theme-ball-the-green-s-colour", "theme", _sub(THEME, 'ball: "#ffd54f"', 'ball: "#50a04a"'), 15, "ball",
     "too close to green (#4f9d4a) to tell apart"),
    ("theme-ball-the-ice-s-colour", "theme", re.sub(r'\nice: "[^"]*"', '\nice: "#fdd04f"', THEME, count=1), 15, "ball",
     "too close to ice (#fdd04f)"),
    # A colour with alpha 00 is invisible, whatever its RGB (QA: the ball, cup and text all gone).
    ("theme-see-through-ball", "theme", _sub(THEME, 'ball: "#ffd54f"', 'ball: "#ffd54f00"'), 15, "ball",
     "as see-through as it is"),
    ("theme-see-through-text", "theme", _sub(THEME, 'text: "#ffffff"', 'text: "#ffffff10"'), 19, "text",
     "too close to background"),
    ("theme-missing-colour", "theme", re.sub(r"\nwall: [^\n]*", "", THEME, count=1), 3, "wall", "missing"),
    ("theme-number-colour", "theme", _sub(THEME, '"#4f9d4a"', "123456"), 5, "green", "valid string"),
    ("theme-unknown-key", "theme", THEME + "sparkle: \"#ffffff\"\n", None, "sparkle", "unknown key"),
    ("theme-latin1", "theme", THEME.encode().replace(b"Grass", "Gr\xe4ss".encode("latin-1")), 3, "(file)",
     "not UTF-8"),
    # --- scenes ------------------------------------------------------------------------------
    ("scene-velocity-minus-inf", "scene", _sub(SCENE, "[-10.0, 0.0]", "[-.inf, 0]"), 6, "bodies[0].velocity[0]",
     "finite"),
    ("scene-velocity-1e308", "scene", _sub(SCENE, "[-10.0, 0.0]", "[-1.0e+308, 0]"), 6, "bodies[0].velocity[0]",
     "greater than or equal to -1000"),
    ("scene-density-denormal", "scene", _sub(SCENE, "    velocity:", "    density: 5.0e-324\n    velocity:"), 6,
     "bodies[0].density", "greater than or equal to 0.001"),
    ("scene-angle-inf", "scene", _sub(SCENE, "    velocity:", "    angle: .inf\n    velocity:"), 6,
     "bodies[0].angle", "finite"),
    ("scene-position-nan", "scene", _sub(SCENE, "[3.0, 0.0]", "[.nan, 0.0]"), 5, "bodies[0].position[0]",
     "finite"),
    ("scene-gravity-nan", "scene", _sub(SCENE, "bodies:", "gravity: [0, .nan]\nbodies:"), 2, "gravity[1]",
     "finite"),
    ("scene-star-100000", "scene", _sub(SCENE, "{regular: 4, radius: 0.5}", "{star: [100000, 2], radius: 0.5}"), 4,
     "bodies[0].shape.star[0]", "less than or equal to 64"),
    ("scene-many-vertices", "scene", _sub(SCENE, "{regular: 4, radius: 0.5}", "{vertices: [" + ", ".join(
        f"[{i}, {i * i % 7}]" for i in range(10_000)) + "]}"), 4, "bodies[0].shape.vertices", "at most 64"),
    ("scene-wall-4000-vertices", "scene", _sub(SCENE, "  - box: {center: [-1.0, 0.0], half: [1.0, 5.0]}",
                                                 "  - polygon: [" + ", ".join(f"[{i}, {i % 2}]" for i in range(4000))
                                                 + "]"), 8, "walls[0].polygon", "at most 64"),
    ("scene-huge-wall", "scene", _sub(SCENE, "half: [1.0, 5.0]", "half: [1.0e+12, 1.0e+12]"), 8,
     "walls[0].box.half[0]", "less than or equal to 1000"),
    ("scene-restitution-5", "scene", _sub(SCENE, "    velocity:", "    restitution: 5\n    velocity:"), 6,
     "bodies[0].restitution", "less than or equal to 1"),
    ("scene-radius-zero", "scene", _sub(SCENE, "radius: 0.5", "radius: 0"), 4, "bodies[0].shape.radius",
     "greater than or equal to 0.01"),
    ("scene-radius-tiny-vertices", "scene", _sub(SCENE, "{regular: 4, radius: 0.5}",
                                                   "{vertices: [[0, 0], [1.0e-300, 0], [0, 1.0e-300]]}"), 4,
     "bodies[0].shape", "zero area"),
    ("scene-spin-huge", "scene", _sub(SCENE, "    velocity:", "    spin: 1.0e+9\n    velocity:"), 6,
     "bodies[0].spin", "less than or equal to 1000"),
    ("scene-seed-negative", "scene", _sub(SCENE, "{regular: 4, radius: 0.5}",
                                          "{random: {seed: -1, vertices: 6}, radius: 0.5}"), 4,
     "bodies[0].shape.random.seed", "greater than or equal to 0"),
    ("scene-bodies-empty", "scene", _sub(_sub(SCENE, "bodies:\n", "bodies: []\nx:\n"), "  - name: ball\n", ""),
     None, None, ""),
    ("scene-empty-file", "scene", "", 1, "(top level)", "should be a mapping"),
    ("scene-name-blank", "scene", _sub(SCENE, "name: ball", 'name: "   "'), 3, "bodies[0].name", "spaces"),
    ("scene-name-invisible", "scene", _sub(SCENE, "name: ball", 'name: "\\u200b"'), 3, "bodies[0].name",
     "digit or sign that shows"),
    ("scene-name-override", "scene", _sub(SCENE, "name: ball", 'name: "\\u202eball"'), 3, "bodies[0].name",
     "U+202E"),
    ("scene-vertices-huge", "scene", _sub(SCENE, "shape: {regular: 4, radius: 0.5}",
                                          "shape: {vertices: [[0, 0], [90000, 0], [0, 90000]]}"),
     4, "bodies[0].shape", "at most 50 m"),
    ("scene-heap", "scene", "name: heap\nbodies:\n" + "".join(f"  - {{name: b{k}, shape: {{regular: 3, radius: 1}}, "
                                                          "position: [0, 0]}\n" for k in range(20)),
     1, "(top level)", "190 pairs of bodies start within reach of each other"),
    ("scene-hole-missing", "scene", _sub(SCENE, "bodies:\n", "hole: meadow:99\nbodies:\n"), 2, "hole", "holes 1 to 9"),
    ("scene-hole-path", "scene", _sub(SCENE, "bodies:\n", "hole: ../../etc/passwd\nbodies:\n"), 2, "hole",
     "not a hole file beside the scene"),
    ("scene-form-feed", "scene", _sub(SCENE, "bodies:\n", "# a\x0cb\nbodies:\n"), 2, "(file)", "U+000C"),
    ("scene-line-separator", "scene", _sub(SCENE, "bodies:\n", "# a\u2028b\nbodies:\n"), 2, "(file)", "U+2028"),
    ("scene-binary", "scene", bytes(range(256)) * 4, None, "(file)", "not UTF-8"),
    ("scene-too-big", "scene", SCENE + "# " + "x" * (1 << 20) + "\n", 0, "(file)", "at most 1024 KiB"),
]


@contextmanager
def deadline(seconds: int):
    """Fail, rather than hang, if a case takes longer than `seconds`."""
    def expired(*_):
        raise TimeoutError(f"took more than {seconds} s")

    old = signal.signal(signal.SIGALRM, expired)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


def place(tmp_path: Path, kind: str, content) -> Path:
    """Write the case where its kind lives, with good files beside it where it needs them."""
    holes = tmp_path / "holes"
    holes.mkdir()
    shutil.copy(HOLES_DIR / "tiles.yaml", holes / "tiles.yaml")
    (holes / "case.yaml").write_text(HOLE)
    target = {"hole": holes / "case.yaml", "library": holes / "tiles.yaml", "courses": holes / "courses.yaml",
              "theme": tmp_path / "themes" / "case.yaml", "scene": tmp_path / "scenes" / "case.yaml"}[kind]
    target.parent.mkdir(exist_ok=True)
    if isinstance(content, bytes):
        target.write_bytes(content)
    else:
        target.write_text(content)
    return target


@pytest.mark.parametrize(("kind", "content", "line", "field", "message"), [c[1:] for c in CASES],
                         ids=[c[0] for c in CASES])
def test_malformed_content_is_refused_in_one_line(tmp_path, capsys, kind, content, line, field, message):
    path = place(tmp_path, kind, content)
    with deadline(10):
        code = main(["validate", str(path)])
    out, err = capsys.readouterr()
    assert code == 1, f"accepted: {out}{err}"
    assert "Traceback" not in err
    problems = err.strip().splitlines()
    assert problems, "no problem reported"
    first = LINE.match(problems[0])
    assert first, f"not one line file:line: field: message: {problems[0]!r}"
    assert Path(first["file"]) == path
    if line is not None:
        assert int(first["line"]) == line, problems[0]
    if field is not None:
        assert first["field"] == field, problems[0]
    assert message.lower() in err.lower(), problems
    assert all(LINE.match(p) for p in problems), problems
    assert re.fullmatch(r"1 file checked, \d+ problems?", out.strip().splitlines()[-1]), out


def test_every_duplicate_key_of_a_file_is_reported(tmp_path, capsys):
    """Not only the first (QA: three keys written twice, one line)."""
    text = _sub(_sub(HOLE, "name: Case", "name: Case\nname: Again"), "par: 3", "par: 3\npar: 4")
    path = place(tmp_path, "hole", text.replace("{at: [0, 0],", "{at: [0, 0], at: [5, 5],"))
    assert main(["validate", str(path)]) == 1
    out, err = capsys.readouterr()
    assert err.strip().splitlines() == [f"{path}:2: name: duplicate key", f"{path}:4: par: duplicate key",
                                        f"{path}:6: tiles[0].at: duplicate key"]
    assert out.strip().splitlines()[-1] == "1 file checked, 3 problems"


def test_the_corpus_is_large_and_covers_every_kind():
    kinds = {c[1] for c in CASES}
    assert len(CASES) >= 60 and kinds == {"hole", "library", "courses", "theme", "scene"}


@pytest.mark.parametrize(("case", "args", "message"), [
    ("seconds-inf", ["simulate", "SCENE", "--seconds", "inf"], "--seconds"),
    ("seconds-nan", ["simulate", "SCENE", "--seconds", "nan"], "--seconds"),
    ("seconds-negative", ["simulate", "SCENE", "--seconds", "-5"], "--seconds"),
    ("seconds-zero", ["simulate", "SCENE", "--seconds", "0"], "--seconds"),
    ("seconds-huge", ["simulate", "SCENE", "--seconds", "1e9"], "--seconds"),
    ("seconds-under-a-frame", ["simulate", "SCENE", "--seconds", "1e-300"], "less than a frame"),
    ("seconds-word", ["simulate", "SCENE", "--seconds", "long"], "--seconds"),
    ("scene-missing", ["simulate", "nowhere.yaml"], "nowhere.yaml:0: (file)"),
    ("render-folder-is-a-file", ["render", "meadow", "2", "--out", "FILE/y.png"], "--out"),
    ("render-not-png", ["render", "meadow", "2", "--out", "OUT/picture.txt"], "--out"),
    ("render-bad-hole", ["render", "meadow", "99", "--out", "OUT/x.png"], "holes 1 to 9"),
    ("render-bad-course", ["render", "nowhere", "1", "--out", "OUT/x.png"], "no course"),
    ("shape-huge", ["render", "meadow", "1", "--shape", "100000", "--out", "OUT/x.png"], "--shape"),
    ("shape-empty", ["render", "meadow", "1", "--shape", "", "--out", "OUT/x.png"], "--shape"),
    ("shape-star-bad", ["render", "meadow", "1", "--shape", "star-6-3", "--out", "OUT/x.png"], "--shape"),
    ("theme-unknown", ["render", "meadow", "1", "--theme", "lava", "--out", "OUT/x.png"], "no theme"),
    ("explain-missing", ["explain", "nowhere:1"], "no course"),
    # `str.isdigit` took other scripts' digits (`--seed ١٢` was 12) and `²`, whose int() then failed in
    # argparse's own words; 5,000 digits were echoed whole (QA, stop 31).
    ("seed-arabic-indic", ["render", "random-nine", "1", "--seed", "١٢", "--out", "OUT/x.png"], "'١٢' is not a seed"),
    ("seed-superscript", ["render", "random-nine", "1", "--seed", "²", "--out", "OUT/x.png"], "'²' is not a seed"),
    ("seed-5000-digits", ["render", "random-nine", "1", "--seed", "9" * 5000, "--out", "OUT/x.png"], "'... is not a"),
    ("players-arabic-indic", ["render", "meadow", "1", "--players", "٢", "--out", "OUT/x.png"], "'٢' is not"),
])
def test_bad_arguments_get_one_line_and_exit_2(tmp_path, capsys, case, args, message):
    (tmp_path / "file.txt").write_text("not a folder")
    args = [a.replace("SCENE", str(SCENES_DIR / "flat-wall.yaml")).replace("OUT", str(tmp_path))
            .replace("FILE", str(tmp_path / "file.txt")) for a in args]
    with deadline(20):
        code = _exit_code(args)
    out, err = capsys.readouterr()
    assert code == 2, (out, err)
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err, err
    assert message in lines[0], lines[0]


def _exit_code(args) -> int:
    try:
        return main(args)
    except SystemExit as exc:  # argparse's own refusal
        return int(exc.code)


def test_simulate_json_is_strict_json_even_when_the_numbers_are_not(tmp_path, capsys):
    path = tmp_path / "far.yaml"
    path.write_text(SCENE.replace("[-10.0, 0.0]", "[-1000.0, 0.0]").replace("walls:\n  - box: {center: [-1.0, 0.0], "
                                                                          "half: [1.0, 5.0]}\n", ""))
    assert main(["simulate", str(path), "--seconds", "2", "--json"]) == 0
    text = capsys.readouterr().out
    report = json.loads(text, parse_constant=lambda name: pytest.fail(f"{name} in the JSON"))
    assert report["bodies"][0]["position"][0] < 0


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="FIFOs and /dev/zero are POSIX")
def test_a_pipe_or_a_device_is_refused_unread_in_one_line(tmp_path, capsys):
    """A FIFO would wait for a writer for ever and /dev/zero never ends (both say size 0)."""
    fifo = tmp_path / "pipe.yaml"
    os.mkfifo(fifo)
    for args, status in ((["simulate", str(fifo)], 2), (["validate", str(fifo)], 1), (["simulate", "/dev/zero"], 2),
                         (["validate", "/dev/zero"], 1), (["replay", "--verify", "/dev/zero"], 2)):
        with deadline(10):
            code = main(args)
        err = capsys.readouterr().err.strip().splitlines()
        assert code == status and len(err) == 1, (args, err)
        assert args[-1] in err[0] and "not a regular file" in err[0], err[0]


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="FIFOs and /dev/zero are POSIX")
def test_generate_refuses_to_write_onto_a_pipe_or_a_device_before_the_proof(tmp_path, capsys):
    """It proved the hole, then waited for ever on the FIFO, or read /dev/zero until memory ran out
    (the old file's text was read to keep it aside; QA, stop 31)."""
    os.mkfifo(tmp_path / "pipe.yaml")
    (tmp_path / "zero.yaml").symlink_to("/dev/zero")
    for name in ("pipe.yaml", "zero.yaml"):
        with deadline(10):
            code = main(["generate", "--seed", "1", "--out", str(tmp_path / name)])
        err = capsys.readouterr().err.strip().splitlines()
        assert code == 2 and err == [f"polygolf: --out: cannot write {tmp_path / name}: not a regular file"]


@pytest.mark.parametrize("args", [["explain", ""], ["simulate", ""], ["simulate", "a" * 300],
                                  ["explain", "meadow:" + "9" * 300], ["validate", "a" * 300 + ".yaml"]])
def test_an_empty_or_overlong_name_on_the_command_line_is_one_line(args, capsys):
    """An empty path has no parts and a name longer than the system allows makes `Path.is_file`
    raise: both were tracebacks (QA, stop 31)."""
    with deadline(20):
        code = _exit_code(args)
    err = capsys.readouterr().err
    assert code == 2 and len(err.strip().splitlines()) == 1 and "Traceback" not in err, err
    assert len(err) < 200


def test_a_windmill_far_from_the_origin_is_the_windmill_its_library_accepted(tmp_path, capsys):
    """The layout checked each placed windmill again, with a tolerance that grows with the distance
    from the origin: a notched arm the library accepts read as crossing itself on a tile 10 km out,
    and the error named no file (with it in the player's content, no course loaded; QA, stop 31)."""
    from polygolf.engine.golf.holes import load_hole_file

    notched = "[[-2, -0.6], [2, -0.4], [2, 0.5], [0.1, 0.5], [0, -0.49999], [-0.1, 0.5], [-2, 0.5]]"
    library = _sub(_sub(LIBRARY, "tile_size: 6.0", "tile_size: 100.0"), "patterns:\n",
                   f"patterns:\n  notched-mill:\n    - {{hazard: windmill, speed: 1.0, polygon: {notched}}}\n")
    (tmp_path / "tiles.yaml").write_text(library)
    arms = []
    for name, first in (("near", 0), ("far", 98)):
        (tmp_path / f"{name}.yaml").write_text(f"name: {name}\npar: 3\ntiles:\n  - {{at: [{first}, 0]}}\n"
                                               f"  - {{at: [{first + 1}, 0], pattern: notched-mill}}\n"
                                               f"  - {{at: [{first + 2}, 0]}}\n")
        assert main(["validate", str(tmp_path / f"{name}.yaml")]) == 0, capsys.readouterr().err
        arms.append(load_hole_file(tmp_path / f"{name}.yaml").layout.windmills[0])
    (near, (nx, _), _), (far, (fx, _), _) = arms
    assert fx - nx == pytest.approx(9800.0)
    assert len(far) == len(near) and max(math.dist(a, b) for a, b in zip(far, near)) < 1e-9


@pytest.fixture
def content_copy(tmp_path, monkeypatch):
    """A copy of the shipped content, used as the game's content folder; no user content."""
    from polygolf.engine.loading import paths

    root = tmp_path / "content"
    shutil.copytree(paths.CONTENT_DIR, root)
    monkeypatch.setattr(paths, "CONTENT_DIR", root)
    monkeypatch.setenv("POLYGOLF_DATA", str(tmp_path / "data"))
    return root


def test_a_broken_theme_is_left_out_and_the_rest_play(content_copy):
    from polygolf.game.session import Game

    (content_copy / "themes" / "night.yaml").write_bytes(b"name: Night\nbackground: \xff\n")
    game = Game.load()
    assert [t.name for t in game.themes] == ["Grass", "Sand"]
    assert len(game.problems) == 1 and "night.yaml:2: (file): not UTF-8" in game.problems[0]
    assert len(game.courses) == 4


def test_asking_for_a_theme_that_could_not_be_read_says_why(content_copy, tmp_path, capsys):
    """`--theme night` with night.yaml broken said only "no theme 'night'" (QA's see-through theme)."""
    night = content_copy / "themes" / "night.yaml"
    night.write_text(re.sub(r'\nball: "#?[0-9a-fA-F]*"', '\nball: "#ffd54f00"', night.read_text(), count=1))
    code = main(["render", "meadow", "1", "--theme", "night", "--out", str(tmp_path / "x.png")])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1, err
    assert err[0].startswith("polygolf: no theme 'night'; themes: grass, sand; not read: ") and str(night) in err[0]
    assert "see-through" in err[0]


def test_every_theme_broken_falls_back_to_a_plain_palette(content_copy):
    from polygolf.game.session import Game
    from polygolf.game.theme import FALLBACK

    for path in (content_copy / "themes").glob("*.yaml"):
        path.write_text("name: [unclosed\n")
    game = Game.load()
    assert game.themes == [FALLBACK] and len(game.problems) == 3


def test_a_broken_courses_file_costs_its_courses_not_the_game(content_copy):
    from polygolf.game.session import Game

    (content_copy / "holes" / "courses.yaml").write_text("courses: {not: a list}\n")
    game = Game.load()
    assert game.courses == [] and game.course is None
    assert "courses.yaml:1: courses" in game.problems[0]


def test_a_broken_hole_is_skipped_and_the_course_plays_on(content_copy):
    from polygolf.engine.golf.holes import load_all_courses

    (content_copy / "holes" / "zig-zag.yaml").write_bytes(b"name: Zig\x00Zag\n")
    courses, problems = load_all_courses()
    meadow = courses[0]
    assert problems == []
    assert [type(h).__name__ for h in meadow.holes].count("ContentError") == 1
    assert "zig-zag.yaml:1: (file): control character U+0000" in str(meadow.holes[2])
    assert len(meadow.playable) == 8


def test_render_of_a_good_hole_works_beside_a_broken_one(content_copy, tmp_path):
    (content_copy / "holes" / "zig-zag.yaml").write_text("name: Zig\npar: 3\ntiles: [{at: [1e99, 0]}]\n")
    out = tmp_path / "castle.png"
    assert main(["render", "meadow", "9", "--out", str(out)]) == 0
    assert out.stat().st_size > 10_000
    assert main(["render", "meadow", "3", "--out", str(tmp_path / "zz.png")]) == 2


def test_player_content_is_added_to_the_shipped_content(content_copy, tmp_path):
    from polygolf.engine.loading.paths import user_content_dir
    from polygolf.game.session import Game

    mine = user_content_dir()
    (mine / "holes").mkdir(parents=True)
    (mine / "themes").mkdir()
    (mine / "holes" / "my-hole.yaml").write_text("name: Mine\npar: 2\ntiles:\n  - {at: [0, 0]}\n  - {at: [1, 0]}\n")
    (mine / "holes" / "courses.yaml").write_text("courses:\n  - name: My Course\n    holes: [my-hole]\n")
    theme = (content_copy / "themes" / "grass.yaml").read_text().replace("name: Grass", "name: Mine")
    (mine / "themes" / "mine.yaml").write_text(theme)
    game = Game.load()
    assert [c.name for c in game.courses][-1] == "My Course"
    mine_course = game.courses[-1]
    assert [h.spec.name for h in mine_course.playable] == ["Mine"]
    assert "Mine" in [t.name for t in game.themes]
    assert main(["validate"]) == 0


def test_a_file_where_the_players_content_folder_belongs_is_said_not_passed_over(content_copy, capsys):
    """content/, content/holes or content/themes written as a file: nothing in it can be read, and
    the menu's problems and `validate` say so, each once, at the file."""
    from polygolf.engine.loading.paths import user_content_dir
    from polygolf.game.session import Game

    mine = user_content_dir()
    mine.mkdir(parents=True)
    (mine / "holes").write_text("courses: []\n")
    (mine / "themes").write_text("name: Mine\n")
    game = Game.load()
    said = [f"{mine / name}:0: (file): a file where a folder belongs" for name in ("holes", "themes")]
    assert [p.split(": nothing")[0] for p in game.problems] == said
    assert "meadow" in [c.id for c in game.courses]  # the shipped courses play
    assert main(["validate"]) == 1
    assert [line.split(": nothing")[0] for line in capsys.readouterr().err.strip().splitlines()] == said
    (mine / "holes").unlink()
    (mine / "themes").unlink()
    mine.rmdir()
    mine.write_text("")
    problems = Game.load().problems
    assert [p.split(": nothing")[0] for p in problems] == [f"{mine}:0: (file): a file where a folder belongs"]
    assert main(["validate"]) == 1


@pytest.mark.parametrize(("key", "shown"), [
    ("a\nb: c", "'a\\nb: c'"), ("abc\rXYZ", "'abc\\rXYZ'"), ("\x1b[31mRED\x1b[0m", "'\\x1b[31mRED\\x1b[0m'"),
    ("\u202egnp.exe", "'\\u202egnp.exe'"), (" padded", "' padded'"), ("k" * 400_000, "'" + "k" * 40 + "'...")],
    ids=["line-break", "carriage-return", "escape-code", "bidi-override", "padded", "400-kb"])
def test_an_unknown_key_is_named_in_one_short_line_with_its_escapes(tmp_path, capsys, key, shown):
    """Whatever an unknown key holds (a line break, a carriage return, a terminal's escape code, a
    direction override, 400 KB), the error stays one line naming it with its escapes, cut short.
    (It was printed as written: a line break split the "one-line" error; an escape code coloured the
    terminal.)"""
    path = tmp_path / "case.yaml"
    path.write_text(HOLE + f"? {json.dumps(key)}\n: 1\n")  # (an explicit key: YAML's plain ones stop at 1 024)
    assert main(["validate", str(path)]) == 1
    err = capsys.readouterr().err
    assert err == f"{path}:6: {shown}: unknown key\n"


def test_a_course_may_not_take_another_courses_id(content_copy, capsys):
    """A course's id names its bests and replays: the player's own content may not reuse the shipped
    content's, one file may not name two courses alike, and none may be Random nine or a seed's nine."""
    from polygolf.engine.loading.paths import user_content_dir

    mine = user_content_dir() / "holes"
    mine.mkdir(parents=True)
    (mine / "my-hole.yaml").write_text("name: Mine\npar: 2\ntiles:\n  - {at: [0, 0]}\n  - {at: [1, 0]}\n")
    for courses, line, taken in (("Meadow", 2, "another content folder"), ("Random Nine", 2, "Random nine"),
                                 ("Random Nine 7", 2, "Random nine's seeds"),  # (seed 7's nine: random-nine-7)
                                 ("Mine\n    holes: [my-hole]\n  - name: mine", 4, "courses[0] 'Mine'")):
        (mine / "courses.yaml").write_text(f"courses:\n  - name: {courses}\n    holes: [my-hole]\n")
        assert main(["validate", str(mine / "courses.yaml")]) == 1
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and err[0].startswith(f"{mine / 'courses.yaml'}:{line}: courses[") and taken in err[0]
    (mine / "courses.yaml").write_text("courses:\n  - name: My Course\n    holes: [my-hole]\n")
    assert main(["validate"]) == 0


def test_every_problem_of_a_courses_file_is_reported_at_once(content_copy, capsys):
    """Names that refuse the file and unknown holes alike: fixing one should not reveal the next."""
    from polygolf.engine.loading.paths import user_content_dir

    mine = user_content_dir() / "holes"
    mine.mkdir(parents=True)
    (mine / "good.yaml").write_text("name: Good\npar: 2\ntiles:\n  - {at: [0, 0]}\n  - {at: [1, 0]}\n")
    (mine / "courses.yaml").write_text("courses:\n  - name: RANDOM NINE\n    holes: [good]\n  - name: 'a:b'\n"
                                       "    holes: [good, missing]\n")
    assert main(["validate", str(mine / "courses.yaml")]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert [line.split(": ")[1] for line in err] == ["courses[0].name", "courses[1].name", "courses[1].holes[1]"], err
    assert "taken by Random nine" in err[0] and "may not hold ':'" in err[1] and "no hole file missing.yaml" in err[2]
    (mine / "loop.yaml").symlink_to(mine / "loop.yaml")  # there, but it cannot be read: says why, not "no file"
    (mine / "courses.yaml").write_text("courses:\n  - name: Mine\n    holes: [good, loop]\n")
    assert main(["validate", str(mine / "courses.yaml")]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"{mine / 'loop.yaml'}:0: (file): " in err[0] and "no hole file" not in err[0], err


def test_a_theme_may_not_take_another_themes_name(content_copy, capsys):
    """The command line and the settings find a theme by its name in any case: the player's theme
    named like a shipped one is left out, with one line at its name, and validate says the same."""
    from polygolf.engine.loading.paths import user_content_dir
    from polygolf.game.theme import load_themes

    mine = user_content_dir() / "themes"
    mine.mkdir(parents=True)
    grass = (content_copy / "themes" / "grass.yaml").read_text()
    assert "\nname: Grass\n" in grass  # (line 3, after two comments)
    (mine / "dusk.yaml").write_text(grass.replace("name: Grass", "name: NIGHT"))
    themes, problems = load_themes()
    assert sorted(t.name for t in themes) == ["Grass", "Night", "Sand"]
    assert [str(p) for p in problems] == [
        f"{mine / 'dusk.yaml'}:3: name: theme name 'NIGHT' is taken by {content_copy / 'themes' / 'night.yaml'}: "
        "give this theme another name"]
    assert main(["validate", str(mine / "dusk.yaml")]) == 1
    assert capsys.readouterr().err.strip().splitlines() == [str(problems[0])]
    assert main(["validate", str(content_copy / "themes" / "night.yaml")]) == 0  # the first one keeps it
    (mine / "dusk.yaml").write_text(grass.replace("name: Grass", "name: Dusk"))
    assert main(["validate"]) == 0
    assert "Dusk" in [t.name for t in load_themes()[0]]


def test_a_course_in_a_courses_file_that_cannot_be_read_says_why(content_copy, tmp_path, capsys):
    """The menu shows a broken courses file's line; the command line, asked for one of its courses,
    said only that there was no such course."""
    from polygolf.engine.loading.paths import user_content_dir

    mine = user_content_dir() / "holes"
    mine.mkdir(parents=True)
    (mine / "courses.yaml").write_text("courses:\n  - name: Mine\n    holes: [../my-hole]\n")
    assert main(["render", "mine", "1", "--out", str(tmp_path / "x.png")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("polygolf: no course 'mine'; courses: meadow, ") \
        and f"; not read: {mine / 'courses.yaml'}:3: courses[0].holes[0]: " in err[0], err


def test_a_hole_is_named_by_its_course_and_number_or_id_everywhere():
    from polygolf.engine.golf.scenes import find_hole

    assert find_hole("meadow:dog-leg", Path.cwd()).id == "dog-leg" == find_hole("meadow:2", Path.cwd()).id
    with pytest.raises(KeyError, match=r"meadow has holes 1 to 9 \(or give a hole's name: straight, dog-leg, "):
        find_hole("meadow:nosuch", Path.cwd())


def test_a_hole_of_one_tile_is_refused_its_tee_would_be_in_the_cup(tmp_path, capsys):
    (tmp_path / "one.yaml").write_text("name: One\npar: 1\ntiles:\n  - {at: [0, 0]}\n")
    assert main(["validate", str(tmp_path / "one.yaml")]) == 1
    assert capsys.readouterr().err.startswith(f"{tmp_path / 'one.yaml'}:3: tiles: a hole needs two tiles or more")


@pytest.mark.parametrize("extra", [["--course", "hazards"], ["--hole", "3"], ["--players", "2"], ["--seed", "4"]])
def test_a_hole_file_played_with_course_options_says_they_are_not_for_it(extra, capsys):
    assert main(["play", str(HOLES_DIR / "straight.yaml"), *extra]) == 2
    assert capsys.readouterr().err == (f"polygolf: {extra[0]}: a hole file is played alone, by one player "
                                       "(they are for a course)\n")


def test_names_on_the_command_line_that_read_as_something_else(content_copy, tmp_path, monkeypatch, capsys):
    """QA of the names: a broken hole named by its id says what is wrong with it; '²' is no hole
    number; a folder named like a scene does not hide it; a course's name may not hold ':' or '/'
    (COURSE:HOLE and paths use them); a theme named ' sand ' or 'SAND' is Sand's; a hole whose library is broken
    does not end `validate --prove` early."""
    from polygolf.engine.loading.paths import user_content_dir

    mine = user_content_dir() / "holes"
    mine.mkdir(parents=True)
    (mine / "good.yaml").write_text("name: Good\npar: 2\ntiles:\n  - {at: [0, 0]}\n  - {at: [1, 0]}\n")
    (mine / "bad.yaml").write_text("name: Bad\npar: 2\ntiles:\n  - {at: [0, 0]}\n  - {at: [1, 0], borders: nosuch}\n")
    (mine / "courses.yaml").write_text("courses:\n  - name: Mine\n    holes: [good, bad]\n")
    assert main(["explain", "mine:bad"]) == 2
    assert capsys.readouterr().err.startswith(f"polygolf: {mine / 'bad.yaml'}:5: tiles[1].borders: unknown border set")
    assert main(["explain", "meadow:\u00b2"]) == 2
    assert capsys.readouterr().err.startswith("polygolf: meadow has holes 1 to 9 (or give a hole's name: straight, ")
    monkeypatch.chdir(tmp_path)
    (tmp_path / "pile").mkdir()
    assert main(["simulate", "pile", "--seconds", "0.05"]) == 0 and capsys.readouterr().out.startswith("pile: ")
    for name in ("Tour: Spring", "Front/Back"):
        (mine / "courses.yaml").write_text(f"courses:\n  - name: '{name}'\n    holes: [good]\n")
        assert main(["validate", str(mine / "courses.yaml")]) == 1
        assert "courses[0].name: a course's name may not hold ':', '/'" in capsys.readouterr().err
    (mine / "courses.yaml").write_text("courses:\n  - name: Mine\n    holes: [good]\n")
    themes = user_content_dir() / "themes"
    themes.mkdir()
    (themes / "dune.yaml").write_text((content_copy / "themes" / "sand.yaml").read_text().replace("name: Sand",
                                                                                                   "name: ' sand '"))
    assert main(["validate", str(themes / "dune.yaml")]) == 1
    assert "name: a name may not start or end with spaces, got ' sand '" in capsys.readouterr().err
    (themes / "dune.yaml").write_text((content_copy / "themes" / "sand.yaml").read_text().replace("name: Sand",
                                                                                                   "name: SAND"))
    assert main(["validate", str(themes / "dune.yaml")]) == 1
    assert "theme name 'SAND' is taken by" in capsys.readouterr().err
    (themes / "dune.yaml").unlink()
    library = tmp_path / "own"
    library.mkdir()
    (library / "tiles.yaml").write_text((content_copy / "holes" / "tiles.yaml").read_text().replace(
        "open-ew: {e: open, w: open}", "open-ew: {e: opn, w: open}"))
    (library / "h.yaml").write_text("name: H\npar: 2\ntiles:\n  - {at: [0, 0]}\n  - {at: [1, 0]}\n")
    assert main(["validate", "--prove", str(library)]) == 1
    out, err = capsys.readouterr()
    assert out.startswith("2 files checked, ") and "tiles.yaml" in err and "Traceback" not in err


def test_ctrl_c_is_one_line(monkeypatch, capsys):
    from polygolf.game import cli

    def interrupted(args):
        raise KeyboardInterrupt

    monkeypatch.setattr(cli, "_scores", interrupted)
    parser = cli.build_parser
    monkeypatch.setattr(cli, "build_parser", lambda: _with_run(parser(), interrupted))
    assert main(["scores"]) == 130
    assert capsys.readouterr().err == "polygolf: stopped\n"


def _with_run(parser, run):
    parser.set_defaults(run=run)
    for action in parser._subparsers._group_actions:  # (each command's own default)
        for sub in action.choices.values():
            sub.set_defaults(run=run)
    return parser


def test_a_link_to_itself_beside_a_watched_hole_does_not_end_the_watching(tmp_path):
    from polygolf.game.watch import FileWatcher

    hole = tmp_path / "hole.yaml"
    hole.write_text("name: first\n")
    watcher = FileWatcher(hole)
    try:
        time.sleep(0.3)  # the watcher's thread is listening
        (tmp_path / "loop.yaml").symlink_to("loop.yaml")  # resolving it raises
        time.sleep(0.5)
        hole.write_text("name: second\n")
        deadline = time.monotonic() + 10.0
        while not watcher.changed() and time.monotonic() < deadline:
            time.sleep(0.05)
        assert time.monotonic() < deadline, "the save after the loop was not seen"
    finally:
        watcher.close()


def _seen(watcher, within: float = 10.0) -> bool:
    """Whether the watcher reports a change within `within` s (a bound against waiting for ever)."""
    deadline = time.monotonic() + within
    while time.monotonic() < deadline:
        if watcher.changed():
            return True
        time.sleep(0.05)
    return False


@pytest.mark.parametrize("how", ["deleted", "renamed"])
def test_a_watched_hole_s_folder_made_again_is_watched_again(tmp_path, how):
    """QA: the folder deleted (or renamed away) and made again, as a `git checkout` does: the watch
    kept the old folder's inode, and no later save was seen, nor any error said."""
    import shutil

    from polygolf.game.watch import FileWatcher

    folder = tmp_path / "holes"
    folder.mkdir()
    hole = folder / "hole.yaml"
    hole.write_text("name: first\n")
    watcher = FileWatcher(hole)
    try:
        time.sleep(0.3)  # the watcher's thread is listening
        if how == "deleted":
            shutil.rmtree(folder)
        else:
            folder.rename(tmp_path / "holes.old")
        assert _seen(watcher)  # the hole gone: a change (the reload says what is wrong)
        folder.mkdir()
        hole.write_text("name: second\n")
        assert _seen(watcher)
        time.sleep(0.5)
        watcher.changed()
        for text in ("name: third\n", "name: fourth\n"):  # saves in the new folder, each seen
            hole.write_text(text)
            assert _seen(watcher), text
    finally:
        watcher.close()


@pytest.mark.parametrize("link", ["hole.yaml", "nowhere.yaml"])
def test_a_watched_hole_made_a_link_to_itself_or_to_nothing_is_a_change(tmp_path, link):
    """QA: the hole file replaced by a link to itself, or to a missing file, was passed over in
    silence (it resolves elsewhere, or not at all): a change, which the reload then names."""
    from polygolf.game.watch import FileWatcher

    hole = tmp_path / "hole.yaml"
    hole.write_text("name: first\n")
    watcher = FileWatcher(hole)
    try:
        time.sleep(0.3)
        hole.unlink()
        assert _seen(watcher)
        time.sleep(0.5)
        watcher.changed()
        hole.symlink_to(link)
        assert _seen(watcher)
    finally:
        watcher.close()


@pytest.mark.parametrize("hole", ["../../../etc/passwd", "/etc/hostname.yaml", "sub/hole.yaml", ".hidden.yaml"])
def test_a_scenes_hole_is_a_file_beside_it_or_a_course_hole(tmp_path, hole, capsys):
    path = tmp_path / "scene.yaml"
    path.write_text(f"hole: {hole}\n" + SCENE)
    assert main(["simulate", str(path), "--seconds", "0.1", "--json"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and LINE.match(err[0].removeprefix("polygolf: ")) and "is not a hole file beside" in err[0]
    assert "root:" not in err[0]


@pytest.mark.parametrize("args", [["render", "random-nine", "10", "--seed", "5", "--out", "x.png"],
                                  ["play", "--course", "random-nine", "--hole", "12", "--seed", "3"],
                                  ["generate", "--seed", "1", "--out", "."]])
def test_what_cannot_be_done_is_said_before_minutes_of_building(args, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "dir.yaml").mkdir()
    args = [a if a != "." else str(tmp_path / "dir.yaml") for a in args]
    started = time.perf_counter()
    assert main(args) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err[-1] in ("polygolf: random-nine has holes 1 to 9", f"polygolf: --out: cannot write {args[-1]}: a folder")
    assert time.perf_counter() - started < 20.0  # a bound against building first, not a speed measurement
    assert not (tmp_path / "generated").exists()


def test_explain_takes_a_hole_file_from_any_folder(tmp_path, capsys):
    shutil.copy(HOLES_DIR / "straight.yaml", tmp_path / "straight.yaml")  # no tiles.yaml beside it
    assert main(["explain", str(tmp_path / "straight.yaml")]) == 0
    assert capsys.readouterr().out.startswith("Straight (straight) at balanced")


def test_explain_of_a_courses_library_or_theme_file_says_what_it_is(capsys):
    """Not 'name: missing' (it was read as a scene)."""
    for path, what in ((HOLES_DIR / "courses.yaml", "a courses file"), (HOLES_DIR / "tiles.yaml", "a tile library"),
                       (THEMES_DIR / "night.yaml", "a theme")):
        assert main(["explain", str(path)]) == 2
        assert capsys.readouterr().err.strip() == (f"polygolf: {path} is {what}: explain takes a hole or a scene "
                                                   "(a file, a name, or COURSE:HOLE)")


def test_scenes_and_holes_are_found_by_name_from_any_folder(tmp_path, monkeypatch, capsys):
    """An installed game's user is not in the source tree: the README's `content/scenes/...` paths,
    and bare names, find the shipped files."""
    monkeypatch.chdir(tmp_path)
    for args, first in ((["simulate", "pile", "--seconds", "0.05"], "pile: 3 frames"),
                        (["simulate", "content/scenes/flat-wall.yaml", "--seconds", "0.05"], "flat-wall: 3 frames"),
                        (["explain", "corner"], "corner at balanced"),
                        (["explain", "content/scenes/corner.yaml"], "corner at balanced"),
                        (["explain", "straight"], "Straight (straight) at balanced")):
        assert main(args) == 0, args
        assert capsys.readouterr().out.startswith(first), args
    assert main(["explain", "nosuch"]) == 2
    assert capsys.readouterr().err.strip() == ("polygolf: no scene or hole 'nosuch': give a file, a scene or hole "
                                               "name, or COURSE:HOLE")
    (tmp_path / "pile.yaml").write_text("name: mine\nbodies:\n"
                                        "  - {name: b, shape: {regular: 4, radius: 0.1}, position: [0, 0]}\n")
    # (a file that is there is the one meant)
    assert main(["simulate", "pile.yaml", "--seconds", "0.05"]) == 0
    assert capsys.readouterr().out.startswith("mine: 3 frames")


def test_explain_finds_the_players_own_courses(content_copy, capsys):
    from polygolf.engine.loading.paths import user_content_dir

    mine = user_content_dir() / "holes"
    mine.mkdir(parents=True)
    (mine / "my-hole.yaml").write_text("name: Mine\npar: 2\ntiles:\n  - {at: [0, 0]}\n  - {at: [1, 0]}\n")
    (mine / "courses.yaml").write_text("courses:\n  - name: My Course\n    holes: [my-hole]\n")
    assert main(["explain", "my-course:1"]) == 0
    assert capsys.readouterr().out.startswith("Mine (my-hole) at balanced")
    assert main(["explain", "my-hole"]) == 0  # by name, in the player's folder
    assert capsys.readouterr().out.startswith("Mine (my-hole) at balanced")


@pytest.mark.parametrize(("old", "new", "field"), [
    ("steep:\n    - {hazard: slope, push: [3.2, 0]", "steep:\n    - {hazard: slope, push: [101, 0]",
     "patterns.slope-east-steep[0].push[0]"),
    ("steep:\n    - {hazard: slope, push: [3.2, 0], ", "steep:\n    - {hazard: slope, ",
     "patterns.slope-east-steep[0]"),
    ("open-ew: {e: open, w: open}", "open-ew: {e: opn, w: open}", "border_sets.open-ew.e"),
    ("twin-posts:\n    - box: {center: [0, 1.4], half: [0.4, 0.4]}",
     "twin-posts:\n    - box: {center: [0, 1.4], half: [0, 0.4]}", "patterns.twin-posts[0].box.half[0]"),
])
def test_a_library_error_names_the_pattern_or_border_set_and_its_line(tmp_path, capsys, old, new, field):
    """Names with a dash (most of the library's) are the user's keys, not pydantic's tags: the error is
    on the item's own line under its own name (it was put at the section's header, the name left out)."""
    assert LIBRARY.count(old) == 1
    text = LIBRARY.replace(old, new)
    line = text[:text.index(new) + len(new)].count("\n") + 1  # the item's line: the last of `new`
    (tmp_path / "tiles.yaml").write_text(text)
    assert main(["validate", str(tmp_path / "tiles.yaml")]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"{tmp_path / 'tiles.yaml'}:{line}: {field}: "), err


def test_a_file_of_many_large_outlines_is_refused_before_any_is_cut_up(tmp_path, capsys):
    wall = "  - polygon: [" + ", ".join(f"[{math.cos(a / 64 * 6.283) * 5:.4f}, {math.sin(a / 64 * 6.283) * 5:.4f}]"
                                       for a in range(64)) + "]\n"
    path = place(tmp_path, "scene", SCENE + wall * 200)
    started = time.perf_counter()
    assert main(["validate", str(path)]) == 1
    assert "12,808 vertices in all: at most 10,000 in one file" in capsys.readouterr().err
    assert time.perf_counter() - started < 20.0  # a bound against hangs, not a speed measurement


def test_a_scene_of_many_large_bodies_is_refused_before_any_outline_is_built(tmp_path, capsys, monkeypatch):
    """The vertex budget is counted from what the file says (a star {p/q} has 2p vertices) before any
    body's outline is built and checked: 2 000 stars of 128 vertices took 70 s to be refused."""
    from polygolf.engine.physics import polygon

    built = []
    real = polygon.normalise
    monkeypatch.setattr(polygon, "normalise", lambda outline: built.append(1) or real(outline))
    bodies = "".join(f"  - {{name: s{k}, shape: {{star: [64, 31], radius: 0.5}}, position: [{k}, 0]}}\n"
                     for k in range(200))
    path = place(tmp_path, "scene", "name: stars\nbodies:\n" + bodies)
    assert main(["validate", str(path)]) == 1
    assert "25,600 vertices in all: at most 10,000 in one file" in capsys.readouterr().err
    assert built == []


def test_numbers_with_an_exponent_and_no_dot_are_numbers(tmp_path, capsys):
    """YAML 1.1 (PyYAML) read `5e-1` as a string, and the author got 'Input should be a valid
    number, got '5e-1''; YAML 1.2 and every author read a number: the scene plays as written plainly."""
    written = _sub(_sub(SCENE, "{regular: 4, radius: 0.5}", "{regular: 4, radius: 5e-1}"),
                   "position: [3.0, 0.0]", "position: [3E0, -0e0]")
    results = []
    for folder, scene in (("plain", SCENE), ("exponents", written)):
        (tmp_path / folder).mkdir()
        assert main(["simulate", str(place(tmp_path / folder, "scene", scene)), "--seconds", "0.1", "--json"]) == 0
        results.append(json.loads(capsys.readouterr().out)["bodies"])
    assert results[0] == results[1]


@pytest.mark.parametrize("middle", ["{at: [1, 0], borders: {e: {gate: 0.3}, w: open}}",
                                    "{at: [1, 0], borders: open-ew, pattern: wall-across}"])
def test_a_hole_whose_cup_no_ball_can_reach_is_refused_by_validate(tmp_path, capsys, middle):
    """Open borders all the way, but a gate narrower than the ball, or a wall across the corridor:
    validate passed it, and only par found it could not be sunk."""
    import shutil

    from polygolf.engine.loading.paths import HOLES_DIR

    library = (HOLES_DIR / "tiles.yaml").read_text()
    (tmp_path / "tiles.yaml").write_text(library.replace(
        "patterns:\n", "patterns:\n  wall-across:\n    - box: {center: [0, 0], half: [0.2, 3]}\n", 1))
    shutil.copy(HOLES_DIR / "straight.yaml", tmp_path / "fine.yaml")
    (tmp_path / "shut.yaml").write_text("name: Shut\npar: 2\ntiles:\n  - {at: [0, 0], borders: open-e}\n"
                                        f"  - {middle}\n  - {{at: [2, 0], borders: open-w}}\n")
    assert main(["validate", str(tmp_path / "fine.yaml"), str(tmp_path / "shut.yaml")]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"{tmp_path / 'shut.yaml'}:6: tiles[2]: the cup cannot be reached from the tee: walls, gates or "
                   "water close every way for a ball 0.9 m across"]


@pytest.mark.parametrize(("radius", "problem"), [
    (1.5, "2 players' balls (3 m across) do not fit apart on the green"),
    (1.0, "with 3 players a ball (2 m across) starts beside the cup: no room near the tee")])
def test_a_hole_whose_hot_seat_balls_cannot_start_apart_is_refused_by_validate(tmp_path, capsys, radius, problem):
    """A library's ball too large for the tee's tile (its radius is within the tile's quarter): two
    to four players' balls were put on top of each other, or beside (or in) the cup, and validate
    said nothing. The start spots now keep off the cup while the green has room, and never overlap
    while it has any; validate says which count of players cannot start."""
    from polygolf.engine.golf.holes import load_hole_file
    from polygolf.engine.golf.world import tee_spots

    (tmp_path / "tiles.yaml").write_text(LIBRARY.replace("radius: 0.45 ", f"radius: {radius} ", 1))
    (tmp_path / "big.yaml").write_text("name: Big Ball\npar: 3\ntiles:\n  - {at: [0, 0], borders: open-e}\n"
                                       "  - {at: [1, 0], borders: open-w}\n")
    assert main(["validate", str(tmp_path / "big.yaml")]) == 1
    assert capsys.readouterr().err.strip().splitlines() == [f"{tmp_path / 'big.yaml'}:4: tiles[0]: {problem}"]
    layout = load_hole_file(tmp_path / "big.yaml").layout
    if radius == 1.0:  # (room for two, apart and off the cup)
        first, second = tee_spots(layout, radius, 2)
        assert math.dist(first, second) >= 2 * radius
        assert min(math.dist(spot, layout.cup) for spot in (first, second)) >= layout.cup_radius + 3.5 * radius


def test_a_hole_far_larger_than_its_green_is_validated_at_once(tmp_path, capsys):
    """Two stray tiles 100 columns off, with the shipped tiles and with tiles 100 m across (both within
    the limits): the route map validate builds covered the whole box at a 0.25 m step (two minutes and
    2 GB; 48 GiB with the large tiles, a traceback). A map of a hole that large is coarser now."""
    from polygolf.engine.golf.holes import load_hole_file
    from polygolf.engine.golf.search import MAX_ROUTE_NODES, RouteMap

    hole = ("name: Far Tiles\npar: 3\ntiles:\n  - {at: [0, 0], borders: open-e}\n  - {at: [100, 100]}\n"
            "  - {at: [-100, -100]}\n  - {at: [1, 0], borders: open-w}\n")
    (tmp_path / "far.yaml").write_text(hole)
    (tmp_path / "large").mkdir()
    (tmp_path / "large" / "far.yaml").write_text(hole)
    (tmp_path / "large" / "tiles.yaml").write_text(LIBRARY.replace("tile_size: 6.0", "tile_size: 100.0", 1))
    assert main(["validate", str(tmp_path / "far.yaml"), str(tmp_path / "large" / "far.yaml")]) == 0
    capsys.readouterr()
    route = RouteMap(load_hole_file(tmp_path / "far.yaml").layout, 0.45)
    assert route.nx * route.ny <= MAX_ROUTE_NODES * 1.01 and route.step > 0.25


def test_yaml_merge_keys_take_a_mappings_keys_where_none_is_written(tmp_path, capsys):
    """`<<: *tile` (YAML's merge key) was refused with PyYAML's "could not determine a constructor"."""
    (tmp_path / "merged.yaml").write_text("name: Merged\npar: 3\ntiles:\n  - &first {at: [0, 0], borders: open-e}\n"
                                          "  - {<<: *first, at: [1, 0], borders: open-ew}\n"
                                          "  - {<<: *first, at: [2, 0], borders: nowhere}\n")
    assert main(["validate", str(tmp_path / "merged.yaml")]) == 1
    assert capsys.readouterr().err == f"{tmp_path / 'merged.yaml'}:6: tiles[2].borders: unknown border set 'nowhere'\n"
    from polygolf.engine.loading.yamlsource import load_yaml

    data, _ = load_yaml(tmp_path / "merged.yaml")
    assert data["tiles"][1] == {"at": [1, 0], "borders": "open-ew"}


@pytest.mark.parametrize("blank", ["\u3164", "\uffa0\u200d", "\u2800\u2800", "\u115f\u1160"])
def test_a_content_name_of_fillers_or_blank_braille_is_refused(blank):
    """QA8: Hangul fillers and the blank Braille pattern are letters and symbols that show nothing;
    a hole or course named with them alone looked like no name at all (the game's player names
    follow the same rule, `limits.shows`)."""
    from pydantic import TypeAdapter, ValidationError

    from polygolf.engine.loading.limits import Name

    with pytest.raises(ValidationError, match="a name needs a letter, digit or sign that shows"):
        TypeAdapter(Name).validate_python(blank)
    assert TypeAdapter(Name).validate_python("Ann\u3164Lee") == "Ann\u3164Lee"  # (kept inside a name that shows)


def test_two_bodies_of_one_name_are_named_on_the_bodies_line(tmp_path, capsys):
    """QA8: the scene check said 'line 1: (top level)'; the error belongs to the bodies, both named."""
    path = tmp_path / "dup.yaml"
    path.write_text(textwrap.dedent("""\
        name: dup
        walls:
          - box: {center: [0, -0.5], half: [5, 0.5]}
        bodies:
          - {name: left, shape: {regular: 5, radius: 0.2}, position: [-1, 1]}
          - {name: right, shape: {regular: 5, radius: 0.2}, position: [1, 1]}
          - {name: left, shape: {regular: 5, radius: 0.2}, position: [0, 2]}
        """))
    assert main(["simulate", str(path), "--seconds", "0.1"]) == 2  # (the command line's code for bad input)
    assert capsys.readouterr().err.strip() == \
        f"polygolf: {path}:4: bodies: bodies[0] and bodies[2] are both named 'left'"


@pytest.mark.parametrize("center", [[3.0, -0.5], [0.0, 0.0]])
def test_a_box_too_thin_for_its_place_is_said_to_be_so(tmp_path, capsys, center):
    """QA8: a box 1e-300 m thick (within the limits: half > 0) was refused as 'polygon has repeated
    vertices', words for a polygon its author never wrote."""
    path = tmp_path / "thin.yaml"
    path.write_text(textwrap.dedent(f"""\
        name: thin
        walls:
          - box: {{center: {center}, half: [1.0e-300, 5.0]}}
        bodies:
          - {{name: a, shape: {{regular: 5, radius: 0.2}}, position: [-1, 1]}}
        """))
    assert main(["simulate", str(path), "--seconds", "0.1"]) == 2
    assert capsys.readouterr().err.strip() == (f"polygolf: {path}:3: walls[0].box: a box of half-size [1e-300, 5.0] "
                                               "is too thin to have an area where it stands")
