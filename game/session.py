"""What the player has chosen and how the round is going: plain Python, no arcade, fully testable."""

from __future__ import annotations

from dataclasses import dataclass, field

from polygolf.engine.golf.holes import Course, Hole, load_all_courses
from polygolf.engine.loading.scene import ShapeSpec
from polygolf.engine.loading.yamlsource import ContentError
from polygolf.game.shapes import CATALOGUE
from polygolf.game.sound import ArcadePlayer, SoundBoard
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


@dataclass
class Round:
    """One course played through. Broken holes are skipped with their error kept for display."""

    course: Course
    results: list[HoleResult] = field(default_factory=list)
    position: int = 0  # index into course.holes of the hole being played
    skipped: list[str] = field(default_factory=list)  # messages for holes that could not be played

    def current(self) -> Hole | None:
        """The hole to play now, skipping (and recording) any broken ones; None when the round is over."""
        holes = self.course.holes
        while self.position < len(holes) and isinstance(holes[self.position], ContentError):
            error = holes[self.position]
            self.skipped.append(f"Hole {self.position + 1} skipped: {error}")
            self.results.append(HoleResult(self.position + 1, "(broken)", 0, None))
            self.position += 1
        return holes[self.position] if self.position < len(holes) else None

    @property
    def number(self) -> int:
        return self.position + 1

    @property
    def hole_count(self) -> int:
        return len(self.course.holes)

    def finish_hole(self, strokes: int, picked_up: bool) -> HoleResult:
        hole = self.current()
        assert hole is not None, "no hole is being played"
        result = HoleResult(self.number, hole.spec.name, hole.spec.par, strokes, picked_up)
        self.results.append(result)
        self.position += 1
        return result

    @property
    def over(self) -> bool:
        return self.current() is None

    @property
    def played(self) -> list[HoleResult]:
        return [r for r in self.results if r.strokes is not None]

    @property
    def total_par(self) -> int:
        return sum(r.par for r in self.played)

    @property
    def total_strokes(self) -> int:
        return sum(r.strokes for r in self.played)  # type: ignore[misc]


@dataclass
class Game:
    """Everything the screens share: content, the player's choices, and the round in progress."""

    courses: list[Course]
    themes: list[Theme]
    theme_index: int = 0
    shape_label: str = CATALOGUE[2][0]
    shape: ShapeSpec = CATALOGUE[2][1]
    course_index: int = 0
    preset: str = "balanced"
    round: Round | None = None
    guide_seen: bool = False
    problems: list[str] = field(default_factory=list)  # content that could not be read, for the menu
    sound: SoundBoard = field(default_factory=lambda: SoundBoard(ArcadePlayer()))

    @classmethod
    def load(cls) -> Game:
        """The shipped and the player's content; what cannot be read is left out and reported."""
        courses, course_problems = load_all_courses()
        themes, theme_problems = load_themes()
        return cls(courses=courses, themes=themes, problems=[str(p) for p in course_problems + theme_problems])

    @property
    def theme(self) -> Theme:
        return self.themes[self.theme_index]

    @property
    def course(self) -> Course | None:
        """The chosen course; None only when no course file could be read."""
        return self.courses[self.course_index] if self.courses else None

    def next_theme(self) -> None:
        self.theme_index = (self.theme_index + 1) % len(self.themes)

    def next_course(self) -> None:
        if self.courses:
            self.course_index = (self.course_index + 1) % len(self.courses)

    def next_shape(self) -> None:
        labels = [label for label, _ in CATALOGUE]
        i = labels.index(self.shape_label) + 1 if self.shape_label in labels else 0
        self.shape_label, self.shape = CATALOGUE[i % len(CATALOGUE)]

    def set_shape(self, label: str, shape: ShapeSpec) -> None:
        self.shape_label, self.shape = label, shape

    def start_round(self, start_at: int = 0) -> Round:
        self.round = Round(self.course, position=start_at)
        return self.round
