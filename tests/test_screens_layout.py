"""Every screen fits the window at the smallest size (640x400) and the common ones, and is laid out
again when the window changes size: no button off the window or on another, no text over the title
or under a button; and the keys the screens share (F11, M, Esc, Tab) do what they say. Checked by
the widgets' and texts' places after a frame is drawn (Xvfb), a screenshot of each kept."""

from __future__ import annotations

import math
import time

import arcade
import pytest

from polygolf.game.drawing import contrast, player_colour
from polygolf.game.flow import ScreenFlow
from polygolf.game.session import Game, Round
from polygolf.game.theme import load_themes
from polygolf.game.views.between import BetweenView
from polygolf.game.views.guide import GUIDE, GuideView
from polygolf.game.views.menu import MenuView
from polygolf.game.views.names import MAX_NAME, NamesView
from polygolf.game.views.pause import PauseView
from polygolf.game.views.play import OVERLAY_WIDTH, PlayView
from polygolf.game.views.replay import ReplayView
from polygolf.game.views.results import ResultsView

from .test_screens import assert_not_blank, click, key, send, shots_dir, snapshot, window  # noqa: F401

SMALL = [(640, 400), (800, 600)]
LONG_NAMES = ["Wilhelmina Wadsworth", "WWWWWWWWWWWWWWWWWWWW", "CPU", "Maximilian Mortimore"]


def resize(win, width: int, height: int) -> None:
    """The window at this size, and every screen told so (as the OS's resize would)."""
    win.set_size(width, height)
    for _ in range(50):
        win.dispatch_events()
        if win.get_size() == (width, height):
            break
        time.sleep(0.01)
    send(win, "on_resize", width, height)


@pytest.fixture
def sized(window):  # noqa: F811
    """The window, put back to 1280x720 after the test."""
    yield window
    resize(window, 1280, 720)


def overlaps(a, b) -> bool:
    return a.left < b.right and b.left < a.right and a.bottom < b.top and b.bottom < a.top


def assert_buttons_fit(view, size, below: float) -> None:
    """Every button of `view` inside the window, under `below` (a title's bottom), on no other."""
    w, h = size
    rects = {name: button.rect for name, button in view.buttons.items()}
    for name, rect in rects.items():
        assert 0 <= rect.left and rect.right <= w and 0 <= rect.bottom and rect.top <= min(h, below), (name, rect)
    names = list(rects)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            assert not overlaps(rects[a], rects[b]), (a, b)


def menu_game() -> Game:
    """Everything the menu can show at once: Random nine (eleven rows), four long names, problems."""
    game = Game.load()
    game.players = list(LONG_NAMES)
    while not game.random_chosen:
        game.next_course()
    game.problems = [f"content/themes/broken{k}.yaml:3: green: not a colour: 'greenish' (expected #RRGGBB)"
                     for k in range(6)]
    return game


@pytest.mark.parametrize("size", SMALL)
def test_the_menu_fits_small_windows_and_is_laid_out_again_on_resize(sized, size, shots_dir):  # noqa: F811
    game = menu_game()
    ScreenFlow(sized, game).menu()
    menu = sized.current_view
    resize(sized, *size)  # made at 1280x720, then the window shrinks: laid out again
    menu.on_draw()
    assert len(menu.buttons) == 13  # eleven rows, three settings side by side
    assert_buttons_fit(menu, size, menu.title.bottom)
    lowest = min(button.rect.bottom for button in menu.buttons.values())
    column_right = max(button.rect.right for button in menu.buttons.values())
    problems = menu.problems
    assert problems.bottom >= 0 and (problems.top <= lowest or problems.left >= column_right)  # clear of them
    assert_not_blank(snapshot(sized, shots_dir, f"layout-menu-{size[0]}"), "menu")
    names = menu.buttons["names"]
    assert names.text.startswith("Names: Wilhelmina") and names.text.endswith(" +3")
    assert all(button.style["normal"].font_size >= 11 for button in menu.buttons.values())


def test_esc_on_the_menu_asks_before_it_quits(window):  # noqa: F811
    game = Game.load()
    quits = []
    flow = ScreenFlow(window, game)
    flow.quit = lambda: quits.append(True)
    flow.menu()
    menu = window.current_view
    key(window, arcade.key.ESCAPE)
    assert not quits and menu.quit_asked > 0
    menu.on_update(5.0)  # the question lapses
    key(window, arcade.key.ESCAPE)
    assert not quits
    key(window, arcade.key.ESCAPE)
    assert quits == [True]


@pytest.mark.parametrize("size", SMALL)
def test_the_guide_ends_above_its_button_and_turns_pages_where_it_must(sized, size, shots_dir):  # noqa: F811
    game = Game.load()
    went: list[str] = []
    guide = GuideView(game, then=lambda: went.append("then"), back=lambda: went.append("back"))
    sized.show_view(guide)
    resize(sized, *size)
    guide.on_draw()
    button = guide.buttons["go"].rect
    seen = set()
    for page in range(len(guide.pages)):
        guide.show_page(page)
        guide.on_draw()
        assert guide.body.bottom >= button.top and guide.body.top <= guide.title.bottom, page
        assert guide.body.font_size >= 12
        seen |= set(guide.body.text.split("\n\n"))
    assert "\n\n".join(guide.pages) == GUIDE and len(seen) == GUIDE.count("\n\n") + 1  # all of it, in order
    assert_buttons_fit(guide, size, guide.title.bottom)
    assert_not_blank(snapshot(sized, shots_dir, f"layout-guide-{size[0]}"), "guide")
    key(sized, arcade.key.ESCAPE)
    assert went == ["back"]  # Esc goes back; only Enter (or the button) goes on
    key(sized, arcade.key.ENTER)
    assert went == ["back", "then"]


def test_the_guide_from_the_menu_goes_back_to_it_on_esc(window):  # noqa: F811
    game = Game.load()
    flow = ScreenFlow(window, game)
    flow.guide()
    key(window, arcade.key.ESCAPE)
    assert isinstance(window.current_view, MenuView)


def test_pause_lays_out_the_hole_under_it_again_and_its_title_clears_the_players(sized, shots_dir):  # noqa: F811
    game = Game.load()
    game.guide_seen, game.players = True, list(LONG_NAMES)
    ScreenFlow(sized, game).new_round()
    play = sized.current_view
    key(sized, arcade.key.ESCAPE)
    pause = sized.current_view
    assert isinstance(pause, PauseView)
    resize(sized, 640, 400)
    pause.on_draw()
    assert play.hud_texts["strokes"].right <= 640  # the HUD under the menu is the new size's
    x0, y0, x1, y1 = play.world.layout.bounds
    for corner in ((x0, y0), (x1, y1)):
        sx, sy = play.camera.project(corner)[:2]
        assert 0 <= sx <= 640 and 0 <= sy <= 400
    players = play.hud_texts["players"]
    assert pause.title.top <= players.bottom
    assert pause.title.bottom >= max(button.rect.top for button in pause.buttons.values())
    assert_not_blank(snapshot(sized, shots_dir, "layout-pause-640"), "pause")
    key(sized, arcade.key.ENTER)  # Enter resumes
    assert sized.current_view is play
    play.close()


@pytest.mark.parametrize("size", [(640, 400), (1280, 720)])
def test_the_f3_panel_lines_fit_it_and_the_players_line_keeps_right_of_it(sized, size, shots_dir):  # noqa: F811
    game = Game.load()
    game.guide_seen, game.players = True, list(LONG_NAMES)
    ScreenFlow(sized, game).new_round()
    play = sized.current_view
    resize(sized, *size)
    key(sized, arcade.key.F3)
    play.on_update(1 / 60)
    play.on_draw()
    shown = [text for text in play.overlay_texts if text.text]
    assert shown and all(text.right <= OVERLAY_WIDTH for text in shown), [t.text for t in shown if t.right > 330]
    assert min(text.bottom for text in shown) >= 0
    assert play.hud_texts["players"].left >= OVERLAY_WIDTH
    assert_not_blank(snapshot(sized, shots_dir, f"layout-f3-{size[0]}"), "f3")
    play.close()


@pytest.mark.parametrize("size", [(640, 400), (1280, 720)])
def test_the_replay_hud_fits_beside_its_hint_and_the_shared_keys_work(sized, size, shots_dir):  # noqa: F811
    game = Game.load()
    game.guide_seen, game.players = True, list(LONG_NAMES)
    flow = ScreenFlow(sized, game)
    flow.new_round()
    play = sized.current_view
    ball = play.world.ball
    play.session.shoot((ball.x, ball.y), (2.0, 0.2))
    for _ in range(60 * 15):
        play.on_update(1 / 60)
        if play.session.can_shoot:
            break
    key(sized, arcade.key.L)
    replay = sized.current_view
    assert isinstance(replay, ReplayView)
    resize(sized, *size)
    flags = []
    draw_flag = replay.hole_art.draw_flag
    replay.hole_art.draw_flag = lambda: (flags.append(True), draw_flag())
    replay.on_draw()
    assert flags, "the flag is drawn"
    assert 0 <= replay.hud.left and replay.hud.right < replay.hint.left
    assert 0 <= replay.scores.left and replay.scores.right <= size[0]
    assert replay.scores.text.startswith("Wilhelmina Wadsworth: 0 strokes · WWWW")
    assert_not_blank(snapshot(sized, shots_dir, f"layout-replay-{size[0]}"), "replay")
    muted = game.sound.muted
    key(sized, arcade.key.M)
    assert game.sound.muted is not muted and sized.current_view is replay
    key(sized, arcade.key.M)
    key(sized, arcade.key.ESCAPE)
    assert sized.current_view is play
    play.close()


def test_names_fit_a_small_window_shift_tab_goes_back_and_a_name_stops_at_twenty(sized, shots_dir):  # noqa: F811
    game = Game.load()
    game.players = list(LONG_NAMES)
    ScreenFlow(sized, game).names()
    names = sized.current_view
    assert isinstance(names, NamesView)
    resize(sized, 640, 400)
    names.on_draw()
    assert names.hint.left >= 0 and names.hint.right <= 640 and names.hint.top <= names.title.bottom
    widgets = [*names.rows, names.skill, names.done]
    for widget in widgets:
        rect = widget.rect
        assert 0 <= rect.bottom and rect.top <= names.hint.bottom and 0 <= rect.left and rect.right <= 640
    assert_not_blank(snapshot(sized, shots_dir, "layout-names-640"), "names")
    active = [box.active for box in names.boxes]
    assert active == [True, False, False, False]
    send(sized, "on_key_press", arcade.key.TAB, arcade.key.MOD_SHIFT)
    assert [box.active for box in names.boxes] == [False, False, False, True]
    key(sized, arcade.key.TAB)
    assert [box.active for box in names.boxes] == [True, False, False, False]
    key(sized, arcade.key.TAB)
    send(sized, "on_text", "m" * 30)  # M is typed, not muted
    assert len(names.boxes[1].text) == MAX_NAME and not game.sound.muted
    for _ in range(MAX_NAME):
        send(sized, "on_text_motion", arcade.key.MOTION_BACKSPACE)
    send(sized, "on_text", "Mo")
    assert names.boxes[1].text == "Mo"
    fullscreen = sized.fullscreen
    key(sized, arcade.key.F11)
    assert sized.fullscreen is not fullscreen
    key(sized, arcade.key.F11)


@pytest.mark.parametrize("size", SMALL)
def test_the_random_nine_screen_fits_small_windows(sized, size, shots_dir):  # noqa: F811
    from polygolf.game.building import NineBuild
    from polygolf.game.views.build import BuildView

    def failing(seed, progress, cancelled):
        progress(3, 9)
        raise OSError(28, "No space left on device: '/home/someone/.local/share/polygolf/generated/nine-5552/x.yaml'")

    game = Game.load()
    game.random_seed = 123456789
    waiting = NineBuild(game.random_seed)
    waiting.waiting = True  # (never started: as the thread sets it while another game builds the seed)
    for build in (NineBuild(game.random_seed), waiting, NineBuild(game.random_seed, build=failing).start()):
        view = BuildView(game, build, ScreenFlow(sized, game))
        sized.show_view(view)
        if build.error is None and build is not waiting:
            build.hole, build.total = 3, 9  # (never started: its progress as the thread would set it)
        elif build.error is not None:
            assert build.wait(5)
        view.on_update(0.1)
        resize(sized, *size)
        view.on_draw()
        texts = [view.title, view.explain, view.status] + ([view.hint] if build.error is None else [])
        for upper, lower in zip(texts, texts[1:]):
            assert lower.top <= upper.bottom, (upper.text, lower.text)
        for text in texts:
            assert 0 <= text.left and text.right <= size[0] and 0 <= text.bottom and text.top <= size[1], text.text
        left, _, width = view.bar
        assert width <= size[0] - 60 and left >= 30
        if build.error is not None:
            assert view.status.bottom >= view.back.rect.top
            assert_not_blank(snapshot(sized, shots_dir, f"layout-build-error-{size[0]}"), "build")
        if build is waiting:
            assert view.status.text == "Another game is building it: waiting for it…"
            assert_not_blank(snapshot(sized, shots_dir, f"layout-build-waiting-{size[0]}"), "build")


@pytest.mark.parametrize("names", [LONG_NAMES, ["Ann", "Bob"]], ids=["long", "short"])
def test_a_players_line_is_never_wrapped_between_holes(sized, names):  # noqa: F811
    game = Game.load()
    round_ = Round(game.courses[0], players=list(names))
    results = round_.finish_hole([(10, True, 3), (5, False, 1), (2, False, 0), (7, False, 2)][:len(names)])
    for size in ((1280, 720), (1920, 1080), (800, 600), (640, 480), (640, 400)):  # (at 9 pt, names cut in the middle)
        between = BetweenView(game, round_, results, ScreenFlow(sized, game))
        sized.show_view(between)
        resize(sized, *size)
        between.on_draw()
        one_line = between.lines.content_height / len(names)
        between.lines.text = between.lines.text.split("\n")[0]
        assert between.lines.content_height == pytest.approx(one_line, abs=2), size  # as high as one of them


def test_scorecard_names_grow_with_the_window(sized):  # noqa: F811
    game = Game.load()
    round_ = Round(game.courses[0], players=["Wilhelmina Wadsworth", "Bob"])
    while not round_.over:
        round_.finish_hole([(4, False, 0), (3, False, 0)])
    sizes = {}
    for size in ((640, 400), (1920, 1080)):
        results = ResultsView(game, round_, ScreenFlow(sized, game))
        sized.show_view(results)
        resize(sized, *size)
        results.on_draw()
        label_w = results._fit(*size)[0]
        name = next(cell for cell in results.cells if cell.col == 0 and cell.text.text.startswith("Wilhelmina"))
        assert name.text.content_width <= label_w - 10
        sizes[size] = name.text.font_size
    assert sizes[(1920, 1080)] == 15 and sizes[(640, 400)] < 15


THEMES, _ = load_themes()


@pytest.mark.parametrize("theme", THEMES, ids=lambda t: t.name)
def test_every_seat_has_a_ball_colour_of_its_own(theme):
    colours = [player_colour(theme, seat) for seat in range(4)]
    assert colours[0] == theme.rgba("ball")
    for i, a in enumerate(colours):
        for b in colours[i + 1:]:
            assert math.dist(a[:3], b[:3]) >= 70, (theme.name, a, b)
    # Seats 2-4 lighter or darker than both greens, not only another hue (QA: Grass's red, 1.04 : 1).
    for colour in colours[1:]:
        assert min(contrast(colour, theme.rgba(green)) for green in ("green", "green_alt")) >= 1.5, (theme.name, colour)


@pytest.mark.parametrize("theme", THEMES, ids=lambda t: t.name)
def test_the_names_screen_s_labels_read_on_its_background(window, theme):  # noqa: F811
    """Each seat's label in its ball's colour only where that reads (QA: Sand's 1.7 : 1), beside a swatch
    of the ball."""
    from arcade.gui import UILabel, UISpace

    game = Game.load()
    game.players = ["Ann", "Bob", "Cy", "Di"]
    game.theme_index = game.themes.index(next(t for t in game.themes if t.name == theme.name))
    ScreenFlow(window, game).names()
    names = window.current_view
    background = theme.rgba("background")
    for seat, row in enumerate(names.rows):
        swatch, label = (w for w in row.children if isinstance(w, UISpace | UILabel))
        assert tuple(swatch._bg_color)[:3] == player_colour(theme, seat)[:3]
        assert contrast(tuple(label._label.color), background) >= 3.0, (theme.name, seat, label._label.color)


@pytest.mark.parametrize("theme", THEMES, ids=lambda t: t.name)
def test_button_labels_read_on_every_theme(theme):
    for field in ("button", "button_hover"):
        assert contrast(theme.rgba("button_text"), theme.rgba(field)) >= 4.5, (theme.name, field)


def test_the_keyboard_reaches_every_button_of_the_menu_and_the_pause_menu(window):  # noqa: F811
    game = Game.load()
    game.guide_seen = True
    flow = ScreenFlow(window, game)
    flow.menu()
    menu = window.current_view
    focused = menu.group.focused_widget
    assert focused is menu.buttons["play"]  # Enter still plays, as it always did
    key(window, arcade.key.DOWN)
    key(window, arcade.key.ENTER)
    assert game.theme.name == "Night" and menu.group.focused_widget is menu.buttons["theme"]  # kept on rebuild
    key(window, arcade.key.UP)
    send(window, "on_key_press", arcade.key.TAB, arcade.key.MOD_SHIFT)
    assert menu.group.focused_widget is menu.buttons["quit"]  # round the end
    key(window, arcade.key.TAB)
    key(window, arcade.key.ENTER)
    play = window.current_view
    assert isinstance(play, PlayView)
    key(window, arcade.key.ESCAPE)
    pause = window.current_view
    assert pause.buttons["resume"].focused
    key(window, arcade.key.DOWN)
    key(window, arcade.key.DOWN)
    key(window, arcade.key.ENTER)
    assert isinstance(window.current_view, MenuView)  # Main menu, pressed from the keyboard


def test_a_text_cut_to_fit_is_cut_where_one_character_less_at_a_time_would_and_in_few_layouts(window):  # noqa: F811
    """`fit_width` halves its way to the cut: the same cut as taking one character off at a time, and
    a text of 100 000 characters (QA: a hand-edited setting froze the menu for good; 3 000 for 84 s)
    in a few dozen layouts."""
    from polygolf.game.drawing import cut_middle, fit_width

    class Counted(arcade.Text):
        layouts = 0

        @property
        def text(self) -> str:
            return arcade.Text.text.fget(self)

        @text.setter
        def text(self, value: str) -> None:
            Counted.layouts += 1
            arcade.Text.text.fset(self, value)

    for middle in (False, True):
        for full, width in [("Wilhelmina Wadsworth-Montgomery of the Lower Meadow", 120), ("iiiiWWWW" * 9, 90),
                            ("N" * 100_000, 300)]:
            text = Counted("", 0, 0, arcade.color.WHITE, 18)
            Counted.layouts = 0
            fit_width(text, full, width, 18, middle=middle)
            assert text.content_width <= width and Counted.layouts <= 40, (full[:20], middle, Counted.layouts)
            if len(full) < 1000:  # one character at a time, as the cut was found before
                one = arcade.Text("", 0, 0, arcade.color.WHITE, text.font_size)
                keep = len(full)
                one.text = full
                while keep > 1 and one.content_width > width:
                    keep -= 1
                    one.text = cut_middle(full, keep) if middle else full[:keep].rstrip() + "…"
                assert text.text == one.text


def test_make_window_asks_for_the_smallest_size_the_screens_fit(monkeypatch):
    from polygolf.game import app

    asked = []

    class Window:  # (a second real window would take arcade's current window from the module's one)
        def __init__(self, *args, **kwargs) -> None:
            pass

        def set_minimum_size(self, width: int, height: int) -> None:
            asked.append((width, height))

    monkeypatch.setattr(arcade, "Window", Window)
    assert isinstance(app.make_window(visible=False), Window)
    assert asked == [app.MIN_SIZE] == [(640, 400)]


@pytest.mark.parametrize("size", [(400, 250), (320, 200), (120, 80), (1, 1)])
def test_every_screen_draws_in_a_window_below_the_smallest_size(sized, size):  # noqa: F811
    """With no window manager the minimum size is not enforced (QA: the scorecard raised ValueError
    for a negative cell under 500x300): every screen still draws, nothing laid out negative."""
    from polygolf.game.building import NineBuild
    from polygolf.game.views.build import BuildView
    from polygolf.game.views.loading import LoadingView

    game = Game.load()
    game.guide_seen, game.players = True, list(LONG_NAMES)
    flow = ScreenFlow(sized, game)
    round_ = Round(game.courses[0], players=list(LONG_NAMES))
    results = round_.finish_hole([(10, True, 3), (5, False, 1), (2, False, 0), (7, False, 2)])
    while not round_.over:
        round_.finish_hole([(4, False, 0), (3, False, 0), (5, False, 0), (2, False, 0)])
    flow.menu()
    views = [sized.current_view, GuideView(game, then=lambda: None, back=lambda: None),
             NamesView(game, flow),
             BetweenView(game, round_, results, flow), ResultsView(game, round_, flow),
             BuildView(game, NineBuild(123), flow), LoadingView(game, then=lambda: None, steps=[])]
    for view in views:
        sized.show_view(view)
        resize(sized, *size)
        view.on_draw()
    flow.new_round()
    play = sized.current_view
    resize(sized, *size)
    play.on_draw()
    key(sized, arcade.key.ESCAPE)
    sized.current_view.on_draw()  # the pause menu over the hole
    play.close()


def long_round(game: Game, holes: int) -> Round:
    from polygolf.engine.golf.holes import Course

    base = game.courses[0]
    course = Course(id=f"long{holes}", name=f"Long {holes}", holes=[base.holes[k % len(base.holes)]
                                                                    for k in range(holes)])
    round_ = Round(course, players=list(LONG_NAMES))
    k = 0
    while not round_.over:
        k += 1
        round_.finish_hole([(1 + (k * 3 + seat) % 9, (k + seat) % 17 == 0, 0) for seat in range(4)])
    return round_


@pytest.mark.parametrize("holes", [9, 18, 36, 100, 500])
@pytest.mark.parametrize("size", [(640, 400), (1280, 720)])
def test_a_long_course_s_scorecard_shows_its_holes_a_page_at_a_time_with_every_total_whole(sized, size, holes,
                                                                                           shots_dir):  # noqa: F811
    """QA8: at 36 holes every total read '1…' (and to par '+…') even at 1280x720, at 100 the cells ran
    over each other. Holes that would be narrower than MIN_CELL are shown 9 or 18 a page (◀ ▶, Page
    Up / Down); the totals are the round's, always whole, and every cell's text fits its cell."""
    from polygolf.game.views.results import MIN_CELL

    game = Game.load()
    round_ = long_round(game, holes)
    view = ResultsView(game, round_, ScreenFlow(sized, game))
    sized.show_view(view)
    resize(sized, *size)
    view.on_draw()
    assert view.per_page == holes or view.per_page in (9, 18) or view.per_page < 9
    if holes > 9:
        assert view.buttons["earlier"].disabled and view.buttons["later"].disabled is (view.pages == 1)
    seen = []
    for page in range(view.pages):
        assert view.page == page
        view.on_draw()
        label_w, cell_w, _, _, rows = view._fit(*size)
        assert cell_w >= MIN_CELL - 1e-9 or view.per_page == holes
        last = view.columns - 1
        totals = [cell for cell in view.cells if cell.col == last]
        assert [cell.text.text for cell in totals] == [cell.full for cell in totals]  # whole, never cut
        assert totals[2].text.text == str(round_.total_strokes(0))
        for cell in view.cells:
            if 0 < cell.col < last and cell.row in rows:  # (a low window leaves the running rows out)
                assert cell.text.content_width <= cell_w, (cell.text.text, cell_w)
                assert "…" not in cell.text.text
        seen += [cell.text.text for cell in view.cells if cell.row == 0 and 0 < cell.col < last]
        if page == 0:
            assert_not_blank(snapshot(sized, shots_dir, f"layout-results-{holes}-{size[0]}"), "results")
        key(sized, arcade.key.PAGEDOWN)
    assert seen == [str(k) for k in range(1, holes + 1)]  # every hole once, in order
    assert view.page == view.pages - 1  # (Page Down on the last page stays there)
    if holes > 9:
        key(sized, arcade.key.PAGEUP)
        assert view.page == max(0, view.pages - 2)


@pytest.mark.parametrize("size", [(640, 400), (1280, 720)])
@pytest.mark.parametrize("name", ["\ufdfd" * 100, "W" * 100, ("Narrow Gates " * 7).strip()], ids=["wide", "W", "words"])
def test_a_long_hole_name_is_cut_short_not_the_whole_hud_shrunk(sized, size, name):  # noqa: F811
    """QA8: a valid 100-character hole name shrank the whole top bar (course, strokes and all) to
    about 8 px. The name alone is cut short with an ellipsis; the rest keeps its size, and the
    hole's number and par stay whole."""
    from polygolf.game.views.play import HUD_FONT, HUD_READABLE

    game = Game.load()
    game.guide_seen = True
    ScreenFlow(sized, game).new_round()
    play = sized.current_view
    resize(sized, *size)
    play._hole_name = name
    line = f"Hole 1 of 9: {name}  ·  Par 3"
    play.place_hud({"course": "Meadow", "hole": line, "strokes": "0 strokes", "players": ""})
    texts = play.hud_texts
    assert texts["course"].font_size == texts["strokes"].font_size == HUD_FONT
    assert texts["hole"].font_size >= HUD_READABLE
    hole = texts["hole"].text
    assert hole.startswith("Hole 1 of 9: ") and hole.endswith("  ·  Par 3")  # its number and par whole
    assert hole == line or (hole.endswith("…  ·  Par 3") and len(hole) < len(line))
    assert hole != line or size == (1280, 720) and name[0] == "N"  # (cut, but where it fits as it is)
    assert texts["course"].right + 16 <= texts["hole"].left and texts["hole"].right + 16 <= texts["strokes"].left
    play.on_draw()
    play.close()
