"""The window commands from a shell: no traceback without a display, `render` without a window,
`validate` over all content."""

from __future__ import annotations

import os
import subprocess
import sys

import numpy as np
from PIL import Image

from polygolf.engine.loading.paths import SCENES_DIR as ROOT_SCENES
from polygolf.game.cli import main
from polygolf.game.theme import Theme


def run(*args, env_changes=None, drop=("DISPLAY", "WAYLAND_DISPLAY", "ARCADE_HEADLESS")):
    env = {k: v for k, v in os.environ.items() if k not in drop}
    env.update(env_changes or {})
    return subprocess.run([sys.executable, "-m", "polygolf.game.cli", *args], capture_output=True, text=True, env=env,
                          timeout=120)


def test_a_content_override_that_is_no_content_folder_is_said_in_one_line(tmp_path):
    """POLYGOLF_CONTENT naming a missing folder, or one without holes/, was taken as an empty content
    folder: "no course 'meadow'; courses: " (an empty list) and the like."""
    for folder in (tmp_path / "missing", tmp_path):
        for args in (["scores"], ["validate"], ["play", "--course", "meadow"]):
            result = run(*args, env_changes={"POLYGOLF_CONTENT": str(folder)})
            assert result.returncode == 2 and result.stdout == ""
            assert result.stderr == f"polygolf: POLYGOLF_CONTENT: {folder} is not a content folder (no holes/ in it)\n"


def test_window_commands_without_a_display_say_so_in_one_line():
    for args in ([], ["play", "--course", "meadow", "--hole", "2"]):
        result = run(*args)
        assert result.returncode == 1
        lines = result.stderr.strip().splitlines()
        assert len(lines) == 1 and "no display" in lines[0] and "Traceback" not in result.stderr


def test_an_unknown_course_or_hole_is_the_error_reported_even_without_a_display():
    for args, message in ((["--course", "nosuch"], "no course 'nosuch'"), (["--hole", "42"], "holes 1 to 9")):
        result = run("play", *args)
        lines = result.stderr.strip().splitlines()
        assert result.returncode == 2 and len(lines) == 1 and message in lines[0], result.stderr


def test_a_broken_hole_file_is_the_error_reported_even_without_a_display(tmp_path):
    """The file is what the author must fix; the display comes after it (exit 2: bad input)."""
    hole = tmp_path / "broken.yaml"
    hole.write_text("name: Broken\npar: 3\ntiles: 7\n")
    missing = tmp_path / "missing.yaml"
    for path, message in ((hole, f"{hole}:3: tiles:"), (missing, f"{missing}:0: (file):")):
        result = run("play", str(path))
        lines = result.stderr.strip().splitlines()
        assert result.returncode == 2 and len(lines) == 1 and lines[0].startswith(f"polygolf: {message}"), result.stderr


def test_window_commands_under_arcade_headless_say_so_in_one_line_and_render_still_works(tmp_path):
    """ARCADE_HEADLESS is `render`'s offscreen context: the game's GUI cannot even be imported under it."""
    for display in ({}, {"DISPLAY": ":0"}):
        result = run("play", "--course", "meadow", env_changes={"ARCADE_HEADLESS": "1", **display})
        lines = result.stderr.strip().splitlines()
        assert result.returncode == 1 and len(lines) == 1 and "no display" in lines[0], result.stderr
    out = tmp_path / "x.png"
    result = run("render", "meadow", "1", "--out", str(out), env_changes={"ARCADE_HEADLESS": "1"})
    assert result.returncode == 0 and out.stat().st_size > 10_000, result.stderr


def test_render_draws_a_hole_to_png_without_a_window(tmp_path):
    out = tmp_path / "dog-leg.png"
    result = run("render", "meadow", "2", "--theme", "sand", "--shape", "star-5-2", "--out", str(out))
    assert result.returncode == 0, result.stderr
    assert Image.open(out).mode == "RGB"  # opaque, as on screen: no alpha to lighten the HUD bar in a viewer
    image = np.asarray(Image.open(out), dtype=np.int16)
    assert image.shape == (720, 1280, 3)
    assert len(np.unique(image.reshape(-1, 3), axis=0)) > 20
    # The sand palette's green covers much of the picture.
    from polygolf.game.theme import find_theme, load_themes

    green = find_theme(load_themes()[0], "sand").rgba("green")[:3]
    assert (np.abs(image - green).sum(axis=2) < 12).mean() > 0.1


def test_the_tee_mat_holds_every_players_ball(tmp_path):
    """One ball: a square mat about it; four across Meadow 1's tee: one long mat about them all."""
    from polygolf.game.theme import find_theme, load_themes

    tee = np.array(find_theme(load_themes()[0], "grass").rgba("tee")[:3])
    sides = {}
    for players in (1, 4):
        out = tmp_path / f"tee-{players}.png"
        result = run("render", "meadow", "1", "--theme", "grass", "--players", str(players), "--out", str(out))
        assert result.returncode == 0, result.stderr
        image = np.asarray(Image.open(out), dtype=np.int16)[60:, :640]  # below the HUD, the tee's half
        rows, cols = np.nonzero((image == tee).all(axis=2))
        sides[players] = (cols.max() - cols.min(), rows.max() - rows.min())
    (w1, h1), (w4, h4) = sides[1], sides[4]
    assert 0.9 < h1 / w1 < 1.1 and abs(w4 - w1) <= 2 and h4 > 3.5 * w4, sides


def test_render_of_an_unknown_course_or_shape_is_one_line(tmp_path):
    for args in (["render", "nowhere", "1"], ["render", "meadow", "1", "--shape", "blob"],
                 ["render", "meadow", "12"]):
        result = run(*args, "--out", str(tmp_path / "x.png"))
        assert result.returncode == 2 and len(result.stderr.strip().splitlines()) == 1, result.stderr


def test_validate_passes_on_shipped_content_and_fails_on_broken(tmp_path, capsys):
    assert main(["validate"]) == 0
    assert "0 problems" in capsys.readouterr().out
    bad = tmp_path / "themes"
    bad.mkdir()
    (bad / "ugly.yaml").write_text("name: Ugly\nbackground: green\n")
    assert main(["validate", str(bad)]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    # Every problem of the file, the bad colour first, then each colour it lacks.
    assert err[0] == f"{bad / 'ugly.yaml'}:2: background: a colour is \"#RRGGBB\" or \"#RRGGBBAA\", got 'green'"
    missing = [name for name in Theme.model_fields if name not in ("name", "background")]
    assert err[1:] == [f"{bad / 'ugly.yaml'}:1: {name}: missing (required)" for name in missing]


def test_validate_of_a_folder_without_content_says_so(tmp_path, capsys):
    """Not "0 files checked, 0 problems" and success: the wrong folder was given (QA: /root)."""
    (tmp_path / "notes.txt").write_text("no yaml here\n")
    assert main(["validate", str(tmp_path)]) == 2
    out, err = capsys.readouterr()
    assert err.strip() == f"polygolf: validate: no content files (*.yaml) in {tmp_path}" and out == ""


def test_a_reader_that_goes_away_is_no_traceback():
    """`polygolf simulate ... | head -c 0`: the pipe closes early; the command stops quietly."""
    scene = ROOT_SCENES / "flat-wall.yaml"
    proc = subprocess.Popen([sys.executable, "-m", "polygolf", "simulate", str(scene), "--json"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    proc.stdout.close()  # gone before the command writes a byte
    err = proc.stderr.read().decode()
    assert proc.wait(timeout=60) == 0 and "Traceback" not in err, err


def test_bench_accuracy_without_its_extra_says_so_before_any_work(monkeypatch, tmp_path, capsys):
    import importlib.util

    from polygolf.game.tools import accuracy

    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec", lambda name, *a: None if name in ("matplotlib", "tqdm")
                        else real(name, *a))
    monkeypatch.setattr(accuracy, "all_cases", lambda *a: (_ for _ in ()).throw(AssertionError("work began")))
    assert main(["bench", "accuracy", "--quick", "--out", str(tmp_path)]) == 2
    assert capsys.readouterr().err == ("polygolf: bench accuracy needs matplotlib and tqdm: "
                                       "pip install 'polygolf[bench]'\n")
    assert main(["bench", "accuracy", "--quick", "--no-progress", "--out", str(tmp_path)]) == 2
    assert "needs matplotlib: pip" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []


def test_a_collision_test_is_not_proven_the_golfer_cannot_play_it(capsys):
    """Its ball is launched again and again: `par` says it passes it over, `validate --prove` has no
    doubt to report of it (it warned that the shipped hole could not be sunk)."""
    assert main(["par", "collision-test"]) == 0
    out, err = capsys.readouterr()
    assert out == "nothing to prove\n"
    assert err == ("polygolf: skipped: collision-test: launches the ball itself (a collision test): the golfer "
                   "cannot play it\n")
    assert main(["validate", "--prove", str(ROOT_SCENES.parent / "holes" / "collision-test.yaml")]) == 0
    assert capsys.readouterr().out == "1 file checked, 0 problems, 0 warnings\n"


def test_an_argument_that_is_not_text_is_one_line(capsys):
    from polygolf.game.cli import main

    assert main(["scores", "--course", "\udcff\udcfe"]) == 2
    assert capsys.readouterr().err == "polygolf: surrogates not allowed: '\\udcff\\udcfe' is not text (utf-8)\n"


def test_the_par_table_keeps_a_long_hole_id_apart_from_its_name():
    from polygolf.engine.golf.search import HoleProof
    from polygolf.game.tools.par import table

    proofs = [HoleProof("blocked_by_obstacle", "Blocked", 3, 11, None, False, [None], 2.0, 10, 3.0),
              HoleProof("straight", "Straight", 2, 2, 1, True, [1], 0.1, 5, 1.0)]
    lines = table(proofs).splitlines()
    assert lines[1].split()[:2] == ["blocked_by_obstacle", "Blocked"]
    assert lines[1].index("Blocked") == lines[2].index("Straight") == lines[0].index("name")


# QA's YAML "billion laughs": nine levels of nine aliases (9**9 values), refused by the loader.
BOMB = """\
a: &a ["x","x","x","x","x","x","x","x","x"]
b: &b [*a,*a,*a,*a,*a,*a,*a,*a,*a]
c: &c [*b,*b,*b,*b,*b,*b,*b,*b,*b]
d: &d [*c,*c,*c,*c,*c,*c,*c,*c,*c]
e: &e [*d,*d,*d,*d,*d,*d,*d,*d,*d]
f: &f [*e,*e,*e,*e,*e,*e,*e,*e,*e]
g: &g [*f,*f,*f,*f,*f,*f,*f,*f,*f]
h: &h [*g,*g,*g,*g,*g,*g,*g,*g,*g]
i: &i [*h,*h,*h,*h,*h,*h,*h,*h,*h]
name: Lol
par: 2
tiles:
  - {at: [0, 0], borders: open-e}
  - {at: [1, 0], borders: open-w}
"""


def _content_with_a_bomb(data) -> tuple:
    """The player's content: Only Bomb (its one hole unreadable) and Half (a good hole, then the bomb)."""
    import shutil

    from polygolf.engine.loading.paths import HOLES_DIR

    holes = data / "content" / "holes"
    holes.mkdir(parents=True)
    shutil.copy(HOLES_DIR / "straight.yaml", holes / "good.yaml")
    (holes / "bomb.yaml").write_text(BOMB)
    (holes / "courses.yaml").write_text("courses:\n  - name: Only Bomb\n    holes: [bomb]\n"
                                        "  - name: Half\n    holes: [good, bomb]\n")
    return holes / "bomb.yaml"


def test_a_course_with_no_playable_hole_is_one_line_and_no_round(isolated_user_data, tmp_path):
    """QA: `play --course only-bomb` went to an empty scorecard ('0 strokes, level par'), and `autoplay`
    exited 0 having saved a round and written a replay that `replay --verify` rejected (0 of 0 holes)."""
    from polygolf.game.store import Store

    bomb = _content_with_a_bomb(isolated_user_data)
    why = f"{bomb}:1: e[5][5][7][5][0]: more than 50,000 values (aliases expanded): too large"
    for args, where in ((["play", "--course", "only-bomb"], ""), (["play", "--course", "Only Bomb", "--hole", "1"], ""),
                        (["autoplay", "--course", "only-bomb", "--preset", "fast"], ""),
                        (["play", "--course", "half", "--hole", "2"], " from hole 2 on")):
        name = "Half" if "half" in args else "Only Bomb"
        result = run(*args)
        assert (result.returncode, result.stdout) == (2, ""), result.stderr
        assert result.stderr == f"polygolf: course '{name}' has no playable hole{where} ({why})\n"
    assert not (isolated_user_data / "replays").exists() and Store(echo=False).round_count() == 0
    for hole in ("1", "bomb"):  # render draws one hole: that hole's error, said once
        out = tmp_path / "bomb.png"
        result = run("render", "only-bomb", hole, "--out", str(out))
        assert (result.returncode, result.stdout, result.stderr) == (2, "", f"polygolf: {why}\n")
        assert not out.exists()


def test_an_empty_theme_name_is_refused_as_an_unknown_one_is(tmp_path):
    from polygolf.engine.loading.paths import HOLES_DIR

    for args in (["play", "--course", "meadow"], ["play", str(HOLES_DIR / "straight.yaml")],
                 ["render", "meadow", "1", "--out", str(tmp_path / "x.png")]):
        for theme in ("", "nope"):
            result = run(*args, "--theme", theme)
            assert result.returncode == 2, (args, theme, result.stderr)
            assert result.stderr.startswith(f"polygolf: no theme {theme!r}; themes: grass")
            assert len(result.stderr.splitlines()) == 1
    assert not (tmp_path / "x.png").exists()


def test_render_takes_a_holes_name_as_par_and_explain_do(tmp_path):
    by_number, by_name = tmp_path / "9.png", tmp_path / "castle.png"
    assert run("render", "meadow", "9", "--out", str(by_number)).returncode == 0
    result = run("render", "Meadow", "castle", "--out", str(by_name))
    assert (result.returncode, result.stdout) == (0, f"{by_name}\n"), result.stderr
    assert np.array_equal(np.asarray(Image.open(by_number)), np.asarray(Image.open(by_name)))
    result = run("render", "meadow", "castel", "--out", str(tmp_path / "x.png"))
    assert result.returncode == 2 and result.stderr == (
        "polygolf: meadow has holes 1 to 9 (or give a hole's name: straight, dog-leg, zig-zag, obstacle-field, "
        "narrow-gates, long-way, u-turn, pinball, castle)\n")
    result = run("render", "random-nine", "castle", "--out", str(tmp_path / "x.png"))
    assert (result.returncode, result.stderr) == (2, "polygolf: random-nine has holes 1 to 9: give a number, not "
                                                     "'castle'\n")
