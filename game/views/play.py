"""The play screen: the hole in the theme's colours, the HUD, and the shot arrow.

Press on the ball and drag: the arrow shows direction and power, where you grabbed the ball sets the
spin, release shoots, Esc cancels; while you drag, a dotted line shows where the ball goes up to its
first bounce (P switches it). H asks the search golfer for a hint (the Hint setting shows one every
turn); a player named CPU is the computer, whose arrow is shown being drawn before it shoots (the
golfer and the preview are `game.caddie`'s). R restarts the hole (back to the tee, a penalty stroke);
L watches the last shot again; Esc (not aiming) pauses. The mouse wheel
zooms about the pointer, a right-drag or the arrow keys pan, 0 fits the hole again. F3 shows the frame
rate and what each system costs a frame, in a panel the hole is fitted beside; 1, 2, 3 switch the
preset (fast, balanced, accurate) live. F11 (fullscreen) and M (mute) work on every screen.

Time: the physics steps whole 1/60 s frames from a fixed-timestep accumulator (`game.timing`), so the
ball rolls at real speed at any frame rate; the ball and windmills are drawn between their last two
poses. Sound and the drop/splash animations follow the events the hole reports (`HolePlay.drain_events`).
The round's rules (turns, scores, recording) are the session's (`session.RoundPlay`); this screen
turns the mouse into its shots and draws it.
"""

from __future__ import annotations

import math
import time
from collections import deque

import arcade

from polygolf.engine.golf.layout import ball_fits
from polygolf.engine.golf.play import HolePlay
from polygolf.game.caddie import Caddie, ShotPreview
from polygolf.game.drawing import (
    HUD_HEIGHT,
    HoleArt,
    PlayerBallArt,
    cut_middle,
    dotted_path,
    draw_arrow,
    draw_backed,
    draw_trail,
    draw_turn_ring,
    fit_camera,
    fit_width,
    shade,
)
from polygolf.game.session import Game, Round, RoundPlay, penalty_text, strokes_text
from polygolf.game.timing import FixedStep, Pose, Poses
from polygolf.game.views.navigation import Navigator, window_key

GRAB_SLACK = 1.25  # a press this many ball radii from the centre still grabs the ball
GRAB_PIXELS = 18  # ... or this many pixels, when the ball is drawn small
FINISH_PAUSE = 1.0  # seconds between the ball dropping and the next screen
PRESET_KEYS = {arcade.key.KEY_1: "fast", arcade.key.KEY_2: "balanced", arcade.key.KEY_3: "accurate"}
OVERLAY_LINES = 24
OVERLAY_WIDTH = 360  # pixels: the F3 panel on the left; the hole is fitted beside it
OVERLAY_FONT, OVERLAY_STEP, OVERLAY_PAD = 11, 17, 10  # its largest font size, line spacing and margins (px)
SMOOTHING = 0.1  # weight of the newest frame in the overlay's running averages
DROP_SECONDS = 0.35  # the ball slides from where it was to the cup's centre, shrinking
LIP_WOBBLE = 0.07  # metres the drawn ball dips toward a cup it rolls over
SPLASH_SECONDS = 0.6
TRAIL_FRAMES = 14  # physics frames of path drawn behind a moving ball
ZOOM_RANGE = (1.0, 6.0)  # times the fitted zoom
ZOOM_STEP = 1.15  # per wheel notch
PAN_KEYS = {arcade.key.LEFT: (-1, 0), arcade.key.RIGHT: (1, 0), arcade.key.UP: (0, 1), arcade.key.DOWN: (0, -1)}
PAN_STEP = 0.15  # of the visible width per arrow-key press
HUD_READABLE = 12  # the hole's line shrinks to this at the least before its name is cut short
HUD_FONT, HUD_SMALLEST, HUD_MARGIN = 15, 10, 16  # the HUD line's font size, the smallest it shrinks to, and its gaps
HINT_ALPHA = 120  # the aim hint: the arrow drawn this faintly


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
        self._hud_lines = {name: "" for name in self.hud_texts}  # as laid out (`place_hud`)
        self._hole_name = ""  # the hole's name in its HUD line: what is cut short when the line is too long
        self._hud_laid_for: tuple[int, bool] = (0, False)  # window width, and whether the F3 panel showed
        self.hint_label = arcade.Text("", 0, 0, theme.rgba("text"), 11, anchor_x="center", anchor_y="center")
        self.overlay = False
        self.overlay_texts = [arcade.Text("", 0, 0, theme.rgba("text"), OVERLAY_FONT, anchor_y="center",
                                          font_name=("DejaVu Sans Mono", "monospace")) for _ in range(OVERLAY_LINES)]
        self._overlay_fitted_for: tuple[int, int] = (0, 0)  # (longest line's characters, window height)
        self.system_us: dict[str, float] = {}
        self.frame_seconds: deque[float] = deque(maxlen=120)  # real time between updates, for F3
        self.draw_ms = 0.0
        self.clock = FixedStep()  # game time runs on across restarts and reloads
        self.world: HolePlay | None = None
        self.session = self.session_for(game, round_)
        self.caddie = Caddie(self.session, game.golfers, game.hint, game.computer_skill)
        self.preview = ShotPreview()
        self.preview_art = None  # the preview's dots, built when its path changes
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
        theme = self.game.theme
        self.hole_art = HoleArt(self.world.layout, theme, self.world.collider.radius,
                                [p.tee for p in self.world.players])
        self.ball_arts = [PlayerBallArt(self.world.outline, theme, seat) for seat in range(len(self.world.players))]
        self.seat_of = {p.entity: seat for seat, p in enumerate(self.world.players)}
        self.ball_poses = [Poses(self.ball_pose(seat)) for seat in range(len(self.world.players))]
        self.windmill_poses = [Poses((w.x, w.y, w.angle)) for w in self.world.windmills]
        self.trail: deque[tuple[float, float]] = deque(maxlen=TRAIL_FRAMES)
        self.drop_from: Pose | None = None  # where the ball was when it dropped
        self.drop_seat = -1  # whose ball it was
        self.drop_time = 0.0
        self.over_cup_time = 0.0
        self.splashes: list[list[float]] = []  # [x, y, age]
        self.aiming = False
        self.grab = self.tip = (0.0, 0.0)
        self.finished_for = 0.0
        self.finish_text: arcade.Text | None = None
        self.zoom = 1.0
        self.pan = (0.0, 0.0)
        self.world.drain_events()
        if self.round.skipped:
            self.show_banner("\n".join(self.round.skipped[-2:]))
        self.fit()
        self.update_hud()

    def restart_hole(self) -> None:
        """R, or Restart hole: the ball whose turn it is goes back to the tee; the strokes taken stay
        and a penalty stroke is added (no free retakes)."""
        if self.session.computer_turn:
            self.show_banner("The computer's ball is the computer's to restart", 2.0)
            return
        if self.session.restart():
            self.aiming = False
            seat = self.world.turn
            self.ball_poses[seat] = Poses(self.ball_pose(seat))
            self.trail.clear()
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
            self.ball_poses[self.world.turn] = Poses(self.ball_pose(self.world.turn))
        self.show_banner("Reloaded", 1.5)

    def show_banner(self, text: str, seconds: float = 6.0) -> None:
        self.banner.text = text
        self.banner_time = seconds

    def ball_pose(self, seat: int) -> Pose:
        ball = self.world.players[seat].body
        return ball.x, ball.y, ball.angle

    # -- layout -----------------------------------------------------------------------------------

    def fit(self) -> None:
        """The camera: the hole fitted below the HUD (beside the F3 panel when it shows), then the
        player's zoom and pan."""
        if self.world is None:
            return
        fit_camera(self.camera, self.world.layout.bounds, self.window.width, self.window.height,
                   left=OVERLAY_WIDTH if self.overlay else 0, zoom=self.zoom, pan=self.pan)
        top = self.window.height - HUD_HEIGHT / 2
        self.hud_texts["course"].position = (16, top)
        self.hud_texts["hole"].position = (self.hud_texts["hole"].x, top)
        self.hud_texts["strokes"].position = (self.window.width - 16, top)
        self.hud_texts["players"].position = (self.window.width - 16, self.window.height - HUD_HEIGHT - 14)
        self.banner.position = (self.window.width / 2, self.window.height - HUD_HEIGHT - 40)
        self.place_hud()

    def zoom_at(self, x: float, y: float, factor: float) -> None:
        """Zoom by `factor` keeping the world point under the pointer (x, y) where it is."""
        before = self.to_world(x, y)
        self.zoom = min(ZOOM_RANGE[1], max(ZOOM_RANGE[0], self.zoom * factor))
        if self.zoom == ZOOM_RANGE[0]:
            self.pan = (0.0, 0.0)  # fully out: the whole hole, centred
        self.fit()
        after = self.to_world(x, y)
        self.pan_by(before[0] - after[0], before[1] - after[1])

    def pan_by(self, dx: float, dy: float) -> None:
        """Move the view by (dx, dy) metres, keeping some of the hole in sight."""
        x0, y0, x1, y1 = self.world.layout.bounds
        self.pan = (min((x1 - x0) / 2, max(-(x1 - x0) / 2, self.pan[0] + dx)),
                    min((y1 - y0) / 2, max(-(y1 - y0) / 2, self.pan[1] + dy)))
        self.fit()

    def on_resize(self, width: int, height: int) -> None:
        self.fit()

    def on_show_view(self) -> None:
        self.fit()

    def update_hud(self) -> None:
        if self.world is None:
            return
        spec, state = self.world.hole.spec, self.world.state
        self._hole_name = spec.name
        extra = f" {penalty_text(state.penalties)}" if state.penalties else ""
        muted = "   [muted]" if self.game.sound.muted else ""
        thinking = "  ·  thinking…" if self.caddie.thinking else ""
        self.place_hud({"course": self.round.course.name,
                        "hole": f"Hole {self.round.number} of {self.round.hole_count}: {spec.name}  ·  Par {spec.par}",
                        "strokes": f"{self.turn_prefix()}{strokes_text(state.score)}{extra}{thinking}{muted}",
                        "players": self.scoreboard()})

    def place_hud(self, lines: dict[str, str] | None = None) -> None:
        """The HUD's lines laid out in the window's width (again only when a line or the width
        changed): the course at the left, the strokes at the right and the hole between them, centred
        where there is room; all three smaller when they do not fit, the hole's name cut short last.
        The players' line under the bar keeps right of the F3 panel when it shows."""
        lines = lines or self._hud_lines
        w = self.window.width
        if lines == self._hud_lines and (w, self.overlay) == self._hud_laid_for:
            return
        self._hud_lines, self._hud_laid_for = lines, (w, self.overlay)
        texts = self.hud_texts
        for name in ("course", "hole", "strokes"):
            texts[name].text, texts[name].font_size = lines[name], HUD_FONT
        # The hole's line counts for at most half the bar: a long name (100 wide characters is a valid
        # one) is cut short with an ellipsis, not the whole bar shrunk to fit it (QA8: 8 px text).
        widths = sum(texts[name].content_width for name in ("course", "strokes"))
        widths += min(texts["hole"].content_width, w / 2)
        if widths + 4 * HUD_MARGIN > w:
            size = max(HUD_SMALLEST, HUD_FONT * (w - 4 * HUD_MARGIN) / max(widths, 1.0))
            for name in ("course", "hole", "strokes"):
                texts[name].font_size = size
        left = HUD_MARGIN + texts["course"].content_width + HUD_MARGIN
        right = w - HUD_MARGIN - texts["strokes"].content_width - HUD_MARGIN
        fit_hole_line(texts["hole"], lines["hole"], self._hole_name, max(right - left, 20.0),
                      texts["hole"].font_size, min(texts["hole"].font_size, HUD_READABLE))
        half = texts["hole"].content_width / 2
        centre = w / 2 if left <= w / 2 - half and w / 2 + half <= right else (left + right) / 2
        texts["hole"].x = centre
        panel = OVERLAY_WIDTH if self.overlay else 0
        room = w - panel - 2 * HUD_MARGIN
        fit_width(texts["players"], lines["players"], room, 13, HUD_SMALLEST)
        players = texts["players"]
        if players.text != lines["players"]:  # cut short, it lost its last players' scores: cut each name
            for keep in range(max(len(name) for name in self.session.players) - 1, 0, -1):  # (as little as fits)
                players.text = self.scoreboard(keep)  # (at the smallest size, where fit_width left it)
                if players.content_width <= room:
                    break
            fit_width(players, players.text, room, HUD_SMALLEST, HUD_SMALLEST)
        self.banner.width = min(900, w - 40)

    def scoreboard(self, keep: int | None = None) -> str:
        """Everyone's strokes on this hole, under the HUD when several play: 'Ann: 2 · Bob: 3 (in)' (a
        colon, so 'Ann 2: 0' is the second Ann's score); names longer than `keep` cut short in the middle
        ('Wilhelmi…rth'), so names that differ at the end stay apart."""
        if self.world is None or len(self.world.players) < 2:
            return ""
        return "  ·  ".join(f"{name if keep is None else cut_middle(name, keep)}: {p.state.score}"
                            f"{' (in)' if p.state.holed else ''}{' (picked up)' if p.state.picked_up else ''}"
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
        if world is None or button != arcade.MOUSE_BUTTON_LEFT or not self.session.can_shoot \
                or self.session.computer_turn:
            return
        wx, wy = self.to_world(x, y)
        reach = max(GRAB_SLACK * world.collider.radius, GRAB_PIXELS / self.camera.zoom)
        if math.hypot(wx - world.ball.x, wy - world.ball.y) <= reach:
            self.aiming = True
            self.grab = self.tip = (wx, wy)

    def on_mouse_drag(self, x: int, y: int, dx: int, dy: int, buttons: int, modifiers: int) -> None:
        if self.aiming:
            self.tip = self.to_world(x, y)
        elif buttons & arcade.MOUSE_BUTTON_RIGHT and self.world is not None:
            self.pan_by(-dx / self.camera.zoom, -dy / self.camera.zoom)

    def on_mouse_release(self, x: int, y: int, button: int, modifiers: int) -> None:
        if not self.aiming or button != arcade.MOUSE_BUTTON_LEFT:
            return
        self.aiming = False
        self.tip = self.to_world(x, y)
        self.session.shoot(self.grab, (self.tip[0] - self.grab[0], self.tip[1] - self.grab[1]))
        self.clear_preview()

    def on_mouse_scroll(self, x: int, y: int, scroll_x: float, scroll_y: float) -> None:
        if self.world is not None and scroll_y:
            self.zoom_at(x, y, ZOOM_STEP ** scroll_y)

    def on_key_press(self, symbol: int, modifiers: int) -> None:
        if window_key(self.window, self.game, symbol):
            self.update_hud()
        elif symbol == arcade.key.ESCAPE:
            if self.aiming:
                self.aiming = False
                self.clear_preview()
            else:
                self.flow.pause(self)
        elif symbol == arcade.key.R:
            self.restart_hole()
        elif symbol == arcade.key.L:
            self.watch_last_shot()
        elif symbol == arcade.key.H:
            if not self.caddie.toggle_hint():
                self.show_banner("A hint is for your own shot, with every ball at rest", 2.0)
        elif symbol == arcade.key.P:
            self.game.toggle_preview()
            self.clear_preview()
            self.show_banner(f"Shot preview: {'on' if self.game.preview else 'off'}", 1.5)
        elif symbol == arcade.key.F3:
            self.overlay = not self.overlay
            self.system_us.clear()
            self.fit()
        elif symbol in PRESET_KEYS:
            self.set_preset(PRESET_KEYS[symbol])
        elif symbol in PAN_KEYS and self.world is not None:
            step = PAN_STEP * self.window.width / self.camera.zoom
            self.pan_by(PAN_KEYS[symbol][0] * step, PAN_KEYS[symbol][1] * step)
        elif symbol in (arcade.key.KEY_0, arcade.key.HOME) and self.world is not None:
            self.zoom, self.pan = 1.0, (0.0, 0.0)
            self.fit()

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
        self.frame_seconds.append(delta_time)
        events, impacts = [], []
        for _ in range(self.clock.advance(delta_time)):
            if self.overlay:
                self.step_profiled(world)
            else:
                self.session.step()
            for seat, poses in enumerate(self.ball_poses):
                poses.moved_to(self.ball_pose(seat))
            for poses, mill in zip(self.windmill_poses, world.windmills):
                poses.moved_to((mill.x, mill.y, mill.angle))
            self.trail.append(self.ball_poses[world.turn].current[:2])
            stepped, struck = world.drain_events()
            self.start_animations(stepped)
            events += stepped
            impacts += struck
        self.game.sound.hear(events, impacts, delta_time)
        self.caddie.update(delta_time)
        if self.caddie.problem:
            self.show_banner(self.caddie.problem, 4.0)
            self.caddie.problem = ""
        self.update_preview()
        self.animate(delta_time)
        self.banner_time = max(0.0, self.banner_time - delta_time)
        self.update_hud()
        if self.session.hole_over:
            self.finished_for += delta_time
            if self.finished_for >= FINISH_PAUSE:
                self.finish_hole()

    def update_preview(self) -> None:
        """The dotted line for the arrow being drawn, the player's or the computer's (worked out again
        only when the arrow changed noticeably, at most every `caddie.PREVIEW_INTERVAL`)."""
        if self.aiming:
            aim = self.grab, (self.tip[0] - self.grab[0], self.tip[1] - self.grab[1])
        else:
            aim = self.caddie.computer_arrow()
        if aim is None or not self.game.preview or self.world is None:
            self.clear_preview()
        elif self.preview.update(self.world, self.session.shape, *aim):
            path = self.preview.path
            self.preview_art = (dotted_path(path, self.game.theme, self.preview.contact)
                                if len(path) > 1 or self.preview.contact is not None else None)

    def clear_preview(self) -> None:
        self.preview.clear()
        self.preview_art = None

    def start_animations(self, events: list[tuple[str, int, int]]) -> None:
        """A physics frame's events, seen right after it: the pose before it is where that ball was."""
        for kind, ball, _ in events:
            seat = self.seat_of.get(ball)
            if seat is None:
                continue
            if kind == "holed":
                self.drop_seat, self.drop_from, self.drop_time = seat, self.ball_poses[seat].previous, 0.0
            elif kind == "penalty":  # water: rings where it went in
                x, y, _ = self.ball_poses[seat].previous
                self.splashes.append([x, y, 0.0])
                self.trail.clear()
            elif kind == "restart":  # back to the tee: nothing splashed
                self.trail.clear()

    def animate(self, delta_time: float) -> None:
        self.drop_time += delta_time
        for splash in self.splashes:
            splash[2] += delta_time
        self.splashes = [s for s in self.splashes if s[2] < SPLASH_SECONDS]
        ball, cup = self.world.ball, self.world.layout.cup
        over = math.hypot(ball.x - cup[0], ball.y - cup[1]) < self.world.layout.cup_radius
        self.over_cup_time = self.over_cup_time + delta_time if over and not self.world.state.holed else 0.0
        if ball.asleep:
            self.trail.clear()

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
        frames = list(self.frame_seconds) or [0.0]
        mean = sum(frames) / len(frames)
        fps = 1 / mean if mean > 0 else 0.0
        lines = [f"preset {world.preset_name}: {knobs.substeps} substeps x {knobs.iterations} iterations",
                 f"  {knobs.position_correction}, ccd {'on' if knobs.ccd else 'off'}",
                 f"fps {fps:5.1f}  frame {mean * 1e3:4.1f} ms  max {max(frames) * 1e3:.1f}",
                 f"draw {self.draw_ms:5.2f} ms   physics {total:6.0f} us",
                 f"contacts {world.contact_count}   physics frames {self.clock.frames}",
                 ""]
        lines += [f"  {name:<12}{self.system_us.get(name, 0.0):7.0f} us" for name in names]
        lines += ["", "F3 hide  1 fast  2 balanced  3 accurate"]
        return lines[:OVERLAY_LINES]

    def draw_overlay(self) -> None:
        """A panel down the left, beside the fitted hole (`fit` leaves it room)."""
        lines = self.overlay_lines()
        top = self.window.height - HUD_HEIGHT
        step = self.fit_overlay(lines)
        arcade.draw_lrbt_rectangle_filled(0, OVERLAY_WIDTH, 0, top, self.game.theme.rgba("panel"))
        for text, line, i in zip(self.overlay_texts, lines, range(len(lines))):
            text.text = line
            text.position = (OVERLAY_PAD, top - OVERLAY_PAD - step * (i + 0.5))
            text.draw()

    def fit_overlay(self, lines: list[str]) -> float:
        """The F3 panel's one font size, so its longest line fits the panel's width and every line
        its height (a monospaced font: a line's width goes with its characters); returns the line
        spacing. Measured again only when the longest line or the window's height changes."""
        top = self.window.height - HUD_HEIGHT
        step = min(OVERLAY_STEP, (top - 2 * OVERLAY_PAD) / max(len(lines), 1))
        longest = max((len(line) for line in lines), default=1)
        if (longest, self.window.height) != self._overlay_fitted_for:
            self._overlay_fitted_for = (longest, self.window.height)
            probe = self.overlay_texts[0]
            probe.text, probe.font_size = "0" * longest, OVERLAY_FONT
            by_width = OVERLAY_FONT * (OVERLAY_WIDTH - 2 * OVERLAY_PAD) / max(probe.content_width, 1.0)
            size = min(OVERLAY_FONT, by_width, OVERLAY_FONT * step / OVERLAY_STEP)
            for text in self.overlay_texts:
                text.font_size = size
        return step

    def finish_hole(self) -> None:
        self.caddie.close()
        results = self.session.finish_hole()
        self.world = None
        self.flow.hole_done(results)

    def watch_last_shot(self) -> None:
        """L: the hole simulated again from its start to the last shot, and that shot shown."""
        if self.session.last_shot() is not None and not self.aiming:
            self.flow.watch_last_shot(self)

    def close(self) -> None:
        """Let go of the hole's world (leaving the hole, or the game)."""
        self.caddie.close()
        self.session.close()
        self.world = None

    def on_draw(self) -> None:
        started = time.perf_counter()
        self.clear()
        world = self.world
        if world is None:
            return
        theme = self.game.theme
        alpha = self.clock.alpha
        with self.camera.activate():
            self.hole_art.draw([b.lit > 0 for b in world.bumpers], [p.at(alpha) for p in self.windmill_poses], theme)
            self.draw_splashes()
            self.draw_balls(alpha)
            self.hole_art.draw_flag()
            self.draw_aim(world, theme)
        self.window.default_camera.use()
        w, h = self.window.width, self.window.height
        arcade.draw_lrbt_rectangle_filled(0, w, h - HUD_HEIGHT, h, theme.rgba("panel"))
        for text in self.hud_texts.values():
            text.draw()
        self.draw_hint_label()
        if self.banner_time > 0:
            draw_backed(self.banner, theme.rgba("panel"))
        if self.overlay:
            self.draw_overlay()
        if self.session.hole_over:
            self.draw_finish_message(w, h)
        self.draw_ms = (time.perf_counter() - started) * 1e3

    def draw_aim(self, world: HolePlay, theme) -> None:
        """The hint (faint), the preview's dots, then the arrow being drawn: the player's or the computer's."""
        hint = self.caddie.shown_hint()
        if hint is not None:
            origin = (world.ball.x + hint.grab[0], world.ball.y + hint.grab[1])
            draw_arrow(origin, (origin[0] + hint.arrow[0], origin[1] + hint.arrow[1]), theme,
                       (world.ball.x, world.ball.y), world.shot_spin(origin, hint.arrow), world.collider.radius,
                       alpha=HINT_ALPHA)
        if self.preview_art is not None:
            self.preview_art.draw()
        aim = ((self.grab, (self.tip[0] - self.grab[0], self.tip[1] - self.grab[1])) if self.aiming
               else self.caddie.computer_arrow())
        if aim is not None:
            origin, arrow = aim
            draw_arrow(origin, (origin[0] + arrow[0], origin[1] + arrow[1]), theme, (world.ball.x, world.ball.y),
                       world.shot_spin(origin, arrow), world.collider.radius)

    def draw_hint_label(self) -> None:
        """'hint' beside the hint arrow's head, in screen space so it reads at any zoom."""
        hint, world = self.caddie.shown_hint(), self.world
        if hint is None:
            return
        tip = (world.ball.x + hint.grab[0] + hint.arrow[0], world.ball.y + hint.grab[1] + hint.arrow[1])
        x, y = self.camera.project(tip)[:2]
        length = math.hypot(*hint.arrow) or 1.0
        self.hint_label.text = f"hint ({self.caddie.hint_level()})"
        self.hint_label.position = (x + 26 * hint.arrow[0] / length, y + 26 * hint.arrow[1] / length + 14)
        draw_backed(self.hint_label, self.game.theme.rgba("panel"), pad=5.0)

    def draw_balls(self, alpha: float) -> None:
        """Every ball still on the green between its last two poses, with a ring around the ball whose
        turn it is when several play; a ball that drops slides and shrinks into the cup."""
        world = self.world
        for seat, player in enumerate(world.players):
            if player.state.holed and seat == self.drop_seat:
                self.draw_drop(seat)
            elif not player.state.finished:
                self.draw_ball(seat, alpha)
        if len(world.players) > 1 and self.session.can_shoot:
            draw_turn_ring(world.ball.x, world.ball.y, world.collider.radius, self.ball_arts[world.turn].colour)

    def draw_drop(self, seat: int) -> None:
        if self.drop_from is None or self.drop_time >= DROP_SECONDS:
            return
        t = self.drop_time / DROP_SECONDS
        ease = t * t * (3 - 2 * t)
        cx, cy = self.world.layout.cup
        fx, fy, angle = self.drop_from
        self.ball_arts[seat].draw_scaled(fx + (cx - fx) * ease, fy + (cy - fy) * ease, angle, 1.0 - 0.75 * ease)

    def draw_ball(self, seat: int, alpha: float) -> None:
        """A ball between its last two poses; the one in play with its trail, dipping toward a cup it
        rolls over (the physics decides; this only shows it)."""
        world = self.world
        x, y, angle = self.ball_poses[seat].at(alpha)
        art = self.ball_arts[seat]
        if seat != world.turn:
            art.draw(x, y, angle, shadow=True)
            return
        if len(self.trail) > 1 and not world.ball.asleep:
            draw_trail([*self.trail, (x, y)], art.colour, 0.6 * world.collider.radius)
        if self.over_cup_time > 0:
            cx, cy = world.layout.cup
            d = math.hypot(cx - x, cy - y) or 1.0
            dip = LIP_WOBBLE * abs(math.sin(self.over_cup_time * 40))
            x, y = x + (cx - x) / d * dip, y + (cy - y) / d * dip
            angle += 0.15 * math.sin(self.over_cup_time * 55)
        art.draw(x, y, angle, shadow=True)

    def draw_splashes(self) -> None:
        colour = self.game.theme.rgba("water")
        for x, y, age in self.splashes:
            t = age / SPLASH_SECONDS
            for ring in (0.5, 1.0):
                r = 0.2 + 1.2 * t * ring
                arcade.draw_circle_outline(x, y, r, shade(colour, 0.7, round(220 * (1 - t))), 0.08, num_segments=32)

    def draw_finish_message(self, w: int, h: int) -> None:
        if self.finish_text is None:
            words = "Picked up" if self.world.state.picked_up else "In the cup!"
            if len(self.world.players) > 1:
                words = "Hole over"
            self.finish_text = arcade.Text(words, w / 2, (h - HUD_HEIGHT) / 2, self.game.theme.rgba("text"), 36,
                                           anchor_x="center", anchor_y="center", bold=True)
        if self.finish_text.position != (w / 2, (h - HUD_HEIGHT) / 2):  # (the window changed size since)
            self.finish_text.position = (w / 2, (h - HUD_HEIGHT) / 2)
        draw_backed(self.finish_text, self.game.theme.rgba("panel"), pad=24.0)


def fit_hole_line(text: arcade.Text, line: str, name: str, width: float, size: float, smallest: float) -> None:
    """The HUD's hole line ('Hole 3 of 9: NAME  ·  Par 3') in `width` px: smaller down to `smallest`,
    then the hole's name alone cut short with an ellipsis (the hole's number and par stay whole; a
    line without the name is cut at its end, as `fit_width` cuts)."""
    fit_width(text, line, width, size, smallest)
    at = line.find(name) if name else -1
    if text.text == line or at < 0:
        return
    head, tail = line[:at], line[at + len(name):]
    fits, wide = 0, len(name)  # the most characters of the name kept that fit, and the fewest that do not
    while wide - fits > 1:
        keep = (fits + wide) // 2
        text.text = f"{head}{name[:keep].rstrip()}…{tail}"
        if text.content_width <= width:
            fits = keep
        else:
            wide = keep
    text.text = f"{head}{name[:fits].rstrip()}…{tail}"
    if text.content_width > width:  # (not even the number and par fit: cut at the end)
        fit_width(text, text.text, width, text.font_size, text.font_size)
