"""Between holes: the hole just played (its golf name alone; every player's line when several play),
the best ever kept for it, and the next hole's number and par."""

from __future__ import annotations

import arcade
from arcade.gui import UIBoxLayout, UIView

from polygolf.game.drawing import cut_middle, draw_backed, fit_width
from polygolf.game.session import Game, HoleResult, Round, escaped, golf_name, par_text, penalty_text, strokes_text
from polygolf.game.views.navigation import Navigator, window_key
from polygolf.game.views.widgets import KeyboardButtons, themed_button, title

PLAYERS_FONT = 17
BUTTON_TOP = 108  # px: the button's top edge above the window's bottom
BUTTON_GAP = 10  # px between the two buttons
GAPS = (65.0, 45.0, 35.0, 65.0)  # px: headline to detail, to the players' lines, their end to the best, to the next


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
        self._results = results
        self._full_lines = "\n".join(self.player_line(seat) for seat in range(len(results)))
        self.lines = arcade.Text(self._full_lines, 0, 0, theme.rgba("text"), PLAYERS_FONT, anchor_x="center",
                                 anchor_y="top", multiline=True, width=1100, align="center")
        hole = round_.course.holes[first.number - 1]
        best = game.best_hole(hole.id) if not isinstance(hole, Exception) else None
        self.best = arcade.Text(
            f"Best on this hole with the {game.shape_label}: {strokes_text(best.strokes)} by {escaped(best.player)}"
            if best else "No best kept for this hole yet: finish the round to set one", 0, 0,
            theme.rgba("text"), 14, anchor_x="center", anchor_y="center", italic=True)
        upcoming = round_.current()
        nxt = f"Next: hole {round_.number} of {round_.hole_count} · {upcoming.spec.name} · par {upcoming.spec.par}" \
            if upcoming is not None else "That was the last hole"
        self.next_text = arcade.Text(nxt, 0, 0, theme.rgba("text"), 20, anchor_x="center", anchor_y="center",
                                     bold=True)
        self.skipped = arcade.Text("\n".join(round_.skipped), 0, 0, theme.rgba("text"), 12,
                                   anchor_x="center", anchor_y="top", multiline=True, width=1000, align="center")
        self._lines = {text: (text.text, text.font_size) for text in (self.headline, self.detail, self.best,
                                                                        self.next_text)}
        self._fitted_to = (0, 0)
        self._squeeze, self._top = 1.0, 0.0
        button = themed_button(theme, "Next hole" if upcoming else "Scorecard", width=260, clicks=self.game.sound)
        button.on_click = self.on_continue  # type: ignore[method-assign]
        leave = themed_button(theme, "Main menu", width=200, clicks=self.game.sound)
        leave.on_click = self.on_menu  # type: ignore[method-assign]
        self.buttons = {"next": button, "menu": leave}
        row = UIBoxLayout(vertical=False, space_between=BUTTON_GAP)
        row.add(button)
        row.add(leave)
        anchor = KeyboardButtons()
        anchor.add(row, anchor_x="center_x", anchor_y="bottom", align_y=BUTTON_TOP - 48)
        self.ui.add(anchor)
        anchor.focus(button)

    def on_continue(self, _event=None) -> None:
        self.flow.next_hole()

    def on_menu(self, _event=None) -> None:
        """Leave the round, as the pause menu's Main menu does (a round is kept only when finished)."""
        self.flow.menu()

    def on_key_press(self, symbol: int, modifiers: int) -> None:
        if window_key(self.window, self.game, symbol):
            return
        if symbol == arcade.key.SPACE:  # (Enter presses the focused button: Next hole unless the arrows moved)
            self.on_continue()
        elif symbol == arcade.key.ESCAPE:
            self.on_menu()

    def player_line(self, seat: int, keep: int | None = None) -> str:
        """The seat's line: the hole's result and the total so far; its name, if longer than `keep`, cut
        in the middle (`drawing.cut_middle`)."""
        round_, result, alone = self.round, self._results[seat], len(self._results) == 1
        total = round_.total_strokes(seat)
        name = round_.players[seat] if keep is None else cut_middle(round_.players[seat], keep)
        return (f"{'' if alone else name + ': '}{result_line(result, not alone)}"
                f"  ·  total so far {strokes_text(total)} ({par_text(total - round_.total_par(seat))})")

    def _fit(self, w: int, h: int) -> None:
        """Every line within the window: each player's line whole (all smaller if the widest does not
        fit), the others shrunk to the width; and the gaps between them closed up (the headline
        smaller) when the window is too low for them above the button."""
        if (w, h) == self._fitted_to:
            return
        self._fitted_to = (w, h)
        self.lines.text = self._full_lines  # (a smaller window's fit may have cut names)
        self.lines.font_size, self.lines.width = PLAYERS_FONT, 10_000  # (no wrapping: the widest line's width)
        self.lines.font_size = max(9.0, PLAYERS_FONT * min(1.0, (w - 40) / max(self.lines.content_width, 1.0)))
        while self.lines.font_size > 9.0:  # smaller until no line wraps at the width it was chosen for
            self.lines.width = 10_000
            unwrapped = self.lines.content_height
            self.lines.width = w - 40
            if self.lines.content_height <= unwrapped:
                break
            self.lines.font_size = max(9.0, self.lines.font_size - 0.5)  # (a space can tip a line over)
        self.lines.width = 10_000
        lines = []
        for seat in range(len(self._results)):  # at 9 pt still too wide: cut the names of the lines that are
            keep = len(self.round.players[seat])
            self.lines.text = self.player_line(seat)
            while keep > 1 and self.lines.content_width > w - 40:
                keep -= 1
                self.lines.text = self.player_line(seat, keep)
            lines.append(self.lines.text)
        self.lines.text = "\n".join(lines)
        self.lines.width = w - 40
        self.skipped.width = min(1100, w - 40)
        for text, (full, size) in self._lines.items():
            fit_width(text, full, w - 40, size)
        # From the headline's centre down to the next hole's line: fixed gaps and the players' lines,
        # between 35 px below the top and the button's top (with room for the skipped holes' lines).
        gaps = sum(GAPS)
        room = (h - 35) - (BUTTON_TOP + 27 + (self.skipped.content_height + 20 if self.round.skipped else 0))
        self._squeeze = max(0.3, min(1.0, (room - self.lines.content_height) / gaps))
        if self._squeeze < 1.0:
            full, size = self._lines[self.headline]
            fit_width(self.headline, full, w - 40, size * max(0.6, self._squeeze))
        lowest = h - 35 - room + self.lines.content_height + gaps * self._squeeze  # the stack's end on the limit
        self._top = min(h - 35, max(h - 130, lowest))

    def on_draw_before_ui(self) -> None:
        w, h = self.window.width, self.window.height
        self._fit(w, h)
        to_detail, to_lines, to_best, to_next = (gap * self._squeeze for gap in GAPS)
        y = self._top
        for text, at in ((self.headline, y), (self.detail, y - to_detail)):
            text.position = (w / 2, at)
            text.draw()
        self.lines.position = (w / 2, y - to_detail - to_lines)
        self.lines.draw()
        below = y - to_detail - to_lines - self.lines.content_height
        self.best.position = (w / 2, below - to_best)
        self.best.draw()
        self.next_text.position = (w / 2, below - to_best - to_next)
        self.next_text.draw()
        if self.round.skipped:  # on a panel: a problem, said in the text's colour, which reads on any theme
            self.skipped.position = (w / 2, below - to_best - to_next - 35)
            draw_backed(self.skipped, self.game.theme.rgba("panel"), pad=8.0)
