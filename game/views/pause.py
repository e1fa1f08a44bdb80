"""The pause menu over the frozen hole: Resume, Restart hole, Main menu (the arrow keys or Tab choose,
Enter presses; Esc resumes)."""

from __future__ import annotations

import arcade
from arcade.gui import UIBoxLayout, UIView

from polygolf.game.drawing import HUD_HEIGHT
from polygolf.game.session import Game
from polygolf.game.views.navigation import Navigator, window_key
from polygolf.game.views.widgets import KeyboardButtons, themed_button, title

BUTTON_HEIGHT, BUTTON_GAP = 48, 10  # px
COLUMN_DROP = 30  # px the buttons sit below the window's middle, leaving the title room above them
PLAYERS_LINE = 23  # px under the HUD bar that the play view's players' line takes when several play


class PauseView(UIView):
    def __init__(self, game: Game, play_view: arcade.View, flow: Navigator) -> None:
        super().__init__()
        self.game = game
        self.play_view = play_view
        self.flow = flow
        theme = game.theme
        self.title = title("Paused", theme, 40)
        column = UIBoxLayout(vertical=True, space_between=BUTTON_GAP)
        self.buttons = {}
        actions = (("resume", "Resume", self.on_resume), ("restart", "Restart hole", self.on_restart),
                   ("menu", "Main menu", self.on_menu))
        for key, text, action in actions:
            button = themed_button(theme, text, width=280, height=BUTTON_HEIGHT, clicks=self.game.sound)
            button.on_click = action  # type: ignore[method-assign]
            column.add(button)
            self.buttons[key] = button
        self.column_height = len(actions) * BUTTON_HEIGHT + (len(actions) - 1) * BUTTON_GAP
        anchor = KeyboardButtons()
        anchor.add(column, anchor_x="center_x", anchor_y="center_y", align_y=-COLUMN_DROP)
        self.ui.add(anchor)
        anchor.focus()

    def on_resume(self, _event=None) -> None:
        self.flow.resume(self.play_view)

    def on_restart(self, _event=None) -> None:
        self.play_view.restart_hole()
        self.flow.resume(self.play_view)

    def on_menu(self, _event=None) -> None:
        self.flow.menu()

    def on_key_press(self, symbol: int, modifiers: int) -> None:
        if window_key(self.window, self.game, symbol):
            return
        if symbol == arcade.key.ESCAPE:  # (Enter presses the focused button: Resume unless the arrows moved)
            self.on_resume()

    def on_resize(self, width: int, height: int) -> None:
        """The hole drawn under the menu is the play view's: it is fitted to the new size too (it
        would be drawn as for the old one, and fitted only on resuming)."""
        self.play_view.on_resize(width, height)

    def title_y(self, w: int, h: int) -> float:
        """The title's centre: above the buttons, below the HUD bar and the players' line under it,
        and no higher than 120 px above the middle (where it sits in a tall window)."""
        size = 40 if h >= 600 else 30
        if self.title.font_size != size:
            self.title.font_size = size
        column_top = h / 2 - COLUMN_DROP + self.column_height / 2
        several = self.game.round is not None and len(self.game.round.players) > 1
        limit = h - HUD_HEIGHT - (PLAYERS_LINE if several else 0)
        return min(h / 2 + 120, (column_top + limit) / 2)

    def on_draw(self) -> None:
        # The hole stays visible, dimmed, under the menu.
        self.play_view.on_draw()
        w, h = self.window.width, self.window.height
        arcade.draw_lrbt_rectangle_filled(0, w, 0, h, (0, 0, 0, 150))
        self.title.position = (w / 2, self.title_y(w, h))
        self.title.draw()
        self.ui.draw()
