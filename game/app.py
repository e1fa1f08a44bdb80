"""The arcade window and the ways into it: the menu, a hole straight away, or a picture of a hole."""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from polygolf.game.session import Game

WINDOW_SIZE = (1280, 720)
MIN_SIZE = (640, 400)  # every screen is laid out for this and up; the window asks the OS not to go smaller
TITLE = "PolyGolf"


class NoDisplay(RuntimeError):
    """No screen to open a window on; str() says what to do instead."""


def _headless() -> bool:
    """Whether arcade is offscreen only: it reads ARCADE_HEADLESS once, when it is imported (`render`
    sets it for itself, and it stays set in that process)."""
    arcade = sys.modules.get("arcade")
    return bool(getattr(arcade, "headless", None) if arcade is not None else os.environ.get("ARCADE_HEADLESS"))


def _check_display() -> None:
    """Before arcade's GUI is imported: it needs a real display, and offscreen (ARCADE_HEADLESS, for
    `render`) it cannot even be imported; either would be a traceback, not this line."""
    if _headless():
        raise NoDisplay("no display for a game window under ARCADE_HEADLESS (it is for drawing offscreen); "
                        "unset it, or draw a hole to a file with `polygolf render`")
    if os.name == "posix" and not os.environ.get("DISPLAY") and not os.environ.get("WAYLAND_DISPLAY"):
        raise NoDisplay("no display to open a window on (DISPLAY is not set); run it under a desktop or "
                        "xvfb-run, or draw a hole to a file with `polygolf render`")


def make_window(visible: bool = True):
    """The game window (resizable). Raises NoDisplay when there is no screen."""
    _check_display()
    import arcade

    try:
        window = arcade.Window(*WINDOW_SIZE, TITLE, resizable=True, visible=visible, antialiasing=True)
    except Exception as exc:  # pyglet raises several kinds when it cannot reach a display
        raise NoDisplay(f"cannot open a window: {exc}") from None
    # (A hint to the window manager: without one a window can still be made smaller, and every screen
    # then still draws, squeezed, never raising.)
    window.set_minimum_size(*MIN_SIZE)
    return window


class StillFrame:
    """The navigator of a rendered picture: one frame is drawn and no screen follows it. (The real
    flow, `game.flow`, imports arcade.gui, which a headless EGL context cannot load.)"""

    def __getattr__(self, move: str):
        def refuse(*_args: object) -> None:
            raise RuntimeError(f"a rendered frame has no next screen (asked for {move!r})")

        return refuse


def run_menu() -> None:
    _check_display()
    from polygolf.game.flow import ScreenFlow
    from polygolf.game.session import Game

    game = Game.load()
    flow = ScreenFlow(make_window(), game)
    flow.loading(then=flow.menu)
    arcade_run(game)


def _game_for(course: str | None, hole: int, theme: str | None, shape, only=None, players: list[str] | None = None,
              seed: int | None = None):
    """The game set up from command-line choices; refuses an unknown course, theme, shape or hole.
    `only`: play this course alone (a hole file). `players`: their names (default: as saved).
    `random-nine` is built first if it is not in the data folder yet (`seed`: default as saved)."""
    from polygolf.engine.golf.holes import find_course
    from polygolf.game.session import RANDOM_NINE, Game
    from polygolf.game.shapes import parse_shape
    from polygolf.game.theme import find_theme

    game = Game.load()
    if players:
        game.players = list(players)
    if only is not None:
        game.courses, game.course_index = [only], 0
    elif course == RANDOM_NINE:
        game.choose_random_nine(seed)
        if game.random_nine is None:
            game.random_nine = build_nine_here(game.random_seed)
    elif not game.courses:
        raise ValueError(game.problems[0] if game.problems else "no course could be read")
    else:
        game.course_index = game.courses.index(find_course(game.courses, course, game.course_problems))
    if theme is not None:  # ('' too: no theme has no name, and it is refused as `--theme nope` is)
        unread = [problem for problem in game.problems if problem not in game.course_problems]  # (the themes')
        game.theme_index = game.themes.index(find_theme(game.themes, theme, unread))
    if shape is not None:
        game.shape_label, game.shape = parse_shape(shape) if isinstance(shape, str) else shape
    if not 1 <= hole <= len(game.course.holes):
        raise ValueError(f"{game.course.name} has holes 1 to {len(game.course.holes)}")
    return game


def build_nine_here(seed: int):
    """Random nine of `seed` built in this process, a console line a hole (the window is not open yet)."""
    import sys
    import time

    from polygolf.engine.golf.nine import NINE, build_nine, nine_folder
    from polygolf.game.startup import prepare_physics
    from polygolf.game.store import not_a_folder

    prepare_physics()  # here, not in each worker process: they load what it compiled
    started = time.perf_counter()
    built = False

    def progress(k: int, total: int) -> None:
        nonlocal built
        built = True
        print(f"polygolf: Random nine, seed {seed}: building hole {k} of {total}...", file=sys.stderr, flush=True)

    waited = False

    def waiting() -> None:
        nonlocal waited
        waited = True
        print(f"polygolf: Random nine, seed {seed}: another game is building it; waiting for it...", file=sys.stderr,
              flush=True)

    try:
        course = build_nine(seed, progress=progress, waiting=waiting)
    except OSError as exc:
        folder = nine_folder(seed)
        why = not_a_folder(folder) or exc.strerror or exc
        raise ValueError(f"cannot write Random nine to {folder}: {why}") from exc
    seconds = time.perf_counter() - started
    ready = (f"{NINE} holes built and proven in {seconds:.0f} s" if built else
             f"{NINE} holes ready, built by another game (waited {seconds:.0f} s)" if waited else
             f"{NINE} holes ready, built before")  # (QA: a folder found built was said built by another game)
    print(f"polygolf: Random nine, seed {seed}: {ready}", file=sys.stderr)
    return course


def run_play(course: str, hole: int, theme: str | None, shape: str | None, preset: str,
             players: list[str] | None = None, seed: int | None = None) -> None:
    from polygolf.game.session import RANDOM_NINE

    if course == RANDOM_NINE:
        _check_display()  # before random-nine's minutes of building
    game = _game_for(course, hole, theme, shape, players=players, seed=seed)  # (a bad choice is said first)
    problem = game.unplayable(hole - 1)
    if problem is not None:  # (every hole broken: no round to open a window for)
        raise ValueError(problem)
    _check_display()  # before arcade.gui is imported
    from polygolf.game.flow import ScreenFlow

    game.preset = preset
    game.guide_seen = True
    flow = ScreenFlow(make_window(), game)
    flow.loading(then=lambda: flow.new_round(hole - 1))
    arcade_run(game)


def run_hole_file(path: Path, theme: str | None, shape, preset: str, watch: bool) -> None:
    """Play one hole file straight away; with `watch`, it is built again each time it is saved. The
    file is read first: a broken one is the error to report, display or not."""
    from polygolf.engine.golf.holes import Course, load_hole_file

    hole = load_hole_file(path)
    game = _game_for(None, 1, theme, shape, Course(id=path.stem, name=path.name, holes=[hole]))  # (a bad theme too)
    _check_display()
    from polygolf.game.flow import ScreenFlow

    game.preset = preset
    game.guide_seen = True
    game.record_rounds = False  # a hole being written: practice, nothing saved
    flow = ScreenFlow(make_window(), game)
    flow.loading(then=flow.new_round)
    if watch:
        import arcade

        from polygolf.game.watch import FileWatcher, HoleReloader

        watcher = FileWatcher(path, path.parent / "tiles.yaml")
        arcade.schedule(HoleReloader(flow, path, watcher), 0.25)
        try:
            arcade_run(game)
        finally:
            watcher.close()
        return
    arcade_run(game)


def run_replay(path: Path) -> None:
    """Show a recorded round in a window, hole by hole, then its scorecard."""
    _check_display()
    from polygolf.game.flow import ScreenFlow
    from polygolf.game.replay import load_for_replay, replay_session
    from polygolf.game.session import Game

    record, course = load_for_replay(path)
    game = Game.load()
    game.shape_label, game.shape = record.shape_label, record.shape  # for this replay only, not saved
    game.show_course(course)  # (the menu after it still offers every course)
    session = replay_session(record, course)
    game.round, game.session = session.round, session
    flow = ScreenFlow(make_window(), game)
    flow.loading(then=lambda: flow.watch_round(record, session))
    arcade_run(game)


def arcade_run(game: Game | None = None) -> None:
    """Run the window until it closes; then the game's round and golfer process go (a search the
    worker is running would otherwise hold up the exit)."""
    import arcade

    try:
        arcade.run()
    finally:
        if game is not None:
            game.close()


def render_hole(course: str, hole: int, theme: str | None, shape: str | None, out: Path,
                size: tuple[int, int] = WINDOW_SIZE, seed: int | None = None, players: list[str] | None = None) -> Path:
    """Draw a hole as the play view shows it, headless, to a PNG (`players`: their names, a ball each
    across the tee; default as saved)."""
    os.environ.setdefault("ARCADE_HEADLESS", "1")
    import arcade

    from polygolf.game.views.play import PlayView

    game = _game_for(course, hole, theme, shape, seed=seed, players=players)
    broken = game.course.holes[hole - 1]
    if isinstance(broken, Exception):
        raise broken
    try:
        window = arcade.Window(*size, TITLE, visible=False)
    except Exception as exc:
        raise NoDisplay(f"cannot open an offscreen GL context: {exc}") from None
    try:
        view = PlayView(game, game.start_round(hole - 1), StillFrame())
        window.show_view(view)
        view.on_draw()
        # Opaque, as on screen: the framebuffer's alpha would let a viewer's backdrop show through the HUD.
        image = arcade.get_image(0, 0, *window.get_framebuffer_size()).convert("RGB")
        out.parent.mkdir(parents=True, exist_ok=True)
        image.save(out)
    finally:
        window.close()
    return out
