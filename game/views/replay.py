"""Watching: a round (or the last shot of a hole) simulated again from recorded inputs and drawn as it
happens. The session (`session.RoundPlay` fed with the inputs) does the simulating; this screen only
paces and draws it. Esc or Enter stops watching; F plays four times as fast; F11 and M as everywhere.

The HUD bar says what is shown and where, fitted between the window's left and the keys' hint; when
several play, their scores are a line of their own under it, as in the play view."""

from __future__ import annotations

from collections.abc import Callable

import arcade

from polygolf.game.drawing import HUD_HEIGHT, HoleArt, PlayerBallArt, fit_camera, fit_width
from polygolf.game.session import Game, RoundPlay, strokes_text
from polygolf.game.timing import FixedStep
from polygolf.game.views.navigation import window_key

END_PAUSE = 1.0  # s the last picture stays before the next hole or the end
OVERRUN = 60 * 30  # frames past a hole's last recorded input before the replay is called out of step
HUD_FONT, HUD_SMALLEST, HUD_MARGIN = 15, 10, 16  # as the play view's HUD


class ReplayView(arcade.View):
    def __init__(self, game: Game, session: RoundPlay, then: Callable[[], None], title: str,
                 from_frame: int = 0, last_frame: int | None = None) -> None:
        """Show `session` (fed with recorded inputs) from frame `from_frame` of its first hole (the
        frames before are simulated unseen); `last_frame`: stop once everything rests after it (one
        shot watched again), else play every hole of the round."""
        super().__init__()
        self.game = game
        self.session = session
        self.then = then
        self.title = title
        self.last_frame = last_frame
        self.fast = False
        self.clock = FixedStep()  # game time as played, at any frame rate (as the play view's)
        self.done_for = 0.0
        self.ended = False
        self.camera = arcade.Camera2D()
        theme = game.theme
        self.background_color = theme.rgba("background")
        self.hud = arcade.Text("", 16, 0, theme.rgba("text"), HUD_FONT, anchor_y="center", bold=True)
        self.scores = arcade.Text("", 0, 0, theme.rgba("text"), 13, anchor_x="right", anchor_y="center")
        self._fitted_for: tuple = ()  # the HUD's lines, the message and the window they were fitted for
        self.message_text = ""
        self.hint = arcade.Text("Esc: back   F: faster", 0, 0, theme.rgba("text"), 13, anchor_x="right",
                                anchor_y="center")
        self.message = arcade.Text("", 0, 0, theme.rgba("text"), 30, anchor_x="center", anchor_y="center", bold=True)
        session.step(max(0, from_frame - session.frame))
        if session.hole is not None:
            session.hole.drain_events()  # (what happened before the part shown is not heard)
        self.show_hole()

    def show_hole(self) -> None:
        hole = self.session.hole
        if hole is None:
            return
        self.hole_art = HoleArt(hole.layout, self.game.theme, hole.collider.radius, [p.tee for p in hole.players])
        self.ball_arts = [PlayerBallArt(hole.outline, self.game.theme, seat) for seat in range(len(hole.players))]
        self.done_for = 0.0
        self.fit()

    def fit(self) -> None:
        if self.session.hole is not None:
            fit_camera(self.camera, self.session.hole.layout.bounds, self.window.width, self.window.height)

    def on_resize(self, width: int, height: int) -> None:
        self.fit()

    def on_show_view(self) -> None:
        self.fit()

    def on_key_press(self, symbol: int, modifiers: int) -> None:
        if window_key(self.window, self.game, symbol):
            return
        if symbol in (arcade.key.ESCAPE, arcade.key.ENTER, arcade.key.RETURN, arcade.key.L):
            self.finish()
        elif symbol == arcade.key.F:
            self.fast = not self.fast

    def finish(self) -> None:
        if not self.ended:
            self.ended = True
            self.session.close()
            self.then()

    # -- pacing -----------------------------------------------------------------------------------

    def at_end(self) -> bool:
        """This hole's part is over: the watched shot has settled, or the hole is finished."""
        session, hole = self.session, self.session.hole
        if self.last_frame is not None:
            return session.frame > self.last_frame and hole.all_at_rest
        return session.hole_over

    def on_update(self, delta_time: float) -> None:
        session = self.session
        if session.hole is None or self.ended:
            return
        if not self.at_end():
            for _ in range(self.clock.advance(delta_time) * (4 if self.fast else 1)):
                session.step(1)
                if self.at_end():
                    break
            self.game.sound.hear(*session.hole.drain_events(), delta_time)  # it sounds as it did when played
            if self.last_frame is None and session.frame > self.last_input_frame() + OVERRUN:
                self.message_text = "This replay is out of step with the game"
                self.last_frame = session.frame  # stop here
            return
        self.done_for += delta_time
        if self.done_for < END_PAUSE:
            return
        if self.last_frame is not None:
            self.finish()
            return
        session.finish_hole()
        if session.start_hole() is None:
            self.finish()
        else:
            self.show_hole()

    def last_input_frame(self) -> int:
        _, inputs = (self.session.feed or {}).get(self.session.round.position, ("", []))
        return inputs[-1].frame if inputs else 0

    # -- drawing ----------------------------------------------------------------------------------

    def hud_lines(self) -> tuple[str, str]:
        """What is shown ('Ann's last shot · hole 2: Dog-leg'), with the score when one plays; and
        when several play, everyone's score for a line of its own ('Ann: 2 strokes · Bob: 1 stroke')."""
        session, hole = self.session, self.session.hole
        what = f"{self.title} · hole {session.round.number}: {hole.hole.spec.name}"
        scores = " · ".join(f"{name}: {strokes_text(p.state.score)}" for name, p in zip(session.players, hole.players))
        fast = "   (x4)" if self.fast else ""
        return (f"{what} · {scores}{fast}", "") if len(hole.players) == 1 else (f"{what}{fast}", scores)

    def place_hud(self, w: int, h: int) -> None:
        """The HUD's line fitted left of the keys' hint, the scores' line under the bar and the
        message fitted to the window (again only when a line or the window changed)."""
        line, scores = self.hud_lines()
        if (line, scores, self.message_text, w, h) == self._fitted_for:
            return
        self._fitted_for = (line, scores, self.message_text, w, h)
        fit_width(self.message, self.message_text, w - 2 * HUD_MARGIN, 30, 14)
        self.message.position = (w / 2, (h - HUD_HEIGHT) / 2)
        fit_width(self.hud, line, w - self.hint.content_width - 3 * HUD_MARGIN, HUD_FONT, HUD_SMALLEST)
        self.hud.position = (HUD_MARGIN, h - HUD_HEIGHT / 2)
        fit_width(self.scores, scores, w - 2 * HUD_MARGIN, 13, HUD_SMALLEST)
        self.scores.position = (w - HUD_MARGIN, h - HUD_HEIGHT - 14)

    def on_draw(self) -> None:
        self.clear()
        hole = self.session.hole
        w, h = self.window.width, self.window.height
        if hole is not None:
            with self.camera.activate():
                self.hole_art.draw([b.lit > 0 for b in hole.bumpers], [(m.x, m.y, m.angle) for m in hole.windmills],
                                   self.game.theme)
                for seat, player in enumerate(hole.players):
                    if not player.state.finished:
                        self.ball_arts[seat].draw(player.body.x, player.body.y, player.body.angle, shadow=True)
                self.hole_art.draw_flag()
            self.window.default_camera.use()
            self.place_hud(w, h)
        arcade.draw_lrbt_rectangle_filled(0, w, h - HUD_HEIGHT, h, self.game.theme.rgba("panel"))
        self.hud.draw()
        self.hint.position = (w - HUD_MARGIN, h - HUD_HEIGHT / 2)
        self.hint.draw()
        self.scores.draw()
        if self.message_text:
            self.message.draw()
