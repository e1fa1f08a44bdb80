"""Getting the physics engine ready before anything steps it.

The engine's kernels are compiled by numba: a first launch compiles them all (seconds), later launches
load them from numba's disk cache (a fraction of a second). Compiling them up front, rather than at
the first call of each, keeps that wait out of a measured run (`simulate`'s `wall_ms`), out of a
window's first frames, and out of worker processes (they load what this process compiled and cached).

One place for it: a command that steps physics headless calls `prepare_physics`, which says what is
happening on one updating stderr line (stdout stays clean: some commands print JSON), only when numba
really compiles and it has taken long enough to notice. Elapsed time alone cannot tell: a load from
the cache on a busy machine can take as long as compiling a small group, and the line says
"Compiling". numba's "numba:compile" event fires for a compile, never for a load from the cache. The
window runs the same steps (`kernel_steps`) on its loading screen (`views/loading.py`).
"""

from __future__ import annotations

import math
import sys
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import TextIO

QUIET_FOR = 0.3  # s of compiling before the line shows: a moment's wait needs no explanation
SECONDS_PER_STEP = 7.5  # a rough first-launch compile of one warm-up group on 2 cores (9 groups, a helper: 64 s)
LEAD = "Compiling the physics engine (first launch only)"


def first_launch_seconds(steps: int) -> int:
    """What a first launch's compile is announced to take: rounded up to 5 s, it need not be exact."""
    return max(5, 5 * math.ceil(steps * SECONDS_PER_STEP / 5))


class ConsoleProgress:
    """`compile_kernels`'s progress callback, written as one line to `stream` (stderr).

    Nothing is written unless numba compiles (`compiling`, set by `watching_compiles`) and the work
    has taken `quiet_for` seconds; a timer shows the line while a long step runs, not only between
    steps. On a terminal the line is rewritten in place (\\r); elsewhere (a log, a pipe) each step
    is a line of its own.
    """

    def __init__(self, stream: TextIO | None = None, quiet_for: float = QUIET_FOR,
                 clock: Callable[[], float] = time.perf_counter) -> None:
        self.stream = stream if stream is not None else sys.stderr
        self.quiet_for = quiet_for
        self.clock = clock
        self.tty = bool(getattr(self.stream, "isatty", lambda: False)())
        self.compiling = False  # numba has compiled something (not only loaded its cache)
        self.shown = False  # a line has been written
        self.finished = False
        self.started: float | None = None
        self._text = ""
        self._width = 0  # of the line on screen, to blank what a shorter one leaves
        self._lock = threading.Lock()  # the timer writes from its own thread
        self._timer: threading.Timer | None = None

    def __call__(self, done: int, total: int, label: str) -> None:
        with self._lock:
            if self.started is None:
                self.started = self.clock()
                self._arm(self.quiet_for)
            if done >= total:
                self._finish()
                return
            self._text = f"{LEAD}: {done + 1}/{total} {label}..."
            if self.shown or self._due():
                self._write(self._text)

    def close(self) -> None:
        """Stop the timer; if the work stopped half-way (an exception), end the line it left open."""
        with self._lock:
            self._stop_timer()
            if self.shown and not self.finished and self.tty:
                self.stream.write("\n")
                self.stream.flush()
            self.finished = True

    def _due(self) -> bool:
        assert self.started is not None
        return self.compiling and self.clock() - self.started > self.quiet_for

    def _arm(self, seconds: float) -> None:
        self._timer = threading.Timer(seconds, self._wake)
        self._timer.daemon = True
        self._timer.start()

    def _wake(self) -> None:
        with self._lock:
            if self.finished or self.shown:
                return
            if self._text and self._due():
                self._write(self._text)
            else:
                self._arm(0.1)  # a compile may start later (a cache missing some kernels)

    def _write(self, text: str) -> None:
        self.shown = True
        if self.tty:
            self.stream.write("\r" + text.ljust(self._width))
            self._width = len(text)
        else:
            self.stream.write(text + "\n")
        self.stream.flush()

    def _finish(self) -> None:
        self._stop_timer()
        self.finished = True
        if not self.shown:
            return
        assert self.started is not None
        text = f"{LEAD}: done in {self.clock() - self.started:.1f} s"
        self.stream.write(("\r" + text.ljust(self._width) if self.tty else text) + "\n")
        self.stream.flush()

    def _stop_timer(self) -> None:
        if self._timer is not None:
            self._timer.cancel()
            self._timer = None


@contextmanager
def watching_compiles(progress: ConsoleProgress) -> Iterator[None]:
    """Set `progress.compiling` when numba starts a compile (its "numba:compile" event fires for a
    compile, never for a load from the cache). Without numba nothing compiles."""
    try:
        from numba.core import event
    except ImportError:
        yield
        return

    class Listener(event.Listener):
        def on_start(self, _event: event.Event) -> None:
            progress.compiling = True

        def on_end(self, _event: event.Event) -> None:
            pass

    with event.install_listener("numba:compile", Listener()):
        yield


def prepare_physics(stream: TextIO | None = None) -> float:
    """Compile (first launch) or load (from the cache) every physics kernel before a command steps
    physics, with a console line while numba compiles. Returns the seconds it took."""
    from polygolf.engine.physics.jit import compile_kernels

    progress = ConsoleProgress(stream)
    try:
        with watching_compiles(progress):
            return compile_kernels(progress)
    finally:
        progress.close()
