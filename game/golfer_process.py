"""The search golfer (`engine.golf.search`) in a worker process, for the play screen's aim hint and
the computer opponent.

A search simulates about a hundred real shots: 1–6 s of CPU at effort "quick", preset "fast". It must
never run in a thread beside the game's world, because esper 3 keeps the current world in module
state and a search switches worlds all the time. So it runs in one worker process of its own: spawned
(nothing of the window is inherited), started the first time a question is asked, shut down with the
game. Questions carry everything the search needs (the hole and ball shape pickle), and the answer is
a `Shot`; the screen polls the future from its `on_update` and never waits.

This module imports no arcade, so the worker starts quickly and `autoplay` uses the same `answer`.
"""

from __future__ import annotations

import multiprocessing
import random
from concurrent.futures import Future, ProcessPoolExecutor
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass

from polygolf.engine.golf.holes import Hole
from polygolf.engine.golf.play import HolePlay
from polygolf.engine.golf.search import SearchGolfer
from polygolf.engine.golf.shots import Shot
from polygolf.engine.loading.scene import ShapeSpec
from polygolf.engine.physics.polygon import Outline, Vec, placed

SEARCH_PRESET = "fast"  # the hint's and the computer's search: fast physics, as `polygolf par` proves holes
SEARCH_EFFORT = "quick"
GOLFERS_KEPT = 4  # holes whose route map a worker keeps (building one costs 0.05–0.5 s)


@dataclass(frozen=True)
class Question:
    """Which shot to play: a ball of `shape` at rest at `start`, turned `angle`, on `hole` whose
    windmills stand at `windmills` (rad) and the other players' balls lie as `others` (outlines), by a
    golfer of `skill` (1 exact; the noise drawn from `seed`)."""

    hole: Hole
    shape: ShapeSpec
    start: Vec
    angle: float
    windmills: tuple[float, ...]
    skill: float = 1.0
    seed: int = 0
    knobs: str = SEARCH_PRESET
    effort: str = SEARCH_EFFORT
    others: tuple[Outline, ...] = ()


def question_for(hole: HolePlay, shape: ShapeSpec, skill: float = 1.0, seed: int = 0,
                 knobs: str = SEARCH_PRESET) -> Question:
    """The question for the ball whose turn it is, as it lies now, among the other balls still in
    play where they rest (the search meets them as walls: it does not plan a shot through them)."""
    ball = hole.ball
    return Question(hole.hole, shape, (ball.x, ball.y), ball.angle, tuple(w.angle for w in hole.windmills),
                    skill, seed, knobs, others=other_balls(hole))


def other_balls(hole: HolePlay) -> tuple[Outline, ...]:
    """The outlines, where they rest, of the balls of the players whose turn it is not and who
    are still playing the hole (a finished ball has left the green)."""
    return tuple(placed(p.collider.outline, p.body.x, p.body.y, p.body.angle)
                 for seat, p in enumerate(hole.players) if seat != hole.turn and not p.state.finished)


def origin_of(shot: Shot) -> Vec:
    """Where the player presses to play `shot`: the ball's centre plus the shot's grab offset."""
    return shot.start[0] + shot.grab[0], shot.start[1] + shot.grab[1]


_golfers: dict[tuple, SearchGolfer] = {}  # in each process: the golfer of a hole, kept between strokes


def _golfer(q: Question) -> SearchGolfer:
    key = (q.hole.id, str(q.hole.path), q.shape.model_dump_json(), q.knobs, q.effort)
    golfer = _golfers.get(key)
    if golfer is None or golfer.hole.spec != q.hole.spec or golfer.hole.layout != q.hole.layout:
        while len(_golfers) >= GOLFERS_KEPT:
            _golfers.pop(next(iter(_golfers)))
        golfer = _golfers[key] = SearchGolfer(q.hole, q.shape, q.knobs, q.effort)
    return golfer


def answer(q: Question) -> Shot:
    """The shot a golfer of `q.skill` plays (runs in the worker; `autoplay` calls it directly)."""
    golfer = _golfer(q)
    return golfer.aim(q.start, q.angle, q.windmills, q.skill, random.Random(q.seed), obstacles=q.others)


def _ready() -> bool:
    return True


class GolferProcess:
    """One worker process answering `Question`s, started on the first question (or `warm_up`) and
    shut down by `close`. `inline=True` answers in the caller's thread instead (headless tests: nothing
    else runs beside it there)."""

    def __init__(self, inline: bool = False) -> None:
        self.inline = inline
        self._pool: ProcessPoolExecutor | None = None

    @property
    def started(self) -> bool:
        return self._pool is not None

    def _executor(self) -> ProcessPoolExecutor:
        if self._pool is None:
            self._pool = ProcessPoolExecutor(max_workers=1, mp_context=multiprocessing.get_context("spawn"))
        return self._pool

    def warm_up(self) -> None:
        """Start the worker now (its imports take a second or two), so the first answer comes sooner."""
        if not self.inline and self._pool is None:
            self._executor().submit(_ready)

    def ask(self, question: Question) -> Future:
        """The answer, to be polled with `done()`; it raises in `result()` if the search failed."""
        if self.inline:
            future: Future = Future()
            try:
                future.set_result(answer(question))
            except Exception as exc:  # handed to whoever polls, as the process would
                future.set_exception(exc)
            return future
        try:
            return self._executor().submit(answer, question)
        except BrokenProcessPool:  # the worker died (killed, out of memory): start another once
            self.close()
            return self._executor().submit(answer, question)

    def close(self) -> None:
        """Stop the worker without waiting for a search it is running (it would hold up the exit)."""
        pool, self._pool = self._pool, None
        if pool is None:
            return
        processes = list(getattr(pool, "_processes", {}).values())  # the executor has no public handle
        pool.shutdown(wait=False, cancel_futures=True)
        for process in processes:
            if process.is_alive():
                process.terminate()
        for process in processes:
            process.join(timeout=1.0)
            if process.is_alive():  # SIGTERM not acted on in time (a loaded machine): no second chance
                process.kill()
                process.join(timeout=1.0)
