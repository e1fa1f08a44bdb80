"""The scorecard in golf form: hole numbers and par, then for each player their score on each hole
with that hole against par, and a labelled running total against par; the winner named; the course's
best kept so far."""

from __future__ import annotations

import arcade
from arcade.gui import UIAnchorLayout, UIBoxLayout, UIView

from polygolf.game.session import Game, HoleResult, Round, par_text, strokes_text
from polygolf.game.views.navigation import Navigator, window_key
from polygolf.game.views.widgets import themed_button, title

LABEL_WIDTH = 200.0


def hole_cell(result: HoleResult) -> str:
    """A hole's score with its score against par: '2 (-1)', '4* (+1)' (picked up), '-' (skipped)."""
    if result.strokes is None:
        return "-"
    return f"{result.strokes}{'*' if result.picked_up else ''} ({par_text(result.strokes - result.par)})"


def running(results: list[HoleResult]) -> list[str]:
    """Score against par after each hole, as golfers keep it (E for level)."""
    out, total = [], 0
    for r in results:
        if r.strokes is None:
            out.append("-")
            continue
        total += r.strokes - r.par
        out.append(par_text(total))
    return out


def verdict(diff: int) -> str:
    return "level par" if diff == 0 else f"{abs(diff)} {'over' if diff > 0 else 'under'} par"


class ResultsView(UIView):
    def __init__(self, game: Game, round_: Round, flow: Navigator) -> None:
        super().__init__()
        self.game = game
        self.flow = flow
        self.round = round_
        theme = game.theme
        self.background_color = theme.rgba("background")
        self.title = title(f"{round_.course.name}: scorecard", theme, 34)
        self.summary = arcade.Text(self.summary_line(), 0, 0, theme.rgba("text"), 20, anchor_x="center",
                                   anchor_y="center", bold=True)
        best = game.best_course()
        this_round = best is not None and game.session is not None and game.session.round is round_ \
            and best.when == game.session.record.recorded_at
        self.best = arcade.Text(f"{'New course' if this_round else 'Course'} best with the {game.shape_label}: "
                                f"{strokes_text(best.strokes)} by "
                                f"{best.player} ({verdict(best.strokes - best.par)})" if best else "", 0, 0,
                                theme.rgba("text"), 14, anchor_x="center", anchor_y="center", italic=True)
        warnings = game.store.warnings[-1:] if game.store is not None else []
        self.warning = arcade.Text(" ".join(w.removeprefix("polygolf: ") for w in warnings), 0, 0,
                                   theme.rgba("arrow_strong"), 12, anchor_x="center", anchor_y="top", multiline=True,
                                   width=1100, align="center")
        self.cells: list[tuple[arcade.Text, int, int]] = []  # text, column, row
        results = round_.results
        alone = len(round_.players) == 1
        rows = [("Hole", [str(r.number) for r in results], "Total"),
                ("Par", [str(r.par) if r.strokes is not None else "-" for r in results], str(round_.total_par()))]
        for seat, name in enumerate(round_.players):
            card = round_.cards[seat]
            strokes, par = round_.total_strokes(seat), round_.total_par(seat)
            rows.append(("Score" if alone else name, [hole_cell(r) for r in card], str(strokes)))
            rows.append(("To par, running" if alone else "  to par, running", running(card), par_text(strokes - par)))
        self.player_rows = {2 + 2 * seat for seat in range(len(round_.players))}
        for row, (label, values, total) in enumerate(rows):
            for col, value in enumerate([label, *values, total]):
                bold = row == 0 or col == len(values) + 1 or (col == 0 and row in self.player_rows | {1})
                size = 13 if row >= 2 and row not in self.player_rows else 15
                self.cells.append((arcade.Text(value, 0, 0, theme.rgba("text"), size,
                                               anchor_x="left" if col == 0 else "center", anchor_y="center",
                                               bold=bold), col, row))
        self.columns = len(results) + 2
        self.rows = len(rows)
        self.note = arcade.Text("* picked up after the last stroke allowed"
                                if any(r.picked_up for card in round_.cards for r in card) else "", 0, 0,
                                theme.rgba("text"), 12, anchor_x="center", anchor_y="center")
        row_box = UIBoxLayout(vertical=False, space_between=16)
        for text, action in (("Play again", self.on_again), ("Main menu", self.on_menu)):
            button = themed_button(theme, text, width=220, clicks=self.game.sound)
            button.on_click = action  # type: ignore[method-assign]
            row_box.add(button)
        anchor = UIAnchorLayout()
        anchor.add(row_box, anchor_x="center_x", anchor_y="bottom", align_y=30)
        self.ui.add(anchor)

    def summary_line(self) -> str:
        round_ = self.round
        if len(round_.players) == 1:
            return f"{strokes_text(round_.total_strokes())}, {verdict(round_.total_strokes() - round_.total_par())}"
        winners = round_.winners()
        seat = round_.players.index(winners[0])
        strokes = round_.total_strokes(seat)
        score = f"{strokes_text(strokes)}, {verdict(strokes - round_.total_par(seat))}"
        if len(winners) > 1:
            return f"A tie: {', '.join(winners[:-1])} and {winners[-1]} with {score}"
        return f"{winners[0]} wins with {score}"

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
        self.title.position = (w / 2, h - 50)
        self.title.draw()
        cell_w = min(96.0, (w - 60 - LABEL_WIDTH) / (self.columns - 1))
        cell_h = min(40.0, (h - 300) / self.rows)
        width = LABEL_WIDTH + cell_w * (self.columns - 1)
        left = (w - width) / 2
        top = h - 95

        def x_of(col: int) -> float:
            return left if col == 0 else left + LABEL_WIDTH + (col - 1) * cell_w

        for row in range(self.rows):
            y0 = top - (row + 1) * cell_h
            colour = theme.rgba("button") if row == 0 else theme.rgba("panel")
            arcade.draw_lrbt_rectangle_filled(left, left + width, y0, y0 + cell_h, colour)
        for col in range(self.columns + 1):
            x = x_of(col) if col < self.columns else left + width
            arcade.draw_line(x, top, x, top - self.rows * cell_h, theme.rgba("text"), 1)
        for row in range(self.rows + 1):
            y = top - row * cell_h
            strong = row in self.player_rows or row in (1, 2)
            arcade.draw_line(left, y, left + width, y, theme.rgba("text"), 2 if strong else 1)
        for text, col, row in self.cells:
            x = x_of(col) + 10 if col == 0 else x_of(col) + cell_w / 2
            text.position = (x, top - (row + 0.5) * cell_h)
            text.draw()
        bottom = top - self.rows * cell_h
        for text, dy in ((self.summary, 35), (self.best, 65), (self.note, 90), (self.warning, 108)):
            text.position = (w / 2, bottom - dy)
            text.draw()
