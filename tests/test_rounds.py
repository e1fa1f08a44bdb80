"""Rounds without a window: several balls in one hole world, turns, the restart penalty, scorecard
wording, the database (and a broken one), replays verified and tampered ones refused, and the
`autoplay`, `scores` and `replay` commands."""

from __future__ import annotations

import json
import math
import os
import re
import sqlite3
from pathlib import Path

import esper
import pytest

from polygolf.engine.components import Collider
from polygolf.engine.golf.golfer import golfer_for
from polygolf.engine.golf.holes import find_course, load_all_courses
from polygolf.engine.golf.layout import ball_fits
from polygolf.engine.golf.play import HolePlay
from polygolf.engine.loading.paths import data_dir
from polygolf.game.cli import main
from polygolf.game.record import RoundRecord, engine, load_record
from polygolf.game.replay import verify
from polygolf.game.session import Game, Round, RoundPlay, par_text, penalty_text, strokes_text
from polygolf.game.shapes import CATALOGUE
from polygolf.game.store import Store
from polygolf.game.views.results import hole_cell, running

PENTAGON = CATALOGUE[2][1]


@pytest.fixture(scope="module")
def courses():
    return load_all_courses()[0]


def hole_of(courses, course: str, number: int):
    return find_course(courses, course).holes[number - 1]


def settle(play: HolePlay, limit: int = 60 * 60) -> int:
    """Step until every ball rests (at least one frame: a requested shot is taken in the next)."""
    for frame in range(1, limit):
        play.step()
        if play.all_at_rest:
            return frame
    raise AssertionError("the balls never came to rest")


def test_every_player_has_a_ball_on_the_tee_clear_of_the_others(courses):
    hole = hole_of(courses, "meadow", 1)
    radius = hole.library.ball.radius
    for players in (1, 2, 3, 4):
        play = HolePlay(hole, PENTAGON, players=players)
        spots = [(p.body.x, p.body.y) for p in play.players]
        assert len(spots) == players and len({p.entity for p in play.players}) == players
        if players == 1:
            assert spots == [hole.layout.tee]  # one player: exactly the tee, as before
        for i, a in enumerate(spots):
            assert ball_fits(hole.layout, *a, radius)
            assert all(math.dist(a, b) >= 2.0 * radius for b in spots[i + 1:])
        play.close()
    with pytest.raises(ValueError, match="1 to 4"):
        HolePlay(hole, PENTAGON, players=5)


def test_balls_knock_each_other_and_each_keeps_its_own_score(courses):
    hole = hole_of(courses, "meadow", 1)
    play = HolePlay(hole, PENTAGON, players=2)
    tee, ahead = hole.layout.route[0], hole.layout.route[1]
    length = math.dist(tee, ahead)
    ux, uy = (ahead[0] - tee[0]) / length, (ahead[1] - tee[1]) / length
    play.turn = 1
    target = (tee[0] + 2.5 * ux, tee[1] + 2.5 * uy)
    play.place_ball(*target)
    play.turn = 0
    play.place_ball(*tee)
    assert play.shoot(tee, (1.5 * ux, 1.5 * uy))
    settle(play)
    second = play.players[1]
    moved = math.dist((second.body.x, second.body.y), target)
    assert moved > 0.5, "the struck ball did not knock the other one"
    assert (play.players[0].state.strokes, second.state.strokes) == (1, 0)
    play.close()


def test_a_holed_ball_leaves_the_green(courses):
    hole = hole_of(courses, "sandbox", 1)
    play = HolePlay(hole, PENTAGON, players=2)
    golfer = golfer_for(hole)
    for _ in range(60 * 60):
        if play.state.holed:
            break
        if play.all_at_rest:
            play.shoot(*golfer.plan((play.ball.x, play.ball.y)))
        play.step()
    first = play.players[0]
    assert first.state.holed and not play.finished
    esper.switch_world(play.sim.world)
    assert not esper.has_component(first.entity, Collider)  # nothing can hit it in the cup
    assert esper.has_component(play.players[1].entity, Collider)
    play.close()


def test_turns_rotate_after_everything_rests_and_a_restart_costs_a_stroke(courses):
    course = find_course(courses, "sandbox")
    session = RoundPlay(Round(course, players=["Ann", "Bob"]), PENTAGON, "Pentagon")
    hole = session.hole
    assert session.player_name == "Ann" and session.can_shoot
    assert session.shoot((hole.ball.x, hole.ball.y), (1.0, 0.3))
    session.step()
    assert not session.can_shoot and session.turn == 0  # still rolling: nobody may shoot
    # Restarting while the ball rolls: the stroke stays, a penalty stroke is added, Ann plays again.
    assert session.restart()
    session.step()
    ann = hole.players[0]
    assert (ann.state.strokes, ann.state.penalties, ann.state.score) == (1, 1, 2)
    assert (ann.body.x, ann.body.y) == ann.tee and session.turn == 0 and session.can_shoot
    assert session.shoot((hole.ball.x, hole.ball.y), (0.8, 0.0))
    while not session.can_shoot:
        session.step()
    assert session.player_name == "Bob"
    assert [i.kind for i in session.inputs] == ["shot", "restart", "shot"]
    session.close()


def test_a_restart_in_the_frame_of_a_shot_withdraws_the_shot(courses):
    """A shot released and the hole restarted before the next frame (R, or Pause -> Restart hole):
    the ball stays on the tee (the shot was never taken from there), the restart's penalty counts
    and the same player plays again. (The shot used to fire from the tee, and the next player was
    skipped.)"""
    course = find_course(courses, "sandbox")
    session = RoundPlay(Round(course, players=["Ann", "Bob"]), PENTAGON, "Pentagon")
    hole = session.hole
    ann = hole.players[0]
    assert session.shoot((ann.body.x, ann.body.y), (1.0, 0.2)) and session.restart()
    for _ in range(30):
        session.step()
    assert (ann.body.x, ann.body.y) == ann.tee and ann.body.asleep
    assert (ann.state.strokes, ann.state.penalties) == (0, 1)
    assert session.turn == 0 and session.can_shoot
    session.close()


def test_scorecard_wording():
    assert strokes_text(1) == "1 stroke" and strokes_text(2) == "2 strokes"
    assert penalty_text(1) == "(+1 penalty stroke)" and penalty_text(3) == "(+3 penalty strokes)"
    assert penalty_text(0) == "" and par_text(0) == "E" and par_text(-2) == "-2" and par_text(1) == "+1"


def test_the_scorecard_shows_each_hole_against_par_and_a_running_total(courses):
    round_ = Round(find_course(courses, "meadow"))
    pars = [h.spec.par for h in round_.course.playable]
    round_.finish_hole([(1, False, 0)])  # a hole in one
    round_.finish_hole([(pars[1] + 2, False, 1)])
    card = round_.results
    assert hole_cell(card[0]) == f"1 ({par_text(1 - pars[0])})" and card[0].strokes - card[0].par == 1 - pars[0]
    assert running(card) == [par_text(1 - pars[0]), par_text(3 - pars[0])]


def test_winners_and_ties(courses):
    round_ = Round(find_course(courses, "sandbox"), players=["Ann", "Bob", "Cy"])
    round_.finish_hole([(2, False, 0), (3, False, 0), (2, False, 0)])
    assert round_.winners() == ["Ann", "Cy"]
    round_.finish_hole([(3, False, 0), (1, False, 0), (3, False, 0)])
    assert round_.winners() == ["Bob"] and round_.standings() == [1, 0, 2]  # 4, 5, 5 strokes


def autoplay(*args: str) -> int:
    """`polygolf autoplay` on the short Sandbox course; the exit status, also for argparse's refusals."""
    try:
        return main(["autoplay", "--course", "sandbox", "--preset", "fast", *args])
    except SystemExit as exc:
        return exc.code


def test_autoplay_saves_the_round_bests_and_a_replay_that_verifies(capsys):
    assert autoplay("--players", "2", "--names", "Ann,Bob") == 0
    out = capsys.readouterr().out
    replays = list((data_dir() / "replays").glob("*.json"))
    assert len(replays) == 1 and f"replay: {replays[0]}" in out
    record = load_record(replays[0])
    assert record.players == ["Ann", "Bob"] and len(record.holes) == 3 and record.preset == "fast"
    assert all(len(h.final) == 2 and h.inputs and h.inputs[0].kind == "shot" for h in record.holes)
    # The card in the database is the one printed.
    with sqlite3.connect(data_dir() / "polygolf.db") as db:
        cards = db.execute("SELECT name, strokes FROM cards ORDER BY seat").fetchall()
    for name, strokes in cards:
        assert f"{name}: {strokes_text(strokes)}" in out
    assert main(["scores", "--json"]) == 0
    bests = json.loads(capsys.readouterr().out)
    holes = [b for b in bests if b["hole"] is not None]
    course = [b for b in bests if b["hole"] is None]
    assert [b["number"] for b in holes] == [1, 2, 3] and len(course) == 1
    assert course[0]["strokes"] == min(s for _, s in cards)
    assert main(["scores", "--course", "sandbox"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert len(lines) == 4 and lines[-1].startswith("sandbox course (Sandbox)")
    assert main(["scores", "--course", "Sandbox"]) == 0  # the course's name, as the menu shows it
    assert capsys.readouterr().out.splitlines() == lines
    assert f"{strokes_text(course[0]['strokes'])}, par {course[0]['par']}" in lines[-1]
    assert main(["replay", str(replays[0]), "--verify"]) == 0
    assert "verified: 3 of 3 holes" in capsys.readouterr().out


def test_autoplay_refuses_a_course_whose_ball_is_launched_for_it(capsys):
    """Collision Test launches the ball again and again: it never rests for the golfer's stroke."""
    assert main(["autoplay", "--course", "collision-test", "--preset", "fast"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "hole 1 launches the ball itself" in err[0]


def test_a_tampered_replay_fails_verify_and_a_broken_one_is_refused(tmp_path, capsys):
    assert autoplay() == 0
    path = next((data_dir() / "replays").glob("*.json"))
    capsys.readouterr()
    data = json.loads(path.read_text())
    x, y = data["holes"][1]["inputs"][0]["arrow"]
    data["holes"][1]["inputs"][0]["arrow"] = [x * 0.97, y * 0.97]  # a slightly weaker first shot on hole 2
    tampered = tmp_path / "tampered.json"
    tampered.write_text(json.dumps(data))
    assert main(["replay", str(tampered), "--verify"]) == 1
    out = capsys.readouterr().out
    assert "hole 1 warm-up: identical" in out and ("DIFFERENT" in out or "not finished" in out)
    assert "does NOT match" in out
    # Results edited by hand fail too: the simulation decides, not the file.
    data = json.loads(path.read_text())
    data["holes"][0]["final"][0]["strokes"] -= 1
    tampered.write_text(json.dumps(data))
    assert main(["replay", str(tampered), "--verify"]) == 1
    assert capsys.readouterr().err == ""  # (this engine's own replay: no excuse)
    # A replay of another engine (or from before replays named theirs) that differs says why it may.
    assert len(data["engine"]) == 16
    for recorded in ("0123456789abcdef", None):
        if recorded is None:
            del data["engine"]
        else:
            data["engine"] = recorded
        tampered.write_text(json.dumps(data))
        assert main(["replay", str(tampered), "--verify"]) == 1
        assert capsys.readouterr().err == (f"polygolf: {tampered} was recorded by another physics engine "
                                           f"({recorded or 'from before replays kept it'}; this one {engine()}): "
                                           "it need not replay bit for bit\n")
    endless = json.loads(path.read_text())
    endless["holes"][0]["frames"] = 10 ** 12  # would take for ever to check: refused before any work
    for text in ("{", json.dumps({"format": "polygolf-replay", "version": 1}), json.dumps([1, 2]),
                 json.dumps(endless)):
        tampered.write_text(text)
        assert main(["replay", str(tampered), "--verify"]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and str(tampered) in err[0] and "Traceback" not in err[0]
    assert main(["replay", str(tmp_path / "missing.json")]) == 2


@pytest.mark.parametrize("text", ["[" * 100_000, '{"format": "polygolf-replay", "version": NaN}',
                                  '{"format": "polygolf-replay", "start_at": -Infinity}',
                                  '{"format": "polygolf-replay", "holes": [{"frames": 1e999}]}',
                                  '{"format": "polygolf-replay", "start_at": ' + "9" * 5000 + "}"],
                         ids=["deep", "nan", "infinity", "overflow", "long-integer"])
def test_a_replay_of_json_no_round_holds_is_not_a_replay(tmp_path, capsys, text):
    path = tmp_path / "odd.json"
    path.write_text(text)
    assert main(["replay", str(path), "--verify"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"polygolf: {path}: not a replay ("), err


@pytest.mark.parametrize(("edit", "where"), [
    (lambda r: r["holes"][0]["inputs"][0].update(grab=["nan", "nan"]), "holes.0.inputs.0.grab.0"),
    (lambda r: r["holes"][0]["inputs"][0].update(arrow=["1e999", "0"]), "holes.0.inputs.0.arrow.0"),
    (lambda r: r["holes"][0]["inputs"][0].update(frame="0"), "holes.0.inputs.0.frame"),
    (lambda r: r["holes"][0]["inputs"][0].update(frame=True), "holes.0.inputs.0.frame"),
    (lambda r: r["holes"][0]["final"][0].update(body=["inf", 0, 0, 0, 0, 0]), "holes.0.final.0.body.0"),
    (lambda r: r.update(players=["a\nb"]), "players.0"),
], ids=["nan-text", "overflow-text", "frame-text", "frame-bool", "body-inf-text", "name-control"])
def test_a_replay_whose_numbers_are_text_or_not_finite_is_not_read(tmp_path, capsys, edit, where):
    """Pydantic's lax mode read "nan", "1e999", "0" and true as numbers and fed them to the
    simulation (exit 1, or 0 for a frame of "0"); a name with a line break went onto the card."""
    record = RoundRecord(recorded_at="2026-11-27T04:00:00", course="sandbox", course_name="Sandbox", fingerprint="f",
                         shape_label="Pentagon", shape=PENTAGON, preset="fast", players=["Ann"],
                         holes=[{"position": 0, "hole": "warm-up", "preset": "fast", "frames": 90,
                                 "inputs": [{"frame": 0, "kind": "shot", "grab": [1.0, 2.0], "arrow": [0.5, 0.0]}],
                                 "final": [{"strokes": 1, "penalties": 0, "holed": True, "picked_up": False,
                                            "body": [1.0, 2.0, 0.0, 0.0, 0.0, 0.0]}]}])
    data = record.model_dump(mode="json")
    path = tmp_path / "edited.json"
    path.write_text(json.dumps(data))
    load_record(path)  # (as written, it reads)
    edit(data)
    path.write_text(json.dumps(data))
    assert main(["replay", str(path), "--verify"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"polygolf: {path}: {where}: "), err


def _save_replays(folder: Path, player: str, start, count: int, out) -> None:
    """(A process of the test below.) `count` rounds of one second and course saved by `player`."""
    start.wait()
    for _ in range(count):
        record = RoundRecord(recorded_at="2026-11-26T14:50:44", course="sandbox", course_name="Sandbox",
                             fingerprint="f", shape_label="Pentagon", shape=PENTAGON, preset="fast", players=[player])
        out.put(str(record.save(folder)))


def test_two_games_saving_replays_at_once_never_share_a_file(tmp_path):
    """Two games on one machine, rounds started in the same second on the same course: each save has
    a file of its own with its own round (one had overwritten the other's, or failed on the shared
    temporary file)."""
    import multiprocessing

    context = multiprocessing.get_context("fork")
    start, out = context.Barrier(2), context.Queue()
    workers = [context.Process(target=_save_replays, args=(tmp_path, name, start, 60, out)) for name in ("Ann", "Bob")]
    for worker in workers:
        worker.start()
    paths = [out.get(timeout=60) for _ in range(120)]
    for worker in workers:
        worker.join(timeout=60)
    assert len(set(paths)) == 120
    players = sorted(load_record(Path(path)).players[0] for path in paths)
    assert players == ["Ann"] * 60 + ["Bob"] * 60
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(Path(path).name for path in paths)  # no .tmp left
    umask = os.umask(0)
    os.umask(umask)
    assert {Path(path).stat().st_mode & 0o777 for path in paths} == {0o666 & ~umask}  # (not 0600: a file like any)


def test_a_replay_is_saved_whatever_its_course_is_called(tmp_path):
    """A course id is its name: '/' or a long name must not cost the round its replay file."""
    saved = []
    for course in ("fun/games", "fun/games", "⛳" * 100, "../.."):
        record = RoundRecord(recorded_at="2026-11-26T14:50:44", course=course, course_name=course, fingerprint="f",
                             shape_label="Pentagon", shape=PENTAGON, preset="fast", players=["Ann"])
        saved.append(record.save(tmp_path / "replays"))
    assert len(set(saved)) == 4 and all(path.parent == tmp_path / "replays" for path in saved)
    assert all(len(path.name.encode()) < 100 and re.fullmatch(r"[\w-]+\.json", path.name, re.ASCII) for path in saved)
    assert load_record(saved[2]).course == "⛳" * 100


@pytest.mark.parametrize("args", [["--players", "5"], ["--players", "two"], ["--players", "0"],
                                  ["--names", "Ann,Ann"], ["--players", "3", "--names", "Ann,Bob"],
                                  ["--players", "2", "--names", "Ann"]])
def test_bad_player_arguments_are_one_line_and_status_2(args, capsys):
    assert autoplay(*args) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("polygolf") and "Traceback" not in err[0]


def test_settings_are_kept_between_launches(courses):
    game = Game.load()
    assert not game.guide_seen and len(game.players) == 1
    game.next_theme()
    game.next_shape()
    game.next_player_count()
    game.mark_guide_seen()
    again = Game.load()
    assert (again.theme.name, again.shape_label, again.players, again.guide_seen) == \
        (game.theme.name, game.shape_label, ["Player 1", "Player 2"], True)


def test_a_seat_added_is_named_by_its_own_number_whatever_the_first_is_called(courses):
    """Player 1 named Ann, then Players clicked: seat 2 was called "Player 1" (on the HUD, the card
    and the bests)."""
    game = Game.load()
    game.set_names(["Ann"])
    seen = []
    for _ in range(4):
        game.next_player_count()
        seen.append(list(game.players))
    assert seen == [["Ann", "Player 2"], ["Ann", "Player 2", "Player 3"], ["Ann", "Player 2", "Player 3", "Player 4"],
                    ["Ann"]]
    game.set_names(["Player 2"])
    game.next_player_count()
    assert game.players == ["Player 2", "Player 1"]  # (its own number taken: the first free one)


def test_the_command_lines_choices_are_for_that_launch_and_the_menus_are_kept(courses):
    """`render --theme sand`, `play --course hazards --shape star-5-2` choose for that launch only:
    saving another setting keeps what was saved for them, until the menu makes that choice again.
    The menu's Sound is kept as any other choice (it was written only with the next change)."""
    from polygolf.game.app import _game_for

    menu = Game.load()
    menu.next_theme()  # the menu's choices: Night, the second shape, Meadow, one player
    saved = {key: menu.settings()[key] for key in ("theme", "shape", "course", "players", "volume")}
    game = _game_for("hazards", 1, "sand", "star-5-2", players=["Ann", "Bob"])
    assert (game.theme.name, game.shape_label, game.course.id, game.players) == ("Sand", "Star {5/2}", "hazards",
                                                                                ["Ann", "Bob"])
    game.toggle_preview()  # another setting, changed in play: written with the saved choices, not these
    game.next_volume()
    again = Game.load()
    assert {key: again.settings()[key] for key in saved} == saved | {"volume": game.sound.volume}
    assert again.preview is False and game.sound.volume != saved["volume"]
    game.next_theme()  # the menu chooses again: kept
    assert Game.load().theme.name == game.theme.name != saved["theme"]
    assert Game.load().course.id == "meadow"


def test_two_game_windows_keep_each_others_choices(courses):
    """Each choice writes itself alone: a second window's click does not put back the first
    window's old choices (every change wrote all of a window's settings)."""
    first, second = Game.load(), Game.load()
    first.next_theme()
    first.next_volume()
    second.next_hint()
    second.next_player_count()
    again = Game.load()
    assert (again.theme.name, again.sound.volume) == (first.theme.name, first.sound.volume) != \
        (second.theme.name, second.sound.volume)
    assert (again.hint, again.players) == (second.hint, second.players) != (first.hint, first.players)


def _save_on_damaged(key: str, folder: Path, start, runs: int, out) -> None:
    """(A process of the test below.) A setting saved in each run's folder as soon as both are ready."""
    for run in range(runs):
        start.wait()
        store = Store(folder / f"run{run}", echo=False)
        out.put((key, run, store.save_settings({key: run}) or store.warnings))


def test_two_games_meeting_one_damaged_database_set_it_aside_once_and_both_save(tmp_path):
    """Two games started together on a damaged database: it is set aside once, the fresh one one of
    them makes is not set aside by the other, and both saves are in it (the second game renamed the
    first's fresh database away as damaged, or found nothing to move and saved nothing)."""
    import multiprocessing

    runs = 40
    for run in range(runs):
        (tmp_path / f"run{run}").mkdir()
        (tmp_path / f"run{run}" / "polygolf.db").write_bytes(b"this is not a database\n" * 200)
    context = multiprocessing.get_context("fork")
    start, out = context.Barrier(2), context.Queue()
    workers = [context.Process(target=_save_on_damaged, args=(key, tmp_path, start, runs, out)) for key in ("a", "b")]
    for worker in workers:
        worker.start()
    saved = [out.get(timeout=120) for _ in range(2 * runs)]
    for worker in workers:
        worker.join(timeout=60)
    assert [ok for _, _, ok in saved] == [True] * len(saved)  # (else the warnings of the saves that failed)
    for run in range(runs):
        folder = tmp_path / f"run{run}"
        with sqlite3.connect(folder / "polygolf.db") as db:
            assert dict(db.execute("SELECT key, value FROM settings")) == {"a": str(run), "b": str(run)}
        aside = list(folder.glob("polygolf.db.corrupt-*"))
        assert len(aside) == 1 and aside[0].read_bytes().startswith(b"this is not a database")


def test_a_damaged_database_whose_lock_another_game_holds_is_given_up_in_seconds(tmp_path):
    """A game stopped (Ctrl-Z) while it set a damaged database aside holds the lock: another waits the
    save's time, not for ever, and says why nothing was saved."""
    import fcntl
    import time

    (tmp_path / "polygolf.db").write_bytes(b"this is not a database\n" * 200)
    with (tmp_path / "polygolf.db.lock").open("a") as held:
        fcntl.flock(held, fcntl.LOCK_EX)
        store = Store(tmp_path, echo=False)
        started = time.monotonic()
        assert store.save_settings({"a": 1}) is False
        assert time.monotonic() - started < 10.0  # (a bound against waiting for ever, not a speed test)
    assert store.warnings == [f"polygolf: {tmp_path / 'polygolf.db'} is damaged (file is not a database) and "
                              "another game is setting it aside; nothing saved"]
    assert Store(tmp_path, echo=False).save_settings({"a": 1})  # the lock let go: set aside, saved


def test_a_database_another_program_holds_locked_is_waited_for_in_full_once_then_briefly(tmp_path, monkeypatch):
    """QA: with the database held locked (`sqlite3`'s BEGIN EXCLUSIVE), every menu click waited the
    whole lock timeout on the window's thread. After a lock, settings and bests wait only briefly for
    some seconds; a round is still waited for in full; the lock let go, all is as before."""
    import polygolf.game.store as store_module

    waits = []
    connect = sqlite3.connect
    monkeypatch.setattr(store_module.sqlite3, "connect", lambda *a, **k: waits.append(k["timeout"]) or connect(*a, **k))
    store = Store(tmp_path, echo=False)
    assert store.save_settings({"a": 1})
    holder = connect(tmp_path / "polygolf.db", isolation_level=None)
    holder.execute("BEGIN EXCLUSIVE")
    waits.clear()
    assert store.save_settings({"a": 2}) is False
    assert store.bests() == [] and store.save_settings({"a": 3}) is False
    assert store.save_round(None, None, None) is None  # (a round: waited for in full, then given up)
    assert waits == [store_module.LOCK_TIMEOUT] + [store_module.BRIEF_WAIT] * 2 + [store_module.LOCK_TIMEOUT]
    # (a choice not saved is said each time: QA8, later losses were silent)
    assert len(store.warnings) == 4 and all("database is locked" in w for w in store.warnings)
    assert store.pending == {"a": 3}  # kept, for the next save
    holder.execute("ROLLBACK")
    holder.close()
    waits.clear()
    assert store.save_settings({"b": 4}) and store.load_settings() == {"a": 3, "b": 4}  # the lock gone: written
    assert store.pending == {}
    assert store.save_settings({"a": 5}) and waits[2:] == [store_module.LOCK_TIMEOUT]  # and waited for in full


def test_settings_a_lock_kept_from_the_database_are_never_dropped_and_said_each_time(tmp_path):
    """QA8: two games on one data folder; a click's choice was lost to 'database is locked', and only
    the first loss was said. Every choice is kept until a save gets through, and the game's close
    writes what is left, waiting for the lock."""
    store = Store(tmp_path, echo=False)
    assert store.save_settings({"theme": "night"})
    holder = sqlite3.connect(tmp_path / "polygolf.db", isolation_level=None)
    holder.execute("BEGIN EXCLUSIVE")
    assert store.save_settings({"volume": 0.25}) is False
    assert store.save_settings({"shape": "star"}) is False
    assert store.save_settings({"volume": 0.5}) is False
    assert len(store.warnings) == 3 and all("cannot save the settings" in w for w in store.warnings)
    holder.execute("ROLLBACK")
    holder.close()
    assert store.flush_settings() and store.pending == {}
    assert Store(tmp_path, echo=False).load_settings() == {"theme": "night", "volume": 0.5, "shape": "star"}


def test_the_settings_read_at_launch_waits_out_another_game_s_write(tmp_path, monkeypatch):
    """QA8: a game launched while another wrote began with the default settings: the read at launch
    waits for the lock in full, and again, before it gives up."""
    import threading
    import time

    import polygolf.game.store as store_module

    assert Store(tmp_path, echo=False).save_settings({"theme": "night"})
    monkeypatch.setattr(store_module, "LOCK_TIMEOUT", 0.3)
    holder = sqlite3.connect(tmp_path / "polygolf.db", isolation_level=None, check_same_thread=False)
    holder.execute("BEGIN EXCLUSIVE")
    threading.Thread(target=lambda: (time.sleep(0.5), holder.execute("ROLLBACK"))).start()
    try:
        store = Store(tmp_path, echo=False)
        assert store.load_settings() == {"theme": "night"}
    finally:
        time.sleep(0.6)
        holder.close()


def test_a_corrupted_database_is_set_aside_and_the_round_saved_to_a_fresh_one(capsys):
    db = data_dir() / "polygolf.db"
    assert autoplay() == 0
    assert Store(echo=False).round_count() == 1
    db.write_bytes(b"\x00garbage, not SQLite\xff" * 200)
    capsys.readouterr()
    assert autoplay() == 0
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "damaged" in err[0] and "corrupt-" in err[0]
    aside = list(data_dir().glob("polygolf.db.corrupt-*"))
    assert len(aside) == 1 and aside[0].read_bytes().startswith(b"\x00garbage")  # kept, not overwritten
    assert Store(echo=False).round_count() == 1  # this round, in a fresh database


def test_an_unusable_data_folder_costs_a_warning_not_the_round(tmp_path, monkeypatch, capsys):
    blocked = tmp_path / "file-not-folder"
    blocked.write_text("in the way")
    monkeypatch.setenv("POLYGOLF_DATA", str(blocked))
    assert autoplay() == 0
    err = capsys.readouterr().err.strip().splitlines()
    assert err and all(line.startswith("polygolf: cannot") for line in err)


def test_a_data_folder_that_is_a_link_to_nowhere_is_said_so():
    """A loop of links (or a link to nothing) where the data folder belongs: mkdir's 'File exists'
    said nothing of why."""
    loop_a, loop_b = Path(tmp := os.environ["POLYGOLF_DATA"]) / "a", Path(tmp) / "b"
    loop_a.parent.mkdir(parents=True, exist_ok=True)
    loop_a.symlink_to(loop_b)
    loop_b.symlink_to(loop_a)
    store = Store(loop_a, echo=False)
    assert store.save_settings({"volume": 0.5}) is False
    assert store.warnings == [f"polygolf: cannot save the settings: {loop_a}: {loop_a} is a link that leads nowhere "
                              "(to nothing, or round a loop of links)"]


def test_a_locked_database_costs_a_warning(capsys):
    store = Store(echo=False)
    assert store.save_settings({"volume": 0.5})
    holder = sqlite3.connect(store.path, isolation_level=None)
    holder.execute("BEGIN EXCLUSIVE")
    try:
        assert store.save_settings({"volume": 0.25}) is False
        assert len(store.warnings) == 1 and "locked" in store.warnings[0]
    finally:
        holder.execute("ROLLBACK")
        holder.close()
    assert Store(echo=False).load_settings() == {"volume": 0.5}  # not written...
    assert store.load_settings() == {"volume": 0.25}  # ... but kept, to be written with the next save


def test_settings_of_the_wrong_type_or_too_deep_fall_back_to_their_defaults():
    """A settings row edited by hand (a list where a name was, JSON nested past the parser's limit)
    is one setting lost, never a game that cannot start."""
    store = Store(echo=False)
    assert store.save_settings({"volume": 0.5})
    with sqlite3.connect(store.path) as db:
        db.executemany("INSERT OR REPLACE INTO settings VALUES (?, ?)",
                       [("hint", "[]"), ("computer_skill", '{"a": 1}'), ("theme", "[1]"), ("course", "{}"),
                        ("players", '["A\u0007B"]'), ("preview", "[" * 100_000), ("guide_seen", b"\x00\xff")])
    game = Game.load()
    assert (game.hint, game.computer_skill, game.preview, game.sound.volume) == ("off", "good", True, 0.5)
    assert store.save_settings({"volume": True})  # (a bool is no volume, though Python counts it a number)
    assert Game.load().sound.volume == 0.75  # (the default)
    assert game.players == ["Player 1"]  # a control character in a saved name: not taken


def test_rows_of_the_wrong_type_are_passed_over_by_the_bests(capsys):
    assert autoplay() == 0
    capsys.readouterr()
    with sqlite3.connect(data_dir() / "polygolf.db") as db:
        db.execute("UPDATE holes SET position = 'abc' WHERE position = 0")
        db.execute("UPDATE cards SET par = 'x'")
    assert main(["scores", "--json"]) == 0
    bests = json.loads(capsys.readouterr().out)
    assert [b["number"] for b in bests] == [2, 3]  # hole 1's row, and the course's (its par), left out
    with sqlite3.connect(data_dir() / "polygolf.db") as db:
        db.execute("UPDATE rounds SET finished_at = x'00ff'")
    assert main(["scores"]) == 0 and capsys.readouterr().out.strip() == "no rounds saved yet"


@pytest.mark.parametrize(("table", "column"), [("cards", "name"), ("rounds", "course_name"), ("rounds", "shape"),
                                             ("holes", "name")])
def test_names_longer_than_a_name_may_be_are_passed_over_by_the_bests(table, column, capsys):
    """A player's, course's, hole's or shape's name edited in at 100 000 characters (QA: the
    scorecard froze cutting it to fit, and `scores` printed it whole) is no round the game kept."""
    assert autoplay() == 0
    capsys.readouterr()
    assert main(["scores", "--json"]) == 0
    kept = json.loads(capsys.readouterr().out)
    with sqlite3.connect(data_dir() / "polygolf.db") as db:
        db.execute(f"UPDATE {table} SET {column} = ? WHERE rowid = (SELECT MIN(rowid) FROM {table})", ("N" * 100_000,))
    assert main(["scores", "--json"]) == 0
    out = capsys.readouterr().out
    assert "N" * 101 not in out and len(json.loads(out)) < len(kept)


def test_a_saved_shape_whose_label_names_another_shape_is_passed_over(courses):
    """QA: "Triangle" saved over a star {8/3} was shown as the Triangle, and kept its rounds as the
    Triangle's bests; a label of 100 000 characters froze the menu cutting it to fit."""
    store = Store(echo=False)
    for label, spec in [("Triangle", {"star": [8, 3], "radius": 1.0}), ("T" * 100_000, {"regular": 3, "radius": 1.0}),
                        ("Random #7", {"random": {"seed": 8, "vertices": 5}, "radius": 1.0})]:
        assert store.save_settings({"shape": {"label": label, "spec": spec}})
        game = Game.load()
        assert (game.shape_label, game.shape) == CATALOGUE[2]  # the default, the pentagon
    for label, spec in [("Star {8/3}", {"star": [8, 3], "radius": 1.0}), ("7-gon", {"regular": 7, "radius": 1.0}),
                        ("Random #8", {"random": {"seed": 8, "vertices": 5}, "radius": 1.0})]:
        assert store.save_settings({"shape": {"label": label, "spec": spec}})
        assert Game.load().shape_label == label  # what the game itself saves is taken


def test_a_refused_write_or_another_versions_database_is_never_set_aside(capsys):
    """Only a file SQLite cannot read is damaged: a constraint that refuses a row, or a database of
    another schema version, costs one warning and the file stays as it is."""
    assert autoplay() == 0
    db = data_dir() / "polygolf.db"
    with sqlite3.connect(db) as conn:
        conn.execute("CREATE TRIGGER refuse BEFORE INSERT ON cards BEGIN SELECT RAISE(ABORT, 'refused'); END")
    capsys.readouterr()
    assert autoplay() == 0
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "cannot" in err[0] and "refused" in err[0]
    assert Store(echo=False).round_count() == 1 and not list(data_dir().glob("polygolf.db.corrupt-*"))
    with sqlite3.connect(db) as conn:
        conn.execute("UPDATE meta SET value = '2' WHERE key = 'schema'")
    store = Store(echo=False)
    assert store.bests() == [] and "schema version 2" in store.warnings[0]
    assert not list(data_dir().glob("polygolf.db.corrupt-*"))
    with sqlite3.connect(db) as conn:  # untouched: the newer game finds its rounds
        assert conn.execute("SELECT COUNT(*) FROM rounds").fetchone()[0] == 1


@pytest.mark.parametrize(("names", "why"), [("J\udcf6rg", "a name is UTF-8 text"),
                                           ("A\x07\x1b[31mRED", "may not hold control characters, got U+0007")])
def test_names_that_are_not_printable_text_are_refused_in_one_line(names, why, capsys):
    assert autoplay("--names", names) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and why in err[-1], err


def test_preset_switches_are_recorded_and_the_round_replays_exactly(courses):
    course = find_course(courses, "sandbox")
    session = RoundPlay(Round(course, players=["Ann", "Bob"]), PENTAGON, "Pentagon", "balanced")
    golfers = {}

    def plan(hole):
        return golfers.setdefault(hole.hole.id, golfer_for(hole.hole)).plan((hole.ball.x, hole.ball.y))

    assert session.shoot(*plan(session.hole))
    for _ in range(20):
        session.step()
    session.set_preset("fast")  # mid-shot: the rest of the roll is simulated at fast
    while not session.hole_over:
        if session.can_shoot:
            session.shoot(*plan(session.hole))
        session.step()
    session.set_preset("accurate")  # after the hole's end: the next holes start with it
    for _ in range(30):
        session.step()
    session.finish_hole()
    session.start_hole()
    session.play_out(plan)
    record = session.record
    assert [h.preset for h in record.holes] == ["balanced", "accurate", "accurate"]
    assert [i.preset for i in record.holes[0].inputs if i.kind == "preset"] == ["fast"]
    lines = list(verify(record, course))
    assert len(lines) == 3 and all(same for _, same in lines), lines


def test_a_restart_never_drops_a_ball_onto_another():
    """Hot seat: player 1 restarts while player 2's ball lies on player 1's tee spot."""
    import math

    from polygolf.engine.golf.holes import find_course, load_all_courses
    from polygolf.engine.golf.play import HolePlay
    from polygolf.engine.loading.scene import ShapeSpec

    hole = find_course(load_all_courses()[0], "meadow").holes[0]
    play = HolePlay(hole, ShapeSpec(regular=6, radius=1.0), "fast", players=2)
    try:
        mine = play.players[0].tee
        play.turn = 0
        play.place_ball(mine[0] + 4.0, mine[1])
        play.turn = 1
        play.place_ball(*mine)
        play.turn = 0
        assert play.restart_ball()
        first, second = play.players[0].body, play.players[1].body
        assert math.dist((first.x, first.y), (second.x, second.y)) >= 2 * play.collider.radius
        play.sim.step(10, measure=True)
        assert play.sim.metrics.max_penetration <= 0.011
    finally:
        play.close()


def test_scores_of_a_course_nobody_knows_says_so_and_of_a_known_one_without_rounds_says_none_yet(capsys):
    assert main(["scores", "--course", "medow"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("polygolf: no course 'medow'; courses: meadow, hazards"), err
    assert main(["scores", "--course", "medow", "--json"]) == 2
    capsys.readouterr()
    for known in ("Meadow", "hazards", "Random nine · seed 12"):
        assert main(["scores", "--course", known]) == 0
        assert capsys.readouterr().out.strip() == f"no rounds saved yet on {known}"


def test_scores_with_a_database_it_cannot_read_says_so(capsys):
    """A folder where the database belongs (or a file it may not read): the store's warning, then
    "no rounds could be read" and a failing exit, not "no rounds saved yet"."""
    (data_dir() / "polygolf.db").mkdir(parents=True)
    assert main(["scores"]) == 1
    out = capsys.readouterr()
    assert out.out.strip() == "no rounds could be read" and "polygolf.db" in out.err


@pytest.mark.parametrize("where, players, shape", [(("hazards", 8), 4, "Square"), (("meadow", 7), 3, "Triangle")])
def test_balls_come_to_rest_against_each_other_fall_asleep_and_the_turn_passes(where, players, shape):
    """Three or four balls stopped touching each other (a row on the ice of The Slide) never fell
    asleep: the first to sleep was woken by a still neighbour, their clocks begun again pair by
    pair never ran out together, and nobody could shoot again (R did not help: the round was lost)."""
    courses, _ = load_all_courses()
    course, hole = find_course(courses, where[0]), where[1]
    label, ball = next((label, ball) for label, ball in CATALOGUE if label == shape)
    session = RoundPlay(Round(course, players=[f"P{k + 1}" for k in range(players)], position=hole - 1), ball, label,
                        "balanced")
    golfer, idle, frames = golfer_for(session.hole.hole), 0, 0
    try:
        while not session.hole.finished and frames < 60 * 600:
            if session.can_shoot:
                idle = 0
                assert session.shoot(*golfer.plan((session.hole.ball.x, session.hole.ball.y)))
            idle += 1
            asleep = [p.body.asleep for p in session.hole.players]
            assert idle < 60 * 60, f"nobody can shoot after a minute: asleep {asleep}"
            session.step()
            frames += 1
        assert session.hole.finished
    finally:
        session.close()


def test_a_courses_file_that_lists_a_hole_many_times_reads_it_once(tmp_path, monkeypatch):
    """500 mentions of a 400-tile hole held the game's start for minutes: each was read and laid out."""
    import shutil

    from polygolf.engine.golf import holes as holes_module
    from polygolf.engine.loading.paths import HOLES_DIR

    shutil.copy(HOLES_DIR / "straight.yaml", tmp_path / "straight.yaml")
    (tmp_path / "courses.yaml").write_text("courses:\n" + "".join(
        f"  - name: Course {c}\n    holes: [{', '.join(['straight'] * 400)}]\n" for c in range(3)))
    reads = []
    real = holes_module.load_hole
    monkeypatch.setattr(holes_module, "load_hole", lambda *args: reads.append(args) or real(*args))
    courses = holes_module.load_courses(tmp_path / "courses.yaml")
    assert len(reads) == 1 and [len(c.holes) for c in courses] == [400, 400, 400]
    assert all(hole.id == "straight" for c in courses for hole in c.holes)


def test_a_round_whose_hole_never_ends_is_one_line_not_a_traceback(capsys):
    courses, _ = load_all_courses()
    session = RoundPlay(Round(find_course(courses, "sandbox"), players=["Ann"]), PENTAGON, "Pentagon", "fast")
    try:
        with pytest.raises(ValueError, match=r"^Sandbox: hole 1 did not finish in 0 s of play \(a ball never came "
                                             r"to rest\); the round is not saved$"):
            session.play_out(lambda hole: ((hole.ball.x, hole.ball.y), (0.5, 0.0)), max_frames=2)
    finally:
        session.close()


def test_autoplay_says_which_holes_of_its_course_it_passes_over(capsys):
    import shutil

    from polygolf.engine.loading.paths import HOLES_DIR

    mine = data_dir() / "content" / "holes"
    mine.mkdir(parents=True)
    shutil.copy(HOLES_DIR / "straight.yaml", mine / "good.yaml")
    (mine / "bad.yaml").write_text("name: Bad\npar: 2\ntiles: [\n")
    (mine / "courses.yaml").write_text("courses:\n  - name: Mine\n    holes: [good, bad, missing]\n")
    assert main(["autoplay", "--course", "mine", "--preset", "fast"]) == 0
    err = capsys.readouterr().err.strip().splitlines()
    assert err[0].startswith(f"polygolf: skipped: {mine / 'bad.yaml'}:4: (yaml): ")
    assert err[1] == f"polygolf: skipped: {mine / 'courses.yaml'}:3: courses[0].holes[2]: no hole file missing.yaml"


def test_rows_out_of_range_are_passed_over_and_names_are_never_shown_raw(capsys):
    """QA: hand-edited rows of -3 and 0 strokes were listed as bests, and a player's name holding a
    line break or a terminal's colour code (ESC [31m) was written raw to the terminal."""
    assert autoplay() == 0
    capsys.readouterr()
    db = data_dir() / "polygolf.db"
    with sqlite3.connect(db) as conn:
        second, = conn.execute("SELECT * FROM holes WHERE position = 1").fetchall()

    def numbers() -> list[int | None]:
        assert main(["scores", "--json"]) == 0
        return [b["number"] for b in json.loads(capsys.readouterr().out)]

    assert numbers() == [1, 2, 3, None]
    for column, value in (("strokes", -3), ("strokes", 0), ("strokes", 100), ("par", 0), ("par", 21),
                          ("position", -1), ("penalties", -1), ("picked_up", 2)):
        with sqlite3.connect(db) as conn:
            conn.execute(f"UPDATE holes SET {column} = ? WHERE position = 1", (value,))
        # Hole 2's row passed over; the course's too where its card is no longer the sum of its holes.
        assert numbers() == ([1, 3] if column in ("strokes", "par") else [1, 3, None]), (column, value)
        with sqlite3.connect(db) as conn:  # (back as it was)
            conn.execute("DELETE FROM holes WHERE position NOT IN (0, 2)")
            conn.execute(f"INSERT INTO holes VALUES ({', '.join('?' * len(second))})", second)
        assert numbers() == [1, 2, 3, None]
    with sqlite3.connect(db) as conn:
        conn.execute("UPDATE cards SET strokes = 0, par = 0")  # a card of 0 strokes: no course best
    assert numbers() == [1, 2, 3]
    with sqlite3.connect(db) as conn:
        conn.execute("UPDATE cards SET name = ?", ("Eve\n\x1b[31mRED\u202e",))
    assert main(["scores"]) == 0
    out = capsys.readouterr().out
    lines = out.splitlines()
    assert len(lines) == 3 and "\x1b" not in out and "\u202e" not in out
    assert all(line.split(", par ")[1].split()[1] == "Eve\\n\\x1b[31mRED\\u202e," for line in lines), lines
    assert main(["scores", "--json"]) == 0  # (JSON escapes it itself; the name is read back as it is)
    out = capsys.readouterr().out
    assert "\x1b" not in out and {b["player"] for b in json.loads(out)} == {"Eve\n\x1b[31mRED\u202e"}


def test_scores_that_cannot_be_read_fail_with_or_without_json(capsys):
    """QA: `scores` exited 1 on a database it could not read, `scores --json` 0 (with an empty list,
    as if no round had been played)."""
    (data_dir() / "polygolf.db").mkdir(parents=True)
    for args in (["scores"], ["scores", "--json"], ["scores", "--course", "meadow", "--json"]):
        assert main(args) == 1
        out = capsys.readouterr()
        assert "polygolf.db" in out.err
        assert out.out == ("no rounds could be read\n" if args == ["scores"] else "")


def test_scores_on_the_fresh_database_that_replaced_a_damaged_one_has_no_rounds_yet(capsys):
    """QA: a damaged database set aside and a fresh one started: 'no rounds could be read', exit 1,
    though everything was read (the fresh one is empty)."""
    data_dir().mkdir(parents=True, exist_ok=True)
    (data_dir() / "polygolf.db").write_bytes(b"\x00garbage, not SQLite\xff" * 200)
    assert main(["scores"]) == 0
    out = capsys.readouterr()
    assert out.out == "no rounds saved yet\n"
    assert "damaged" in out.err and "starting a fresh one" in out.err
    assert len(list(data_dir().glob("polygolf.db.corrupt-*"))) == 1
    (data_dir() / "polygolf.db").write_bytes(b"\x00garbage again\xff" * 200)
    assert main(["scores", "--json"]) == 0 and capsys.readouterr().out == "[]\n"


@pytest.mark.parametrize(("names", "why"), [
    ("\u0301\u0301", "a name needs a letter, digit or sign that shows"),  # accents alone: invisible
    ("Ann,\u200b", "a name needs a letter, digit or sign that shows"),  # a zero-width space alone
    ("Ann,\u3164", "a name needs a letter, digit or sign that shows"),  # a Hangul filler alone (QA8)
    ("\u3164\u3164,Bob", "a name needs a letter, digit or sign that shows"),
    ("Ann,\uffa0", "a name needs a letter, digit or sign that shows"),  # halfwidth Hangul filler
    ("Ann,\u115f\u1160", "a name needs a letter, digit or sign that shows"),  # choseong, jungseong fillers
    ("Ann,\u2800", "a name needs a letter, digit or sign that shows"),  # a blank Braille cell
    ("Ann,\u2800\u2062\u3000\u3164", "a name needs a letter, digit or sign that shows"),  # Cf, space, filler
    ("Ann,Bo\u202eb", "may not hold control characters, got U+202E"),  # a direction override
    ("An\u200bn,Bob", "may not hold an invisible space or hyphen, got U+200B"),  # 'Ann' to the eye (QA)
    ("An\u00adn,Bob", "may not hold an invisible space or hyphen, got U+00AD"),  # a soft hyphen
    ("A\u0301nn,\u00c1nn", "every player needs a different name"),  # one name, typed two ways
    (" \u00c1nn , Bob,A\u0301nn", "every player needs a different name"),  # (spaces about it are no part)
    ("Abcdefghijklmnopqrstu", "at most 20 characters"),
])
def test_player_names_follow_the_rules_of_a_courses_name(names, why, capsys):
    assert autoplay("--names", names) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("polygolf: --names: ") and why in err[0], err


def test_names_written_with_joiners_are_names():
    """Persian, Devanagari and an emoji family need U+200C / U+200D, which are no control characters:
    taken as a course's name takes them, and shown as they are (QA: refused as 'not printable')."""
    from polygolf.game.cli import names_arg
    from polygolf.game.session import escaped

    names = ["\u0645\u06cc\u200c\u062e\u0648\u0627\u0647\u0645", "\u0915\u094d\u200d\u0937",
             "\U0001f468\u200d\U0001f469\u200d\U0001f467"]
    assert names_arg(",".join(names)) == names
    assert [escaped(name) for name in names] == names
    assert escaped("Eve\n\x1b[31m\u202e") == "Eve\\n\\x1b[31m\\u202e"


def test_players_named_with_joiners_play_a_round_and_its_replay(capsys):
    """QA: the round's record held a player's name to `str.isprintable`, which refuses the joiners the
    names screen takes: every round of a Persian or emoji-family player failed to start (and the
    saved names made every launch fail)."""
    names = ["\u0645\u06cc\u200c\u062e\u0648\u0627\u0647\u0645", "\U0001f468\u200d\U0001f469\u200d\U0001f467"]
    assert autoplay("--players", "2", "--names", ",".join(names)) == 0, capsys.readouterr().err
    replay = next((data_dir() / "replays").glob("*.json"))
    assert json.loads(replay.read_text())["players"] == names
    capsys.readouterr()
    assert main(["replay", "--verify", str(replay)]) == 0, capsys.readouterr()


def test_player_names_are_kept_in_composed_form():
    from polygolf.game.cli import names_arg

    assert names_arg("A\u0301nn,Bo\u0308b") == ["\u00c1nn", "B\u00f6b"]  # 'Ánn', 'Böb' as one character each
    assert names_arg("Abcdefghijklmnopqrs\u0301") == ["Abcdefghijklmnopqr\u015b"]  # 20 typed, 19 composed
    store = Store(echo=False)
    for saved, taken in ((["A\u0301nn", "Bob"], ["\u00c1nn", "Bob"]), (["A\u0301nn", "\u00c1nn"], ["Player 1"]),
                         (["\u0301", "Bob"], ["Player 1"])):
        assert store.save_settings({"players": saved})
        assert Game.load().players == taken, saved


def _verify_with_inputs(tmp_path, capsys, edit) -> str:
    """`replay --verify` of the round `autoplay` recorded, with hole 1's inputs as `edit(inputs, end
    frame)` makes them: its output (exit 1 asserted)."""
    path = next((data_dir() / "replays").glob("*.json"))
    data = json.loads(path.read_text())
    data["holes"][0]["inputs"] = edit(data["holes"][0]["inputs"], data["holes"][0]["frames"])
    tampered = tmp_path / "tampered.json"
    tampered.write_text(json.dumps(data))
    capsys.readouterr()
    assert main(["replay", str(tampered), "--verify"]) == 1
    out = capsys.readouterr().out.splitlines()
    assert out[-1] == f"{tampered}: does NOT match: 1 of 3 holes simulated again", out
    return out[0]


def test_a_replay_with_inputs_live_play_could_never_have_taken_fails_verify(tmp_path, capsys):
    """QA's replay added 20,000 shots to hole 1, at frames 0 to 19,999 (it ends at frame 137): they
    were passed over in silence and the round verified 'identical', exit 0."""
    assert autoplay() == 0
    path = next((data_dir() / "replays").glob("*.json"))
    capsys.readouterr()
    assert main(["replay", str(path), "--verify"]) == 0  # (as recorded)
    data = json.loads(path.read_text())
    shot, = data["holes"][0]["inputs"]
    end = data["holes"][0]["frames"]
    assert shot["frame"] == 0 and shot["kind"] == "shot" and 60 < end < 1000

    line = _verify_with_inputs(tmp_path, capsys, lambda inputs, end: [dict(shot, frame=k) for k in range(20_000)])
    assert line == ("hole 1 warm-up: 19,999 of 20,000 recorded inputs could never have been taken (the shot at "
                    "frame 1: a ball was still moving; and 19,998 more)")
    line = _verify_with_inputs(tmp_path, capsys, lambda inputs, end: inputs + [dict(shot, frame=end + 5)])
    assert line == (f"hole 1 warm-up: 1 of 2 recorded inputs could never have been taken (the shot at frame "
                    f"{end + 5}: after the hole ended (frame {end}))")
    line = _verify_with_inputs(tmp_path, capsys, lambda inputs, end: inputs + [{"frame": end, "kind": "restart"}])
    assert line.endswith(f"(the restart at frame {end}: after the hole ended (frame {end}))")
    line = _verify_with_inputs(tmp_path, capsys, lambda inputs, end: inputs * 2)
    assert line.endswith("(the shot at frame 0: a shot was taken in this frame already)")
    line = _verify_with_inputs(tmp_path, capsys, lambda inputs, end: [dict(shot, frame=5), shot])
    assert line.endswith("(the shot at frame 0: out of frame order (frame 5 was reached first))")


def test_a_replay_s_course_is_chosen_for_now_and_every_course_stays_on_offer():
    """`polygolf replay` chooses the replay's course for the menu after it (Play again plays it), but
    leaves every course and Random nine to choose (QA: the Course button then offered only it)."""
    from polygolf.engine.golf.holes import Course

    game = Game.load(Store(echo=False))
    offered = [c.id for c in game.courses]
    game.show_course(game.courses[1])
    assert [c.id for c in game.courses] == offered and game.course is game.courses[1]
    nine = Course("random-nine-4711", "Random nine #4711", [])
    game.show_course(nine)
    assert [c.id for c in game.courses] == offered and game.random_chosen and game.course is nine
    assert game.random_seed == 4711 and game.course_label == "Random nine #4711"
    game.next_course()
    assert game.course is game.courses[0]


def test_of_tied_rounds_the_best_is_the_one_finished_first(monkeypatch):
    """QA: a round was stamped with the time it began, so of two windows' rounds with equal scores the
    best went to the one begun first though the other finished first; in one second, to the seat
    order. Now stamped when kept, and in one second the one kept first."""
    from polygolf.game import store as store_module

    course = find_course(load_all_courses()[0], "sandbox")
    store = Store(echo=False)
    ann = RoundPlay(Round(course, players=["Ann"]), CATALOGUE[2][1], "Pentagon", "fast")
    bob = RoundPlay(Round(course, players=["Bob"]), CATALOGUE[2][1], "Pentagon", "fast")
    ann.record.recorded_at, bob.record.recorded_at = "2026-01-01T00:00:00", "2026-01-01T00:00:05"  # Ann began first
    monkeypatch.setattr(store_module, "utc_stamp", lambda: "2026-01-01T00:10:00", raising=False)  # kept in one second
    try:
        for play in (bob, ann):  # Bob finishes first, with Ann's score
            while play.round.current() is not None:
                play.round.finish_hole([(2, False, 0)])
            store.save_round(play.round, play.record, None)
        assert store.best_course("sandbox", "Pentagon").player == "Bob"
        assert {b.player for b in store.bests("sandbox") if b.hole is not None} == {"Bob"}
    finally:
        ann.close()
        bob.close()


def test_a_replays_folder_that_is_a_file_is_named_so_and_the_round_is_kept(capsys):
    """QA: 'cannot save the replay in .../replays: File exists' (mkdir's words) did not say why."""
    data_dir().mkdir(parents=True, exist_ok=True)
    (data_dir() / "replays").write_text("not a folder")
    assert autoplay() == 0
    err = capsys.readouterr().err
    folder = data_dir() / "replays"
    assert f"cannot save the replay in {folder}: {folder} is a file, not a folder" in err
    assert Store(echo=False).round_count() == 1  # the round itself is kept


@pytest.mark.parametrize("name", ["\u3164", "\uffa0", "\u1160", "\u115f", "\u2800", "\u2800\u3164",
                                  "\u3164\u2062\u3164", "\u3164\u00a0\u3164", "\u2800\ufff9\u2800"])
def test_a_name_of_characters_that_show_nothing_is_refused_as_an_empty_one(name):
    """QA8: Hangul fillers and the blank Braille cell are letters and signs to Unicode but show nothing:
    the Names screen, --names and the settings all go through `player_name`."""
    from polygolf.game.session import player_name

    with pytest.raises(ValueError, match="a name needs a letter, digit or sign that shows"):
        player_name(name)


@pytest.mark.parametrize("name", ["Ann\u3164", "\u2800A", "A\u2062B", "\ud55c\uad6d\uc5b4", "\u2801"])
def test_a_name_with_something_that_shows_is_kept_as_it_is(name):
    from polygolf.game.session import player_name

    assert player_name(name) == name


def _history(folder: Path, seed: int) -> None:
    """A database of rounds as years of play leave them, and hands edit them: courses sharing hole ids,
    a hole twice in a course, ties (one second, one finish time for many rounds), incomplete rounds,
    rows edited to the wrong type or to values no round holds."""
    import random

    rnd = random.Random(seed)
    Store(folder, echo=False).load_settings()  # the schema
    with sqlite3.connect(folder / "polygolf.db") as db:
        for rid in range(1, 400):
            course = rnd.choice(["meadow", "hazards"])
            holes = ["a", "b", "a", "c"] if course == "meadow" else ["b", "d", "c"]
            when = f"2026-01-{rnd.randint(1, 3):02d}T00:00:0{rnd.randint(0, 1)}"
            complete = int(rnd.random() < 0.85)
            db.execute("INSERT INTO rounds VALUES (?, ?, ?, ?, ?, 'fast', 2, ?, 'f', NULL)",
                       (rid, when, course, course.title(), rnd.choice(["Pentagon", "Star"]), complete))
            for seat in range(rnd.randint(1, 3)):
                strokes = [rnd.choice([1, 2, 2, 3, 3, 3, 4]) for _ in holes]
                pars = [3] * len(holes)
                card = [sum(strokes), sum(pars)]
                if rnd.random() < 0.05:
                    card[0] += 1  # a card that is not the sum of its holes
                db.execute("INSERT INTO cards VALUES (?, ?, ?, ?, ?)", (rid, seat, f"P{rid}.{seat}", *card))
                for position, (hole, n) in enumerate(zip(holes, strokes)):
                    value = rnd.choice([n] * 30 + ["2", 0, 100, 2.0])  # now and then edited by hand
                    db.execute("INSERT INTO holes VALUES (?, ?, ?, ?, ?, 3, ?, 0, 0)",
                               (rid, seat, position, hole, hole.upper(), value))


@pytest.mark.parametrize("many_ties", [0, 10**9, None])
@pytest.mark.parametrize("seed", range(4))
def test_a_best_asked_alone_is_the_one_the_whole_history_gives(tmp_path, monkeypatch, seed, many_ties):
    """QA8: best_hole and best_course worked out every best from the whole history (3 s at 10 000
    rounds, on the window's thread). Asked by index now, they give the very rows `bests` gives: the
    same place, strokes and holder on every tie rule, both ways of finding who was first, and where
    an index cannot be made (None: a read-only file), from the whole history as before."""
    import polygolf.game.store as store_module

    if many_ties is None:
        monkeypatch.setattr(store_module, "INDEXES", {**store_module.INDEXES, "unmade": "nowhere (x)"})
    else:
        monkeypatch.setattr(store_module, "MANY_TIES", many_ties)
    _history(tmp_path, seed)
    store = Store(tmp_path, echo=False)
    every = store.bests()
    assert len(every) > 10
    for course in ("meadow", "hazards", "nowhere"):
        for shape in ("Pentagon", "Star", "Hexagon"):
            expected = {b.hole: b for b in every if b.course == course and b.shape == shape}
            for hole in ("a", "b", "c", "d", "z"):
                assert store.best_hole(course, hole, shape) == expected.get(hole), (course, hole, shape)
            assert store.best_course(course, shape) == expected.get(None), (course, shape)


def test_a_best_takes_milliseconds_at_ten_thousand_rounds(tmp_path):
    """QA8's many-rounds: 10 000 copies of one round (every best tied 10 000 ways)."""
    import time

    _history(tmp_path, 0)
    with sqlite3.connect(tmp_path / "polygolf.db") as db:
        db.execute("UPDATE rounds SET finished_at = '2026-01-01T00:00:00'")
        for _ in range(5):  # 400 -> 12 800 rounds
            top = db.execute("SELECT MAX(id) FROM rounds").fetchone()[0]
            db.execute(f"INSERT INTO rounds SELECT id + {top}, finished_at, course, course_name, shape, preset, "
                       "players, complete, fingerprint, replay FROM rounds")
            db.execute(f"INSERT INTO cards SELECT round_id + {top}, seat, name, strokes, par FROM cards")
            db.execute(f"INSERT INTO holes SELECT round_id + {top}, seat, position, hole, name, par, strokes, "
                       "penalties, picked_up FROM holes")
    store = Store(tmp_path, echo=False)
    assert store.best_hole("meadow", "a", "Pentagon") is not None  # (the indexes made, once)
    started = time.perf_counter()
    for hole in ("a", "b", "c"):
        assert store.best_hole("meadow", hole, "Pentagon") is not None
    assert store.best_course("meadow", "Pentagon") is not None
    assert time.perf_counter() - started < 0.25  # (4 asks; 3 s each before, on a quiet machine)


def _record(player: str = "Ann") -> RoundRecord:
    return RoundRecord(recorded_at="2026-11-26T14:50:44", course="sandbox", course_name="Sandbox", fingerprint="f",
                       shape_label="Pentagon", shape=PENTAGON, preset="fast", players=[player])


def test_a_replay_s_name_is_taken_only_with_its_whole_text(tmp_path, monkeypatch):
    """QA8: kill -9 between taking a replay's name and writing its text left a 0-byte replay. The
    text is written to a temporary first and linked to the free name: a replay never exists empty."""
    folder = tmp_path / "replays"
    text = json.dumps(_record().model_dump(mode="json"), indent=1)
    links = []
    link = os.link

    def checked(source, target):
        assert Path(source).read_text(encoding="utf-8") == text  # whole before it has the name
        assert all(p.stat().st_size > 0 for p in Path(target).parent.glob("*.json"))  # never an empty one
        links.append(Path(target).name)
        link(source, target)

    monkeypatch.setattr(os, "link", checked)
    first, second = _record().save(folder), _record().save(folder)
    assert links == [first.name, "20261126T145044-sandbox.json", second.name]  # (the second met the first's name)
    assert sorted(p.name for p in folder.iterdir()) == sorted([first.name, second.name])  # no temporary left
    assert load_record(second).players == ["Ann"]


def test_a_replay_is_saved_where_the_file_system_has_no_hard_links(tmp_path, monkeypatch):
    def refuse(source, target):
        raise PermissionError(1, "Operation not permitted")

    monkeypatch.setattr(os, "link", refuse)
    path = _record().save(tmp_path)
    assert load_record(path).players == ["Ann"] and [p.name for p in tmp_path.iterdir()] == [path.name]


def test_empty_replays_and_stale_temporaries_are_cleared_at_start_and_nothing_else():
    """QA8: what kill -9 during a save left (an empty `.json`, a hidden `.tmp`) stayed for ever. At
    start, those older than a minute go; younger ones may be another game's save under way."""
    import time

    from polygolf.game.record import STALE, sweep_replays

    folder = data_dir() / "replays"
    folder.mkdir(parents=True)
    good = _record().save(folder)
    old = time.time() - 2 * STALE
    files = {"empty-old.json": b"", "empty-new.json": b"", ".a-1-ff.tmp": b"{", ".b-2-ee.tmp": b"{",
             "notes.txt": b""}
    for name, data in files.items():
        (folder / name).write_bytes(data)
    for name in ("empty-old.json", ".a-1-ff.tmp", "notes.txt"):
        os.utime(folder / name, (old, old))
    os.utime(good, (old, old))
    (folder / "dir.json").mkdir()
    os.utime(folder / "dir.json", (old, old))
    Game.load()
    assert sorted(p.name for p in folder.iterdir()) == sorted([good.name, "empty-new.json", ".b-2-ee.tmp",
                                                               "notes.txt", "dir.json"])
    assert sweep_replays(folder / "nowhere") == []  # (no folder: nothing, no error)
