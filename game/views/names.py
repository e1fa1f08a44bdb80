"""The players' names, one box each (the count is the menu's Players choice). Enter or Done keeps
them (an empty box keeps its default, a repeated name is numbered); Esc leaves them as they were."""

from __future__ import annotations

import arcade
from arcade.gui import UIAnchorLayout, UIBoxLayout, UIInputText, UILabel, UIView

from polygolf.game.drawing import PLAYER_COLOURS
from polygolf.game.session import Game
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
        self.hint = arcade.Text("Tab: next name   Enter: done   Esc: back, unchanged", 0, 0, theme.rgba("text"), 13,
                                anchor_x="center", anchor_y="center", italic=True)
        column = UIBoxLayout(vertical=True, space_between=14)
        self.boxes: list[UIInputText] = []
        for seat, name in enumerate(game.players):
            row = UIBoxLayout(vertical=False, space_between=16)
            colour = PLAYER_COLOURS[seat] or theme.rgba("ball")
            row.add(UILabel(text=f"Player {seat + 1}", width=130, font_size=16, text_color=colour, bold=True))
            box = UIInputText(text=name, width=320, height=40, font_size=16, text_color=theme.rgba("text"),
                              caret_color=theme.rgba("text"))
            box.with_background(color=theme.rgba("panel"))
            row.add(box)
            column.add(row)
            self.boxes.append(box)
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
            out.append(name if name not in out else f"{name} {seat + 1}"[:MAX_NAME])
        return out

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
        w, h = self.window.width, self.window.height
        self.title.position = (w / 2, h - 90)
        self.title.draw()
        self.hint.position = (w / 2, h - 140)
        self.hint.draw()
