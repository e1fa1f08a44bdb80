"""The scorecard in standard golf form: hole numbers, par and score in rows, with totals."""

from __future__ import annotations

import arcade
from arcade.gui import UIAnchorLayout, UIBoxLayout, UIView

from polygolf.game.session import Game, Round
from polygolf.game.views.navigation import Navigator, window_key
from polygolf.game.views.widgets import themed_button, title


class ResultsView(UIView):
    def __init__(self, game: Game, round_: Round, flow: Navigator) -> None:
        super().__init__()
        self.game = game
        self.flow = flow
        self.round = round_
        theme = game.theme
        self.background_color = theme.rgba("background")
        self.title = title(f"{round_.course.name}: scorecard", theme, 36)
        diff = round_.total_strokes - round_.total_par
        verdict = "level par" if diff == 0 else f"{abs(diff)} {'over' if diff > 0 else 'under'} par"
        self.summary = arcade.Text(f"{round_.total_strokes} strokes, {verdict}", 0, 0, theme.rgba("text"), 20,
                                   anchor_x="center", anchor_y="center", bold=True)
        self.cells: list[tuple[arcade.Text, int, int]] = []  # text, column, row
        results = round_.results
        rows = [("Hole", [str(r.number) for r in results], "Total"),
                ("Par", [str(r.par) if r.strokes is not None else "-" for r in results], str(round_.total_par)),
                ("Score", [(str(r.strokes) + ("*" if r.picked_up else "")) if r.strokes is not None else "-"
                           for r in results], str(round_.total_strokes)),
                ("+/-", _running(results), f"{round_.total_strokes - round_.total_par:+d}")]
        for row, (label, values, total) in enumerate(rows):
            for col, value in enumerate([label, *values, total]):
                bold = row == 0 or col == 0 or col == len(values) + 1
                self.cells.append((arcade.Text(value, 0, 0, theme.rgba("text"), 18, anchor_x="center",
                                               anchor_y="center", bold=bold), col, row))
        self.columns = len(results) + 2
        self.rows = len(rows)
        self.note = arcade.Text("* picked up after the last stroke allowed" if any(r.picked_up for r in results)
                                else "", 0, 0, theme.rgba("text"), 12, anchor_x="center", anchor_y="center")
        row_box = UIBoxLayout(vertical=False, space_between=16)
        for text, action in (("Play again", self.on_again), ("Main menu", self.on_menu)):
            button = themed_button(theme, text, width=220, clicks=self.game.sound)
            button.on_click = action  # type: ignore[method-assign]
            row_box.add(button)
        anchor = UIAnchorLayout()
        anchor.add(row_box, anchor_x="center_x", anchor_y="bottom", align_y=50)
        self.ui.add(anchor)

    def on_again(self, _event=None) -> None:
        self.flow.new_round()

    def on_menu(self, _event=None) -> None:
        self.flow.menu()

    def on_key_press(self, symbol: int, modifiers: int) -> None:
        if window_key(self.window, self.game, symbol):
            return
        if symbol in (arcade.key.ENTER, arcade.key.RETURN, arcade.key.ESCAPE):
            self.on_menu()

    def on_draw_before_ui(self) -> None:
        theme = self.game.theme
        w, h = self.window.width, self.window.height
        self.title.position = (w / 2, h - 70)
        self.title.draw()
        cell_w = min(90.0, (w - 80) / self.columns)
        cell_h = 46.0
        left = (w - cell_w * self.columns) / 2
        top = h / 2 + 110
        # Grid: a panel per row, the header row stronger.
        for row in range(self.rows):
            y0 = top - (row + 1) * cell_h
            colour = theme.rgba("button") if row == 0 else theme.rgba("panel")
            arcade.draw_lrbt_rectangle_filled(left, left + cell_w * self.columns, y0, y0 + cell_h, colour)
        for col in range(self.columns + 1):
            x = left + col * cell_w
            arcade.draw_line(x, top, x, top - self.rows * cell_h, theme.rgba("text"), 1)
        for row in range(self.rows + 1):
            y = top - row * cell_h
            arcade.draw_line(left, y, left + cell_w * self.columns, y, theme.rgba("text"), 1)
        for text, col, row in self.cells:
            text.position = (left + (col + 0.5) * cell_w, top - (row + 0.5) * cell_h)
            text.draw()
        self.summary.position = (w / 2, top - self.rows * cell_h - 50)
        self.summary.draw()
        self.note.position = (w / 2, top - self.rows * cell_h - 85)
        self.note.draw()


def _running(results) -> list[str]:
    """Score against par after each hole, as golfers keep it (E for level)."""
    out, total = [], 0
    for r in results:
        if r.strokes is None:
            out.append("-")
            continue
        total += r.strokes - r.par
        out.append("E" if total == 0 else f"{total:+d}")
    return out
