"""What the player has chosen and how the round is going: plain Python, no arcade, fully testable."""

from __future__ import annotations

import unicodedata
from collections import deque
from collections.abc import Callable, Collection
from dataclasses import dataclass, field
from pathlib import Path

from pydantic import TypeAdapter, ValidationError

from polygolf import __version__
from polygolf.engine.golf.holes import Course, Hole, load_all_courses
from polygolf.engine.golf.nine import COURSE_ID as RANDOM_NINE
from polygolf.engine.golf.nine import load_nine, new_seed
from polygolf.engine.golf.play import HolePlay
from polygolf.engine.loading.limits import Name, breaks_a_line
from polygolf.engine.loading.scene import ShapeSpec
from polygolf.engine.loading.yamlsource import ContentError
from polygolf.engine.physics.polygon import Vec
from polygolf.game.golfer_process import GolferProcess
from polygolf.game.record import (
    BallEnd,
    HoleRecord,
    Input,
    RoundRecord,
    engine,
    fingerprint,
    sweep_replays,
    utc_stamp,
)
from polygolf.game.shapes import CATALOGUE, labels_shape
from polygolf.game.sound import ArcadePlayer, SoundBoard
from polygolf.game.store import Best, Store, not_a_folder
from polygolf.game.theme import Theme, load_themes

_NAMES = {-4: "Condor", -3: "Albatross", -2: "Eagle", -1: "Birdie", 0: "Par", 1: "Bogey",
          2: "Double bogey", 3: "Triple bogey"}


def golf_name(strokes: int, par: int) -> str:
    """The name golfers give a score: 'Hole in one!', 'Birdie', 'Bogey', '+4' ..."""
    if strokes == 1:
        return "Hole in one!"
    diff = strokes - par
    return _NAMES.get(diff, f"{diff:+d}")


@dataclass(slots=True)
class HoleResult:
    number: int  # 1-based position in the course
    name: str
    par: int
    strokes: int | None  # None: the hole was skipped (broken content)
    picked_up: bool = False
    penalties: int = 0  # of the strokes, those added by water and restarts


def strokes_text(n: int) -> str:
    return f"{n} stroke{'' if n == 1 else 's'}"


def penalty_text(n: int) -> str:
    """'(+1 penalty stroke)', '(+2 penalty strokes)', or '' for none."""
    return f"(+{n} penalty stroke{'' if n == 1 else 's'})" if n else ""


COMPUTER = "CPU"  # a player named so ("CPU 2" for a second one) is played by the search golfer
HINTS = {"off": None, "rough": 0.5, "good": 0.8, "exact": 1.0}  # the aim hint's setting -> its golfer's skill
SKILLS = {"rough": 0.5, "good": 0.8, "exact": 1.0}  # the computer opponent's setting -> its skill


def _one_of(value: object, options: Collection[str]) -> str | None:
    """A saved choice if it is still one of `options` (a setting edited to a list or a number is not)."""
    return value if isinstance(value, str) and value in options else None


def is_computer(name: str) -> bool:
    """The computer plays a seat whose name is CPU, any case, alone or followed by more ("CPU 2"):
    a name, so the HUD, scorecard, bests and replays all say who played without anything new."""
    words = name.split()
    return bool(words) and words[0].lower() == COMPUTER.lower()


MAX_NAME = 20  # characters of a player's name
_CONTENT_NAME = TypeAdapter(Name)  # the rules every name in the content follows (a course's, a hole's)


def player_name(text: str) -> str:
    """`text` as a player's name, or a ValueError saying why it cannot be one. The name is taken in
    Unicode's composed form (NFC), so 'Ánn' typed as one character or as 'A' and an accent is one
    player, and is held to the rules a course's name is (`limits.Name`: no control characters or
    direction overrides, no spaces about it, something in it that shows: a name of accents alone is
    none; nor halves of surrogate pairs, which bytes that are not UTF-8 come as) and at most MAX_NAME
    characters."""
    name = unicodedata.normalize("NFC", text)
    if any(unicodedata.category(c) == "Cs" for c in name):  # (how bytes that are not UTF-8 come)
        raise ValueError("a name is UTF-8 text (bytes of another encoding in it)")
    try:
        _CONTENT_NAME.validate_python(name)
    except ValidationError as exc:
        raise ValueError(exc.errors(include_url=False)[0]["msg"].removeprefix("Value error, ")) from None
    if len(name) > MAX_NAME:
        raise ValueError(f"a name is at most {MAX_NAME} characters")
    return name


def escaped(text: str) -> str:
    """`text` to show on a terminal or a screen: every character no name may hold (a newline, an ESC
    starting a terminal's colour code, a direction override: `limits.breaks_a_line`) as its Python
    escape, '\\x1b'; the rest as it is (a joiner in a Persian name too). For what was read back from
    the database, which a hand may have edited."""
    return "".join(c.encode("unicode_escape", "backslashreplace").decode("ascii") if breaks_a_line(c) else c
                   for c in text)


def unplayable(course: Course, start_at: int = 0) -> str | None:
    """Why a round of `course` from hole `start_at + 1` cannot be played: every hole from there is
    broken (one line, with the first hole's error); None when there is a hole to play. A round of
    no hole would end at once on an empty scorecard, and be saved and recorded as if played."""
    holes = course.holes[start_at:]
    if any(isinstance(hole, Hole) for hole in holes):
        return None
    broken = [hole for hole in holes if isinstance(hole, ContentError)]
    where = f" from hole {start_at + 1} on" if start_at else ""
    why = f"{broken[0]}{f'; and {len(broken) - 1} more' if len(broken) > 1 else ''}" if broken else "no holes"
    return f"course {course.name!r} has no playable hole{where} ({why})"


def par_text(diff: int) -> str:
    """A score against par as golfers write it: E for level, else signed."""
    return "E" if diff == 0 else f"{diff:+d}"


@dataclass
class Round:
    """One course played through by one to four players, a scorecard each. Broken holes are skipped
    with their error kept for display."""

    course: Course
    players: list[str] = field(default_factory=lambda: ["Player 1"])
    cards: list[list[HoleResult]] = field(default_factory=list)  # one per player, in seat order
    position: int = 0  # index into course.holes of the hole being played
    skipped: list[str] = field(default_factory=list)  # messages for holes that could not be played
    start_at: int = 0

    def __post_init__(self) -> None:
        if not self.cards:
            self.cards = [[] for _ in self.players]
        self.start_at = self.position

    def current(self) -> Hole | None:
        """The hole to play now, skipping (and recording) any broken ones; None when the round is over."""
        holes = self.course.holes
        while self.position < len(holes) and isinstance(holes[self.position], ContentError):
            error = holes[self.position]
            self.skipped.append(f"Hole {self.position + 1} skipped: {error}")
            for card in self.cards:
                card.append(HoleResult(self.position + 1, "(broken)", 0, None))
            self.position += 1
        return holes[self.position] if self.position < len(holes) else None

    @property
    def number(self) -> int:
        return self.position + 1

    @property
    def hole_count(self) -> int:
        return len(self.course.holes)

    def finish_hole(self, scores: list[tuple[int, bool, int]]) -> list[HoleResult]:
        """Every player's (strokes, picked up, penalties) on the hole being played, in seat order."""
        hole = self.current()
        assert hole is not None, "no hole is being played"
        assert len(scores) == len(self.players), "one score per player"
        results = [HoleResult(self.number, hole.spec.name, hole.spec.par, strokes, picked_up, penalties)
                   for strokes, picked_up, penalties in scores]
        for card, result in zip(self.cards, results):
            card.append(result)
        self.position += 1
        return results

    @property
    def over(self) -> bool:
        return self.current() is None

    @property
    def complete(self) -> bool:
        """Every hole of the course was played (a round started part-way is not a course score)."""
        return self.over and self.start_at == 0 and all(r.strokes is not None for r in self.results)

    @property
    def results(self) -> list[HoleResult]:
        """The first player's card (a one-player round's only one)."""
        return self.cards[0]

    def played(self, seat: int = 0) -> list[HoleResult]:
        return [r for r in self.cards[seat] if r.strokes is not None]

    def total_par(self, seat: int = 0) -> int:
        return sum(r.par for r in self.played(seat))

    def total_strokes(self, seat: int = 0) -> int:
        return sum(r.strokes for r in self.played(seat))  # type: ignore[misc]

    def standings(self) -> list[int]:
        """Seats from the fewest strokes to the most (ties keep seat order)."""
        return sorted(range(len(self.players)), key=lambda seat: self.total_strokes(seat))

    def winners(self) -> list[str]:
        """Who has the fewest strokes (several on a tie); nobody in a one-player round."""
        if len(self.players) < 2:
            return []
        best = min(self.total_strokes(seat) for seat in range(len(self.players)))
        return [name for seat, name in enumerate(self.players) if self.total_strokes(seat) == best]


class RoundPlay:
    """A round being played: the one implementation of its rules, shared by the window (mouse input),
    `autoplay` (the scripted golfer), watching a shot again and replays (recorded inputs, `feed`).

    It builds each hole's world with a ball per player, keeps turns, takes shots and restarts, steps
    frames, and records every input at its frame with each hole's end (`record`).

    Turn order is strict rotation: each player plays one stroke in seat order, skipping players whose
    ball is finished; the next player's turn starts when every ball is at rest. A restart (the ball
    back on its tee spot) keeps the strokes taken, adds a penalty stroke, and the same player plays on.
    """

    def __init__(self, round_: Round, shape: ShapeSpec, shape_label: str, preset: str = "balanced",
                 feed: dict[int, tuple[str, list[Input]]] | None = None) -> None:
        self.round = round_
        self.shape = shape
        self.preset = preset
        self.feed = feed  # position -> (preset at its start, inputs) to play on that hole (a replay); None: live
        self.hole: HolePlay | None = None
        self.frame = 0  # frames stepped on this hole
        self.waiting: tuple[int, int] | None = None  # (player, strokes before) of a shot not yet settled
        self.ended: HoleRecord | None = None  # the hole's record, taken when its last ball finished
        self.record = RoundRecord(
            game_version=__version__, engine=engine(),
            recorded_at=utc_stamp(),
            course=round_.course.id, course_name=round_.course.name, fingerprint=fingerprint(round_.course),
            shape_label=shape_label, shape=shape, preset=preset, players=list(round_.players),
            start_at=round_.position)
        self._inputs: list[Input] = []
        self._pending: deque[Input] = deque()
        # A replay's inputs that could never have been taken, this hole: why, each (see `_feed`).
        self.refused: list[str] = []
        self.hole_preset = preset  # the preset the hole being played started with
        self.start_hole()

    # -- reading ----------------------------------------------------------------------------------

    @property
    def players(self) -> list[str]:
        return self.round.players

    @property
    def turn(self) -> int:
        return self.hole.turn if self.hole is not None else 0

    @property
    def player_name(self) -> str:
        return self.players[self.turn]

    @property
    def computer_turn(self) -> bool:
        """The seat whose turn it is is the computer's (live play only: a replay plays its inputs)."""
        return self.feed is None and self.hole is not None and is_computer(self.player_name)

    @property
    def hole_over(self) -> bool:
        return self.hole is not None and self.hole.finished

    @property
    def can_shoot(self) -> bool:
        """The player whose turn it is may shoot: everything is at rest and their ball is in play."""
        return self.feed is None and self._refusal("shot", self.turn) is None

    def _refusal(self, kind: str, player: int) -> str | None:
        """Why `player` may not give an input of `kind` now (None: they may): the rules live play
        records inputs by (`shoot`, `restart`), which a replay's inputs are held to as they come."""
        hole = self.hole
        if hole is None or self.ended is not None:
            return "after the hole ended"
        if kind == "preset":
            return None
        if player != hole.turn:
            return f"not {self.players[player]}'s turn but {self.players[hole.turn]}'s"
        if hole.state.finished:
            return "that ball had finished the hole"
        if kind == "shot" and not hole.all_at_rest:
            return "a ball was still moving"
        if kind == "shot" and self.waiting is not None:
            return "a shot was taken in this frame already"
        return None

    @property
    def inputs(self) -> list[Input]:
        """This hole's inputs so far."""
        return list(self._inputs)

    def last_shot(self) -> Input | None:
        return next((i for i in reversed(self._inputs) if i.kind == "shot"), None)

    # -- the hole ---------------------------------------------------------------------------------

    def start_hole(self) -> HolePlay | None:
        """The round's current hole with every ball on the tee (None when the round is over)."""
        self.close()
        hole = self.round.current()
        if hole is None:
            return None
        self._pending, self.refused = deque(), []
        if self.feed is not None:
            self.preset, pending = self.feed.get(self.round.position, (self.preset, []))
            self._pending = deque(pending)
        self.hole = HolePlay(hole, self.shape, self.preset, len(self.players))
        self.frame, self.waiting, self.ended = 0, None, None
        self._inputs = []
        self.hole_preset = self.preset
        return self.hole

    def restart_hole(self) -> None:
        """Build the hole again from the start: only where nothing is scored (a hole file being edited)."""
        self.start_hole()

    def shoot(self, grab: tuple[float, float], arrow: tuple[float, float]) -> bool:
        """The player whose turn it is shoots; False if it is not a shot (too short, or not allowed now)."""
        if not self.can_shoot:
            return False
        return self._apply(Input(frame=self.frame, kind="shot", player=self.turn, grab=grab, arrow=arrow))

    def restart(self) -> bool:
        """The player whose turn it is goes back to the tee: strokes kept, a penalty stroke added."""
        if self.feed is not None or self._refusal("restart", self.turn) is not None:
            return False
        return self._apply(Input(frame=self.frame, kind="restart", player=self.turn))

    def set_preset(self, name: str) -> None:
        """Switch the accuracy preset live (recorded: it changes what the physics does; after the hole's
        end it only changes the next holes, whose records say which preset they start with)."""
        self.preset = name
        if self.hole is not None and self.ended is None:
            self._apply(Input(frame=self.frame, kind="preset", preset=name))
        elif self.hole is not None:
            self.hole.set_preset(name)

    def _apply(self, action: Input) -> bool:
        hole = self.hole
        if action.kind == "preset":
            self.preset = action.preset
            hole.set_preset(action.preset)
            done = True
        else:
            hole.turn = action.player
            if action.kind == "shot":
                strokes = hole.state.strokes
                done = hole.shoot(action.grab, action.arrow)
                if done:
                    self.waiting = (action.player, strokes)
            else:
                done = hole.restart_ball()
                self.waiting = None  # stroke and distance: the same player plays again from the tee
        if done:
            self._inputs.append(action)
        return done

    def step(self, frames: int = 1, profile: bool = False) -> None:
        """Advance the hole `frames` frames (a replay's inputs go in at their frames); once every ball
        is finished the hole's end is recorded, and further frames only animate."""
        hole = self.hole
        if hole is None:
            return
        for _ in range(frames):
            while self._pending and self._pending[0].frame <= self.frame and self.ended is None:
                self._feed(self._pending.popleft())
            hole.step(profile=profile)
            if self.ended is not None:
                continue
            self.frame += 1
            self._next_turn()
            if hole.finished:
                self.ended = self._hole_record()

    def _feed(self, action: Input) -> None:
        """A replay's input, at its frame: taken only if live play could have taken it there (it
        records no other), else passed over and said in `refused` (`replay.verify` fails on it)."""
        why = (f"out of frame order (frame {self.frame} was reached first)" if action.frame != self.frame
               else self._refusal(action.kind, action.player))
        if why is None and not self._apply(action):
            why = "too short to be a shot" if action.kind == "shot" else "not taken"
        if why is not None:
            self.refused.append(f"the {action.kind} at frame {action.frame}: {why}")

    @property
    def unplayed(self) -> list[Input]:
        """A replay's inputs for this hole still to come: once it has ended, inputs it never reached."""
        return list(self._pending)

    def _next_turn(self) -> None:
        """Strict rotation: when everything rests after a shot, the next seat whose ball is in play."""
        hole = self.hole
        if not hole.all_at_rest or hole.finished:
            return
        if self.waiting is not None:
            player, strokes = self.waiting
            if hole.players[player].state.strokes == strokes and not hole.players[player].state.finished:
                self.waiting = None  # not taken (not at rest): the same player again
                return
            self.waiting = None
        elif not hole.state.finished:
            return
        seats = len(hole.players)
        for k in range(1, seats + 1):
            seat = (hole.turn + k) % seats
            if not hole.players[seat].state.finished:
                hole.turn = seat
                return

    def _hole_record(self) -> HoleRecord:
        ends = [BallEnd(strokes=p.state.strokes, penalties=p.state.penalties, holed=p.state.holed,
                        picked_up=p.state.picked_up,
                        body=(p.body.x, p.body.y, p.body.angle, p.body.vx, p.body.vy, p.body.spin))
                for p in self.hole.players]
        return HoleRecord(position=self.round.position, hole=self.hole.hole.id, preset=self.hole_preset,
                          inputs=self._inputs, frames=self.frame, final=ends)

    def finish_hole(self) -> list[HoleResult]:
        """Write every player's score on their card, keep the hole's record, and let the world go."""
        hole = self.hole
        assert hole is not None and hole.finished, "the hole is not finished"
        self.record.holes.append(self.ended or self._hole_record())
        results = self.round.finish_hole([(p.state.score, p.state.picked_up, p.state.penalties)
                                          for p in hole.players])
        self.close()
        return results

    def play_out(self, plan: Callable[[HolePlay], tuple[Vec, Vec]], max_frames: int = 60 * 60 * 10) -> None:
        """Play the rest of the round with `plan` choosing each shot (the scripted golfer), or with the
        fed inputs; each hole ends when its balls are finished, or after `max_frames` frames."""
        while self.hole is not None:
            while not self.hole.finished and self.frame < max_frames:
                if self.can_shoot and not self.shoot(*plan(self.hole)):
                    self.restart()  # the plan cannot move the ball: take the penalty rather than loop
                self.step()
            if not self.hole.finished:  # (content: a ball that never rests, say; its hole passed validation)
                raise ValueError(f"{self.round.course.name}: hole {self.round.number} did not finish in "
                                 f"{max_frames / 60:.0f} s of play (a ball never came to rest); the round is not saved")
            self.finish_hole()
            self.start_hole()

    def close(self) -> None:
        if self.hole is not None:
            self.hole.close()
            self.hole = None


MAX_PLAYERS = 4


def default_names(count: int) -> list[str]:
    return [f"Player {k + 1}" for k in range(count)]


@dataclass
class Game:
    """Everything the screens share: content, the player's choices, and the round in progress.
    With a `store`, the choices are read at launch and written back whenever they change.

    The Course choice cycles through the content's courses and then Random nine: nine generated holes
    from `random_seed` (`engine.golf.nine`). `random_nine` is that course once built or found in the
    data folder; until then the choice has no course to play, and the flow builds it first."""

    courses: list[Course]
    themes: list[Theme]
    theme_index: int = 0
    shape_label: str = CATALOGUE[2][0]
    shape: ShapeSpec = CATALOGUE[2][1]
    course_index: int = 0
    preset: str = "balanced"
    round: Round | None = None
    guide_seen: bool = False
    players: list[str] = field(default_factory=lambda: default_names(1))
    problems: list[str] = field(default_factory=list)  # content that could not be read, for the menu
    course_problems: list[str] = field(default_factory=list)  # of those, the courses files' (`find_course`)
    store: Store | None = None
    session: RoundPlay | None = None
    record_rounds: bool = True  # False: practice (a hole file being edited): nothing saved
    sound: SoundBoard = field(default_factory=lambda: SoundBoard(ArcadePlayer()))
    random_seed: int = field(default_factory=new_seed)
    random_nine: Course | None = None  # the course of random_seed, once built or found built
    hint: str = "off"  # the aim hint: a key of HINTS
    preview: bool = True  # the dotted line of the shot being aimed, up to its first bounce
    computer_skill: str = "good"  # a key of SKILLS
    golfers: GolferProcess = field(default_factory=GolferProcess)  # the search golfer's process, started on demand

    @classmethod
    def load(cls, store: Store | None = None) -> Game:
        """The shipped and the player's content (what cannot be read is left out and reported), with
        the settings saved last time."""
        courses, course_problems = load_all_courses()
        themes, theme_problems = load_themes()
        game = cls(courses=courses, themes=themes, problems=[str(p) for p in course_problems + theme_problems],
                   course_problems=[str(p) for p in course_problems],
                   store=store if store is not None else Store())
        game.apply_settings(game.store.load_settings())
        sweep_replays(game.store.folder / "replays")  # (what a game killed while it saved left there)
        return game

    # -- settings ---------------------------------------------------------------------------------

    def settings(self) -> dict[str, object]:
        return {"theme": self.theme.name, "shape": {"label": self.shape_label, "spec": self.shape.model_dump(
            mode="json", exclude_none=True)}, "course": RANDOM_NINE if self.random_chosen else self.course.id,
            "players": self.players, "volume": self.sound.volume, "muted": self.sound.muted,
            "guide_seen": self.guide_seen, "hint": self.hint, "preview": self.preview,
            "computer_skill": self.computer_skill, "random_seed": self.random_seed}

    def apply_settings(self, saved: dict[str, object]) -> None:
        """Take what was saved; a value that no longer fits (a theme or course gone) is left at its default."""
        themes = [t.name for t in self.themes]
        if _one_of(saved.get("theme"), themes):
            self.theme_index = themes.index(saved["theme"])
        seed = saved.get("random_seed")
        if isinstance(seed, int) and not isinstance(seed, bool) and 0 <= seed < 2**63:
            self.random_seed = seed
        courses = [c.id for c in self.courses]
        if _one_of(saved.get("course"), courses):
            self.course_index = courses.index(saved["course"])
        elif saved.get("course") == RANDOM_NINE:
            self.course_index = len(self.courses)
            self.random_nine = self._cached_nine()
        shape = saved.get("shape")
        if isinstance(shape, dict) and isinstance(shape.get("label"), str):
            try:
                spec = ShapeSpec.model_validate(shape.get("spec"))
            except ValueError:
                spec = None
            if spec is not None and labels_shape(shape["label"], spec):
                self.set_shape(shape["label"], spec)
        names = saved.get("players")
        if isinstance(names, list) and 1 <= len(names) <= MAX_PLAYERS and all(isinstance(n, str) for n in names):
            try:
                names = [player_name(n.strip()[:MAX_NAME]) for n in names]
            except ValueError:
                names = []  # (edited by hand to a name the game would not take: the default)
            if names and len(set(names)) == len(names):
                self.players = names
        volume = saved.get("volume")
        if isinstance(volume, int | float) and not isinstance(volume, bool) and 0.0 <= volume <= 1.0:
            self.sound.volume = float(volume)  # the sound board's volume is the one setting
        if isinstance(saved.get("muted"), bool):
            self.sound.muted = saved["muted"]
        self.guide_seen = saved.get("guide_seen") is True
        self.hint = _one_of(saved.get("hint"), HINTS) or self.hint
        self.preview = saved["preview"] if isinstance(saved.get("preview"), bool) else self.preview
        self.computer_skill = _one_of(saved.get("computer_skill"), SKILLS) or self.computer_skill

    def save_settings(self, *chosen: str) -> None:
        """Write back the settings the menu just chose, those alone: what the command line chose for
        this launch is not written (`render --theme sand` keeps the menu's theme), nor is what another
        game window open at the same time chose since this one started."""
        if self.store is not None:
            settings = self.settings()
            self.store.save_settings({key: settings[key] for key in chosen})

    # -- choices ----------------------------------------------------------------------------------

    @property
    def theme(self) -> Theme:
        return self.themes[self.theme_index]

    @property
    def random_chosen(self) -> bool:
        """Random nine is the chosen course (the choice after the content's courses)."""
        return self.course_index >= len(self.courses)

    @property
    def course(self) -> Course | None:
        """The chosen course; None when Random nine is chosen but not built yet, or no course could be read."""
        return self.random_nine if self.random_chosen else self.courses[self.course_index]

    @property
    def course_label(self) -> str:
        """The chosen course as the menu's button names it: Random nine with its seed (built or not) as
        'Random nine #4711', like 'Random #42' for a random polygon (the full name is too long there)."""
        return f"Random nine #{self.random_seed}" if self.random_chosen else self.courses[self.course_index].name

    def next_theme(self) -> None:
        self.theme_index = (self.theme_index + 1) % len(self.themes)
        self.save_settings("theme")

    def next_course(self) -> None:
        """The next course; after the last, Random nine (found in the data folder if built before)."""
        self.course_index = (self.course_index + 1) % (len(self.courses) + 1)
        if self.random_chosen:
            self.random_nine = self._cached_nine()
        self.save_settings("course")

    def show_course(self, course: Course) -> None:
        """`course` chosen for now (a replay's, as the content has it now): one of the content's courses,
        or a Random nine of its seed; not saved as the menu's choice, and every course stays on offer."""
        ids = [c.id for c in self.courses]
        if course.id in ids:
            self.course_index = ids.index(course.id)
            self.courses[self.course_index] = course
        else:  # a Random nine (`replay.load_for_replay` finds no other course outside the content)
            self.course_index = len(self.courses)
            self.random_seed, self.random_nine = int(course.id.removeprefix(f"{RANDOM_NINE}-")), course

    def choose_random_nine(self, seed: int | None = None) -> None:
        """Random nine of `seed` (default: the seed chosen last), from the data folder if built before.
        (The command line's choice: not saved as the menu's.)"""
        self.course_index = len(self.courses)
        if seed is not None and seed != self.random_seed:
            self.random_seed, self.random_nine = seed, None
        if self.random_nine is None:
            self.random_nine = self._cached_nine()

    def new_random_seed(self) -> None:
        """Another Random nine: a fresh seed (its course is built when it is first played)."""
        self.random_seed = new_seed()
        self.random_nine = self._cached_nine()
        self.save_settings("random_seed")

    def _cached_nine(self) -> Course | None:
        try:
            return load_nine(self.random_seed)
        except (ContentError, OSError):  # no library to draw from, or no data folder: built (and said) on Play
            return None

    def next_shape(self) -> None:
        labels = [label for label, _ in CATALOGUE]
        i = labels.index(self.shape_label) + 1 if self.shape_label in labels else 0
        self.shape_label, self.shape = CATALOGUE[i % len(CATALOGUE)]
        self.save_settings("shape")

    def set_shape(self, label: str, shape: ShapeSpec) -> None:
        self.shape_label, self.shape = label, shape
        self.save_settings("shape")

    def next_player_count(self) -> None:
        """1, 2, 3, 4, 1 ... players (names kept for the seats that stay)."""
        count = len(self.players) % MAX_PLAYERS + 1
        players = self.players[:count]
        for seat in range(len(players), count):  # a new seat: "Player N" for its own number N, if free
            players.append(next(name for name in [f"Player {seat + 1}", *default_names(2 * MAX_PLAYERS)]
                                if name not in players))
        self.players = players
        self.save_settings("players")

    def set_names(self, names: list[str]) -> None:
        """The players' names (their count is the number of players)."""
        self.players = list(names[:MAX_PLAYERS]) or default_names(1)
        self.save_settings("players")

    def next_hint(self) -> None:
        """Aim hint: off, rough, good, exact, off ..."""
        names = list(HINTS)
        self.hint = names[(names.index(self.hint) + 1) % len(names)]
        self.save_settings("hint")

    def next_volume(self) -> None:
        """The menu's Sound: the next volume step (unmuting), kept for the next launch."""
        muted = self.sound.muted
        self.sound.next_volume()
        self.save_settings("volume", *(("muted",) if muted else ()))

    def toggle_mute(self) -> None:
        """M: sound off or back on, kept for the next launch (the volume stays as it was)."""
        self.sound.toggle_mute()
        self.save_settings("muted")

    def toggle_preview(self) -> None:
        self.preview = not self.preview
        self.save_settings("preview")

    def next_computer_skill(self) -> None:
        names = list(SKILLS)
        self.computer_skill = names[(names.index(self.computer_skill) + 1) % len(names)]
        self.save_settings("computer_skill")

    def close(self) -> None:
        """The game is closing: the round's world and the golfer's process go, and the settings a
        locked database kept from being written are written now (waiting for the lock in full)."""
        self.close_session()
        self.golfers.close()
        if self.store is not None:
            self.store.flush_settings()

    def mark_guide_seen(self) -> None:
        if not self.guide_seen:
            self.guide_seen = True
            self.save_settings("guide_seen")

    # -- rounds -----------------------------------------------------------------------------------

    def unplayable(self, start_at: int = 0) -> str | None:
        """Why the chosen course has no round to play from hole `start_at + 1` (see `unplayable`), or None."""
        return unplayable(self.course, start_at) if self.course is not None else None

    def show_problem(self, problem: str) -> None:
        """A content problem found since launch (a course with no hole to play), first in the menu's
        list (said once however often it is found)."""
        if problem in self.problems:
            self.problems.remove(problem)
        self.problems.insert(0, problem)

    def start_round(self, start_at: int = 0) -> Round:
        """A new round of the chosen course for the chosen players, and its session (see RoundPlay).
        A ValueError (one line) if the course has no hole to play from there."""
        problem = self.unplayable(start_at)
        if problem is not None:
            raise ValueError(problem)
        self.close_session()
        self.round = Round(self.course, players=list(self.players), position=start_at)
        self.session = RoundPlay(self.round, self.shape, self.shape_label, self.preset)
        return self.round

    def close_session(self) -> None:
        if self.session is not None:
            self.session.close()
            self.session = None

    def save_round(self, session: RoundPlay) -> Path | None:
        """Keep a finished round: its replay file, then its card in the database. Either failing costs
        a warning, never the round. Returns the replay's path."""
        if self.store is None:
            return None
        replay = None
        try:
            replay = session.record.save(self.store.folder / "replays")
        except OSError as exc:
            folder = self.store.folder / "replays"
            self.store.warn(f"cannot save the replay in {folder}: {not_a_folder(folder) or exc.strerror or exc}")
        self.store.save_round(session.round, session.record, replay)
        return replay

    def best_hole(self, hole_id: str) -> Best | None:
        if self.store is None or self.course is None:
            return None
        return self.store.best_hole(self.course.id, hole_id, self.shape_label)

    def best_course(self) -> Best | None:
        if self.store is None or self.course is None:
            return None
        return self.store.best_course(self.course.id, self.shape_label)
