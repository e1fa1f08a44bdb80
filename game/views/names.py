"""The players' names, one box each (the count is the menu's Players choice). Enter or Done keeps
them (an empty box keeps its default; a repeated name is numbered); a name the rules of names refuse
is said so in place of the hint, and its box waits for another. Esc leaves them as they were.
Tab moves to the next box, Shift+Tab back; F11 works here as everywhere (M is a letter in a name).

A player named CPU is the computer (`session.is_computer`): each row's Computer button names its
seat so (or gives it back a person's name), and the Computer plays button sets how well it aims."""

from __future__ import annotations

import unicodedata

import arcade
from arcade.gui import UIAnchorLayout, UIBoxLayout, UIFlatButton, UILabel, UISpace, UIView
from arcade.gui.experimental.restricted_input import UIRestrictedInput

from polygolf.game.drawing import contrast, draw_backed, player_colour
from polygolf.game.session import MAX_NAME, Game, is_computer, player_name
from polygolf.game.views.navigation import Navigator, window_key
from polygolf.game.views.widgets import themed_button, title

ROW_HEIGHT = (32, 40)  # px: a row's height, in the shortest window and where there is room
ROW_GAP = (6, 14)  # px between rows: when rows would be under 36 px, and otherwise
MARGIN = 10  # px
TALL = 600  # px: a window this high has the large title
SWATCH = 18  # px: the seat's ball beside its label
HINT = "Tab: next name   Shift+Tab: back   Enter: done   Esc: back, unchanged   A player named CPU is the computer"
LABEL_CONTRAST = 3.0  # WCAG's least for large text: a label in its ball's colour at least this far from the background


class NameBox(UIRestrictedInput):
    """A name's box: it takes no more than MAX_NAME characters (typed or pasted), its text in the
    middle of its height."""

    def __init__(self, **kwargs) -> None:
        super().__init__(**kwargs)
        self.layout.content_valign = "center"

    def validate(self, text: str) -> bool:
        return len(text) <= MAX_NAME


class NamesView(UIView):
    def __init__(self, game: Game, flow: Navigator) -> None:
        super().__init__()
        self.game = game
        self.flow = flow
        theme = game.theme
        self.background_color = theme.rgba("background")
        self.title = title("Who is playing?", theme, 36)
        self.hint = arcade.Text(HINT, 0, 0, theme.rgba("text"), 13, anchor_x="center", anchor_y="top", italic=True,
                                multiline=True, width=1200, align="center")
        self.refused = False  # whether the hint's place says why a name was refused
        self.column = UIBoxLayout(vertical=True, space_between=ROW_GAP[1])
        self.rows: list[UIBoxLayout] = []
        self.boxes: list[NameBox] = []
        self.toggles: list[UIFlatButton] = []  # each row's Person / Computer button
        for seat, name in enumerate(game.players):
            row = UIBoxLayout(vertical=False, space_between=16)
            # The seat's ball as a swatch (edged in the text's colour, so a dark ball shows on a dark
            # background), and its label in the ball's colour where that reads on the background, else in
            # the text's (QA: Sand's seat 2 and 3 at 1.7 : 1).
            colour = player_colour(theme, seat)
            readable = contrast(colour, theme.rgba("background")) >= LABEL_CONTRAST
            row.add(UISpace(width=SWATCH, height=SWATCH, color=colour).with_border(width=2, color=theme.rgba("text")))
            row.add(UILabel(text=f"Player {seat + 1}", width=130, font_size=16,
                            text_color=colour if readable else theme.rgba("text"), bold=True))
            box = NameBox(text=name[:MAX_NAME], width=320, height=ROW_HEIGHT[1], font_size=16,
                          text_color=theme.rgba("text"), caret_color=theme.rgba("text"))
            box.with_background(color=theme.rgba("panel"))
            row.add(box)
            toggle = themed_button(theme, self.toggle_text(name), width=130, height=ROW_HEIGHT[1], font_size=13)
            toggle.on_click = lambda _event, seat=seat: self.on_toggle(seat)  # type: ignore[method-assign]
            row.add(toggle)
            self.column.add(row)
            self.rows.append(row)
            self.boxes.append(box)
            self.toggles.append(toggle)
        self.skill = themed_button(theme, self.skill_text(), width=320, height=ROW_HEIGHT[1], font_size=14)
        self.skill.on_click = self.on_skill  # type: ignore[method-assign]
        self.column.add(self.skill)
        self.done = themed_button(theme, "Done", width=220, height=ROW_HEIGHT[1])
        self.done.on_click = self.on_done  # type: ignore[method-assign]
        self.column.add(self.done)
        self.anchor = UIAnchorLayout()
        self.anchor.add(self.column, anchor_x="center_x", anchor_y="top")
        self.ui.add(self.anchor)
        self.lay_out(self.window.width, self.window.height)
        if self.boxes:
            self.boxes[0].activate()

    def lay_out(self, w: int, h: int) -> None:
        """The title, the hint (wrapped to the window) under it, and the rows in the room under that:
        as high as fits above the window's bottom, closer together in a short window."""
        tall = h >= TALL
        self.title.font_size = 36 if tall else 26
        self.title.position = (w / 2, h - (70 if tall else 30))
        self.hint.font_size = 13 if tall else 12
        self.hint.width = w - 4 * MARGIN
        self.hint.position = (w / 2, self.title.bottom - (16 if tall else 6))
        top = self.hint.bottom - (24 if tall else 10)
        rows = len(self.boxes) + 2
        gap = ROW_GAP[1]
        height = (top - MARGIN - gap * (rows - 1)) / rows
        if height < 36:
            gap = ROW_GAP[0]
            height = (top - MARGIN - gap * (rows - 1)) / rows
        height = max(ROW_HEIGHT[0], min(ROW_HEIGHT[1], height))
        top -= max(0.0, top - MARGIN - rows * height - (rows - 1) * gap) / 2  # in the middle of the room left
        for widget in (*self.boxes, *self.toggles, self.skill, self.done):
            widget.rect = widget.rect.resize(height=height)
        column = UIBoxLayout(vertical=True, space_between=gap)  # (a box layout's spacing is set when it is made)
        for child in (*self.rows, self.skill, self.done):
            self.column.remove(child)
            column.add(child)
        self.anchor.clear()
        self.anchor.add(column, anchor_x="center_x", anchor_y="top", align_y=top - h)
        self.column = column

    def on_resize(self, width: int, height: int) -> None:
        self.lay_out(width, height)

    def names(self) -> list[str]:
        """The boxes' names, tidied (`tidy`); an empty box, or a name the rules refuse
        (`session.player_name`, a course's name's rules: one of accents alone shows nothing), gets
        its seat's default, and a repeat a number."""
        out: list[str] = []
        for seat, box in enumerate(self.boxes):
            name = tidy(box.text)
            try:
                name = player_name(name)
            except ValueError:
                name = f"Player {seat + 1}"
            number, base = seat + 1, name
            while name in out:  # a repeat: numbered, cut to leave the number room (never the same again)
                suffix = f" {number}"
                name, number = base[:MAX_NAME - len(suffix)].rstrip() + suffix, number + 1
            out.append(name)
        return out

    def refusal(self) -> tuple[int, str] | None:
        """The first seat whose box holds a name the rules refuse, and why (an empty box is no
        refusal: it keeps its seat's default)."""
        for seat, box in enumerate(self.boxes):
            name = tidy(box.text)
            if name:
                try:
                    player_name(name)
                except ValueError as exc:
                    return seat, str(exc)
        return None

    @staticmethod
    def toggle_text(name: str) -> str:
        return "Computer" if is_computer(name) else "Person"

    def skill_text(self) -> str:
        return f"Computer plays: {self.game.computer_skill}"

    def on_toggle(self, seat: int) -> None:
        """A person's seat becomes the computer's (named CPU), or the computer's a person's again."""
        box = self.boxes[seat]
        if is_computer(box.text):
            box.text = f"Player {seat + 1}"
        else:
            box.text = "CPU" if not any(is_computer(b.text) for b in self.boxes) else f"CPU {seat + 1}"
        self.toggles[seat].text = self.toggle_text(box.text)

    def on_skill(self, _event=None) -> None:
        """How well the computer aims: rough, good, exact (kept with the settings at once)."""
        self.game.next_computer_skill()
        self.skill.text = self.skill_text()

    def on_done(self, _event=None) -> None:
        """Keep the names, unless one is refused: then say why where the hint was and wait in its box
        (QA: the name was silently replaced by the seat's default)."""
        refused = self.refusal()
        if refused is not None:
            seat, why = refused
            self.hint.text = f"Player {seat + 1}'s name: {why}. Type another, or empty the box for Player {seat + 1}."
            self.hint.italic, self.hint.bold, self.refused = False, True, True
            for box in self.boxes:
                box.deactivate()
            self.boxes[seat].activate()
            self.lay_out(self.window.width, self.window.height)
            return
        self.game.set_names(self.names())
        self.flow.menu()

    def on_key_press(self, symbol: int, modifiers: int) -> bool | None:
        if symbol == arcade.key.F11:  # (not M: it is typed into a name)
            return window_key(self.window, self.game, symbol)
        if symbol in (arcade.key.ENTER, arcade.key.RETURN):
            self.on_done()
            return True
        if symbol == arcade.key.ESCAPE:
            self.flow.menu()
            return True
        if symbol == arcade.key.TAB and self.boxes:
            active = next((k for k, box in enumerate(self.boxes) if box.active), -1)
            step = -1 if modifiers & arcade.key.MOD_SHIFT else 1
            for box in self.boxes:
                box.deactivate()
            self.boxes[(active + step) % len(self.boxes) if active >= 0 or step > 0 else -1].activate()
            return True
        return None

    def on_draw_before_ui(self) -> None:
        for box, toggle in zip(self.boxes, self.toggles):  # a name typed in says who plays, too
            text = self.toggle_text(box.text)
            if toggle.text != text:
                toggle.text = text
        self.title.draw()
        if self.refused:
            draw_backed(self.hint, self.game.theme.rgba("panel"), pad=6.0)
        else:
            self.hint.draw()


def tidy(text: str) -> str:
    """A box's text as a name: in Unicode's composed form (NFC: 'Ánn' typed either way is one name),
    runs of spaces as one, trimmed to MAX_NAME."""
    return unicodedata.normalize("NFC", " ".join(text.split()))[:MAX_NAME].rstrip()
