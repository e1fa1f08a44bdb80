"""What the play screen's helpers know, without arcade: the aim hint, the computer opponent's turn,
and the shot preview. Plain Python on a `RoundPlay`, so a headless test drives them as the screen does.

- `Caddie` asks the search golfer (`golfer_process`) for the ball whose turn it is: a hint for a
  person (when the Hint setting is on, or H asks), the shot for the computer. An answer counts only
  for the situation it was asked about (the same hole, turn, strokes and ball pose): if the ball moved
  or the turn changed meanwhile it is dropped. The computer's arrow is shown being drawn for
  `SHOW_SECONDS`, then shot through `RoundPlay.shoot`, the player's own path, so it is recorded and
  replayed like any shot.
- `ShotPreview` simulates the shot being aimed with the game's physics (`simulate_shots`, one ball, the
  windmills as they stand) up to its first contact, inline: a path costs 3–4 ms (median; 5–7 ms
  at the 90th percentile, 24–26 ms at worst, a long roll on a slope; benchmarks/bench_caddie.py) at
  the hole's preset, so it is worked out again only when the arrow changed noticeably, at most every
  `PREVIEW_INTERVAL` and never more than `PREVIEW_SHARE` of the time.

The search sees only the ball being played (other players' balls are not in its world); the preview
has them as walls where they rest, which is exact up to the first contact, where it stops.
"""

from __future__ import annotations

import math
import random
import time
from concurrent.futures import Future
from dataclasses import dataclass

from polygolf.engine.golf.golfer import golfer_for
from polygolf.engine.golf.play import HolePlay
from polygolf.engine.golf.shots import Shot, simulate_shots
from polygolf.engine.loading.scene import ShapeSpec
from polygolf.engine.physics.polygon import Vec
from polygolf.game.golfer_process import GolferProcess, origin_of, other_balls, question_for
from polygolf.game.session import HINTS, SKILLS, RoundPlay, is_computer

SHOW_SECONDS = 0.8  # the computer's arrow is drawn out over this, then shot
DRAW_SHARE = 0.7  # of it spent drawing the arrow out; the rest it is held still
HINT_WHEN_OFF = "good"  # H with the Hint setting off asks for this skill

PREVIEW_INTERVAL = 0.1  # s: a new preview path at most this often
PREVIEW_SECONDS = 4.0  # game time a preview follows the ball at most
PREVIEW_CHANGE = 0.03  # m the arrow's tip or grab point must move for a new path
PREVIEW_SHARE = 0.25  # of the time, at most, spent working previews out (a slow path waits longer)


Situation = tuple  # (hole, turn, strokes, penalties, x, y, angle): what an answer is valid for


@dataclass
class Asked:
    situation: Situation
    purpose: str  # "hint" or "play"
    future: Future
    since: float


class Caddie:
    """The search golfer at one play screen's side. Call `update` every frame; read `hint`,
    `computer_arrow()` and `thinking` to draw."""

    def __init__(self, session: RoundPlay, golfers: GolferProcess, hint: str = "off",
                 computer_skill: str = "good", rng: random.Random | None = None) -> None:
        self.session = session
        self.golfers = golfers
        self.hint_setting = hint
        self.computer_skill = computer_skill
        self.rng = rng or random.Random()
        self.asked: Asked | None = None
        self.hint: Shot | None = None  # for `hint_for`'s situation
        self.hint_for: Situation | None = None
        self.play: Shot | None = None  # the computer's chosen shot, being shown
        self.play_for: Situation | None = None
        self.shown = 0.0  # s the computer's arrow has been shown
        self.wanted: Situation | None = None  # H asked for a hint here
        self.dismissed: Situation | None = None  # H hid the hint here
        self.problem = ""  # the last search's failure, for the screen to say once
        self.failed_for: Situation | None = None  # not asked again here (a worker that cannot start)
        self.latency = 0.0  # s the last answer took, asked to collected
        self.warm = hint == "off" and not any(is_computer(n) for n in session.players)  # True: nothing to start

    # -- reading ----------------------------------------------------------------------------------

    def situation(self) -> Situation | None:
        """What a shot now would be played from; None while anything moves (no shot can be taken)."""
        session, hole = self.session, self.session.hole
        if hole is None or not session.can_shoot:
            return None
        ball, state = hole.ball, hole.state
        return id(hole), hole.turn, state.strokes, state.penalties, ball.x, ball.y, ball.angle

    @property
    def thinking(self) -> bool:
        """A search for the situation now is under way (the HUD says so)."""
        now = self.situation()
        return now is not None and self.asked is not None and self.asked.situation == now

    def shown_hint(self) -> Shot | None:
        """The hint to draw: only for the situation it was found for."""
        now = self.situation()
        return self.hint if now is not None and self.hint_for == now and self.dismissed != now else None

    def computer_arrow(self) -> tuple[Vec, Vec] | None:
        """(grab point, arrow) of the computer's shot as drawn so far: it grows like a player's drag,
        then holds still until it is shot."""
        if self.play is None or self.play_for != self.situation():
            return None
        t = min(1.0, self.shown / (DRAW_SHARE * SHOW_SECONDS))
        ease = 1.0 - (1.0 - t) ** 3
        return origin_of(self.play), (self.play.arrow[0] * ease, self.play.arrow[1] * ease)

    def hint_level(self) -> str:
        """The Hint setting the hint is worked out at (H with the setting off: HINT_WHEN_OFF)."""
        return self.hint_setting if self.hint_setting != "off" else HINT_WHEN_OFF

    def hint_skill(self) -> float:
        return HINTS[self.hint_level()]  # type: ignore[return-value]

    # -- the player's keys ------------------------------------------------------------------------

    def toggle_hint(self) -> bool:
        """H: ask for a hint for this shot, or hide the one shown (or being worked out). False when no
        hint can be given now (it is the computer's turn, or the balls still move)."""
        now = self.situation()
        if now is None or self.session.computer_turn:
            return False
        showing = self.dismissed != now and (self.wanted == now or self.hint_setting != "off")
        if showing:
            self.dismissed, self.wanted = now, None
        else:
            self.dismissed, self.wanted = None, now
        return True

    # -- every frame ------------------------------------------------------------------------------

    def update(self, dt: float) -> bool:
        """Collect an answer, ask a question the situation calls for, and play the computer's shot once
        it has been shown. True if the computer shot this frame."""
        if not self.warm:  # the first frame, not the constructor: a rendered still starts no process
            self.golfers.warm_up()
            self.warm = True
        now = self.situation()
        self._collect(now)
        if now is None:
            return False
        if self.session.computer_turn:
            if self.play is not None and self.play_for == now:
                self.shown += dt
                if self.shown >= SHOW_SECONDS:
                    return self._shoot(self.play)
            elif not self._asking(now):
                self._ask(now, "play", SKILLS[self.computer_skill])
        elif self._hint_wanted(now) and now not in (self.hint_for, self.failed_for) and not self._asking(now):
            self._ask(now, "hint", self.hint_skill())
        return False

    def _hint_wanted(self, now: Situation) -> bool:
        return self.dismissed != now and (self.hint_setting != "off" or self.wanted == now)

    def _asking(self, now: Situation) -> bool:
        return self.asked is not None and self.asked.situation == now

    def _ask(self, now: Situation, purpose: str, skill: float) -> None:
        if self.asked is not None:
            self.asked.future.cancel()  # too late if the worker has begun it; its answer is dropped
        question = question_for(self.session.hole, self.session.shape, skill, self.rng.randrange(2 ** 31))
        self.asked = Asked(now, purpose, self.golfers.ask(question), time.perf_counter())

    def _collect(self, now: Situation | None) -> None:
        asked = self.asked
        if asked is None or not asked.future.done():
            return
        self.asked = None
        if asked.future.cancelled() or asked.situation != now:
            return  # stale: the ball moved or the turn changed while it searched
        self.latency = time.perf_counter() - asked.since
        try:
            shot = asked.future.result()
        except Exception as exc:  # the search failed: say so; the computer falls back on the planner
            self.problem = f"The golfer could not search: {exc}"
            self.failed_for = now
            if asked.purpose != "play":
                return
            hole = self.session.hole
            origin, arrow = golfer_for(hole.hole).plan((hole.ball.x, hole.ball.y))
            shot = Shot((hole.ball.x, hole.ball.y), arrow, (origin[0] - hole.ball.x, origin[1] - hole.ball.y))
        if asked.purpose == "hint":
            self.hint, self.hint_for = shot, now
        else:
            self.play, self.play_for, self.shown = shot, now, 0.0

    def _shoot(self, shot: Shot) -> bool:
        """The computer releases its arrow: the same call a player's mouse release makes."""
        self.play = self.play_for = None
        if not self.session.shoot(origin_of(shot), shot.arrow):
            self.session.restart()  # it cannot move the ball: a penalty, rather than asking for ever
        return True

    def close(self) -> None:
        """This screen is done with the golfer (the process stays, the game's to close)."""
        if self.asked is not None:
            self.asked.future.cancel()
            self.asked = None


class ShotPreview:
    """The dotted line of the shot being aimed: where the ball goes up to its first bounce (or rest,
    or the cup, or water), from the same physics as the shot itself."""

    def __init__(self) -> None:
        self.path: list[Vec] = []
        self.contact: Vec | None = None  # where the ball first strikes something, just past the path's end
        self._key: tuple[float, float, float, float] | None = None
        self._when = -math.inf
        self.cost = 0.0  # s the last path took to work out
        self.count = 0  # paths worked out

    def clear(self) -> None:
        self.path, self.contact, self._key = [], None, None

    def update(self, hole: HolePlay, shape: ShapeSpec, grab: Vec, arrow: Vec, now: float | None = None) -> bool:
        """Work the path out again if the arrow changed noticeably and the last one is old enough.
        True if it did."""
        now = time.perf_counter() if now is None else now
        key = (grab[0], grab[1], grab[0] + arrow[0], grab[1] + arrow[1])
        wait = max(PREVIEW_INTERVAL, self.cost / PREVIEW_SHARE)
        if self._key is not None and (now - self._when < wait
                                      or max(abs(a - b) for a, b in zip(key, self._key)) < PREVIEW_CHANGE):
            return False
        started = time.perf_counter()
        self.path, self.contact = preview_path(hole, shape, grab, arrow)
        self.cost = time.perf_counter() - started
        self.count += 1
        self._key, self._when = key, now
        return True


def preview_path(hole: HolePlay, shape: ShapeSpec, grab: Vec, arrow: Vec) -> tuple[list[Vec], Vec | None]:
    """The path of the ball whose turn it is, shot at `grab` (a world point) along `arrow`: its centre
    a frame at a time up to the frame in which it first strikes a wall, bumper, windmill or another
    player's ball, with the point it strikes; or up to where it rests, drops, or reaches water (None).
    At the hole's own preset, so it is the shot as it will be played. The other balls stand in as
    walls where they rest: they do not move before they are struck, and the preview ends there."""
    ball = hole.ball
    start = (ball.x, ball.y)
    shot = Shot(start, arrow, (grab[0] - ball.x, grab[1] - ball.y), ball.angle)
    result, = simulate_shots(hole.hole, [shot], hole.knobs, shape=shape, max_seconds=PREVIEW_SECONDS, path=True,
                             windmills=[w.angle for w in hole.windmills], until_contact=True,
                             obstacles=other_balls(hole))
    path = result.path
    if result.contact is not None:
        path = path[:result.contact]
    elif result.penalties:
        path = path[:-1]  # the last point is where water put the ball back
    return [start, *path], result.contact_at
