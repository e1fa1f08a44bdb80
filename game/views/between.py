"""Between holes: the hole just played with its golf name, and the next hole's number and par."""

from __future__ import annotations

import arcade
from arcade.gui import UIAnchorLayout, UIView

from polygolf.game.session import Game, HoleResult, Round, golf_name
from polygolf.game.views.navigation import Navigator, window_key
from polygolf.game.views.widgets import themed_button, title


class BetweenView(UIView):
    def __init__(self, game: Game, round_: Round, result: HoleResult, flow: Navigator) -> None:
        super().__init__()
        self.game = game
        self.flow = flow
        self.round = round_
        theme = game.theme
        self.background_color = theme.rgba("background")
        name = "Picked up" if result.picked_up else golf_name(result.strokes, result.par)
        self.headline = title(name, theme, 44)
        self.detail = arcade.Text(
            f"Hole {result.number} · {result.name}: {result.strokes} strokes, par {result.par}",
            0, 0, theme.rgba("text"), 18, anchor_x="center", anchor_y="center")
        upcoming = round_.current()
        nxt = f"Next: hole {round_.number} of {round_.hole_count} · {upcoming.spec.name} · par {upcoming.spec.par}" \
            if upcoming is not None else "That was the last hole"
        self.next_text = arcade.Text(nxt, 0, 0, theme.rgba("text"), 20, anchor_x="center", anchor_y="center",
                                     bold=True)
        self.total = arcade.Text(
            f"Total so far: {round_.total_strokes} strokes, par {round_.total_par} "
            f"({round_.total_strokes - round_.total_par:+d})", 0, 0, theme.rgba("text"), 15,
            anchor_x="center", anchor_y="center")
        self.skipped = arcade.Text("\n".join(round_.skipped), 0, 0, theme.rgba("arrow_strong"), 12,
                                   anchor_x="center", anchor_y="top", multiline=True, width=1000, align="center")
        button = themed_button(theme, "Next hole" if upcoming else "Scorecard", width=260, clicks=self.game.sound)
        button.on_click = self.on_continue  # type: ignore[method-assign]
        anchor = UIAnchorLayout()
        anchor.add(button, anchor_x="center_x", anchor_y="bottom", align_y=60)
        self.ui.add(anchor)

    def on_continue(self, _event=None) -> None:
        self.flow.next_hole()

    def on_key_press(self, symbol: int, modifiers: int) -> None:
        if window_key(self.window, self.game, symbol):
            return
        if symbol in (arcade.key.ENTER, arcade.key.RETURN, arcade.key.SPACE):
            self.on_continue()

    def on_draw_before_ui(self) -> None:
        w, h = self.window.width, self.window.height
        for text, y in ((self.headline, h - 150), (self.detail, h - 215), (self.next_text, h / 2 - 10),
                        (self.total, h / 2 - 50)):
            text.position = (w / 2, y)
            text.draw()
        if self.round.skipped:
            self.skipped.position = (w / 2, h / 2 - 90)
            self.skipped.draw()
