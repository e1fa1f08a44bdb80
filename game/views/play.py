"""The play screen: the hole in the theme's colours, the HUD, and the shot arrow.

Press on the ball and drag: the arrow shows direction and power, where you grabbed the ball sets the
spin, release shoots, Esc cancels. R restarts the hole (back to the tee, a penalty stroke); L watches
the last shot again; Esc (not aiming) pauses. F3 shows what each system costs a frame; 1, 2, 3 switch
the preset (fast, balanced, accurate) live. The round's rules (turns, scores, recording) are the
session's (`session.RoundPlay`); this screen turns the mouse into its shots and draws it.
"""

from __future__ import annotations

import math

import arcade

from polygolf.engine.golf.layout import ball_fits
from polygolf.engine.golf.play import HolePlay
from polygolf.game.drawing import HUD_HEIGHT, HoleArt, PlayerBallArt, draw_arrow, draw_turn_ring, fit_camera
from polygolf.game.session import Game, Round, RoundPlay, penalty_text, strokes_text
from polygolf.game.views.navigation import Navigator

GRAB_SLACK = 1.25  # a press this many ball radii from the centre still grabs the ball
FINISH_PAUSE = 1.0  # seconds between the ball dropping and the next screen
PRESET_KEYS = {arcade.key.KEY_1: "fast", arcade.key.KEY_2: "balanced", arcade.key.KEY_3: "accurate"}
OVERLAY_LINES = 18
SMOOTHING = 0.1  # weight of the newest frame in the overlay's running averages


class PlayView(arcade.View):
    def __init__(self, game: Game, round_: Round, flow: Navigator) -> None:
        super().__init__()
        self.game = game
        self.round = round_
        self.flow = flow
        self.camera = arcade.Camera2D()
        theme = game.theme
        self.background_color = theme.rgba("background")
        self.hud_texts = {
            "course": arcade.Text("", 16, 0, theme.rgba("text"), 15, anchor_y="center", bold=True),
            "hole": arcade.Text("", 0, 0, theme.rgba("text"), 15, anchor_x="center", anchor_y="center"),
            "strokes": arcade.Text("", 0, 0, theme.rgba("text"), 15, anchor_x="right", anchor_y="center"),
            "players": arcade.Text("", 0, 0, theme.rgba("text"), 13, anchor_x="right", anchor_y="center"),
        }
        self.banner = arcade.Text("", 0, 0, theme.rgba("text"), 13, anchor_x="center", anchor_y="center",
                                  multiline=True, width=900, align="center")
        self.banner_time = 0.0
        self.overlay = False
        self.overlay_texts = [arcade.Text("", 0, 0, theme.rgba("text"), 12, font_name=("DejaVu Sans Mono", "monospace"))
                              for _ in range(OVERLAY_LINES)]
        self.system_us: dict[str, float] = {}
        self.world: HolePlay | None = None
        self.session = self.session_for(game, round_)
        self.start_hole()

    @staticmethod
    def session_for(game: Game, round_: Round) -> RoundPlay:
        """The game's session of this round (made by `Game.start_round`), or a new one."""
        if game.session is not None and game.session.round is round_:
            return game.session
        game.close_session()
        game.session = RoundPlay(round_, game.shape, game.shape_label, game.preset)
        return game.session

    # -- hole lifecycle ---------------------------------------------------------------------------

    def start_hole(self) -> None:
        session = self.session
        self.world = session.hole if session.hole is not None and not session.hole_over else session.start_hole()
        if self.world is None:
            return
        self.hole_art = HoleArt(self.world.layout, self.game.theme)
        self.ball_arts = [PlayerBallArt(self.world.outline, self.game.theme, seat)
                          for seat in range(len(self.world.players))]
        self.aiming = False
        self.grab = self.tip = (0.0, 0.0)
        self.finished_for = 0.0
        self.finish_text: arcade.Text | None = None
        if self.round.skipped:
            self.show_banner("\n".join(self.round.skipped[-2:]))
        self.fit()
        self.update_hud()

    def restart_hole(self) -> None:
        """R, or Restart hole: the ball whose turn it is goes back to the tee; the strokes taken stay
        and a penalty stroke is added (no free retakes)."""
        if self.session.restart():
            self.aiming = False
            who = self.turn_prefix()
            self.show_banner(f"{who}{'b' if who else 'B'}ack to the tee: +1 penalty stroke", 2.5)

    def reload_hole(self) -> None:
        """The hole's file changed (`--watch`): build it again, the ball where it was if it still fits."""
        where = (self.world.ball.x, self.world.ball.y) if self.world is not None else None
        self.session.restart_hole()
        self.start_hole()
        if self.world is not None and where is not None and ball_fits(self.world.layout, *where,
                                                                      self.world.collider.radius):
            self.world.place_ball(*where)
        self.show_banner("Reloaded", 1.5)

    def show_banner(self, text: str, seconds: float = 6.0) -> None:
        self.banner.text = text
        self.banner_time = seconds

    # -- layout -----------------------------------------------------------------------------------

    def fit(self) -> None:
        if self.world is None:
            return
        fit_camera(self.camera, self.world.layout.bounds, self.window.width, self.window.height)
        top = self.window.height - HUD_HEIGHT / 2
        self.hud_texts["course"].position = (16, top)
        self.hud_texts["hole"].position = (self.window.width / 2, top)
        self.hud_texts["strokes"].position = (self.window.width - 16, top)
        self.hud_texts["players"].position = (self.window.width - 16, self.window.height - HUD_HEIGHT - 14)
        self.banner.position = (self.window.width / 2, self.window.height - HUD_HEIGHT - 40)

    def on_resize(self, width: int, height: int) -> None:
        self.fit()

    def on_show_view(self) -> None:
        self.fit()

    def update_hud(self) -> None:
        if self.world is None:
            return
        spec, state = self.world.hole.spec, self.world.state
        self.hud_texts["course"].text = self.round.course.name
        self.hud_texts["hole"].text = (f"Hole {self.round.number} of {self.round.hole_count}: {spec.name}"
                                       f"  ·  Par {spec.par}")
        extra = f" {penalty_text(state.penalties)}" if state.penalties else ""
        self.hud_texts["strokes"].text = f"{self.turn_prefix()}{strokes_text(state.score)}{extra}"
        self.hud_texts["players"].text = self.scoreboard()

    def scoreboard(self) -> str:
        """Everyone's strokes on this hole, under the HUD when several play: 'Ann 2 · Bob 3 (in)'."""
        if self.world is None or len(self.world.players) < 2:
            return ""
        return "  ·  ".join(f"{name} {p.state.score}{' (in)' if p.state.holed else ''}"
                            f"{' (picked up)' if p.state.picked_up else ''}"
                            for name, p in zip(self.session.players, self.world.players))

    def turn_prefix(self) -> str:
        """'Ann: ' when several play (whose turn the HUD is about), '' alone."""
        return f"{self.session.player_name}: " if len(self.session.players) > 1 else ""

    # -- input ------------------------------------------------------------------------------------

    def to_world(self, x: float, y: float) -> tuple[float, float]:
        point = self.camera.unproject((x, y))
        return point[0], point[1]

    def on_mouse_press(self, x: int, y: int, button: int, modifiers: int) -> None:
        world = self.world
        if world is None or button != arcade.MOUSE_BUTTON_LEFT or not self.session.can_shoot:
            return
        wx, wy = self.to_world(x, y)
        if math.hypot(wx - world.ball.x, wy - world.ball.y) <= GRAB_SLACK * world.collider.radius:
            self.aiming = True
            self.grab = self.tip = (wx, wy)

    def on_mouse_drag(self, x: int, y: int, dx: int, dy: int, buttons: int, modifiers: int) -> None:
        if self.aiming:
            self.tip = self.to_world(x, y)

    def on_mouse_release(self, x: int, y: int, button: int, modifiers: int) -> None:
        if not self.aiming or button != arcade.MOUSE_BUTTON_LEFT:
            return
        self.aiming = False
        self.tip = self.to_world(x, y)
        self.session.shoot(self.grab, (self.tip[0] - self.grab[0], self.tip[1] - self.grab[1]))

    def on_key_press(self, symbol: int, modifiers: int) -> None:
        if symbol == arcade.key.ESCAPE:
            if self.aiming:
                self.aiming = False
            else:
                self.flow.pause(self)
        elif symbol == arcade.key.R:
            self.restart_hole()
        elif symbol == arcade.key.L:
            self.watch_last_shot()
        elif symbol == arcade.key.F3:
            self.overlay = not self.overlay
            self.system_us.clear()
        elif symbol in PRESET_KEYS:
            self.set_preset(PRESET_KEYS[symbol])

    def set_preset(self, name: str) -> None:
        """Switch the accuracy preset live; the next holes keep it."""
        self.game.preset = name
        if self.world is not None:
            self.session.set_preset(name)
        self.system_us.clear()
        self.show_banner(f"Preset: {name}", 2.0)

    # -- frame ------------------------------------------------------------------------------------

    def on_update(self, delta_time: float) -> None:
        world = self.world
        if world is None:
            return
        if self.overlay:
            self.step_profiled(world)
        else:
            self.session.step()
        self.banner_time = max(0.0, self.banner_time - delta_time)
        self.update_hud()
        if self.session.hole_over:
            self.finished_for += delta_time
            if self.finished_for >= FINISH_PAUSE:
                self.finish_hole()

    def step_profiled(self, world: HolePlay) -> None:
        """One frame with every system timed; keeps running averages in µs per frame."""
        before = world.system_seconds()
        self.session.step(profile=True)
        for name, total in world.system_seconds().items():
            spent = (total - before.get(name, 0.0)) * 1e6
            old = self.system_us.get(name)
            self.system_us[name] = spent if old is None else old + SMOOTHING * (spent - old)

    def overlay_lines(self) -> list[str]:
        world = self.world
        knobs = world.knobs
        names = world.system_names
        total = sum(self.system_us.get(n, 0.0) for n in names)
        lines = [f"preset {world.preset_name}: {knobs.substeps} substeps x {knobs.iterations} iterations, "
                 f"{knobs.position_correction}, ccd {'on' if knobs.ccd else 'off'}",
                 f"physics {total:7.0f} us per frame   contacts {world.contact_count}",
                 ""]
        lines += [f"  {name:<12}{self.system_us.get(name, 0.0):7.0f} us" for name in names]
        lines += ["", "F3 hide   1 fast   2 balanced   3 accurate"]
        return lines[:OVERLAY_LINES]

    def draw_overlay(self) -> None:
        lines = self.overlay_lines()
        top = self.window.height - HUD_HEIGHT - 12
        width = 600
        arcade.draw_lrbt_rectangle_filled(8, 8 + width, top - 18 * len(lines) - 8, top + 4,
                                          self.game.theme.rgba("panel"))
        for text, line, i in zip(self.overlay_texts, lines, range(len(lines))):
            text.text = line
            text.position = (16, top - 14 - 18 * i)
            text.draw()

    def finish_hole(self) -> None:
        results = self.session.finish_hole()
        self.world = None
        self.flow.hole_done(results)

    def watch_last_shot(self) -> None:
        """L: the hole simulated again from its start to the last shot, and that shot shown."""
        if self.session.last_shot() is not None and not self.aiming:
            self.flow.watch_last_shot(self)

    def close(self) -> None:
        """Let go of the hole's world (leaving the hole, or the game)."""
        self.session.close()
        self.world = None

    def on_draw(self) -> None:
        self.clear()
        world = self.world
        if world is None:
            return
        with self.camera.activate():
            self.hole_art.draw([b.lit > 0 for b in world.bumpers], [(w.x, w.y, w.angle) for w in world.windmills],
                               self.game.theme)
            self.draw_balls(world)
            if self.aiming:
                draw_arrow(self.grab, self.tip, self.game.theme)
        self.window.default_camera.use()
        w, h = self.window.width, self.window.height
        arcade.draw_lrbt_rectangle_filled(0, w, h - HUD_HEIGHT, h, self.game.theme.rgba("panel"))
        for text in self.hud_texts.values():
            text.draw()
        if self.banner_time > 0:
            self.banner.draw()
        if self.overlay:
            self.draw_overlay()
        if self.session.hole_over:
            self.draw_finish_message(w, h)

    def draw_balls(self, world: HolePlay) -> None:
        """Every ball still in play (a finished one has left the green; the last one drops visibly),
        with a ring around the ball whose turn it is when several play."""
        for seat, player in enumerate(world.players):
            if player.state.finished and not (self.session.hole_over and self.finished_for <= 0.3
                                              and player.state.holed and seat == world.turn):
                continue
            body = player.body
            self.ball_arts[seat].draw(body.x, body.y, body.angle)
        if len(world.players) > 1 and self.session.can_shoot:
            draw_turn_ring(world.ball.x, world.ball.y, world.collider.radius, self.ball_arts[world.turn].colour)

    def draw_finish_message(self, w: int, h: int) -> None:
        if self.finish_text is None:
            words = "Picked up" if self.world.state.picked_up else "In the cup!"
            if len(self.world.players) > 1:
                words = "Hole over"
            self.finish_text = arcade.Text(words, w / 2, (h - HUD_HEIGHT) / 2, self.game.theme.rgba("text"), 36,
                                           anchor_x="center", anchor_y="center", bold=True)
        self.finish_text.draw()
