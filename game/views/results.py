"""The scorecard in golf form: hole numbers and par, then for each player their score on each hole
with that hole against par, and a labelled running total against par; the winner named; the course's
best kept so far."""

from __future__ import annotations

from dataclasses import dataclass

import arcade
from arcade.gui import UIBoxLayout, UIView

from polygolf.game.drawing import draw_backed, fit_width
from polygolf.game.session import Game, HoleResult, Round, escaped, par_text, strokes_text
from polygolf.game.views.navigation import Navigator, window_key
from polygolf.game.views.widgets import KeyboardButtons, themed_button, title

LABEL_WIDTH = (110.0, 220.0, 360.0)  # px: the label column fits the longest label, at least the first, at most
# the second or, in a wide window, a quarter of it up to the third (long names stay large at 1920 px)
CELL_WIDTH = 96.0
# A hole's column is never narrower: more holes than fit so are shown a page at a time (nine or
# eighteen, as a card's front and back nines), turned with the ◀ ▶ buttons or Page Up / Page Down
# (QA8: at 36 holes every total read "1…", at 100 the cells ran over each other).
MIN_CELL = 34.0
TOTAL_WIDTH = (64.0, 96.0)  # px: the Total column, always wide enough for its numbers (at least, at most)
BELOW_TABLE = 200.0  # px under the table: the winner, the best, the notes and the buttons


@dataclass(slots=True)
class Cell:
    """A scorecard cell: its text, column and row, its full and short strings and its own size."""

    text: arcade.Text
    col: int
    row: int
    full: str
    short: str
    size: float


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
                                f"{escaped(best.player)} ({verdict(best.strokes - best.par)})" if best else "", 0, 0,
                                theme.rgba("text"), 14, anchor_x="center", anchor_y="center", italic=True)
        warnings = game.store.warnings[-1:] if game.store is not None else []
        self.warning = arcade.Text(" ".join(w.removeprefix("polygolf: ") for w in warnings), 0, 0,
                                   theme.rgba("text"), 12, anchor_x="center", anchor_y="top", multiline=True,
                                   width=1100, align="center")
        self.cells: list[Cell] = []
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
        self.running_rows = {3 + 2 * seat for seat in range(len(round_.players))}
        self.table = rows
        self.holes = len(results)
        self.rows = len(rows)
        labels = [arcade.Text(label, 0, 0, font_size=15, bold=True) for label, _, _ in rows]
        self._label_width = max(LABEL_WIDTH[0], 20.0 + max(text.content_width for text in labels))
        totals = [arcade.Text(total, 0, 0, font_size=15, bold=True) for _, _, total in rows]
        self._total_width = min(TOTAL_WIDTH[1], max(TOTAL_WIDTH[0], 16.0 + max(t.content_width for t in totals)))
        self.page = 0
        self._total_w, _, self.per_page = self._columns_for(self.window.width if self.window else 1280)
        self._sized_for: tuple[int, int] | None = None
        self.page_text = arcade.Text("", 0, 0, theme.rgba("text"), 13, anchor_x="center", anchor_y="center")
        self._build_cells()
        self.note = arcade.Text("* picked up after the last stroke allowed"
                                if any(r.picked_up for card in round_.cards for r in card) else "", 0, 0,
                                theme.rgba("text"), 12, anchor_x="center", anchor_y="center")
        self._lines = {text: (text.text, text.font_size) for text in (self.summary, self.best, self.note)}
        row_box = UIBoxLayout(vertical=False, space_between=16)
        self.buttons = {}
        choices = [("again", "Play again", self.on_again, 220), ("menu", "Main menu", self.on_menu, 220)]
        if self.holes > 9:  # (pages where the window is too narrow for every hole)
            choices = [("earlier", "◀", self.on_earlier, 56), *choices, ("later", "▶", self.on_later, 56)]
        for key, text, action, width in choices:
            button = themed_button(theme, text, width=width, clicks=self.game.sound)
            button.on_click = action  # type: ignore[method-assign]
            row_box.add(button)
            self.buttons[key] = button
        self._mark_pages()
        anchor = KeyboardButtons()
        anchor.add(row_box, anchor_x="center_x", anchor_y="bottom", align_y=30)
        self.ui.add(anchor)
        anchor.focus(self.buttons["menu"])  # where Enter and Esc always went; the arrows reach Play again

    @property
    def pages(self) -> int:
        return -(-self.holes // self.per_page) if self.holes else 1

    def _build_cells(self) -> None:
        """The cells of the page shown: the labels, its holes' columns and the totals (the round's)."""
        theme = self.game.theme
        start = self.page * self.per_page
        shown = range(start, min(self.holes, start + self.per_page))
        self.cells = []
        for row, (label, values, total) in enumerate(self.table):
            page = [values[k] for k in shown]
            for col, value in enumerate([label, *page, total]):
                bold = row == 0 or col == len(page) + 1 or (col == 0 and row in self.player_rows | {1})
                size = 13 if row in self.running_rows else 15
                # A hole's score without its "(+1)" where the cell is too narrow: the row below has it.
                short = value.split(" (")[0] if row in self.player_rows and 0 < col <= len(page) else value
                self.cells.append(Cell(arcade.Text(value, 0, 0, theme.rgba("text"), size,
                                                   anchor_x="left" if col == 0 else "center", anchor_y="center",
                                                   bold=bold), col, row, value, short, size))
        self.columns = len(shown) + 2
        self.page_text.text = (f"Holes {shown.start + 1}–{shown.stop} of {self.holes}  ·  ◀ ▶ or Page Up / Down"
                               if self.pages > 1 else "")
        self._sized_for = None
        self._mark_pages()

    def _mark_pages(self) -> None:
        """◀ and ▶ greyed where there is no page that way."""
        for key, able in (("earlier", self.page > 0), ("later", self.page < self.pages - 1)):
            if key in getattr(self, "buttons", {}):
                self.buttons[key].disabled = not able

    def turn_page(self, step: int) -> None:
        page = max(0, min(self.pages - 1, self.page + step))
        if page != self.page:
            self.page = page
            self._build_cells()

    def on_earlier(self, _event=None) -> None:
        self.turn_page(-1)

    def on_later(self, _event=None) -> None:
        self.turn_page(1)

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
        if symbol in (arcade.key.PAGEDOWN, arcade.key.PAGEUP):
            self.turn_page(1 if symbol == arcade.key.PAGEDOWN else -1)
        elif symbol in (arcade.key.ENTER, arcade.key.RETURN, arcade.key.ESCAPE):
            self.on_menu()

    def _columns_for(self, w: int) -> tuple[float, float, int]:
        """(Total column width, label column width, holes a page) in a window `w` px wide."""
        total_w = max(1.0, min(self._total_width, 0.2 * w))
        roomy = min(0.25 * w, LABEL_WIDTH[2], w - 60 - total_w - CELL_WIDTH * self.holes)  # (cells kept full width)
        # Every length at least a pixel: a window below the smallest size (no window manager keeps it
        # from one) is drawn squeezed, never with a negative cell (QA: ValueError under 500x300).
        label_w = max(1.0, min(self._label_width, max(LABEL_WIDTH[1], roomy), 0.3 * (w - 60)))
        fit = max(1, int((w - 60 - label_w - total_w) // MIN_CELL))
        holes = max(1, self.holes)
        return total_w, label_w, holes if fit >= holes else 18 if fit >= 18 else 9 if fit >= 9 else fit

    def _fit(self, w: int, h: int) -> tuple[float, float, float, float, list[int]]:
        """(label column width, cell width, cell height, the table's top, the rows shown) for this
        window, every cell's text fitted when the window is resized: a row's cells share one size,
        as large as its widest cell allows (a hole's score without its "(+1)" if that would be under
        10 points; a long name cut short); the running rows are left out where the window is too
        low for every row to be readable. Holes that would be narrower than MIN_CELL are shown a page
        (9 or 18 of them) at a time, the Total column always its full width."""
        total_w, label_w, per_page = self._columns_for(w)
        if per_page != self.per_page:
            first = self.page * self.per_page  # (the first hole shown stays on the page shown)
            self.page, self.per_page = first // per_page, per_page
            self._build_cells()
        shown_holes = max(1, self.columns - 2)
        cell_w = max(1.0, min(CELL_WIDTH, (w - 60 - label_w - total_w) / shown_holes))
        top = h - (95 if h >= 600 else 62)
        room = max(1.0, top - BELOW_TABLE)
        shown = [row for row in range(self.rows) if room / self.rows >= 22 or row not in self.running_rows]
        cell_h = min(40.0, room / len(shown))
        if self._sized_for != (w, h):
            self._sized_for = (w, h)
            self.title.font_size = 34 if h >= 600 else 24
            for rows in ({0, 1}, self.player_rows, self.running_rows):  # alike rows alike
                cells = [cell for cell in self.cells if cell.row in rows]
                _fit_row([cell for cell in cells if cell.col == 0], label_w - 14, cell_h, 11)
                _fit_row([cell for cell in cells if 0 < cell.col < self.columns - 1], cell_w - 6, cell_h, 10)
                _fit_row([cell for cell in cells if cell.col == self.columns - 1], total_w - 6, cell_h, 10)
            for text, (full, size) in self._lines.items():
                fit_width(text, full, w - 40, size)
            fit_width(self.page_text, self.page_text.text, w - 40, 13)
            self.warning.width = min(1100, w - 40)
        self._total_w = total_w
        return label_w, cell_w, cell_h, top, shown

    def on_draw_before_ui(self) -> None:
        theme = self.game.theme
        w, h = self.window.width, self.window.height
        label_w, cell_w, cell_h, top, shown = self._fit(w, h)
        total_w = self._total_w
        self.title.position = (w / 2, (h + top) / 2)
        self.title.draw()
        width = label_w + cell_w * (self.columns - 2) + total_w
        left = (w - width) / 2
        height = len(shown) * cell_h

        def x_of(col: int) -> float:
            return left if col == 0 else left + label_w + (col - 1) * cell_w

        for place, row in enumerate(shown):
            y0 = top - (place + 1) * cell_h
            colour = theme.rgba("button") if row == 0 else theme.rgba("panel")
            arcade.draw_lrbt_rectangle_filled(left, left + width, y0, y0 + cell_h, colour)
        for col in range(self.columns + 1):
            x = x_of(col) if col < self.columns else left + width
            arcade.draw_line(x, top, x, top - height, theme.rgba("text"), 2 if col == self.columns - 1 else 1)
        for place in range(len(shown) + 1):
            below = shown[place] if place < len(shown) else -1
            strong = below in self.player_rows or below in (1, 2) or place == len(shown)
            arcade.draw_line(left, top - place * cell_h, left + width, top - place * cell_h, theme.rgba("text"),
                             2 if strong else 1)
        places = {row: place for place, row in enumerate(shown)}
        for cell in self.cells:
            if cell.row in places:
                x = (x_of(cell.col) + 10 if cell.col == 0 else left + width - total_w / 2
                     if cell.col == self.columns - 1 else x_of(cell.col) + cell_w / 2)
                cell.text.position = (x, top - (places[cell.row] + 0.5) * cell_h)
                cell.text.draw()
        bottom = top - height
        if self.page_text.text:
            self.page_text.position = (w / 2, bottom - 13)
            self.page_text.draw()
        for text, dy in ((self.summary, 35), (self.best, 65), (self.note, 90)):
            text.position = (w / 2, bottom - dy)
            text.draw()
        self.warning.position = (w / 2, bottom - 108)  # on a panel: the text's colour reads on any theme
        draw_backed(self.warning, theme.rgba("panel"), pad=8.0)


def _fit_row(cells: list[Cell], width: float, height: float, readable: float) -> None:
    """One size for these cells of a row: the largest at which each fits `width` and the row's
    `height`, at most their own; with their short strings if the full ones would be under
    `readable` points; at least 8 points, anything still too wide cut short."""
    if not cells:
        return

    def size_for(strings: list[str]) -> float:
        size = min(cell.size for cell in cells)
        for cell, string in zip(cells, strings):
            cell.text.text, cell.text.font_size = string, cell.size
            if cell.text.content_width > width:
                size = min(size, cell.size * width / cell.text.content_width)
        size = max(8.0, min(size, 0.55 * height))
        while size > 8.0 and any(_width_at(cell.text, size) > width for cell in cells):
            size = max(8.0, size - 0.5)  # (a width is not quite proportional to the size)
        return size

    strings = [cell.full for cell in cells]
    size = size_for(strings)
    if size < readable and any(cell.short != cell.full for cell in cells):
        strings = [cell.short for cell in cells]
        size = size_for(strings)
    for cell, string in zip(cells, strings):  # (a name, in the first column, cut in the middle)
        fit_width(cell.text, string, width, size, size, middle=cell.col == 0)


def _width_at(text: arcade.Text, size: float) -> float:
    text.font_size = size
    return text.content_width
