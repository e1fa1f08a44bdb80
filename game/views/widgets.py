"""Themed arcade.gui pieces shared by the menu-like screens."""

from __future__ import annotations

import arcade
from arcade.gui import UIFlatButton, UIKeyPressEvent, UIOnClickEvent, UIWidget
from arcade.gui.experimental.focus import UIFocusGroup
from pyglet.event import EVENT_HANDLED

from polygolf.game.drawing import fit_width
from polygolf.game.sound import SoundBoard
from polygolf.game.theme import Theme

SMALLEST_LABEL = 11  # points: a button's label is never smaller (it is cut short instead)
LABEL_PAD = 8  # px of a button's width kept clear of its label
FOCUS_BORDER = 4  # px: the focused (or hovered) button's edge, twice the others' (Night's light edges hid it)


def button_style(theme: Theme, font_size: float = 16) -> dict[str, UIFlatButton.UIStyle]:
    normal = UIFlatButton.UIStyle(font_size=font_size, font_color=theme.rgba("button_text"), bg=theme.rgba("button"),
                                  border=theme.rgba("wall_edge"), border_width=2)
    hover = UIFlatButton.UIStyle(font_size=font_size, font_color=theme.rgba("button_text"),
                                 bg=theme.rgba("button_hover"), border=theme.rgba("text"), border_width=FOCUS_BORDER)
    press = UIFlatButton.UIStyle(font_size=font_size, font_color=theme.rgba("button"), bg=theme.rgba("text"),
                                 border=theme.rgba("text"), border_width=2)
    disabled = UIFlatButton.UIStyle(font_size=font_size, font_color=(*theme.rgba("text")[:3], 110),
                                    bg=theme.rgba("panel"), border=theme.rgba("wall_edge"), border_width=2)
    return {"normal": normal, "hover": hover, "press": press, "disabled": disabled}


def themed_button(theme: Theme, text: str, width: float = 320, height: float = 48, font_size: float = 16,
                  clicks: SoundBoard | None = None) -> UIFlatButton:
    """A button in the theme's colours; with `clicks`, every press is heard (before its action runs)."""
    button = UIFlatButton(text=text, width=width, height=height, style=button_style(theme, font_size))
    if clicks is not None:
        button.push_handlers(on_click=lambda _event: clicks.click())
    return button


def label_width(text: str, font_size: float) -> float:
    """How wide `text` is in pixels in a button's font at `font_size`."""
    return arcade.Text(text, 0, 0, font_size=font_size, font_name=UIFlatButton.UIStyle.font_name).content_width


def fitted_label(text: str, width: float, font_size: float) -> tuple[str, float]:
    """(label, font size) for `text` on a button `width` px wide: at `font_size` if it fits, else
    smaller down to SMALLEST_LABEL, else cut short there with an ellipsis (`drawing.fit_width`)."""
    probe = arcade.Text("", 0, 0, font_size=font_size, font_name=UIFlatButton.UIStyle.font_name)
    fit_width(probe, text, width - LABEL_PAD, font_size, min(font_size, SMALLEST_LABEL))
    return probe.text, probe.font_size


def title(text: str, theme: Theme, size: int = 40) -> arcade.Text:
    return arcade.Text(text, 0, 0, theme.rgba("text"), size, anchor_x="center", anchor_y="center", bold=True)


class KeyboardButtons(UIFocusGroup):
    """An anchor layout whose buttons the keyboard reaches: Tab / Shift+Tab or the arrow keys move the
    focus (a focused button has the hover look), Enter or Space presses the focused one. Call
    `focus` once the buttons are in it."""

    FORWARD = (arcade.key.DOWN, arcade.key.RIGHT)
    BACK = (arcade.key.UP, arcade.key.LEFT)

    def focus(self, widget: UIWidget | None = None) -> None:
        """The focus on `widget` (by default the first button)."""
        self.detect_focusable_widgets()
        if self._focusable_widgets:
            self.set_focus(widget if widget is not None else ...)

    def on_event(self, event) -> bool | None:
        focused = self.focused_widget
        if isinstance(event, UIKeyPressEvent) and focused is not None:
            if event.symbol in self.FORWARD:
                self.focus_next()
                return EVENT_HANDLED
            if event.symbol in self.BACK:
                self.focus_previous()
                return EVENT_HANDLED
            if event.symbol in (arcade.key.ENTER, arcade.key.RETURN) and not focused.disabled:
                x, y = focused.rect.center
                focused.dispatch_event("on_click", UIOnClickEvent(source=focused, x=int(x), y=int(y),
                                                                  button=arcade.MOUSE_BUTTON_LEFT, modifiers=0))
                return EVENT_HANDLED
        return super().on_event(event)
