"""The first screen: the physics engine's compiled kernels made ready, with a bar, before anything
steps physics.

A first launch compiles them (a minute, `game.startup`); later launches load them from numba's
cache in a fraction of a second and this screen is gone as soon. The warm-up steps run one after the
other on a thread of their own, started once the screen has been drawn, while the window goes on
drawing and answering (numba's compiler is Python and LLVM: the window's thread gets the interpreter
every few milliseconds; a frame is seldom late by more than a quarter of a second). Nothing else
steps physics until they are done. Started from a terminal, the same compile also shows as the
command line's one stderr line (`startup.ConsoleProgress`).
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

import arcade

from polygolf.game.session import Game
from polygolf.game.startup import ConsoleProgress, first_launch_seconds, watching_compiles
from polygolf.game.views.navigation import window_key
from polygolf.game.views.widgets import title

if TYPE_CHECKING:  # (the engine, and numba with it, is imported when the screen starts)
    from polygolf.engine.physics.jit import Step

BAR = (560, 22)  # pixels, as the Random nine build's
LOADING_DRAW_RATE = 1 / 10  # s between frames while the kernels compile


class LoadingView(arcade.View):
    def __init__(self, game: Game, then: Callable[[], None], steps: Sequence[Step] | None = None,
                 console: ConsoleProgress | None = None) -> None:
        super().__init__()
        if steps is None:
            from polygolf.engine.physics.jit import kernel_steps

            steps = kernel_steps()
        self.game = game
        self.then = then
        self.steps = list(steps)
        self.console = console if console is not None else ConsoleProgress()
        self.done = 0  # steps run (written by the warm-up thread)
        self.drawn = False  # a frame has been drawn: the warm-up may start
        self.finished = False
        self.error: BaseException | None = None  # what stopped the warm-up thread, raised on the window's
        self._worker: threading.Thread | None = None
        self.started = time.perf_counter()
        self._draw_rate = 1 / 60  # the window's, given back when the screen goes
        theme = game.theme
        self.background_color = theme.rgba("background")
        self.title = title("PolyGolf", theme, 48)
        self.explain = arcade.Text(
            "Preparing the physics engine — first launch compiles it (about "
            f"{first_launch_seconds(len(self.steps))} s); later launches start at once",
            0, 0, theme.rgba("text"), 16, anchor_x="center", anchor_y="center", multiline=True, width=760,
            align="center", italic=True)
        self.status = arcade.Text("", 0, 0, theme.rgba("text"), 18, anchor_x="center", anchor_y="center", bold=True)
        self.elapsed = arcade.Text("", 0, 0, theme.rgba("text"), 13, anchor_x="center", anchor_y="center")

    @property
    def fraction(self) -> float:
        """How much of the work is done, 0 to 1."""
        return self.done / len(self.steps) if self.steps else 1.0

    def on_show_view(self) -> None:
        # A bar needs few frames: the core a software renderer (llvmpipe) would spend on 60 goes to
        # the compile's helper process instead (`jit.helped`).
        self._draw_rate = getattr(self.window, "_draw_rate", 1 / 60)
        self.window.set_draw_rate(max(self._draw_rate, LOADING_DRAW_RATE))

    def on_hide_view(self) -> None:
        self.window.set_draw_rate(self._draw_rate)

    def on_update(self, delta_time: float) -> None:
        if self.finished or not self.drawn:
            return  # the screen is drawn before the first step, which may take seconds
        if self._worker is None:
            self._worker = threading.Thread(target=self._warm_up, name="warm-up", daemon=True)
            self._worker.start()
        if self._worker.is_alive():
            return
        self._worker.join()
        self.finished = True
        self.console.close()
        if self.error is not None:
            raise self.error
        self.then()

    def _warm_up(self) -> None:
        """Every step in order, on the warm-up thread."""
        from polygolf.engine.physics.jit import helped, settle

        total = len(self.steps)
        try:
            with watching_compiles(self.console), helped(self.steps) as steps:
                for label, warm in steps:
                    self.console(self.done, total, label)
                    warm()
                    self.done += 1
            settle()
            self.console(total, total, "ready")
        except BaseException as error:  # noqa: BLE001 - handed to the window's thread, raised there
            self.error = error

    def on_key_press(self, symbol: int, modifiers: int) -> None:
        window_key(self.window, self.game, symbol)

    def on_draw(self) -> None:
        self.clear()
        theme = self.game.theme
        w, h = self.window.width, self.window.height
        self.title.position = (w / 2, h / 2 + 140)  # the block in the middle of the window
        self.title.draw()
        width = max(1, min(760, w - 60))
        if self.explain.width != width:
            self.explain.width = width
        self.explain.position = (w / 2, h / 2 + 65)
        self.explain.draw()
        total = len(self.steps)
        if self.done < total:
            self.status.text = f"Step {self.done + 1} of {total}: {self.steps[self.done][0]}"
        else:
            self.status.text = "Ready"
        self.status.position = (w / 2, h / 2 - 10)
        self.status.draw()
        bw, bh = max(0.0, min(BAR[0], w - 60)), BAR[1]  # (never negative in a window under the smallest size)
        left, bottom = (w - bw) / 2, h / 2 - 62
        arcade.draw_lrbt_rectangle_filled(left, left + bw, bottom, bottom + bh, theme.rgba("panel"))
        arcade.draw_lrbt_rectangle_filled(left, left + bw * self.fraction, bottom, bottom + bh, theme.rgba("button"))
        arcade.draw_lrbt_rectangle_outline(left, left + bw, bottom, bottom + bh, theme.rgba("text"), 2)
        seconds = time.perf_counter() - self.started
        if seconds >= 1.0:  # not "0 s" on a start that is over before it could be read
            self.elapsed.text = f"{seconds:.0f} s so far"
            self.elapsed.position = (w / 2, bottom - 30)
            self.elapsed.draw()
        self.drawn = True
