"""The real screens in a real window (Xvfb via pytest-xvfb), driven by synthesised mouse and key
events: every screen drawn to a PNG and looked at by numbers, a theme change that changes the
pixels, and a whole 9-hole round played by scripted shots through the mouse."""

from __future__ import annotations

import functools
import math
import os
import time
from pathlib import Path

import arcade
import numpy as np
import pytest

from polygolf.engine.golf.golfer import golfer_for
from polygolf.engine.golf.holes import load_courses
from polygolf.engine.physics.presets import PRESETS
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
    aim(window, play, (ball.x, ball.y + 0.3), (4.0, 0.8), release=False)  # grabbed off-centre: spin shown
    assert play.world.shot_spin(play.grab, (play.tip[0] - play.grab[0], play.tip[1] - play.grab[1])) < -1.0
    assert_not_blank(snapshot(window, shots_dir, "play-aiming-spin"), "play")
    key(window, arcade.key.ESCAPE)
    assert not play.aiming and window.current_view is play
    key(window, arcade.key.ESCAPE)  # now pauses
    assert isinstance(window.current_view, PauseView)
    assert_not_blank(snapshot(window, shots_dir, "pause"), "pause")
    between = show(window, BetweenView(game, round_, round_.finish_hole([(3, False, 0)]), flow))
    assert_not_blank(snapshot(window, shots_dir, "between"), "between")
    # Between holes: Enter goes on (the first button has the focus), Esc leaves the round for the menu.
    assert between.buttons["next"].rect.right < between.buttons["menu"].rect.left  # side by side, not overlapping
    key(window, arcade.key.ESCAPE)
    assert isinstance(window.current_view, MenuView) and game.round is None
    game.round = round_
    between = show(window, BetweenView(game, round_, round_.finish_hole([(3, False, 0)]), flow))
    key(window, arcade.key.ENTER)
    assert isinstance(window.current_view, PlayView) and window.current_view.round.number == 3
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
    totals = [cell.text.text for cell in results.cells if cell.col == results.columns - 1]
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


def test_the_end_of_hole_message_is_centred_again_after_a_resize(window, game):
    """It was placed once, where the window's middle was when it first showed: after the window
    shrank it sat on the cup, or off the window."""
    from polygolf.game.views.play import HUD_HEIGHT

    play = show(window, PlayView(game, game.start_round(), ScreenFlow(window, game)))
    play.draw_finish_message(1024, 700)
    play.draw_finish_message(800, 600)
    assert play.finish_text.position == (400, (600 - HUD_HEIGHT) / 2)


def test_f3_overlay_shows_each_systems_cost_and_keys_switch_the_preset(window, game, shots_dir):
    play = show(window, PlayView(game, game.start_round(), ScreenFlow(window, game)))
    key(window, arcade.key.F3)
    assert play.overlay
    play.world.shoot((play.world.ball.x, play.world.ball.y), (2.0, 0.0))
    for _ in range(30):
        frame(window)
    lines = play.overlay_lines()
    knobs = PRESETS["balanced"]
    assert lines[0].startswith(f"preset balanced: {knobs.substeps} substeps x {knobs.iterations} iterations")
    fps_line = next(line for line in lines if line.startswith("fps"))
    assert float(fps_line.split()[1]) == pytest.approx(60.0) and "frame 16.7 ms" in fps_line
    x0, y0, x1, y1 = play.world.layout.bounds
    from polygolf.game.views.play import OVERLAY_WIDTH

    assert play.camera.project((x0, y0))[0] >= OVERLAY_WIDTH  # the panel hides no part of the hole
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


def play_for(view: PlayView, seconds: float, fps: int) -> None:
    for _ in range(round(seconds * fps)):
        view.on_update(1 / fps)


def test_the_ball_follows_the_same_path_at_20_and_144_fps(window, game):
    """Physics steps whole fixed frames whatever the frame rate: the same shot, played for the same
    real time at 20 and at 144 frames a second, leaves the ball in bit-identical states."""
    states = []
    for fps in (20, 144):
        play = show(window, PlayView(game, game.start_round(), ScreenFlow(window, game)))
        ball = play.world.ball
        play.world.shoot((ball.x, ball.y + 0.1), (3.0, 1.5))
        play_for(play, 1.5, fps)
        states.append((play.clock.frames, ball.x, ball.y, ball.angle, ball.vx, ball.vy, ball.spin))
        assert not ball.asleep  # still rolling: the comparison is mid-flight, not two balls at rest
        play.close()
    assert states[0] == states[1]
    assert states[0][0] == 90  # 1.5 s of real time is 90 physics frames at either rate


def test_a_slow_frame_rate_still_plays_in_real_time_and_draws_between_poses(window, game):
    play = show(window, PlayView(game, game.start_round(), ScreenFlow(window, game)))
    ball = play.world.ball
    play.world.shoot((ball.x, ball.y), (3.0, 0.0))
    play_for(play, 2.0, 35)
    assert play.clock.frames == 120
    drawn = play.ball_poses[play.world.turn].at(play.clock.alpha)
    before, after = play.ball_poses[play.world.turn].previous, play.ball_poses[play.world.turn].current
    assert min(before[0], after[0]) <= drawn[0] <= max(before[0], after[0])


def hazard_points(layout):
    """(kind, colour field, point inside) for every hazard of a hole, away from its edges."""
    from polygolf.engine.components.hazards import Region

    found = []
    fields = {"sand": "sand_zone", "water": "water", "ice": "ice", "slope": "slope"}
    for kind, outline, _ in layout.zones:
        xs, ys = zip(*outline)
        region = Region(tuple(outline), (min(xs), min(ys), max(xs), max(ys)))
        inside = [(x, y) for x in np.linspace(min(xs), max(xs), 9)[1:-1] for y in np.linspace(min(ys), max(ys), 9)[1:-1]
                  if all(region.contains(x + dx, y + dy) for dx in (-0.6, 0.6) for dy in (-0.6, 0.6))]
        cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
        found.append((kind, fields[kind], min(inside, key=lambda p: math.hypot(p[0] - cx, p[1] - cy)), 1.2))
    for outline, _, _ in layout.bumpers:
        centre = (sum(x for x, _ in outline) / len(outline), sum(y for _, y in outline) / len(outline))
        found.append(("bumper", "bumper", centre, 0.25))
    for _, pivot, _ in layout.windmills:
        found.append(("windmill", "windmill", pivot, 0.2))
    return found


@pytest.mark.parametrize("theme_name", ["Grass", "Night", "Sand"])
def test_every_hazard_is_drawn_in_its_own_colour_in_every_theme(window, game, shots_dir, theme_name):
    """Each hazard's patch on screen holds its theme colour and hardly any green; slopes are a tinted
    floor with chevrons in the slope colour."""
    game.theme_index = [t.name for t in game.themes].index(theme_name)
    game.course_index = [c.name for c in game.courses].index("Hazards")
    theme = game.theme
    seen = set()
    for number in range(1, len(game.course.holes) + 1):
        play = show(window, PlayView(game, game.start_round(number - 1), ScreenFlow(window, game)))
        pixels = snapshot(window, shots_dir, f"hazards-{number}-{theme_name.lower()}")
        height = pixels.shape[0]
        for kind, field, (x, y), half in hazard_points(play.world.layout):
            (sx0, sy0), (sx1, sy1) = (play.camera.project((x - half / 2, y - half / 2))[:2],
                                      play.camera.project((x + half / 2, y + half / 2))[:2])
            patch = pixels[height - int(sy1):height - int(sy0), int(sx0):int(sx1)].reshape(-1, 3)
            near = {name: (np.abs(patch - theme.rgba(name)[:3]).sum(axis=1) < 30).mean()
                    for name in ("green", "green_alt", field)}
            assert near["green"] + near["green_alt"] < 0.05, (number, kind, near)
            assert near[field] >= (0.03 if kind == "slope" else 0.5), (number, kind, near)
            if kind == "slope":
                floor = np.median(patch, axis=0)
                assert np.abs(floor - theme.rgba("green")[:3]).sum() > 25, (number, floor)
            seen.add(kind)
        play.close()
    assert seen == {"sand", "water", "ice", "slope", "bumper", "windmill"}


def test_menu_clicks_and_the_volume_button_are_heard(window, game):
    from polygolf.game.sound import SoundBoard

    from .test_sound import RecordingPlayer

    player = RecordingPlayer()
    game.sound = SoundBoard(player, volume=0.5)
    show(window, MenuView(game, ScreenFlow(window, game)))
    click(window, "volume")
    assert game.sound.volume == 0.75 and "75%" in window.current_view.buttons["volume"].text
    click(window, "theme")
    assert [name for name, _ in player.played] == ["click", "click"]
    assert player.played[0][1] == pytest.approx(0.6 * 0.5)  # heard at the old volume, before it changed
    key(window, arcade.key.M)
    click(window, "shape")
    assert len(player.played) == 2 and game.sound.muted
    assert window.current_view.buttons["volume"].text == "Sound: off"  # (it still said 75% while muted)
    again = Game.load()
    assert again.sound.muted and again.sound.volume == 0.75  # kept for the next launch, as the volume is
    key(window, arcade.key.M)
    assert not Game.load().sound.muted and window.current_view.buttons["volume"].text == "Sound: 75%"


def test_zoom_keeps_the_point_under_the_pointer_and_right_drag_pans(window, game):
    play = show(window, PlayView(game, game.start_round(), ScreenFlow(window, game)))
    fitted = play.camera.zoom
    target = play.world.layout.cup
    sx, sy = play.camera.project(target)[:2]
    send(window, "on_mouse_scroll", int(sx), int(sy), 0, 3)
    assert play.camera.zoom == pytest.approx(fitted * 1.15 ** 3)
    after = play.to_world(int(sx), int(sy))
    assert math.dist(after, target) < 2 / play.camera.zoom  # within a pixel or two
    before = play.to_world(640, 360)
    send(window, "on_mouse_press", 640, 360, arcade.MOUSE_BUTTON_RIGHT, 0)
    send(window, "on_mouse_drag", 700, 360, 60, 0, arcade.MOUSE_BUTTON_RIGHT, 0)
    moved = play.to_world(640, 360)
    assert moved[0] == pytest.approx(before[0] - 60 / play.camera.zoom)
    key(window, arcade.key.KEY_0)
    assert play.camera.zoom == pytest.approx(fitted)


def test_the_ball_slides_into_the_cup_from_where_it_dropped(window, game, shots_dir):
    play = show(window, PlayView(game, game.start_round(), ScreenFlow(window, game)))
    world = play.world
    cx, cy = world.layout.cup
    world.place_ball(cx - 1.2, cy)
    play.ball_poses[0] = type(play.ball_poses[0])(play.ball_pose(0))
    world.shoot((cx - 1.2, cy), (0.45, 0.0))
    for _ in range(80):
        play.on_update(1 / 20)  # three physics frames an update: the drop is still seen from where it began
        if world.state.holed:
            break
    assert world.state.holed and play.drop_from is not None
    assert math.dist(play.drop_from[:2], (cx, cy)) > 0.05  # it was drawn from where it was, not the centre
    assert_not_blank(snapshot(window, shots_dir, "play-holed-banner"), "holed")


def test_a_fast_ball_over_the_cup_wobbles_and_rolls_on(window, game):
    play = show(window, PlayView(game, game.start_round(), ScreenFlow(window, game)))
    world = play.world
    cx, cy = world.layout.cup
    world.place_ball(cx - 2.0, cy)
    world.shoot((cx - 2.0, cy), (2.4, 0.0))  # 12 m/s: far too fast to drop
    wobbled, furthest = False, world.ball.x
    for _ in range(40):
        frame(window, draw=True)
        wobbled |= play.over_cup_time > 0
        furthest = max(furthest, world.ball.x)
    assert wobbled and not world.state.holed and furthest > cx + 0.8  # over the cup and past it


def test_f11_switches_fullscreen_and_back(window, game):
    show(window, PlayView(game, game.start_round(), ScreenFlow(window, game)))
    before = window.fullscreen
    key(window, arcade.key.F11)
    assert window.fullscreen is not before
    key(window, arcade.key.F11)
    assert window.fullscreen is before
    window.set_size(1280, 720)
    send(window, "on_resize", 1280, 720)


def test_random_nine_is_built_with_its_progress_shown_then_played_with_its_seed_on_screen(window, game, shots_dir,
                                                                                        monkeypatch):
    """Menu with Random nine chosen (its seed on the Course button, New seed under it), the build
    screen ("Building hole 3 of 9…"), then the hole with the seed in the HUD, and the scorecard."""
    import threading
    from types import SimpleNamespace

    from polygolf.engine.golf import nine
    from polygolf.game.views.build import BuildView

    gate = threading.Semaphore(0)

    def held_proof():
        def prove(hole):  # the golfer's stand-in: sinks every hole, once the test lets it
            assert gate.acquire(timeout=30)
            return SimpleNamespace(sunk=True, estimated_par=3, best_strokes=2, seconds=0.0)
        return prove

    monkeypatch.setattr("polygolf.game.building.build_nine", functools.partial(nine.build_nine, prove=held_proof()))
    game.guide_seen = True
    flow = ScreenFlow(window, game)
    flow.menu()
    while not game.random_chosen:
        click(window, "course")
    game.random_seed, game.random_nine = 4711, None
    window.current_view.build()
    menu = window.current_view
    assert menu.buttons["course"].text == "Course: Random nine #4711" and "seed" in menu.buttons
    assert_not_blank(snapshot(window, shots_dir, "menu-random-nine"), "menu")
    click(window, "play")
    view = window.current_view
    assert isinstance(view, BuildView)
    from polygolf.game.views.build import DRAW_RATE

    assert window._draw_rate == DRAW_RATE  # drawn slowly, so the workers have the cores
    gate.release()
    gate.release()  # holes 1 and 2 are proven; hole 3 waits
    for _ in range(500):
        frame(window)
        if view.status.text == "Building hole 3 of 9…":
            break
        time.sleep(0.01)
    assert view.status.text == "Building hole 3 of 9…"
    assert_not_blank(snapshot(window, shots_dir, "build-random-nine"), "build")
    for _ in range(60):
        gate.release()
    assert view.build.wait(30)
    frame(window)
    play = window.current_view
    assert isinstance(play, PlayView) and play.hud_texts["course"].text == "Random nine · seed 4711"
    assert window._draw_rate == pytest.approx(1 / 60)  # and back at full rate to play
    assert play.hud_texts["hole"].text.startswith("Hole 1 of 9: Random 4711-1")
    assert_not_blank(snapshot(window, shots_dir, "play-random-nine"), "play")
    round_ = play.round
    while not round_.over:
        round_.finish_hole([(3, False, 0)])
    show(window, ResultsView(game, round_, flow))
    assert window.current_view.title.text == "Random nine · seed 4711: scorecard"
    assert_not_blank(snapshot(window, shots_dir, "results-random-nine"), "results")
    # New seed: another course, built when it is played; Esc on its build screen goes back to the menu.
    flow.menu()
    click(window, "seed")
    assert game.random_seed != 4711 and game.random_nine is None
    assert window.current_view.buttons["course"].text == f"Course: Random nine #{game.random_seed}"
    click(window, "play")
    build = window.current_view
    assert isinstance(build, BuildView)
    key(window, arcade.key.ESCAPE)
    for _ in range(60):
        gate.release()
    assert build.build.wait(30)
    frame(window)
    assert isinstance(window.current_view, MenuView)
