"""The players' names, one box each (the count is the menu's Players choice). Enter or Done keeps
them (an empty box keeps its default, a repeated name is numbered); Esc leaves them as they were.

A player named CPU is the computer (`session.is_computer`): each row's Computer button names its
seat so (or gives it back a person's name), and the Computer plays button sets how well it aims."""

from __future__ import annotations

import arcade
from arcade.gui import UIAnchorLayout, UIBoxLayout, UIFlatButton, UIInputText, UILabel, UIView

from polygolf.game.drawing import PLAYER_COLOURS
from polygolf.game.session import Game, is_computer
from polygolf.game.views.navigation import Navigator
from polygolf.game.views.widgets import themed_button, title

MAX_NAME = 20


class NamesView(UIView):
    def __init__(self, game: Game, flow: Navigator) -> None:
        super().__init__()
        self.game = game
        self.flow = flow
        theme = game.theme
        self.background_color = theme.rgba("background")
        self.title = title("Who is playing?", theme, 36)
        self.hint = arcade.Text("Tab: next name   Enter: done   Esc: back, unchanged   A player named CPU is the "
                                "computer", 0, 0, theme.rgba("text"), 13, anchor_x="center", anchor_y="center",
                                italic=True)
        column = UIBoxLayout(vertical=True, space_between=14)
        self.boxes: list[UIInputText] = []
        self.toggles: list[UIFlatButton] = []  # each row's Person / Computer button
        for seat, name in enumerate(game.players):
            row = UIBoxLayout(vertical=False, space_between=16)
            colour = PLAYER_COLOURS[seat] or theme.rgba("ball")
            row.add(UILabel(text=f"Player {seat + 1}", width=130, font_size=16, text_color=colour, bold=True))
            box = UIInputText(text=name, width=320, height=40, font_size=16, text_color=theme.rgba("text"),
                              caret_color=theme.rgba("text"))
            box.with_background(color=theme.rgba("panel"))
            row.add(box)
            toggle = themed_button(theme, self.toggle_text(name), width=130, height=40, font_size=13)
            toggle.on_click = lambda _event, seat=seat: self.on_toggle(seat)  # type: ignore[method-assign]
            row.add(toggle)
            column.add(row)
            self.boxes.append(box)
            self.toggles.append(toggle)
        self.skill = themed_button(theme, self.skill_text(), width=320, height=40, font_size=14)
        self.skill.on_click = self.on_skill  # type: ignore[method-assign]
        column.add(self.skill)
        done = themed_button(theme, "Done", width=220)
        done.on_click = self.on_done  # type: ignore[method-assign]
        column.add(done)
        anchor = UIAnchorLayout()
        anchor.add(column, anchor_x="center_x", anchor_y="center_y", align_y=-20)
        self.ui.add(anchor)
        if self.boxes:
            self.boxes[0].activate()

    def names(self) -> list[str]:
        """The boxes' names, tidied: trimmed to MAX_NAME, empty ones and repeats given defaults."""
        out: list[str] = []
        for seat, box in enumerate(self.boxes):
            name = " ".join(box.text.split())[:MAX_NAME] or f"Player {seat + 1}"
            number, base = seat + 1, name
            while name in out:  # a repeat: numbered, cut to leave the number room (never the same again)
                suffix = f" {number}"
                name, number = base[:MAX_NAME - len(suffix)].rstrip() + suffix, number + 1
            out.append(name)
        return out

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
        self.game.set_names(self.names())
        self.flow.menu()

    def on_key_press(self, symbol: int, modifiers: int) -> bool | None:
        if symbol in (arcade.key.ENTER, arcade.key.RETURN):
            self.on_done()
            return True
        if symbol == arcade.key.ESCAPE:
            self.flow.menu()
            return True
        if symbol == arcade.key.TAB and self.boxes:
            active = next((k for k, box in enumerate(self.boxes) if box.active), -1)
            for box in self.boxes:
                box.deactivate()
            self.boxes[(active + 1) % len(self.boxes)].activate()
            return True
        return None

    def on_draw_before_ui(self) -> None:
        for box, toggle in zip(self.boxes, self.toggles):  # a name typed in says who plays, too
            text = self.toggle_text(box.text)
            if toggle.text != text:
                toggle.text = text
        w, h = self.window.width, self.window.height
        self.title.position = (w / 2, h - 90)
        self.title.draw()
        self.hint.position = (w / 2, h - 140)
        self.hint.draw()
