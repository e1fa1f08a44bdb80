"""Random nine built in a background thread, so its screen can show the progress and stay responsive.

Why a thread and not a hole per frame: proving one hole takes seconds, and a window that draws nothing
for seconds looks hung. The thread waits on the worker processes that prove the holes
(`engine.golf.nine.build_nine`); should it ever simulate itself (one worker), it is the only one to:
esper keeps its worlds in module state, so two threads must never simulate at once, and the screen
that shows the build draws text only and leaves for the menu only after the thread has stopped.
"""

from __future__ import annotations

import inspect
import threading
import time
from collections.abc import Callable

from polygolf.engine.golf.holes import Course
from polygolf.engine.golf.nine import NINE, BuildCancelled, build_nine


class NineBuild:
    """One build of Random nine for `seed`; read `hole`, `course`, `error` and `finished` from any thread."""

    def __init__(self, seed: int, build: Callable[..., Course] | None = None) -> None:
        self.seed = seed
        self.total = NINE
        self.hole = 0  # the hole being built (1-based); 0 before the first
        self.waiting = False  # for another game building the same seed (until this one builds or has it)
        self.course: Course | None = None
        self.error: str | None = None
        self.started = 0.0
        self.seconds = 0.0
        self._build = build or build_nine
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, name=f"random-nine-{seed}", daemon=True)

    def start(self) -> NineBuild:
        self.started = time.perf_counter()
        self._thread.start()
        return self

    def _run(self) -> None:
        try:
            told = {"waiting": self._waiting} if _takes(self._build, "waiting") else {}
            self.course = self._build(self.seed, progress=self._progress, cancelled=self._stop.is_set, **told)
        except BuildCancelled:
            pass
        except Exception as exc:  # any failure is shown on the screen, never a dead thread and a hung screen
            self.error = str(exc) or type(exc).__name__
        finally:
            self.seconds = time.perf_counter() - self.started

    def _progress(self, hole: int, total: int) -> None:
        self.hole, self.total = hole, total

    def _waiting(self) -> None:
        self.waiting = True

    def cancel(self) -> None:
        """Stop soon: the workers are stopped, the holes finished are kept for next time."""
        self._stop.set()

    @property
    def cancelled(self) -> bool:
        return self._stop.is_set()

    @property
    def finished(self) -> bool:
        return self._thread.ident is not None and not self._thread.is_alive()

    def wait(self, timeout: float | None = None) -> bool:
        self._thread.join(timeout)
        return self.finished

    @property
    def status(self) -> str:
        """One line for the screen: what is happening now."""
        if self.error is not None:
            return f"Could not build it: {self.error}"
        if self.course is not None:
            if self.waiting and self.hole == 0:
                return f"Ready: another game built it (waited {self.seconds:.0f} s)"
            return f"Built in {self.seconds:.0f} s"
        if self.cancelled:
            return "Stopping (the holes finished are kept for next time)…"
        if self.hole == 0 and self.waiting:
            return "Another game is building it: waiting for it…"
        if self.hole == 0:
            return "Looking for holes already built…"
        return f"Building hole {self.hole} of {self.total}…"


def _takes(build: Callable[..., Course], name: str) -> bool:
    """Whether `build` takes the keyword `name` (a build given in its place may take only the first ones)."""
    try:
        parameters = inspect.signature(build).parameters.values()
    except (TypeError, ValueError):
        return False
    return any(p.name == name or p.kind is p.VAR_KEYWORD for p in parameters)
