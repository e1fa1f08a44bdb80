"""The menu: Play, Environment (themes), Polygon (shapes), Random polygon, Course (the courses, then Random
nine with its seed, and then New seed under it), Players, Names; a row of settings (Sound, the aim Hint,
the shot Preview); Guide, Quit. The chosen polygon is drawn beside the buttons.

The layout is worked out from the window's size (`menu_layout`) and made again on every resize: the
button column under the title, lower buttons closer together in a short window, the polygon beside
them only where there is room. The arrow keys or Tab move between the buttons and Enter presses one
(Play at first); Esc asks before it quits: a second Esc within a few seconds does."""

from __future__ import annotations

from dataclasses import dataclass

import arcade
from arcade.gui import UIBoxLayout, UIView

from polygolf.engine.golf.layout import ball_outline
from polygolf.game.drawing import PolygonArt, draw_backed, fit_width
from polygolf.game.session import Game
from polygolf.game.shapes import random_shape
from polygolf.game.views.navigation import Navigator, window_key
from polygolf.game.views.widgets import (
    LABEL_PAD,
    KeyboardButtons,
    fitted_label,
    label_width,
    themed_button,
    title,
)

COLUMN_WIDTH = 320  # px
ROW_HEIGHT = (24, 42)  # px: a button's height, fewest and most
ROW_GAP = (3, 6)  # px between buttons: in a short window, and where a button can be 36 px high
MARGIN = 10  # px kept clear at the window's edges
TALL = 560  # px: a window this high has the large title and the subtitle
PREVIEW_RADIUS = (40, 110)  # px: the spinning polygon, smallest shown (else left out) and largest
PROBLEMS_SHOWN = 4  # content problems listed at most (then "... and N more"); fewer where there is no room
READABLE_ROW = 30  # px: buttons are not squeezed under this to list more problems
QUIT_SECONDS = 3.0  # a second Esc within this quits


@dataclass(frozen=True, slots=True)
class MenuLayout:
    """Where everything goes in a window of one size (px, y up)."""

    title_y: float
    title_size: int
    subtitle_y: float | None  # None: left out (a short window)
    column_left: float
    column_top: float
    column_width: float
    row_height: float
    row_gap: float
    font_size: int
    preview: tuple[float, float, float] | None  # the polygon's centre and radius, or None: no room


def menu_layout(w: int, h: int, rows: int, bottom: float = 0.0, preview: bool = True) -> MenuLayout:
    """The menu's layout for a `w` x `h` window with `rows` rows of buttons, above `bottom` px kept
    for the content problems' lines: the buttons as high as fits between the title and the bottom
    (24 to 42 px), the column left of the middle but never off the window, the polygon right of it
    (if `preview` and there is room)."""
    tall = h >= TALL
    column_top = h - 145 if tall else h - 62
    room = column_top - MARGIN - bottom
    gap = ROW_GAP[1]
    height = (room - gap * (rows - 1)) / rows
    if height < 36:
        gap = ROW_GAP[0]
        height = (room - gap * (rows - 1)) / rows
    height = max(ROW_HEIGHT[0], min(ROW_HEIGHT[1], height))
    used = rows * height + (rows - 1) * gap
    if tall:  # a high window: the title and the buttons in its middle, not all at the top
        column_top = max(MARGIN + bottom + used, min(column_top, (h + used) / 2 + 40))
    title_y, title_size = (column_top + 75, 48) if tall else (h - 32, 34)
    subtitle_y = column_top + 30 if tall else None
    width = min(COLUMN_WIDTH, w - 2 * MARGIN)
    left = max(2 * MARGIN, w / 2 - 180 - width / 2)
    right = left + width
    radius = min(PREVIEW_RADIUS[1], h / 5, (w - right) / 2 - 2 * MARGIN, used / 2 - 30)
    place = None
    if preview and radius >= PREVIEW_RADIUS[0]:  # beside the column's middle, a little up: its caption below
        place = (min(w / 2 + 230, (right + w) / 2), column_top - used / 2 + 15, radius)
    font = round(max(11, min(16, 0.4 * height)))
    return MenuLayout(title_y, title_size, subtitle_y, left, column_top, width, height, gap, font, place)


def names_label(players: list[str], width: float, font_size: float) -> str:
    """'Names: Ann, Bob' if it fits a button `width` px wide at `font_size`, else the first name, cut
    as short as it needs, and how many more: 'Names: Wilhelmina W… +3'."""
    label = "Names: " + ", ".join(players)
    room = width - LABEL_PAD
    if label_width(label, font_size) <= room:
        return label
    first, more = players[0], f" +{len(players) - 1}" if len(players) > 1 else ""
    for keep in range(len(first), 0, -1):
        label = f"Names: {first[:keep].rstrip()}{'…' if keep < len(first) else ''}{more}"
        if label_width(label, font_size) <= room:
            break
    return label


class MenuView(UIView):
    def __init__(self, game: Game, flow: Navigator) -> None:
        super().__init__()
        self.game = game
        self.flow = flow
        self.spin = 0.0
        self.quit_asked = 0.0  # seconds left in which a second Esc quits
        self.buttons: dict = {}
        self.group: KeyboardButtons | None = None
        self.build()

    def build(self) -> None:
        """The screen in the game's current choices and theme, laid out for the window's size."""
        game, theme = self.game, self.game.theme
        w, h = self.window.width, self.window.height
        focused = self.group.focused_widget if self.group is not None else None
        was_focused = next((key for key, button in self.buttons.items() if button is focused), "play")
        self.ui.clear()
        self.background_color = theme.rgba("background")
        layout = self.layout = self.lay_out_problems(w, h, 11 if game.random_chosen else 10)
        self.title = title("PolyGolf", theme, layout.title_size)
        self.subtitle = arcade.Text("mini golf with a polygon for a ball", 0, 0, theme.rgba("text"), 14,
                                    anchor_x="center", anchor_y="center", italic=True)
        self.shape_caption = arcade.Text(game.shape_label, 0, 0, theme.rgba("text"), 18, anchor_x="center",
                                         anchor_y="center")
        if layout.preview is not None:
            fit_width(self.shape_caption, game.shape_label, 2 * (w - layout.preview[0] - MARGIN), 18, 11)
        self.quit_note = arcade.Text("Press Esc again to quit", 0, 0, theme.rgba("text"), 14, anchor_x="center",
                                     anchor_y="center")
        column = UIBoxLayout(vertical=True, space_between=layout.row_gap)
        self.buttons = {}
        seed = [("seed", "New seed", self.on_new_seed)] if game.random_chosen else []
        settings = UIBoxLayout(vertical=False, space_between=6)  # one row: small settings, side by side
        small = (
            ("volume", f"Sound: {self.volume_label}", self.on_volume),
            ("hint", f"Hint: {game.hint}", self.on_hint),
            ("preview", f"Preview: {'on' if game.preview else 'off'}", self.on_preview),
        )
        font = min(12, layout.font_size)
        natural = [label_width(text, font) + LABEL_PAD for _, text, _ in small]  # the row shared out by these
        for (key, text, action), share in zip(small, natural):
            width = (layout.column_width - 6 * (len(small) - 1)) * share / sum(natural)
            label, size = fitted_label(text, width, font)
            button = themed_button(theme, label, width=width, height=layout.row_height, font_size=size,
                                   clicks=self.game.sound)
            button.on_click = action  # type: ignore[method-assign]
            settings.add(button)
            self.buttons[key] = button
        for key, text, action in (
            ("play", "Play", self.on_play),
            ("theme", f"Environment: {theme.name}", self.on_theme),
            ("shape", f"Polygon: {game.shape_label}", self.on_shape),
            ("random", "Random polygon", self.on_random),
            ("course", f"Course: {game.course_label}", self.on_course),
            *seed,
            ("players", f"Players: {len(game.players)}", self.on_players),
            ("names", names_label(game.players, layout.column_width, layout.font_size), self.on_names),
            ("settings", None, None),
            ("guide", "How to play", self.on_guide),
            ("quit", "Quit", self.on_quit),
        ):
            if text is None:
                column.add(settings)
                continue
            # A long label (a long seed given on the command line) gets a smaller font, or is cut short.
            label, size = fitted_label(text, layout.column_width, layout.font_size)
            button = themed_button(theme, label, width=layout.column_width, height=layout.row_height,
                                   font_size=size, clicks=self.game.sound)
            button.on_click = action  # type: ignore[method-assign]
            column.add(button)
            self.buttons[key] = button
        self.group = KeyboardButtons()
        self.group.add(column, anchor_x="left", anchor_y="top", align_x=layout.column_left,
                       align_y=layout.column_top - h)
        self.ui.add(self.group)
        self.group.focus(self.buttons.get(was_focused))  # where it was before the screen was made again
        self.ball_art = PolygonArt(ball_outline(game.shape, 1.0), theme, scale=1.0)
        self.preview = arcade.Camera2D()
        self._built_for = (w, h)
        self.ui.execute_layout()  # the buttons where they show now: a click before the next frame finds them

    def lay_out_problems(self, w: int, h: int, rows: int) -> MenuLayout:
        """Content that could not be read is left out of the game and said here (not crashed on),
        in `self.problems`: under the buttons in a tall window, as many as leave them readable; in a
        short one beside them, in the polygon's place. Returns the menu's layout around them."""
        tall = h >= TALL
        self.problems = arcade.Text("", 0, 0, self.game.theme.rgba("text"), 11, anchor_x="center",
                                    anchor_y="bottom" if tall else "top", multiline=True, width=min(1200, w - 40),
                                    align="center")
        problems = self.game.problems
        if not problems:
            return menu_layout(w, h, rows)
        layout = menu_layout(w, h, rows, preview=tall)
        if not tall:
            right = layout.column_left + layout.column_width
            self.problems.width = max(100, w - right - 3 * MARGIN)
            self.problems.position = ((right + w) / 2, layout.column_top)
        for count in range(min(PROBLEMS_SHOWN, len(problems)), 0, -1):
            more = [f"... and {len(problems) - count} more"] if len(problems) > count else []
            self.problems.text = "\n".join(problems[:count] + more)
            if tall:
                self.problems.position = (w / 2, MARGIN)
                layout = menu_layout(w, h, rows, self.problems.content_height + 2 * MARGIN)
                if layout.row_height >= READABLE_ROW:
                    break
            elif self.problems.content_height <= layout.column_top - MARGIN:
                break
        return layout

    def on_resize(self, width: int, height: int) -> None:
        if (width, height) != self._built_for:  # (the window says its size again when shown)
            self.build()

    # Actions: each changes the game's choices and rebuilds the screen in the new look.
    def on_play(self, _event=None) -> None:
        if self.game.course is not None or self.game.random_chosen:
            self.flow.new_round()  # Random nine is built first if it is not yet

    def on_theme(self, _event=None) -> None:
        self.game.next_theme()
        self.build()

    def on_shape(self, _event=None) -> None:
        self.game.next_shape()
        self.build()

    def on_random(self, _event=None) -> None:
        self.game.set_shape(*random_shape())
        self.build()

    def on_course(self, _event=None) -> None:
        self.game.next_course()
        self.build()

    def on_new_seed(self, _event=None) -> None:
        """Another Random nine (built when it is played)."""
        self.game.new_random_seed()
        self.build()

    def on_players(self, _event=None) -> None:
        """1 to 4 players taking turns on one machine."""
        self.game.next_player_count()
        self.build()

    def on_names(self, _event=None) -> None:
        self.flow.names()

    @property
    def volume_label(self) -> str:
        sound = self.game.sound
        return "off" if sound.muted or sound.volume == 0 else f"{round(sound.volume * 100)}%"

    def on_volume(self, _event=None) -> None:
        self.game.next_volume()
        self.build()

    def on_hint(self, _event=None) -> None:
        """The aim hint: off, rough, good, exact (how well the suggested arrow is aimed)."""
        self.game.next_hint()
        self.build()

    def on_preview(self, _event=None) -> None:
        """The dotted line of the shot being aimed, on or off."""
        self.game.toggle_preview()
        self.build()

    def on_guide(self, _event=None) -> None:
        self.flow.guide()

    def on_quit(self, _event=None) -> None:
        self.flow.quit()

    def on_key_press(self, symbol: int, modifiers: int) -> None:
        if window_key(self.window, self.game, symbol):
            if symbol == arcade.key.M:
                self.build()  # (the Sound button says "off" while muted)
            return
        if symbol in (arcade.key.ENTER, arcade.key.RETURN, arcade.key.SPACE):
            self.on_play()
        elif symbol == arcade.key.ESCAPE:
            # One Esc too many (backing out of a screen) should not close the game: a second one does.
            if self.quit_asked > 0:
                self.on_quit()
            else:
                self.quit_asked = QUIT_SECONDS

    def on_update(self, delta_time: float) -> None:
        self.spin += 0.6 * delta_time
        self.quit_asked = max(0.0, self.quit_asked - delta_time)

    def on_draw_before_ui(self) -> None:
        w = self.window.width
        layout = self.layout
        self.title.position = (w / 2, layout.title_y)
        self.title.draw()
        if layout.subtitle_y is not None:
            self.subtitle.position = (w / 2, layout.subtitle_y)
            self.subtitle.draw()
        if layout.preview is not None:  # the chosen polygon, large, to the right of the buttons
            cx, cy, radius = layout.preview
            with self._scaled(cx, cy, radius):
                self.ball_art.draw(0.0, 0.0, self.spin)
            self.shape_caption.position = (cx, cy - radius - 30)
            self.shape_caption.draw()
        if self.game.problems:
            draw_backed(self.problems, self.game.theme.rgba("panel"), pad=8.0)

    def on_draw_after_ui(self) -> None:
        if self.quit_asked > 0:  # over the buttons: it is what the next key does
            self.quit_note.position = (self.window.width / 2, self.window.height / 2)
            draw_backed(self.quit_note, (*self.game.theme.rgba("panel")[:3], 255), pad=16.0)

    def _scaled(self, cx: float, cy: float, radius: float):
        """A camera that shows the unit-radius ball `radius` pixels big, centred at (cx, cy)."""
        w, h = self.window.width, self.window.height
        self.preview.match_window()
        self.preview.zoom = radius
        self.preview.position = (-(cx - w / 2) / radius, -(cy - h / 2) / radius)
        return self.preview.activate()
