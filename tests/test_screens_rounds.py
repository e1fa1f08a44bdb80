"""Rounds in the real window (Xvfb), driven by synthesised mouse and key events: two players to the
scorecard and their bests on the next round, the restart penalty, the last shot watched again, and a
database broken between launches."""

from __future__ import annotations

import time

import arcade
import pytest

from polygolf.engine.golf.golfer import golfer_for
from polygolf.engine.loading.paths import data_dir
from polygolf.game.drawing import text_box
from polygolf.game.flow import ScreenFlow
from polygolf.game.record import load_record
from polygolf.game.replay import load_for_replay, verify
from polygolf.game.session import Game
from polygolf.game.store import Store
from polygolf.game.views.between import BetweenView
from polygolf.game.views.guide import GuideView
from polygolf.game.views.pause import PauseView
from polygolf.game.views.play import PlayView
from polygolf.game.views.replay import ReplayView
from polygolf.game.views.results import ResultsView

from .test_screens import aim, assert_not_blank, click, frame, key, shots_dir, snapshot, window  # noqa: F401


def start_sandbox_round(win, players: int) -> Game:
    """From the menu, as a newcomer: Course until Sandbox, Players until `players`, Play, the guide."""
    game = Game.load()
    ScreenFlow(win, game).menu()
    while game.course.id != "sandbox":
        click(win, "course")
    while len(game.players) != players:
        click(win, "players")
    assert win.current_view.buttons["players"].text == f"Players: {players}"
    click(win, "play")
    if isinstance(win.current_view, GuideView):
        key(win, arcade.key.ENTER)
    assert isinstance(win.current_view, PlayView)
    return game


def play_to(win, stop, shots: list | None = None, max_frames: int = 60 * 60 * 3):
    """Play with the scripted golfer through the mouse until `stop(view)`; between holes, go on.
    `shots` collects (hole number, seat) of every shot in order."""
    golfers = {}
    for step in range(max_frames):
        view = win.current_view
        if stop(view):
            return view
        if isinstance(view, BetweenView):
            key(win, arcade.key.ENTER)
            continue
        assert isinstance(view, PlayView), type(view)
        session = view.session
        if session.can_shoot:
            world = view.world
            golfer = golfers.setdefault(id(world), golfer_for(world.hole))
            origin, arrow = golfer.plan((world.ball.x, world.ball.y))
            seat, strokes = world.turn, world.state.strokes
            aim(win, view, origin, arrow)
            frame(win)
            assert world.players[seat].state.strokes == strokes + 1, "the synthesised drag did not shoot"
            if shots is not None:
                shots.append((view.round.number, seat))
            continue
        frame(win, draw=step % 40 == 0)
    pytest.fail("never got there")


def test_two_players_play_to_the_scorecard_and_see_their_bests_next_round(window, shots_dir):  # noqa: F811
    game = start_sandbox_round(window, 2)
    play = window.current_view
    assert [p.body.asleep for p in play.world.players] == [True, True]
    assert play.hud_texts["strokes"].text == "Player 1: 0 strokes"
    assert play.hud_texts["players"].text == "Player 1: 0  ·  Player 2: 0"
    assert_not_blank(snapshot(window, shots_dir, "play-two-players"), "play")
    shots: list[tuple[int, int]] = []
    between = play_to(window, lambda v: isinstance(v, BetweenView), shots)
    assert_not_blank(snapshot(window, shots_dir, "between-two-players"), "between")
    assert "Player 1: " in between.lines.text and "Player 2: " in between.lines.text
    assert between.best.text.startswith("No best kept")  # nothing saved yet: the round is not over
    # Strict rotation: the seats alternate while both balls are in play.
    first_hole = [seat for number, seat in shots if number == 1]
    card = [r.strokes for r in game.round.cards[0]], [r.strokes for r in game.round.cards[1]]
    both = 2 * min(card[0][0], card[1][0])
    assert first_hole[:both] == [0, 1] * (both // 2)
    results = play_to(window, lambda v: isinstance(v, ResultsView), shots)
    round_ = results.round
    totals = [round_.total_strokes(0), round_.total_strokes(1)]
    assert totals == [sum(1 for _, seat in shots if seat == k) + sum(r.penalties for r in round_.cards[k])
                      for k in (0, 1)]
    winners = [name for name, total in zip(round_.players, totals) if total == min(totals)]
    assert (f"{winners[0]} wins" if len(winners) == 1 else "A tie") in results.summary.text
    player_rows = [cell.text.text for cell in results.cells if cell.col == 0]
    assert player_rows == ["Hole", "Par", "Player 1", "  to par, running", "Player 2", "  to par, running"]
    assert_not_blank(snapshot(window, shots_dir, "results-two-players"), "results")
    # Saved: the round in the database, its replay on disk, and it verifies.
    assert Store(echo=False).round_count() == 1
    replay, = (data_dir() / "replays").glob("*.json")
    record, course = load_for_replay(replay)
    assert record.players == ["Player 1", "Player 2"] and all(same for _, same in verify(record, course))
    # The next round shows the bests between holes and on the scorecard.
    click(window, _button(results, "Play again"))
    assert isinstance(window.current_view, PlayView)
    between = play_to(window, lambda v: isinstance(v, BetweenView))
    best_hole_1 = min(round_.cards[0][0].strokes, round_.cards[1][0].strokes)
    assert "Best on this hole with the Pentagon: " in between.best.text
    assert f": {best_hole_1} stroke" in between.best.text
    assert_not_blank(snapshot(window, shots_dir, "between-with-best"), "between")
    results = play_to(window, lambda v: isinstance(v, ResultsView))
    assert results.best.text.startswith(("Course best with the Pentagon: ", "New course best with the Pentagon: "))
    assert_not_blank(snapshot(window, shots_dir, "results-with-best"), "results")


def _button(view, text: str):
    """A GUI button by its label."""
    for widget in view.ui.walk_widgets():
        if getattr(widget, "text", None) == text:
            return widget
    raise AssertionError(f"no button {text!r}")


def test_restart_keeps_the_strokes_and_adds_a_penalty_stroke(window, shots_dir):  # noqa: F811
    game = start_sandbox_round(window, 1)
    play = window.current_view
    world = play.world
    tee = (world.ball.x, world.ball.y)
    aim(window, play, tee, (1.2, 0.4))
    for _ in range(5):
        frame(window)
    assert world.state.strokes == 1 and not world.ball_at_rest
    key(window, arcade.key.R)  # while it rolls: no free retake
    frame(window)
    assert (world.state.strokes, world.state.penalties, world.state.score) == (1, 1, 2)
    assert (world.ball.x, world.ball.y) == tee and world.ball_at_rest
    assert play.hud_texts["strokes"].text == "2 strokes (+1 penalty stroke)"
    assert play.splashes == []  # (no water's rings at the tee: QA)
    assert_not_blank(snapshot(window, shots_dir, "play-restart-penalty"), "play")
    key(window, arcade.key.ESCAPE)
    pause = window.current_view
    assert isinstance(pause, PauseView)
    click(window, _button(pause, "Restart hole"))
    frame(window)
    assert window.current_view is play and (world.state.strokes, world.state.penalties) == (1, 2)
    assert play.hud_texts["strokes"].text == "3 strokes (+2 penalty strokes)"
    # The restarts are in the recording, so the hole still replays exactly.
    assert [i.kind for i in game.session.inputs] == ["shot", "restart", "restart"]


def test_l_shows_the_last_shot_again_and_returns_to_the_hole(window, shots_dir):  # noqa: F811
    start_sandbox_round(window, 2)
    play = window.current_view
    world = play.world
    for _ in range(2):  # a shot each
        origin, arrow = golfer_for(world.hole).plan((world.ball.x, world.ball.y))
        aim(window, play, origin, arrow)
        while not play.session.can_shoot:
            frame(window)
    live = [(p.body.x, p.body.y, p.body.angle) for p in world.players]
    key(window, arcade.key.L)
    replay = window.current_view
    assert isinstance(replay, ReplayView) and replay.title == "Player 2's last shot"
    assert replay.session.frame == play.session.last_shot().frame  # the frames before were simulated unseen
    # Game time as played at any frame rate (QA: a frame a window update, 2.4x fast at 144 Hz).
    start = replay.session.frame
    replay.on_update(1 / 20)
    replay.on_update(1 / 144)  # (not yet a whole frame: none; the rest waits)
    assert replay.session.frame == start + 3
    replay.fast = True
    replay.on_update(1 / 60 - 1 / 144)
    assert replay.session.frame == start + 7
    replay.fast = False
    for _ in range(20):
        frame(window)
    assert_not_blank(snapshot(window, shots_dir, "replay-last-shot"), "replay")
    for _ in range(60 * 30):
        if replay.at_end():
            break
        frame(window)
    again = [(p.body.x, p.body.y, p.body.angle) for p in replay.session.hole.players]
    assert again == live  # simulated again, bit for bit
    for _ in range(120):
        if window.current_view is play:
            break
        frame(window)
    assert window.current_view is play
    assert [(p.body.x, p.body.y, p.body.angle) for p in world.players] == live  # the hole as it was
    assert play.session.can_shoot and play.session.player_name == "Player 1"


def test_a_database_broken_between_launches_costs_one_line_and_the_round_is_kept(window, shots_dir, capsys):  # noqa: F811
    store = Store(echo=False)
    store.save_settings({"guide_seen": True})
    store.path.write_bytes(b"SQLite format 3\x00" + b"\xde\xad\xbe\xef" * 500)  # a header, then garbage
    capsys.readouterr()
    start_sandbox_round(window, 1)
    # One line for the database (a machine without an audio device also says so once: not counted).
    err = [line for line in capsys.readouterr().err.strip().splitlines() if "no sound" not in line]
    assert len(err) == 1 and "damaged" in err[0] and "polygolf.db.corrupt-" in err[0]
    results = play_to(window, lambda v: isinstance(v, ResultsView))
    assert "damaged" in results.warning.text
    assert_not_blank(snapshot(window, shots_dir, "results-after-broken-db"), "results")
    aside, = data_dir().glob("polygolf.db.corrupt-*")
    assert aside.read_bytes().endswith(b"\xde\xad\xbe\xef")
    assert Store(echo=False).round_count() == 1
    replay, = (data_dir() / "replays").glob("*.json")
    assert load_record(replay).course == "sandbox"


def test_a_recorded_round_is_shown_hole_by_hole_then_its_scorecard(window, shots_dir):  # noqa: F811
    from polygolf.game.cli import main
    from polygolf.game.replay import replay_session
    from polygolf.game.sound import SoundBoard

    from .test_sound import RecordingPlayer

    assert main(["autoplay", "--course", "sandbox", "--players", "2", "--preset", "fast"]) == 0
    replay, = (data_dir() / "replays").glob("*.json")
    record, course = load_for_replay(replay)
    game = Game.load()
    heard = RecordingPlayer()
    game.sound = SoundBoard(heard)
    session = replay_session(record, course)
    ScreenFlow(window, game).watch_round(record, session)
    view = window.current_view
    assert isinstance(view, ReplayView) and view.title.startswith("Replay of ")
    holes_seen = set()
    for step in range(60 * 60 * 3):
        if isinstance(window.current_view, ResultsView):
            break
        if session.hole is not None:
            holes_seen.add(session.round.number)
        frame(window)
        if step == 90:
            assert_not_blank(snapshot(window, shots_dir, "replay-round"), "replay")
    results = window.current_view
    assert isinstance(results, ResultsView) and holes_seen == {1, 2, 3}
    sounds = [name for name, _ in heard.played]
    assert sounds.count("hit") >= 6 and sounds.count("drop") == 6, sounds  # as it sounded played (it was silent)
    assert [[r.strokes for r in card] for card in results.round.cards] == \
        [[h.final[seat].strokes + h.final[seat].penalties for h in record.holes] for seat in (0, 1)]


def test_players_type_their_names_and_the_game_keeps_them(window, shots_dir):  # noqa: F811
    from polygolf.game.views.menu import MenuView
    from polygolf.game.views.names import NamesView

    from .test_screens import send

    game = Game.load()
    ScreenFlow(window, game).menu()
    click(window, "players")
    click(window, "names")
    names = window.current_view
    assert isinstance(names, NamesView) and len(names.boxes) == 2
    for typed in ("Ann", "Ann"):  # a repeated name is told apart
        for _ in range(len("Player 1")):
            send(window, "on_text_motion", arcade.key.MOTION_BACKSPACE)
        send(window, "on_text", typed)
        names.on_draw()
        key(window, arcade.key.TAB)
    assert [box.text for box in names.boxes] == ["Ann", "Ann"]
    assert_not_blank(snapshot(window, shots_dir, "names"), "names")
    key(window, arcade.key.ENTER)
    assert isinstance(window.current_view, MenuView)
    assert window.current_view.buttons["names"].text == "Names: Ann, Ann 2"
    assert Game.load().players == ["Ann", "Ann 2"]  # kept for the next launch


def test_a_name_the_rules_refuse_is_said_so_and_waits_to_be_typed_again(window, shots_dir):  # noqa: F811
    """QA: a name of accents alone (it shows nothing) silently became 'Player 2'. Done now says why
    where the hint was and keeps the screen, the refused box active; emptied, the box keeps its
    seat's default and Done goes back to the menu."""
    from polygolf.game.views.menu import MenuView
    from polygolf.game.views.names import HINT, NamesView

    from .test_screens import send

    game = Game.load()
    game.players = ["Ann", "Bob"]
    ScreenFlow(window, game).names()
    names = window.current_view
    assert isinstance(names, NamesView)
    names.boxes[1].text = "\u0301\u0301"
    key(window, arcade.key.ENTER)
    assert window.current_view is names
    assert names.hint.text.startswith("Player 2's name: a name needs a letter") and names.refused
    assert names.boxes[1].active and not names.boxes[0].active
    assert_not_blank(snapshot(window, shots_dir, "names-refused"), "names-refused")
    for _ in range(2):
        send(window, "on_text_motion", arcade.key.MOTION_BACKSPACE)
    assert names.boxes[1].text == ""
    key(window, arcade.key.ENTER)
    assert isinstance(window.current_view, MenuView)
    assert game.players == ["Ann", "Player 2"] and HINT not in names.hint.text


def test_repeated_long_names_are_numbered_within_the_length():
    """Two players typing the same 20-character name (the longest) are still told apart."""
    from types import SimpleNamespace

    from polygolf.game.views.names import NamesView

    long = "Alexandra Worthingto"
    boxes = [SimpleNamespace(text=text) for text in (long, long, f"{long[:18]} 2", long)]
    names = NamesView.names(SimpleNamespace(boxes=boxes))
    assert len(set(names)) == 4 and all(len(name) <= 20 for name in names)
    assert names[:3] == [long, f"{long[:18]} 2", f"{long[:18]} 3"]


LONG_NAMES = ["Alexandra Worthingto", "Alexandra Worthingt2", "CPU", "Christopher Robinson"]


def _extent(text: arcade.Text) -> tuple[float, float]:
    """A text's left and right edges on the screen (`drawing.text_box`)."""
    left, _, right, _ = text_box(text)
    return left, right


@pytest.mark.parametrize("size", [(640, 400), (800, 600), (1280, 720)])
def test_screens_keep_long_names_and_scores_inside_their_places(window, size, shots_dir):  # noqa: F811
    """Four players with the longest names, picked up on every hole: no scorecard cell runs out of
    its column, no HUD text into another, no between-holes line off the window."""
    from polygolf.engine.golf.holes import find_course
    from polygolf.game.session import Round

    window.set_size(*size)
    for _ in range(50):  # (the X server may take a moment: a screen drawn before would be the old size's)
        window.dispatch_events()
        if window.get_size() == size:
            break
        time.sleep(0.01)
    game = Game.load()
    course = find_course(game.courses, "meadow")
    round_ = Round(course, players=list(LONG_NAMES))
    for _ in range(9):
        results = round_.finish_hole([(10, True, 3), (5, False, 1), (2, False, 0), (7, False, 2)])
    between = BetweenView(game, round_, results, ScreenFlow(window, game))
    window.show_view(between)
    between.on_draw()
    for text in (between.headline, between.detail, between.lines, between.best, between.next_text):
        left, right = _extent(text)
        assert 0 <= left and right <= size[0], text.text
    assert between.next_text.y - between.next_text.content_height / 2 > 108  # above the button
    results_view = ResultsView(game, round_, ScreenFlow(window, game))
    window.show_view(results_view)
    results_view.on_draw()
    label_w, cell_w, _, _, _ = results_view._fit(*size)
    for cell in results_view.cells:
        room = label_w - 10 if cell.col == 0 else results_view._total_w if cell.col == results_view.columns - 1 \
            else cell_w  # (the Total column has a width of its own: QA8)
        assert cell.text.content_width <= room, (cell.text.text, cell.text.content_width, room)
    labels = [cell.text.text for cell in results_view.cells if cell.col == 0 and cell.row in results_view.player_rows]
    assert len(set(labels)) == len(labels) == 4, labels  # names cut in the middle stay apart (QA: 'WWWW…' twice)
    assert_not_blank(snapshot(window, shots_dir, f"results-long-names-{size[0]}"), "results")
    game.players = list(LONG_NAMES)
    play = PlayView(game, game.start_round(1), ScreenFlow(window, game))
    window.show_view(play)
    play.on_draw()
    course_text, hole_text, strokes_text = (play.hud_texts[k] for k in ("course", "hole", "strokes"))
    edges = [_extent(course_text), _extent(hole_text), _extent(strokes_text)]
    assert 0 <= edges[0][0] and edges[0][1] < edges[1][0] and edges[1][1] < edges[2][0] and edges[2][1] <= size[0]
    assert _extent(play.hud_texts["players"])[0] >= 0
    assert play.hud_texts["players"].text.count(": 0") == 4  # every player's score, names cut instead (QA)
    window.set_size(1280, 720)
    window.dispatch_events()


def test_names_typed_two_ways_are_one_name_and_a_name_that_shows_nothing_is_none():
    """'Ánn' typed as one character or as A and an accent is one player (numbered as a repeat), and
    a name of accents alone (it shows nothing) keeps its seat's default, as an empty box does."""
    from types import SimpleNamespace

    from polygolf.game.views.names import NamesView

    boxes = [SimpleNamespace(text=text) for text in ("\u00c1nn", "A\u0301nn", "\u0301\u0301", " \u200b ")]
    assert NamesView.names(SimpleNamespace(boxes=boxes)) == ["\u00c1nn", "\u00c1nn 2", "Player 3", "Player 4"]


def test_a_course_with_no_playable_hole_shows_its_problem_in_the_menu_and_starts_no_round(window):  # noqa: F811
    """QA: Play on a course whose every hole is unreadable went straight to an empty scorecard."""
    from polygolf.game.views.menu import MenuView

    from .test_game_cli import _content_with_a_bomb

    bomb = _content_with_a_bomb(data_dir())
    game = Game.load()
    ScreenFlow(window, game).menu()
    while game.course.id != "only-bomb":
        click(window, "course")
    for _ in range(2):
        click(window, "play")
        menu = window.current_view
        assert isinstance(menu, MenuView) and game.round is None and game.session is None
        problems = menu.problems.text.split("\n")
        assert problems[0].startswith(f"course 'Only Bomb' has no playable hole ({bomb}:1: ")
        assert sum(p.startswith("course 'Only Bomb'") for p in problems) == 1  # (said once, however often asked)
    assert Store(echo=False).round_count() == 0 and not (data_dir() / "replays").exists()
    click(window, "course")  # Half: its first hole plays
    click(window, "play")
    if isinstance(window.current_view, GuideView):
        key(window, arcade.key.ENTER)
    assert isinstance(window.current_view, PlayView) and window.current_view.world.hole.id == "good"
    window.current_view.close()
