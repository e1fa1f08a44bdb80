"""Random nine being built: the seed, "Building hole 3 of 9…" with a bar, and Esc to go back. The build
runs in `game.building.NineBuild`'s thread; this screen only draws its progress, then starts the round
(or says what went wrong)."""

from __future__ import annotations

import arcade
from arcade.gui import UIAnchorLayout, UIView

from polygolf.engine.golf.nine import course_name
from polygolf.game.building import NineBuild
from polygolf.game.session import Game
from polygolf.game.views.navigation import Navigator, window_key
from polygolf.game.views.widgets import themed_button, title

BAR = (560, 22)  # pixels
DRAW_RATE = 1 / 10  # s between frames while building: software OpenGL drawing 60 a second would take a
# good part of a core from the workers proving the holes, and a progress line needs no more


class BuildView(UIView):
    def __init__(self, game: Game, build: NineBuild, flow: Navigator) -> None:
        super().__init__()
        self.game = game
        self.build = build
        self.flow = flow
        theme = game.theme
        self.background_color = theme.rgba("background")
        self.title = title(course_name(build.seed), theme, 36)
        self.explain = arcade.Text("Nine holes drawn from the seed, each played by the golfer to be sure it can be "
                                   "sunk and to set its par. Built once, kept for next time.", 0, 0,
                                   theme.rgba("text"), 14, anchor_x="center", anchor_y="center", multiline=True,
                                   width=760, align="center", italic=True)
        self.status = arcade.Text(build.status, 0, 0, theme.rgba("text"), 20, anchor_x="center", anchor_y="center",
                                  bold=True, multiline=True, width=1100, align="center")
        self.hint = arcade.Text("Esc: back to the menu (the holes built are kept)", 0, 0, theme.rgba("text"), 13,
                                anchor_x="center", anchor_y="center")
        self.back = themed_button(theme, "Main menu", width=220, clicks=game.sound)
        self.back.on_click = self.on_back  # type: ignore[method-assign]
        self.back.visible = False
        anchor = UIAnchorLayout()
        anchor.add(self.back, anchor_x="center_x", anchor_y="bottom", align_y=60)
        self.ui.add(anchor)
        self.buttons = {"menu": self.back}

    def on_show_view(self) -> None:
        self.saved_draw_rate = getattr(self.window, "_draw_rate", 1 / 60)
        self.window.set_draw_rate(DRAW_RATE)
        super().on_show_view()

    def on_hide_view(self) -> None:
        self.window.set_draw_rate(self.saved_draw_rate)
        super().on_hide_view()

    def on_update(self, delta_time: float) -> None:
        build = self.build
        self.status.text = build.status
        if not build.finished:
            return
        if build.course is not None and not build.cancelled:
            self.game.random_nine = build.course
            self.flow.new_round()
        elif build.error is not None:
            self.back.visible = True  # stay and say why
        else:
            self.flow.menu()  # cancelled, and the thread has stopped

    def on_back(self, _event=None) -> None:
        if self.build.finished:
            self.flow.menu()
        else:
            self.build.cancel()  # the menu follows once the thread has stopped (on_update)

    def on_key_press(self, symbol: int, modifiers: int) -> None:
        if window_key(self.window, self.game, symbol):
            return
        if symbol == arcade.key.ESCAPE or (self.build.error and symbol in (arcade.key.ENTER, arcade.key.RETURN)):
            self.on_back()

    def on_draw_before_ui(self) -> None:
        theme = self.game.theme
        w, h = self.window.width, self.window.height
        self.title.position = (w / 2, h - 110)
        self.title.draw()
        self.explain.position = (w / 2, h - 170)
        self.explain.draw()
        self.status.position = (w / 2, h / 2 + 10)
        self.status.draw()
        if self.build.error is None:
            bw, bh = BAR
            left, bottom = (w - bw) / 2, h / 2 - 50
            done = max(0, self.build.hole - 1) / self.build.total if self.build.course is None else 1.0
            arcade.draw_lrbt_rectangle_filled(left, left + bw, bottom, bottom + bh, theme.rgba("panel"))
            arcade.draw_lrbt_rectangle_filled(left, left + bw * done, bottom, bottom + bh, theme.rgba("button"))
            arcade.draw_lrbt_rectangle_outline(left, left + bw, bottom, bottom + bh, theme.rgba("text"), 2)
            self.hint.position = (w / 2, bottom - 40)
            self.hint.draw()
