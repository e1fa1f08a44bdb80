"""The pause menu over the frozen hole: Resume, Restart hole, Main menu."""

from __future__ import annotations

import arcade
from arcade.gui import UIAnchorLayout, UIBoxLayout, UIView

from polygolf.game.session import Game
from polygolf.game.views.navigation import Navigator, window_key
from polygolf.game.views.widgets import themed_button, title


class PauseView(UIView):
    def __init__(self, game: Game, play_view: arcade.View, flow: Navigator) -> None:
        super().__init__()
        self.game = game
        self.play_view = play_view
        self.flow = flow
        theme = game.theme
        self.title = title("Paused", theme, 40)
        column = UIBoxLayout(vertical=True, space_between=10)
        actions = (("Resume", self.on_resume), ("Restart hole", self.on_restart), ("Main menu", self.on_menu))
        for text, action in actions:
            button = themed_button(theme, text, width=280, clicks=self.game.sound)
            button.on_click = action  # type: ignore[method-assign]
            column.add(button)
        anchor = UIAnchorLayout()
        anchor.add(column, anchor_x="center_x", anchor_y="center_y", align_y=-30)
        self.ui.add(anchor)

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
        if symbol == arcade.key.ESCAPE:
            self.on_resume()

    def on_draw(self) -> None:
        # The hole stays visible, dimmed, under the menu.
        self.play_view.on_draw()
        w, h = self.window.width, self.window.height
        arcade.draw_lrbt_rectangle_filled(0, w, 0, h, (0, 0, 0, 150))
        self.title.position = (w / 2, h / 2 + 120)
        self.title.draw()
        self.ui.draw()
