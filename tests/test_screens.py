"""The real screens in a real window (Xvfb via pytest-xvfb), driven by synthesised mouse and key
events: every screen drawn to a PNG and looked at by numbers, a theme change that changes the
pixels, and a whole 9-hole round played by scripted shots through the mouse."""

from __future__ import annotations

import os
from pathlib import Path

import arcade
import numpy as np
import pytest

from polygolf.engine.golf.golfer import golfer_for
from polygolf.engine.golf.holes import load_courses
from polygolf.game.flow import ScreenFlow
from polygolf.game.session import Game, HoleResult
from polygolf.game.views.between import BetweenView
from polygolf.game.views.guide import GuideView
from polygolf.game.views.menu import MenuView
from polygolf.game.views.pause import PauseView
from polygolf.game.views.play import PlayView
from polygolf.game.views.results import ResultsView

LEFT = arcade.MOUSE_BUTTON_LEFT


@pytest.fixture(scope="module")
def window():
    assert os.environ.get("DISPLAY"), "window tests need a display: run under Xvfb (pytest-xvfb does it)"
    win = arcade.Window(1280, 720, "PolyGolf test", resizable=True)
    yield win
    win.close()


@pytest.fixture
def game():
    return Game.load()


@pytest.fixture(scope="module")
def shots_dir(tmp_path_factory) -> Path:
    path = Path(os.environ.get("POLYGOLF_SCREENSHOTS", tmp_path_factory.mktemp("screens")))
    path.mkdir(parents=True, exist_ok=True)
    return path


def send(window, *event):
    """Post an input event the way the OS would, then let pyglet deliver its queue."""
    window.dispatch_event(*event)
    window.dispatch_events()


def show(window, view):
    window.show_view(view)
    view.on_draw()  # lays out the GUI, so buttons have their places
    return view


def frame(window, draw: bool = False):
    window.current_view.on_update(1 / 60)
    if draw:
        window.current_view.on_draw()


def click(window, name_or_widget, view=None):
    """Click a button the way a player does: a frame is drawn first, so the button is where it shows."""
    view = view or window.current_view
    view.on_draw()
    widget = view.buttons[name_or_widget] if isinstance(name_or_widget, str) else name_or_widget
    x, y = widget.rect.center
    send(window, "on_mouse_motion", x, y, 0, 0)
    send(window, "on_mouse_press", x, y, LEFT, 0)
    send(window, "on_mouse_release", x, y, LEFT, 0)


def key(window, symbol):
    send(window, "on_key_press", symbol, 0)
    send(window, "on_key_release", symbol, 0)


def drag(window, start, end, steps: int = 6, release: bool = True):
    sx, sy = start
    ex, ey = end
    send(window, "on_mouse_press", sx, sy, LEFT, 0)
    for i in range(1, steps + 1):
        x, y = sx + (ex - sx) * i / steps, sy + (ey - sy) * i / steps
        send(window, "on_mouse_drag", x, y, (ex - sx) / steps, (ey - sy) / steps, LEFT, 0)
    if release:
        send(window, "on_mouse_release", ex, ey, LEFT, 0)


def snapshot(window, shots_dir: Path, name: str) -> np.ndarray:
    window.current_view.on_draw()
    image = arcade.get_image(0, 0, *window.get_framebuffer_size()).convert("RGB")
    image.save(shots_dir / f"{name}.png")
    return np.asarray(image, dtype=np.int16)


def assert_not_blank(pixels: np.ndarray, name: str):
    colours = len(np.unique(pixels.reshape(-1, 3), axis=0))
    assert colours > 20 and pixels.std() > 8, f"{name} looks blank ({colours} colours, std {pixels.std():.1f})"


def aim(window, view: PlayView, origin, arrow, release: bool = True):
    """Press on the ball at `origin` (world) and drag the arrow, all in screen pixels."""
    start = view.camera.project(origin)
    end = view.camera.project((origin[0] + arrow[0], origin[1] + arrow[1]))
    drag(window, (start[0], start[1]), (end[0], end[1]), release=release)


def test_every_screen_draws_something(window, game, shots_dir):
    flow = ScreenFlow(window, game)
    show(window, MenuView(game, flow))
    assert_not_blank(snapshot(window, shots_dir, "menu"), "menu")
    round_ = game.start_round()
    show(window, GuideView(game, then=flow.next_hole))
    assert_not_blank(snapshot(window, shots_dir, "guide"), "guide")
    play = show(window, PlayView(game, round_, flow))
    ball = play.world.ball
    aim(window, play, (ball.x, ball.y), (2.5, 1.0), release=False)
    assert play.aiming
    pixels = snapshot(window, shots_dir, "play-aiming")
    assert_not_blank(pixels, "play")
    key(window, arcade.key.ESCAPE)  # cancels the shot, does not pause
    assert not play.aiming and window.current_view is play
    key(window, arcade.key.ESCAPE)  # now pauses
    assert isinstance(window.current_view, PauseView)
    assert_not_blank(snapshot(window, shots_dir, "pause"), "pause")
    show(window, BetweenView(game, round_, round_.finish_hole([(3, False, 0)]), flow))
    assert_not_blank(snapshot(window, shots_dir, "between"), "between")
    while not round_.over:
        round_.finish_hole([(4, False, 0)])
    show(window, ResultsView(game, round_, flow))
    assert_not_blank(snapshot(window, shots_dir, "results"), "results")


def test_environment_button_changes_the_look(window, game, shots_dir):
    flow = ScreenFlow(window, game)
    show(window, MenuView(game, flow))
    before = snapshot(window, shots_dir, "menu-grass")
    click(window, "theme")
    assert game.theme.name != "Grass"
    after = snapshot(window, shots_dir, f"menu-{game.theme.name.lower()}")
    assert np.abs(before - after).mean() > 10
    # And on the play screen too.
    game.theme_index = 0
    show(window, PlayView(game, game.start_round(), flow))
    grass = snapshot(window, shots_dir, "play-grass")
    game.theme_index = [t.name for t in game.themes].index("Sand")
    show(window, PlayView(game, game.start_round(), flow))
    sand = snapshot(window, shots_dir, "play-sand")
    assert np.abs(grass - sand).mean() > 10


def test_polygon_buttons_change_the_ball(window, game):
    show(window, MenuView(game, ScreenFlow(window, game)))
    first = game.shape_label
    click(window, "shape")
    assert game.shape_label != first
    click(window, "random")
    assert game.shape_label.startswith("Random #")
    click(window, "course")
    assert game.course.name == "Hazards"


def test_a_full_round_of_nine_holes_ends_on_the_scorecard_with_the_right_totals(window, game, shots_dir):
    ScreenFlow(window, game).menu()
    assert game.course.name == "Meadow"
    click(window, "play")
    assert isinstance(window.current_view, GuideView)  # offered before the first round
    key(window, arcade.key.ENTER)
    assert isinstance(window.current_view, PlayView)

    scores: dict[int, int] = {}
    golfers = {}
    for step in range(60 * 60 * 4):
        view = window.current_view
        if isinstance(view, ResultsView):
            break
        if isinstance(view, BetweenView):
            key(window, arcade.key.ENTER)
            continue
        assert isinstance(view, PlayView), type(view)
        world = view.world
        if world.state.finished:
            scores[view.round.number] = world.state.score
        elif world.ball_at_rest:
            golfer = golfers.setdefault(id(world), golfer_for(world.hole))
            origin, arrow = golfer.plan((world.ball.x, world.ball.y))
            strokes = world.state.strokes
            aim(window, view, origin, arrow)
            frame(window)
            assert world.state.strokes == strokes + 1, "the synthesised drag did not shoot"
            continue
        frame(window, draw=step % 30 == 0)
    else:
        pytest.fail("the round did not end")

    results = window.current_view
    assert isinstance(results, ResultsView)
    round_ = results.round
    assert [r.number for r in round_.results] == list(range(1, 10))
    assert {r.number: r.strokes for r in round_.results} == scores
    assert round_.total_strokes() == sum(scores.values())
    assert round_.total_par() == sum(h.spec.par for h in game.course.playable)
    totals = [text.text for text, col, row in results.cells if col == results.columns - 1]
    diff = round_.total_strokes() - round_.total_par()
    assert totals == ["Total", str(round_.total_par()), str(round_.total_strokes()), "E" if diff == 0 else f"{diff:+d}"]
    assert_not_blank(snapshot(window, shots_dir, "results-played"), "results")


def test_a_broken_hole_is_skipped_with_a_visible_message(window, tmp_path, shots_dir):
    import shutil

    from polygolf.engine.loading.paths import HOLES_DIR

    shutil.copy(HOLES_DIR / "tiles.yaml", tmp_path / "tiles.yaml")
    shutil.copy(HOLES_DIR / "straight.yaml", tmp_path / "straight.yaml")
    (tmp_path / "broken.yaml").write_text("name: Broken\npar: 3\ntiles:\n  - {at: [0, 0], borders: nowhere}\n")
    (tmp_path / "courses.yaml").write_text("courses:\n  - name: Mixed\n    holes: [broken, straight]\n")
    game = Game(courses=load_courses(tmp_path / "courses.yaml"), themes=Game.load().themes)
    play = show(window, PlayView(game, game.start_round(), ScreenFlow(window, game)))
    assert play.world.hole.id == "straight"
    assert "Hole 1 skipped" in play.banner.text and "broken.yaml:4: tiles[0].borders" in play.banner.text
    assert_not_blank(snapshot(window, shots_dir, "play-skipped-banner"), "play")
    result, = play.round.finish_hole([(2, False, 0)])
    assert play.round.results[0] == HoleResult(1, "(broken)", 0, None)
    assert result.number == 2


def test_the_window_resizes_and_the_hole_still_fits(window, game, shots_dir):
    play = show(window, PlayView(game, game.start_round(), ScreenFlow(window, game)))
    window.set_size(800, 600)
    send(window, "on_resize", 800, 600)
    x0, y0, x1, y1 = play.world.layout.bounds
    for corner in ((x0, y0), (x1, y1)):
        sx, sy = play.camera.project(corner)
        assert 0 <= sx <= 800 and 0 <= sy <= 600
    snapshot(window, shots_dir, "play-800x600")
    window.set_size(1280, 720)
    send(window, "on_resize", 1280, 720)


def test_f3_overlay_shows_each_systems_cost_and_keys_switch_the_preset(window, game, shots_dir):
    play = show(window, PlayView(game, game.start_round(), ScreenFlow(window, game)))
    key(window, arcade.key.F3)
    assert play.overlay
    play.world.shoot((play.world.ball.x, play.world.ball.y), (2.0, 0.0))
    for _ in range(30):
        frame(window)
    lines = play.overlay_lines()
    assert lines[0].startswith("preset balanced: 4 substeps x 8 iterations")
    for name in play.world.system_names:
        line = next(line for line in lines if line.strip().startswith(name + " "))
        assert float(line.split()[-2]) >= 0.0
    assert play.system_us["narrowphase"] > 0.0 and play.system_us["integrate"] > 0.0
    key(window, arcade.key.KEY_1)
    frame(window)
    assert play.world.knobs.substeps == 2 and game.preset == "fast"
    assert play.overlay_lines()[0].startswith("preset fast: 2 substeps")
    assert_not_blank(snapshot(window, shots_dir, "play-overlay"), "overlay")
    key(window, arcade.key.KEY_2)
    key(window, arcade.key.F3)
    assert not play.overlay and game.preset == "balanced"


def test_a_watched_hole_file_reloads_on_save_and_keeps_the_ball(window, game, tmp_path, shots_dir):
    import time

    from polygolf.engine.golf.holes import Course, load_hole_file
    from polygolf.game.watch import FileWatcher, HoleReloader

    path = tmp_path / "mine.yaml"
    path.write_text("name: Mine\npar: 2\ntiles:\n  - {at: [0, 0]}\n  - {at: [1, 0]}\n")
    game.courses, game.course_index, game.guide_seen = [Course("mine", "mine.yaml", [load_hole_file(path)])], 0, True
    flow = ScreenFlow(window, game)
    flow.new_round()
    play = flow.playing
    play.world.place_ball(4.0, 2.0)
    watcher = FileWatcher(path)
    reload = HoleReloader(flow, path, watcher)
    try:
        time.sleep(0.3)  # the watcher's thread is listening
        path.write_text("name: Mine, longer\npar: 3\ntiles:\n  - {at: [0, 0]}\n  - {at: [1, 0]}\n  - {at: [2, 0]}\n")
        for _ in range(100):
            reload()
            if play.world.hole.spec.name == "Mine, longer":
                break
            time.sleep(0.05)
        assert play.world.hole.spec.name == "Mine, longer" and len(play.world.layout.floor) == 3
        assert (play.world.ball.x, play.world.ball.y) == (4.0, 2.0)  # it still fits: kept
        assert_not_blank(snapshot(window, shots_dir, "play-watch-reloaded"), "reloaded")
        path.write_text("name: Mine\npar: 3\ntiles:\n  - {at: [0, 0], borders: nowhere}\n")
        for _ in range(100):
            reload()
            if "nowhere" in play.banner.text:
                break
            time.sleep(0.05)
        assert "mine.yaml:4: tiles[0].borders: unknown border set 'nowhere'" in play.banner.text
        assert play.world.hole.spec.name == "Mine, longer"  # the last good version plays on
        snapshot(window, shots_dir, "play-watch-broken")
    finally:
        watcher.close()
