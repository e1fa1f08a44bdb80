"""A round as data: every input that changed the simulation, at the frame it came, so the round can be
simulated again bit for bit (the engine is deterministic), and how each hole ended, to check that it was.

The file is JSON (`replays/*.json` in the data folder). Floats are written with `repr`, which reads back
to the same double, so recorded grab points, arrows and final ball states survive the round trip exactly.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError

from polygolf.engine.golf.holes import Course, Hole
from polygolf.engine.loading.scene import ShapeSpec

FORMAT = "polygolf-replay"
FORMAT_VERSION = 1
MAX_REPLAY_BYTES = 16 * 1024 * 1024
MAX_HOLE_FRAMES = 60 * 60 * 60  # an hour of play on one hole: more is not a round, and would take long to check
Frame = Annotated[int, Field(ge=0, le=MAX_HOLE_FRAMES)]


class ReplayError(ValueError):
    """A replay file that cannot be read; str() is one line naming the file and what is wrong."""


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid")


class Input(_Strict):
    """One thing a player did, before frame `frame` of the hole was stepped: a shot (grab point and
    arrow, world metres), a restart (back to the tee, a penalty stroke), or a preset switch."""

    frame: Frame
    kind: Literal["shot", "restart", "preset"]
    player: Annotated[int, Field(ge=0, le=3)] = 0
    grab: tuple[float, float] | None = None
    arrow: tuple[float, float] | None = None
    preset: Literal["fast", "balanced", "accurate"] | None = None


class BallEnd(_Strict):
    """How one player's ball ended a hole: its score and its body's state, to compare bit for bit."""

    strokes: int
    penalties: int
    holed: bool
    picked_up: bool
    body: tuple[float, float, float, float, float, float]  # x, y, angle, vx, vy, spin


class HoleRecord(_Strict):
    position: Annotated[int, Field(ge=0)]  # index of the hole in its course
    hole: str  # the hole's id (file name), to say which hole a mismatch is on
    preset: Literal["fast", "balanced", "accurate"]  # at the hole's start
    inputs: list[Input] = []
    frames: Frame = 0  # frames stepped until every ball was finished
    final: list[BallEnd] = []


class RoundRecord(_Strict):
    format: Literal["polygolf-replay"] = FORMAT
    version: Literal[1] = FORMAT_VERSION
    game_version: str = ""
    recorded_at: str = ""
    course: str  # course id
    course_name: str
    fingerprint: str  # of the content played (see `fingerprint`)
    shape_label: str
    shape: ShapeSpec
    preset: Literal["fast", "balanced", "accurate"]
    players: Annotated[list[Annotated[str, Field(min_length=1, max_length=100)]], Field(min_length=1, max_length=4)]
    start_at: Annotated[int, Field(ge=0)] = 0
    holes: list[HoleRecord] = []

    def save(self, folder: Path) -> Path:
        """Write the record as `folder/<recorded_at>-<course>.json` (atomically: a temporary file
        renamed), and return the path."""
        folder.mkdir(parents=True, exist_ok=True)
        stamp = self.recorded_at.replace(":", "").replace("-", "")
        path = folder / f"{stamp}-{self.course}.json"
        n = 1
        while path.exists():
            n += 1
            path = folder / f"{stamp}-{self.course}-{n}.json"
        tmp = path.with_suffix(".tmp")
        tmp.write_text(json.dumps(self.model_dump(mode="json"), indent=1))
        tmp.replace(path)
        return path


def load_record(path: Path) -> RoundRecord:
    """A replay file, checked; anything wrong is a ReplayError of one line."""
    try:
        if path.stat().st_size > MAX_REPLAY_BYTES:
            raise ReplayError(f"{path}: larger than {MAX_REPLAY_BYTES // 1024 // 1024} MiB: not a replay")
        data = json.loads(path.read_bytes().decode("utf-8"))
    except OSError as exc:
        raise ReplayError(f"{path}: cannot read: {exc.strerror or exc}") from None
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise ReplayError(f"{path}: not a replay (not JSON: {exc})") from None
    if not isinstance(data, dict) or data.get("format") != FORMAT:
        raise ReplayError(f"{path}: not a replay (no \"format\": \"{FORMAT}\")")
    try:
        return RoundRecord.model_validate(data)
    except ValidationError as exc:
        error = exc.errors(include_url=False)[0]
        where = ".".join(str(part) for part in error["loc"]) or "(top)"
        raise ReplayError(f"{path}: {where}: {error['msg']}") from None


def hole_fingerprint(hole: Hole) -> str:
    """The parsed content a hole plays from: its spec and its tile library (comments and layout of
    the YAML do not matter; every number that reaches the simulation does)."""
    digest = hashlib.sha256()
    digest.update(hole.library.model_dump_json().encode())
    digest.update(hole.spec.model_dump_json().encode())
    return digest.hexdigest()


def fingerprint(course: Course) -> str:
    """A hash of every hole of the course (a broken hole by its error) and the libraries they use."""
    digest = hashlib.sha256(course.id.encode())
    for hole in course.holes:
        digest.update((hole_fingerprint(hole) if isinstance(hole, Hole) else f"broken:{hole}").encode())
    return digest.hexdigest()[:32]
