"""How to play, and how spin works. Offered before the first round and from the menu.

The text is fitted between the title and the buttons whenever the window's size changes: as large
as fits (14 to 11 points), else a page at a time (Previous / Next, or the arrow keys)."""

from __future__ import annotations

from collections.abc import Callable

import arcade
from arcade.gui import UIAnchorLayout, UIBoxLayout, UIView

from polygolf.game.session import Game
from polygolf.game.views.navigation import window_key
from polygolf.game.views.widgets import themed_button, title

GUIDE = """\
Your ball is a polygon. Get it into the cup in as few strokes as you can.

Shooting: when the ball has stopped, press on it, drag an arrow and let go. The arrow points where the \
ball goes; the longer it is, the harder the shot (it grows wider and darker toward full power). Dots \
show where it will go up to its first bounce (P hides them). Esc cancels a shot. Stuck? H shows a hint.

Spin: where you grab the ball sets its spin. Grab it at the centre for a straight shot. Grab it off \
centre and it turns as it goes (the arc round the ball shows which way), and a spinning polygon kicks \
sideways when it meets a wall. Spin is capped, so a soft shot never carries a wild spin.

The cup: the ball drops only if it is slow enough over the cup; fastest over the middle, not at all \
on the rim. Too fast and it lips out.

Scoring: each hole has a par. After 10 strokes the ball is picked up. R puts your ball back on the tee \
for a penalty stroke (the strokes taken stay). L shows your last shot again; Esc pauses.

Friends: up to four play on one machine, in turn (one stroke each, in seat order); every ball is on \
the green and they knock each other about. Fewest strokes wins. A player named CPU is the computer.

View: the mouse wheel zooms, a right-drag or the arrow keys pan, 0 fits the hole. F11 fullscreen, M mute."""

BODY_SIZES = (14, 12)  # points: the whole guide on one page at the largest of these that fits
PAGE_SIZE = 12  # points: the text's size when it is shown a page at a time
TALL = 600  # px: a window this high has the large title and buttons
GAP = 14  # px between the text and the title, and the text and the buttons


def paginate(paragraphs: list[str], fits: Callable[[str], bool]) -> list[str]:
    """The paragraphs gathered into as few pages as `fits` allows, in order (a paragraph too long
    for a page has a page of its own)."""
    pages: list[str] = []
    for paragraph in paragraphs:
        joined = f"{pages[-1]}\n\n{paragraph}" if pages else paragraph
        if pages and fits(joined):
            pages[-1] = joined
        else:
            pages.append(paragraph)
    return pages


class GuideView(UIView):
    def __init__(self, game: Game, then: Callable[[], None], back: Callable[[], None] | None = None) -> None:
        """`then`: what "Got it" (or Enter) goes on to; `back`: where Esc goes (by default `then`:
        from the menu both go back to it; before a first round, Esc should not tee off)."""
        super().__init__()
        self.game = game
        self.then = then
        self.back = back or then
        theme = game.theme
        self.background_color = theme.rgba("background")
        self.title = title("How to play", theme, 36)
        self.body = arcade.Text(GUIDE, 0, 0, theme.rgba("text"), BODY_SIZES[0], multiline=True, width=1040,
                                anchor_x="center", anchor_y="top")
        self.page_line = arcade.Text("", 0, 0, theme.rgba("text"), 11, anchor_x="center", anchor_y="center",
                                     italic=True)
        self.pages = [GUIDE]
        self.page = 0
        self.buttons: dict = {}
        self.anchor = UIAnchorLayout()
        self.ui.add(self.anchor)
        self.fit(self.window.width, self.window.height)

    def fit(self, w: int, h: int) -> None:
        """The title, the buttons and the text between them for a `w` x `h` window: the whole guide
        at the largest size that fits, else pages of it at PAGE_SIZE."""
        tall = h >= TALL
        self.title.font_size = 36 if tall else 26
        self.title.position = (w / 2, h - (60 if tall else 30))
        button_height, button_y = (48, 40) if tall else (40, 12)
        self.body.width = min(1040, w - 60)
        self.body.position = (w / 2, self.title.bottom - GAP)
        room = self.body.y - (button_y + button_height + GAP)
        whole = next((size for size in range(BODY_SIZES[0], BODY_SIZES[1] - 1, -1)
                      if self._height(GUIDE, size) <= room), None)
        if whole is not None:
            self.body.font_size, self.pages = whole, [GUIDE]
        else:
            self.page_line.position = (w / 2, button_y + button_height + GAP)
            room -= 2 * GAP  # the page's number under the text
            self.body.font_size = PAGE_SIZE
            self.pages = paginate(GUIDE.split("\n\n"), lambda text: self._height(text, PAGE_SIZE) <= room)
        self.page = min(self.page, len(self.pages) - 1)
        self._make_buttons(button_height, button_y)
        self.show_page(self.page)

    def _height(self, text: str, size: float) -> float:
        """How high the body is with `text` at `size` points (at its width)."""
        self.body.text, self.body.font_size = text, size
        return self.body.content_height

    def _make_buttons(self, height: int, y: int) -> None:
        """Got it (and Previous / Next when there are pages), in a row at the bottom."""
        theme = self.game.theme
        row = UIBoxLayout(vertical=False, space_between=16)
        self.buttons = {}
        paged = len(self.pages) > 1
        for key, text, width, action in (("previous", "Previous", 130, self.on_previous),
                                         ("go", "Got it" if self.game.guide_seen else "Got it: tee off", 260,
                                          self.on_continue),
                                         ("next", "Next", 130, self.on_next)):
            if key != "go" and not paged:
                continue
            button = themed_button(theme, text, width=width, height=height, clicks=self.game.sound)
            button.on_click = action  # type: ignore[method-assign]
            row.add(button)
            self.buttons[key] = button
        self.anchor.clear()
        self.anchor.add(row, anchor_x="center_x", anchor_y="bottom", align_y=y)

    def show_page(self, page: int) -> None:
        self.page = max(0, min(len(self.pages) - 1, page))
        self.body.text = self.pages[self.page]
        self.page_line.text = (f"Page {self.page + 1} of {len(self.pages)}   (← → turn the page)"
                               if len(self.pages) > 1 else "")
        for key, disabled in (("previous", self.page == 0), ("next", self.page == len(self.pages) - 1)):
            if key in self.buttons:
                self.buttons[key].disabled = disabled

    def on_resize(self, width: int, height: int) -> None:
        self.fit(width, height)

    def on_previous(self, _event=None) -> None:
        self.show_page(self.page - 1)

    def on_next(self, _event=None) -> None:
        self.show_page(self.page + 1)

    def on_continue(self, _event=None) -> None:
        self.game.mark_guide_seen()
        self.then()

    def on_key_press(self, symbol: int, modifiers: int) -> None:
        if window_key(self.window, self.game, symbol):
            return
        last = self.page == len(self.pages) - 1
        if symbol in (arcade.key.ENTER, arcade.key.RETURN) or (symbol == arcade.key.SPACE and last):
            self.on_continue()
        elif symbol in (arcade.key.RIGHT, arcade.key.PAGEDOWN, arcade.key.SPACE):
            self.on_next()
        elif symbol in (arcade.key.LEFT, arcade.key.PAGEUP):
            self.on_previous()
        elif symbol == arcade.key.ESCAPE:
            self.back()

    def on_draw_before_ui(self) -> None:
        self.title.draw()
        self.body.draw()
        if self.page_line.text:
            self.page_line.draw()
