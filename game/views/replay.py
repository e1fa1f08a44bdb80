"""Watching: a round (or the last shot of a hole) simulated again from recorded inputs and drawn as it
happens. The session (`session.RoundPlay` fed with the inputs) does the simulating; this screen only
paces and draws it. Esc or Enter stops watching; F plays four times as fast."""

from __future__ import annotations

from collections.abc import Callable

import arcade

from polygolf.game.drawing import HUD_HEIGHT, HoleArt, PlayerBallArt, fit_camera
from polygolf.game.session import Game, RoundPlay, strokes_text

END_PAUSE = 1.0  # s the last picture stays before the next hole or the end
OVERRUN = 60 * 30  # frames past a hole's last recorded input before the replay is called out of step


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
        self.done_for = 0.0
        self.ended = False
        self.camera = arcade.Camera2D()
        theme = game.theme
        self.background_color = theme.rgba("background")
        self.hud = arcade.Text("", 16, 0, theme.rgba("text"), 15, anchor_y="center", bold=True)
        self.hint = arcade.Text("Esc: back   F: faster", 0, 0, theme.rgba("text"), 13, anchor_x="right",
                                anchor_y="center")
        self.message = arcade.Text("", 0, 0, theme.rgba("text"), 30, anchor_x="center", anchor_y="center", bold=True)
        session.step(max(0, from_frame - session.frame))
        self.show_hole()

    def show_hole(self) -> None:
        hole = self.session.hole
        if hole is None:
            return
        self.hole_art = HoleArt(hole.layout, self.game.theme)
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
            session.step(4 if self.fast else 1)
            if self.last_frame is None and session.frame > self.last_input_frame() + OVERRUN:
                self.message.text = "This replay is out of step with the game"
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

    def on_draw(self) -> None:
        self.clear()
        session, hole = self.session, self.session.hole
        w, h = self.window.width, self.window.height
        if hole is not None:
            with self.camera.activate():
                self.hole_art.draw([b.lit > 0 for b in hole.bumpers], [(m.x, m.y, m.angle) for m in hole.windmills],
                                   self.game.theme)
                for seat, player in enumerate(hole.players):
                    if not player.state.finished:
                        self.ball_arts[seat].draw(player.body.x, player.body.y, player.body.angle)
            self.window.default_camera.use()
            scores = " · ".join(f"{name}: {strokes_text(p.state.score)}"
                                for name, p in zip(session.players, hole.players))
            self.hud.text = (f"{self.title} · hole {session.round.number}: {hole.hole.spec.name} · {scores}"
                             + ("   (x4)" if self.fast else ""))
        arcade.draw_lrbt_rectangle_filled(0, w, h - HUD_HEIGHT, h, self.game.theme.rgba("panel"))
        self.hud.position = (16, h - HUD_HEIGHT / 2)
        self.hud.draw()
        self.hint.position = (w - 16, h - HUD_HEIGHT / 2)
        self.hint.draw()
        if self.message.text:
            self.message.position = (w / 2, (h - HUD_HEIGHT) / 2)
            self.message.draw()
