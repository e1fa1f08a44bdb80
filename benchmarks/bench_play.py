"""Frames per second of the play view at 1280x720 on this machine's renderer, and physics time per
frame on every hole (a benchmark script, not a test). Needs a display: run it under xvfb-run.

    xvfb-run -a -s "-screen 0 1280x720x24" python benchmarks/bench_play.py [--frames 240] [--course meadow]

The scripted golfer plays each hole so the ball is moving most of the time. A frame is on_update
(given the real time since the last frame, as arcade would: the accumulator steps as many 1/60 s
physics frames as are due, plays sounds, updates the HUD) + on_draw + the buffer swap; FPS is
1 / median frame time, so it is what the game could reach without vsync. "speed" is game time over
the real time the frames took (a hole's restart and the golfer's planning left out): 1.00 means the
ball rolls at real speed whatever the frame rate; only frames longer than the 0.25 s catch-up cap
lose time. The physics figure is the median time of one physics frame (HolePlay.step) as the view steps it.
"""

from __future__ import annotations

import argparse
import statistics
import time

import arcade

from polygolf.engine.golf.golfer import golfer_for
from polygolf.engine.golf.holes import find_course
from polygolf.engine.physics.settings import FRAME_DT
from polygolf.game.flow import ScreenFlow
from polygolf.game.session import Game
from polygolf.game.views.play import PlayView


def timed_steps(world, physics: list[float]) -> None:
    """Time every physics frame the view steps on `world` into `physics` (seconds), without changing
    what is stepped."""
    step = world.step

    def timed(*args, **kwargs):
        t0 = time.perf_counter()
        step(*args, **kwargs)
        physics.append(time.perf_counter() - t0)

    world.step = timed


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--frames", type=int, default=240, help="frames measured per hole")
    parser.add_argument("--course", default="meadow")
    parser.add_argument("--preset", default="balanced")
    args = parser.parse_args()

    window = arcade.Window(1280, 720, "PolyGolf benchmark", vsync=False)
    game = Game.load()
    game.course_index = game.courses.index(find_course(game.courses, args.course))
    game.preset = args.preset
    print(f"{game.course.name}, preset {args.preset}, {args.frames} frames a hole, 1280x720, "
          f"renderer: {window.ctx.info.RENDERER}")
    print(f"{'hole':<18}{'frame ms':>10}{'fps':>8}{'draw ms':>9}{'speed':>7}{'physics us':>12}{'p95 physics us':>16}")
    all_frames, all_physics, speeds = [], [], []
    flow = ScreenFlow(window, game)
    for number in range(1, len(game.course.holes) + 1):
        view = PlayView(game, game.start_round(number - 1), flow)
        window.show_view(view)
        world = view.world
        golfer = golfer_for(world.hole)
        frames, draws, physics = [], [], []
        timed_steps(world, physics)
        last = time.perf_counter()
        played, stepped_before = 0.0, 0  # real seconds handed to the game; frames stepped before them
        for i in range(args.frames + 10):
            outside = time.perf_counter()  # a restart and the golfer's thinking are not play time
            if world.state.finished:  # the hole again from the start (R would only add a penalty stroke)
                view.session.restart_hole()
                view.start_hole()
                world = view.world
                timed_steps(world, physics)
                golfer = golfer_for(world.hole)
            if world.ball_at_rest:
                world.shoot(*golfer.plan((world.ball.x, world.ball.y)))
            last += time.perf_counter() - outside
            t0 = time.perf_counter()
            if i == 10:
                stepped_before = len(physics)
            if i >= 10:
                played += t0 - last
            view.on_update(t0 - last)  # the accumulator steps what the real time calls for
            last = t0
            t1 = time.perf_counter()
            view.on_draw()
            window.flip()
            window.dispatch_events()
            t2 = time.perf_counter()
            frames.append(t2 - t0)
            draws.append(t2 - t1)
        speed = (len(physics) - stepped_before) * FRAME_DT / played
        frames, draws = frames[10:], draws[10:]
        speeds.append(speed)
        all_frames += frames
        all_physics += physics
        frame_ms = statistics.median(frames) * 1e3
        print(f"{world.hole.spec.name:<18}{frame_ms:>10.2f}{1000 / frame_ms:>8.0f}"
              f"{statistics.median(draws) * 1e3:>9.2f}{speed:>7.2f}{statistics.median(physics) * 1e6:>12.0f}"
              f"{statistics.quantiles(physics, n=20)[-1] * 1e6:>16.0f}", flush=True)
        world.close()
    frame_ms = statistics.median(all_frames) * 1e3
    print(f"{'all holes':<18}{frame_ms:>10.2f}{1000 / frame_ms:>8.0f}{'':>9}{min(speeds):>7.2f}"
          f"{statistics.median(all_physics) * 1e6:>12.0f}{statistics.quantiles(all_physics, n=20)[-1] * 1e6:>16.0f}")
    window.close()


if __name__ == "__main__":
    main()
