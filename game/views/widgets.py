"""Themed arcade.gui pieces shared by the menu-like screens."""

from __future__ import annotations

import arcade
from arcade.gui import UIFlatButton

from polygolf.game.sound import SoundBoard
from polygolf.game.theme import Theme


def button_style(theme: Theme, font_size: int = 16) -> dict[str, UIFlatButton.UIStyle]:
    normal = UIFlatButton.UIStyle(font_size=font_size, font_color=theme.rgba("button_text"), bg=theme.rgba("button"),
                                  border=theme.rgba("wall_edge"), border_width=2)
    hover = UIFlatButton.UIStyle(font_size=font_size, font_color=theme.rgba("button_text"),
                                 bg=theme.rgba("button_hover"), border=theme.rgba("text"), border_width=2)
    press = UIFlatButton.UIStyle(font_size=font_size, font_color=theme.rgba("button"), bg=theme.rgba("text"),
                                 border=theme.rgba("text"), border_width=2)
    return {"normal": normal, "hover": hover, "press": press, "disabled": normal}


def themed_button(theme: Theme, text: str, width: int = 320, height: int = 48, font_size: int = 16,
                  clicks: SoundBoard | None = None) -> UIFlatButton:
    """A button in the theme's colours; with `clicks`, every press is heard (before its action runs)."""
    button = UIFlatButton(text=text, width=width, height=height, style=button_style(theme, font_size))
    if clicks is not None:
        button.push_handlers(on_click=lambda _event: clicks.click())
    return button


def title(text: str, theme: Theme, size: int = 40) -> arcade.Text:
    return arcade.Text(text, 0, 0, theme.rgba("text"), size, anchor_x="center", anchor_y="center", bold=True)

