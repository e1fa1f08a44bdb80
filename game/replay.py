"""Replays: a recorded round (`record.RoundRecord`) played again by the same session code that played
it (`session.RoundPlay` fed with its inputs), shown in a window or checked headless: `verify` passes
only if every hole ends with every ball's strokes, flags and body state bit for bit as recorded, and
every recorded input is one live play could have taken where it stands (none after the hole ended, no
shot while a ball still moved: the recorder writes no such)."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

from polygolf.engine.golf.holes import Course, load_all_courses
from polygolf.engine.golf.nine import COURSE_ID as RANDOM_NINE
from polygolf.engine.golf.nine import load_nine
from polygolf.game.record import ReplayError, RoundRecord, fingerprint, load_record
from polygolf.game.session import Round, RoundPlay

SLACK_FRAMES = 60  # a hole may run this much past its recorded end before it is called a mismatch


def load_for_replay(path: Path) -> tuple[RoundRecord, Course]:
    """The record and the course it was played on, as the content is now. A ReplayError (one line) if
    the file is not a replay, or the course is gone or changed since."""
    record = load_record(path)
    courses, _ = load_all_courses()
    course = next((c for c in courses if c.id == record.course), None)
    seed = record.course.removeprefix(f"{RANDOM_NINE}-")
    if course is None and record.course.startswith(f"{RANDOM_NINE}-") and seed.isdigit() and len(seed) < 20:
        course = load_nine(int(seed))  # a Random nine: the one built in the data folder, if it still is
    if course is None:
        raise ReplayError(f"{path}: course {record.course!r} is not in this game's content")
    if fingerprint(course) != record.fingerprint:
        raise ReplayError(f"{path}: the content of course {record.course!r} changed since the round was recorded")
    if not 0 <= record.start_at < len(course.holes):
        raise ReplayError(f"{path}: start_at: no hole {record.start_at + 1} in {course.name}")
    for hole in record.holes:
        if any(i.player >= len(record.players) for i in hole.inputs):
            raise ReplayError(f"{path}: holes: an input names a player who is not playing")
        if any(i.kind == "shot" and (i.grab is None or i.arrow is None) for i in hole.inputs):
            raise ReplayError(f"{path}: holes: a shot without its grab point or arrow")
        if any(i.kind == "preset" and i.preset is None for i in hole.inputs):
            raise ReplayError(f"{path}: holes: a preset switch without its preset")
    return record, course


def replay_session(record: RoundRecord, course: Course) -> RoundPlay:
    """A session that plays the recorded inputs, hole by hole, at their frames."""
    round_ = Round(course, players=list(record.players), position=record.start_at)
    feed = {hole.position: (hole.preset, list(hole.inputs)) for hole in record.holes}
    return RoundPlay(round_, record.shape, record.shape_label, record.preset, feed=feed)


def verify(record: RoundRecord, course: Course) -> Iterator[tuple[str, bool]]:
    """Play the round again headless: (line, matched) for each recorded hole, as each is played (a
    long round says how it goes)."""
    session = replay_session(record, course)
    try:
        for recorded in record.holes:
            hole = session.hole
            label = f"hole {recorded.position + 1} {recorded.hole}"
            if hole is None or session.round.position != recorded.position or hole.hole.id != recorded.hole:
                yield f"{label}: not the hole the round plays next", False
                break
            while session.ended is None and session.frame <= recorded.frames + SLACK_FRAMES:
                session.step()
            ended = session.ended
            # Inputs live play could never have recorded (after the hole ended, a second shot while the
            # balls still moved...) are no part of the round, even where the end is the same without them.
            bogus = session.refused + [f"the {i.kind} at frame {i.frame}: after the hole ended (frame {ended.frames})"
                                       for i in (session.unplayed if ended is not None else [])]
            if bogus:
                more = f"; and {len(bogus) - 1:,} more" if len(bogus) > 1 else ""
                yield (f"{label}: {len(bogus):,} of {len(recorded.inputs):,} recorded inputs could never have been "
                       f"taken ({bogus[0]}{more})", False)
                break
            if ended is None:
                yield (f"{label}: not finished {SLACK_FRAMES} frames after its recorded end "
                       f"(frame {recorded.frames})", False)
                break
            same = ended.final == recorded.final and ended.frames == recorded.frames
            scores = ", ".join(str(player.state.score) for player in hole.players)
            yield (f"{label}: {'identical' if same else 'DIFFERENT'} (frame {ended.frames} of {recorded.frames}; "
                   f"scores {scores})", same)
            session.finish_hole()
            session.start_hole()
    finally:
        session.close()
