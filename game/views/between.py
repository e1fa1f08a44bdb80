"""Between holes: the hole just played (its golf name alone; every player's line when several play),
the best ever kept for it, and the next hole's number and par."""

from __future__ import annotations

import arcade
from arcade.gui import UIAnchorLayout, UIView

from polygolf.game.session import Game, HoleResult, Round, golf_name, par_text, penalty_text, strokes_text
from polygolf.game.views.navigation import Navigator, window_key
from polygolf.game.views.widgets import themed_button, title


def result_line(result: HoleResult, named: bool) -> str:
    """'2 strokes (+1 penalty stroke)'; `named`: 'Birdie, 2 strokes' (the headline names it alone)."""
    penalty = f" {penalty_text(result.penalties)}" if result.penalties else ""
    name = "Picked up" if result.picked_up else golf_name(result.strokes, result.par)
    return f"{name + ', ' if named else ''}{strokes_text(result.strokes)}{penalty}"


class BetweenView(UIView):
    def __init__(self, game: Game, round_: Round, results: list[HoleResult] | HoleResult, flow: Navigator) -> None:
        super().__init__()
        self.game = game
        self.flow = flow
        self.round = round_
        results = results if isinstance(results, list) else [results]
        first = results[0]
        theme = game.theme
        self.background_color = theme.rgba("background")
        alone = len(results) == 1
        headline = ("Picked up" if first.picked_up else golf_name(first.strokes, first.par)) if alone \
            else f"Hole {first.number} done"
        self.headline = title(headline, theme, 44)
        self.detail = arcade.Text(f"Hole {first.number} · {first.name} · par {first.par}", 0, 0,
                                  theme.rgba("text"), 18, anchor_x="center", anchor_y="center")
        lines = []
        for seat, result in enumerate(results):
            total = round_.total_strokes(seat)
            lines.append(f"{'' if alone else round_.players[seat] + ': '}{result_line(result, not alone)}"
                         f"  ·  total so far {strokes_text(total)} ({par_text(total - round_.total_par(seat))})")
        self.lines = arcade.Text("\n".join(lines), 0, 0, theme.rgba("text"), 17, anchor_x="center", anchor_y="top",
                                 multiline=True, width=1100, align="center")
        hole = round_.course.holes[first.number - 1]
        best = game.best_hole(hole.id) if not isinstance(hole, Exception) else None
        self.best = arcade.Text(
            f"Best on this hole with the {game.shape_label}: {strokes_text(best.strokes)} by {best.player}"
            if best else "No best kept for this hole yet: finish the round to set one", 0, 0,
            theme.rgba("text"), 14, anchor_x="center", anchor_y="center", italic=True)
        upcoming = round_.current()
        nxt = f"Next: hole {round_.number} of {round_.hole_count} · {upcoming.spec.name} · par {upcoming.spec.par}" \
            if upcoming is not None else "That was the last hole"
        self.next_text = arcade.Text(nxt, 0, 0, theme.rgba("text"), 20, anchor_x="center", anchor_y="center",
                                     bold=True)
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
        for text, y in ((self.headline, h - 130), (self.detail, h - 195)):
            text.position = (w / 2, y)
            text.draw()
        self.lines.position = (w / 2, h - 240)
        self.lines.draw()
        below = h - 240 - self.lines.content_height
        self.best.position = (w / 2, below - 35)
        self.best.draw()
        self.next_text.position = (w / 2, below - 100)
        self.next_text.draw()
        if self.round.skipped:
            self.skipped.position = (w / 2, below - 135)
            self.skipped.draw()
