"""The first screen: the physics engine's compiled kernels made ready, with a bar, before anything
steps physics.

A first launch compiles them (seconds, `game.startup`); later launches load them from numba's cache
in a fraction of a second and this screen is gone after a frame or two. The warm-up steps run in
`on_update`, as many as fit in FRAME_BUDGET but at least one, and only after a frame has been drawn
since the last: the window shows the bar and the step being compiled between two long steps (it does
not answer while one runs; none takes more than a few seconds). Started from a terminal, the same
compile also shows as the command line's one stderr line (`startup.ConsoleProgress`).
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence

import arcade

from polygolf.game.session import Game
from polygolf.game.startup import ConsoleProgress, first_launch_seconds, watching_compiles
from polygolf.game.views.navigation import window_key
from polygolf.game.views.widgets import title

BAR = (560, 22)  # pixels, as the Random nine build's
FRAME_BUDGET = 0.05  # s of warm-up steps in one frame: cached steps take milliseconds, all go in one

Step = tuple[str, Callable[[], None]]


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
        self.done = 0  # steps run
        self.drawn = False  # a frame drawn since the last steps ran
        self.finished = False
        self.started = time.perf_counter()
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

    def on_update(self, delta_time: float) -> None:
        if self.finished or not self.drawn:
            return  # the screen is drawn before the first step, which may take seconds
        began, total = time.perf_counter(), len(self.steps)
        try:
            with watching_compiles(self.console):
                while self.done < total:
                    label, warm = self.steps[self.done]
                    self.console(self.done, total, label)
                    warm()
                    self.done += 1
                    if time.perf_counter() - began > FRAME_BUDGET:
                        break
        except BaseException:
            self.console.close()
            raise
        self.drawn = False
        if self.done == total:
            self.finished = True
            self.console(total, total, "ready")
            self.console.close()
            self.then()

    def on_key_press(self, symbol: int, modifiers: int) -> None:
        window_key(self.window, self.game, symbol)

    def on_draw(self) -> None:
        self.clear()
        theme = self.game.theme
        w, h = self.window.width, self.window.height
        self.title.position = (w / 2, h / 2 + 140)  # the block in the middle of the window
        self.title.draw()
        width = min(760, w - 60)
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
        bw, bh = min(BAR[0], w - 60), BAR[1]
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
