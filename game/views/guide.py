"""How to play, and how spin works. Offered before the first round and from the menu."""

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


class GuideView(UIView):
    def __init__(self, game: Game, then: Callable[[], None]) -> None:
        super().__init__()
        self.game = game
        self.then = then
        theme = game.theme
        self.background_color = theme.rgba("background")
        self.title = title("How to play", theme, 36)
        self.body = arcade.Text(GUIDE, 0, 0, theme.rgba("text"), 14, multiline=True, width=1040,
                                anchor_x="center", anchor_y="top")
        row = UIBoxLayout(vertical=False, space_between=16)
        go = themed_button(theme, "Got it" if game.guide_seen else "Got it: tee off", width=260, clicks=self.game.sound)
        go.on_click = self.on_continue  # type: ignore[method-assign]
        row.add(go)
        anchor = UIAnchorLayout()
        anchor.add(row, anchor_x="center_x", anchor_y="bottom", align_y=40)
        self.ui.add(anchor)

    def on_continue(self, _event=None) -> None:
        self.game.mark_guide_seen()
        self.then()

    def on_key_press(self, symbol: int, modifiers: int) -> None:
        if window_key(self.window, self.game, symbol):
            return
        if symbol in (arcade.key.ENTER, arcade.key.RETURN, arcade.key.SPACE, arcade.key.ESCAPE):
            self.on_continue()

    def on_draw_before_ui(self) -> None:
        w, h = self.window.width, self.window.height
        self.title.position = (w / 2, h - 60)
        self.title.draw()
        width = min(1040, w - 60)  # the whole guide above the button at 720 px; narrower windows wrap more
        if self.body.width != width:
            self.body.width = width
        self.body.position = (w / 2, h - 100)
        self.body.draw()
