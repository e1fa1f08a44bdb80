"""A round as data: every input that changed the simulation, at the frame it came, so the round can be
simulated again bit for bit (the engine is deterministic), and how each hole ended, to check that it was.

The file is JSON (`replays/*.json` in the data folder). Floats are written with `repr`, which reads back
to the same double, so recorded grab points, arrows and final ball states survive the round trip exactly.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import re
import secrets
import stat
import time
from datetime import datetime, timezone
from functools import cache
from pathlib import Path
from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError

from polygolf.engine.golf.holes import Course, Hole
from polygolf.engine.loading.limits import Name
from polygolf.engine.loading.scene import ShapeSpec
from polygolf.engine.loading.yamlsource import read_at_most
from polygolf.engine.physics.jit import engine_fingerprint

FORMAT = "polygolf-replay"
FORMAT_VERSION = 1
MAX_REPLAY_BYTES = 16 * 1024 * 1024
MAX_FILE_COURSE = 60  # characters of the course id in a replay's file name
MAX_INT_DIGITS = 20  # with a sign: every count in a replay is far smaller
MAX_HOLE_FRAMES = 60 * 60 * 60  # an hour of play on one hole: more is not a round, and would take long to check
# Numbers as JSON writes them, no other type taken for one ("0", true, "nan" and "1e999" are not a frame or
# a coordinate), and finite.
Count = Annotated[int, Field(strict=True)]
Frame = Annotated[int, Field(ge=0, le=MAX_HOLE_FRAMES, strict=True)]
Number = Annotated[float, Field(strict=True, allow_inf_nan=False)]




def utc_stamp() -> str:
    """Now in UTC to the second, as a round's record and the rounds kept are stamped."""
    return datetime.now(timezone.utc).strftime("%Y-%m-%dT%H:%M:%S")


class ReplayError(ValueError):
    """A replay file that cannot be read; str() is one line naming the file and what is wrong."""


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid")


class Input(_Strict):
    """One thing a player did, before frame `frame` of the hole was stepped: a shot (grab point and
    arrow, world metres), a restart (back to the tee, a penalty stroke), or a preset switch."""

    frame: Frame
    kind: Literal["shot", "restart", "preset"]
    player: Annotated[int, Field(ge=0, le=3, strict=True)] = 0
    grab: tuple[Number, Number] | None = None
    arrow: tuple[Number, Number] | None = None
    preset: Literal["fast", "balanced", "accurate"] | None = None


class BallEnd(_Strict):
    """How one player's ball ended a hole: its score and its body's state, to compare bit for bit."""

    strokes: Count
    penalties: Count
    holed: Annotated[bool, Field(strict=True)]
    picked_up: Annotated[bool, Field(strict=True)]
    body: tuple[Number, Number, Number, Number, Number, Number]  # x, y, angle, vx, vy, spin


class HoleRecord(_Strict):
    position: Annotated[int, Field(ge=0, strict=True)]  # index of the hole in its course
    hole: str  # the hole's id (file name), to say which hole a mismatch is on
    preset: Literal["fast", "balanced", "accurate"]  # at the hole's start
    inputs: list[Input] = []
    frames: Frame = 0  # frames stepped until every ball was finished
    final: list[BallEnd] = []


class RoundRecord(_Strict):
    format: Literal["polygolf-replay"] = FORMAT
    version: Literal[1] = FORMAT_VERSION
    game_version: str = ""
    engine: str = ""  # the physics engine's digest (`engine`); "" in replays from before it was kept
    recorded_at: str = ""
    course: str  # course id
    course_name: str
    fingerprint: str  # of the content played (see `fingerprint`)
    shape_label: str
    shape: ShapeSpec
    preset: Literal["fast", "balanced", "accurate"]
    # The one rule names have (`limits.Name`): `str.isprintable`, asked here before, refused the joiners
    # of a Persian or an emoji family's name, which the names screen takes (QA: no such round started).
    players: Annotated[list[Name], Field(min_length=1, max_length=4)]
    start_at: Annotated[int, Field(ge=0, strict=True)] = 0
    holes: list[HoleRecord] = []

    def save(self, folder: Path) -> Path:
        """Write the record as `folder/<recorded_at>-<course>.json` (or `-2`, `-3` ... after it, when
        another round of that second has the name), and return the path. The name is taken with an
        exclusive create, so two games saving at once never share one, and the text goes in by a
        temporary file of this process's renamed over it, so no reader sees half of it. The course id
        is made safe for a file name (a course's name may hold '/' or be long), so no round is lost
        for its name; the file itself says the course."""
        folder.mkdir(parents=True, exist_ok=True)
        text = json.dumps(self.model_dump(mode="json"), indent=1)
        stamp = _file_safe(self.recorded_at.replace(":", "").replace("-", ""))
        course = _file_safe(self.course)[:MAX_FILE_COURSE] or "_"
        linked = _save_linked(folder, text, stamp, course)
        if linked is not None:
            return linked
        n = 1
        while True:
            path = folder / (f"{stamp}-{course}.json" if n == 1 else f"{stamp}-{course}-{n}.json")
            try:
                path.open("x").close()  # this round's name now: no other process takes it
                break
            except FileExistsError:
                n += 1
        try:
            tmp = folder / f".{path.stem}-{os.getpid()}-{secrets.token_hex(4)}.tmp"  # (made with the usual mode)
            try:
                with tmp.open("x", encoding="utf-8") as out:
                    out.write(text)
                os.replace(tmp, path)
            except BaseException:
                tmp.unlink(missing_ok=True)
                raise
        except BaseException:
            path.unlink(missing_ok=True)  # (not a replay: the name goes back)
            raise
        return path


def _save_linked(folder: Path, text: str, stamp: str, course: str) -> Path | None:
    """The text written whole to a temporary file first, then given the first free name by a hard
    link (which fails if the name is taken): a game killed at any point leaves no empty replay
    (QA8: kill -9 between taking the name and writing it left a 0-byte one), only, at worst, a
    temporary that `sweep_replays` clears. None where the folder's file system has no hard links
    (the name is then taken first, as before)."""
    tmp = folder / f".{stamp}-{course}-{os.getpid()}-{secrets.token_hex(4)}.tmp"
    try:
        with tmp.open("x", encoding="utf-8") as out:
            out.write(text)
        n = 1
        while True:
            path = folder / (f"{stamp}-{course}.json" if n == 1 else f"{stamp}-{course}-{n}.json")
            try:
                os.link(tmp, path)
                return path
            except FileExistsError:
                n += 1
            except OSError:  # (no hard links here: EPERM, ENOTSUP, EXDEV...)
                return None
    finally:
        tmp.unlink(missing_ok=True)


STALE = 60.0  # s: an empty replay or a temporary older than this is no save under way


def sweep_replays(folder: Path, now: float | None = None) -> list[Path]:
    """Clear what a game killed while it saved a round can leave in the replays folder: an empty
    `*.json` (a name taken, the text never written) and a `.*.tmp` (the text, never renamed), once
    older than STALE (younger, they may be another game's save under way). Never raises: what cannot
    be read or removed is left. Returns what was removed."""
    now = time.time() if now is None else now
    gone = []
    try:
        found = list(folder.glob("*.json")) + list(folder.glob(".*.tmp"))
    except OSError:
        return gone
    for path in found:
        try:
            facts = path.lstat()
            if not stat.S_ISREG(facts.st_mode) or now - facts.st_mtime < STALE:
                continue
            if path.suffix == ".tmp" or facts.st_size == 0:
                path.unlink()
                gone.append(path)
        except OSError:
            continue
    return gone


def _file_safe(text: str) -> str:
    """`text` with every run of characters other than letters, digits, '-' and '_' made one '_'."""
    return re.sub(r"[^A-Za-z0-9_-]+", "_", text)


class _NotAReplayNumber(ValueError):
    """A number no replay holds: NaN, an infinity, or an integer too long to be a count."""


def _refuse_constant(name: str) -> float:
    raise _NotAReplayNumber(f"{name} is not a number JSON allows")


def _finite_float(text: str) -> float:
    value = float(text)
    if not math.isfinite(value):
        raise _NotAReplayNumber(f"{text[:20]} is out of range")
    return value


def _short_int(text: str) -> int:
    """Checked before converting: past 4,300 digits int() raises an error that names no file, and a
    long one is slow to convert."""
    if len(text) > MAX_INT_DIGITS:
        raise _NotAReplayNumber(f"an integer of {len(text):,} digits")
    return int(text)


def load_record(path: Path) -> RoundRecord:
    """A replay file, checked; anything wrong is a ReplayError of one line."""
    try:
        raw = read_at_most(path, MAX_REPLAY_BYTES)
    except OSError as exc:
        raise ReplayError(f"{path}: cannot read: {exc.strerror or exc}") from None
    if len(raw) > MAX_REPLAY_BYTES:
        raise ReplayError(f"{path}: larger than {MAX_REPLAY_BYTES // 1024 // 1024} MiB: not a replay")
    try:
        data = json.loads(raw.decode("utf-8"), parse_constant=_refuse_constant, parse_float=_finite_float,
                          parse_int=_short_int)
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise ReplayError(f"{path}: not a replay (not JSON: {exc})") from None
    except RecursionError:
        raise ReplayError(f"{path}: not a replay (nested too deeply)") from None
    except _NotAReplayNumber as exc:
        raise ReplayError(f"{path}: not a replay ({exc})") from None
    if not isinstance(data, dict) or data.get("format") != FORMAT:
        raise ReplayError(f"{path}: not a replay (no \"format\": \"{FORMAT}\")")
    try:
        return RoundRecord.model_validate(data)
    except ValidationError as exc:
        error = exc.errors(include_url=False)[0]
        where = ".".join(str(part) for part in error["loc"]) or "(top)"
        raise ReplayError(f"{path}: {where}: {error['msg'].removeprefix('Value error, ')}") from None


def hole_fingerprint(hole: Hole) -> str:
    """The parsed content a hole plays from: its spec and its tile library (comments and layout of
    the YAML do not matter; every number that reaches the simulation does)."""
    digest = hashlib.sha256()
    digest.update(hole.library.model_dump_json().encode())
    digest.update(hole.spec.model_dump_json().encode())
    return digest.hexdigest()


@cache
def engine() -> str:
    """This physics engine's digest (`jit.engine_fingerprint`: its kernels' sources and numba's
    version). A replay keeps the one it was recorded with: another engine need not replay it bit for
    bit, and `replay --verify` says so."""
    return engine_fingerprint()


def fingerprint(course: Course) -> str:
    """A hash of every hole of the course (a broken hole by its error) and the libraries they use."""
    digest = hashlib.sha256(course.id.encode())
    for hole in course.holes:
        digest.update((hole_fingerprint(hole) if isinstance(hole, Hole) else f"broken:{hole}").encode())
    return digest.hexdigest()[:32]
