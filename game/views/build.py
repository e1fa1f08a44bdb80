"""Random nine being built: the seed, "Building hole 3 of 9…" with a bar, and Esc to go back. The build
runs in `game.building.NineBuild`'s thread; this screen only draws its progress, then starts the round
(or says what went wrong)."""

from __future__ import annotations

import arcade
from arcade.gui import UIAnchorLayout, UIView

from polygolf.engine.golf.nine import course_name
from polygolf.game.building import NineBuild
from polygolf.game.drawing import fit_width
from polygolf.game.session import Game
from polygolf.game.views.navigation import Navigator, window_key
from polygolf.game.views.widgets import themed_button, title

BAR = (560, 22)  # pixels
TALL = 600  # px: a window this high has the larger sizes and gaps
MARGIN = 20  # px
DRAW_RATE = 1 / 10  # s between frames while building: software OpenGL drawing 60 a second would take a
# good part of a core from the workers proving the holes, and a progress line needs no more


def breakable(status: str) -> str:
    """`status` with a line allowed to break after each slash: a path in an error has no spaces, and
    would run off the window rather than wrap."""
    return status.replace("/", "/\u200b")


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
                                   theme.rgba("text"), 14, anchor_x="center", anchor_y="top", multiline=True,
                                   width=760, align="center", italic=True)
        self.status = arcade.Text(breakable(build.status), 0, 0, theme.rgba("text"), 20, anchor_x="center",
                                  anchor_y="top", bold=True, multiline=True, width=1100, align="center")
        self.hint = arcade.Text("Esc: back to the menu (the holes built are kept)", 0, 0, theme.rgba("text"), 13,
                                anchor_x="center", anchor_y="top", multiline=True, width=760, align="center")
        self.back = themed_button(theme, "Main menu", width=220, clicks=game.sound)
        self.back.on_click = self.on_back  # type: ignore[method-assign]
        self.back.visible = False
        self.anchor = UIAnchorLayout()
        self.anchor.add(self.back, anchor_x="center_x", anchor_y="bottom", align_y=60)
        self.ui.add(self.anchor)
        self.buttons = {"menu": self.back}
        self.bar = (0.0, 0.0, 0.0)  # the progress bar's left, bottom and width (px)
        self._laid_out_for: tuple[int, int, str, bool] = (0, 0, "", False)  # window, status, failed

    def on_show_view(self) -> None:
        self.saved_draw_rate = getattr(self.window, "_draw_rate", 1 / 60)
        self.window.set_draw_rate(DRAW_RATE)
        super().on_show_view()

    def on_hide_view(self) -> None:
        self.window.set_draw_rate(self.saved_draw_rate)
        super().on_hide_view()

    def on_update(self, delta_time: float) -> None:
        build = self.build
        self.status.text = breakable(build.status)
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

    def lay_out(self, w: int, h: int) -> None:
        """Sizes and places for a `w` x `h` window (as the loading screen: widths from the window):
        the title fitted to the width, then the explanation, the status, the bar and the hint, each
        under the one before by its height, the whole in the middle of the room above the button
        (shown when the build failed)."""
        tall = h >= TALL
        gap = 28 if tall else 12
        fit_width(self.title, course_name(self.build.seed), w - 2 * MARGIN, 36 if tall else 26, 14)
        for text, widest, size in ((self.explain, 760, 14 if tall else 12), (self.status, 1100, 20 if tall else 16),
                                   (self.hint, 760, 13 if tall else 12)):
            text.width, text.font_size = min(widest, w - 2 * MARGIN), size
        failed = self.build.error is not None
        button_height = 48 if tall else 40
        self.back.rect = self.back.rect.resize(height=button_height)
        self.anchor.remove(self.back)
        self.anchor.add(self.back, anchor_x="center_x", anchor_y="bottom", align_y=60 if tall else MARGIN)
        floor = (60 if tall else MARGIN) + button_height + gap if failed else MARGIN
        bar_height = BAR[1]
        heights = [self.title.content_height, self.explain.content_height, self.status.content_height]
        if not failed:
            heights += [bar_height, self.hint.content_height]
        block = sum(heights) + gap * (len(heights) - 1)
        y = min(h - MARGIN, max(floor + block, (h + floor + block) / 2))  # the block's top
        self.title.position = (w / 2, y - heights[0] / 2)
        y -= heights[0] + gap
        self.explain.position = (w / 2, y)
        y -= heights[1] + gap
        self.status.position = (w / 2, y)
        y -= heights[2] + gap
        bar_width = max(0.0, min(BAR[0], w - 60))  # (never negative in a window under the smallest size)
        self.bar = ((w - bar_width) / 2, y - bar_height, bar_width)
        self.hint.position = (w / 2, y - bar_height - gap)

    def on_draw_before_ui(self) -> None:
        theme = self.game.theme
        w, h = self.window.width, self.window.height
        if self._laid_out_for != (w, h, self.status.text, self.build.error is not None):
            self.lay_out(w, h)
            self._laid_out_for = (w, h, self.status.text, self.build.error is not None)
        self.title.draw()
        self.explain.draw()
        self.status.draw()
        if self.build.error is None:
            left, bottom, width = self.bar
            top = bottom + BAR[1]
            done = max(0, self.build.hole - 1) / self.build.total if self.build.course is None else 1.0
            arcade.draw_lrbt_rectangle_filled(left, left + width, bottom, top, theme.rgba("panel"))
            arcade.draw_lrbt_rectangle_filled(left, left + width * done, bottom, top, theme.rgba("button"))
            arcade.draw_lrbt_rectangle_outline(left, left + width, bottom, top, theme.rgba("text"), 2)
            self.hint.draw()
