"""The menu: Play, Environment (themes), Polygon (shapes), Random polygon, Course (the courses, then Random
nine with its seed, and then New seed under it), Players, Names; a row of settings (Sound, the aim Hint,
the shot Preview); Guide, Quit. The chosen polygon is drawn beside the buttons."""

from __future__ import annotations

import arcade
from arcade.gui import UIAnchorLayout, UIBoxLayout, UIView

from polygolf.engine.golf.layout import ball_outline
from polygolf.game.drawing import PolygonArt
from polygolf.game.session import Game
from polygolf.game.shapes import random_shape
from polygolf.game.views.navigation import Navigator, window_key
from polygolf.game.views.widgets import themed_button, title


class MenuView(UIView):
    def __init__(self, game: Game, flow: Navigator) -> None:
        super().__init__()
        self.game = game
        self.flow = flow
        self.spin = 0.0
        self.build()

    def build(self) -> None:
        game, theme = self.game, self.game.theme
        self.ui.clear()
        self.background_color = theme.rgba("background")
        self.title = title("PolyGolf", theme, 48)
        self.subtitle = arcade.Text("mini golf with a polygon for a ball", 0, 0, theme.rgba("text"), 14,
                                    anchor_x="center", anchor_y="center", italic=True)
        self.shape_caption = arcade.Text(game.shape_label, 0, 0, theme.rgba("text"), 18, anchor_x="center",
                                         anchor_y="center")
        # Ten rows fit under the title at 720 px; eleven (New seed) with a little less space between.
        column = UIBoxLayout(vertical=True, space_between=4 if game.random_chosen else 6)
        self.buttons = {}
        seed = [("seed", "New seed", self.on_new_seed)] if game.random_chosen else []
        settings = UIBoxLayout(vertical=False, space_between=6)  # one row: small settings, side by side
        for key, text, action in (
            ("volume", f"Sound: {self.volume_label}", self.on_volume),
            ("hint", f"Hint: {game.hint}", self.on_hint),
            ("preview", f"Preview: {'on' if game.preview else 'off'}", self.on_preview),
        ):
            button = themed_button(theme, text, width=102, height=42, font_size=12, clicks=self.game.sound)
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
            ("names", "Names: " + ", ".join(game.players), self.on_names),
            ("settings", None, None),
            ("guide", "How to play", self.on_guide),
            ("quit", "Quit", self.on_quit),
        ):
            if text is None:
                column.add(settings)
                continue
            # A long label (a long seed given on the command line) gets a smaller font rather than spilling over.
            button = themed_button(theme, text, height=42, font_size=min(16, 16 * 25 // len(text)),
                                   clicks=self.game.sound)
            button.on_click = action  # type: ignore[method-assign]
            column.add(button)
            self.buttons[key] = button
        anchor = UIAnchorLayout()
        anchor.add(column, anchor_x="center_x", anchor_y="center_y", align_x=-180, align_y=-40)
        self.ui.add(anchor)
        self.ball_art = PolygonArt(ball_outline(game.shape, 1.0), theme, scale=1.0)
        self.preview = arcade.Camera2D()
        # Content that could not be read is left out of the game and said here, not crashed on.
        shown = game.problems[:4] + ([f"... and {len(game.problems) - 4} more"] if len(game.problems) > 4 else [])
        self.problems = arcade.Text("\n".join(shown), 0, 0, theme.rgba("arrow_strong"), 11, anchor_x="center",
                                    anchor_y="bottom", multiline=True, width=1200, align="center")

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
        self.game.sound.next_volume()
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
            return
        if symbol in (arcade.key.ENTER, arcade.key.RETURN, arcade.key.SPACE):
            self.on_play()
        elif symbol == arcade.key.ESCAPE:
            self.on_quit()

    def on_update(self, delta_time: float) -> None:
        self.spin += 0.6 * delta_time

    def on_draw_before_ui(self) -> None:
        w, h = self.window.width, self.window.height
        self.title.position = (w / 2, h - 70)
        self.subtitle.position = (w / 2, h - 115)
        self.title.draw()
        self.subtitle.draw()
        # The chosen polygon, large, to the right of the buttons.
        cx, cy = w / 2 + 230, h / 2 - 40
        radius = min(110.0, h / 5)
        with self._scaled(cx, cy, radius):
            self.ball_art.draw(0.0, 0.0, self.spin)
        self.shape_caption.position = (cx, cy - radius - 30)
        self.shape_caption.draw()
        if self.game.problems:
            self.problems.position = (w / 2, 12)
            self.problems.draw()

    def _scaled(self, cx: float, cy: float, radius: float):
        """A camera that shows the unit-radius ball `radius` pixels big, centred at (cx, cy)."""
        w, h = self.window.width, self.window.height
        self.preview.match_window()
        self.preview.zoom = radius
        self.preview.position = (-(cx - w / 2) / radius, -(cy - h / 2) / radius)
        return self.preview.activate()
