"""What the play screen's helpers cost (a benchmark script, not a test; no display needed):

- the aim hint's latency through the worker process: from asking to the answer, the first one with
  the worker's start, then each Meadow hole from its tee (search at preset fast, effort quick);
- the shot preview's cost per recompute (one shot simulated up to its first contact, inline in the
  game's process) over a spread of arrows from every tee of Meadow and Hazards, per preset.

    python benchmarks/bench_caddie.py [--preset fast --preset balanced]
"""

from __future__ import annotations

import argparse
import math
import statistics
import time

from polygolf.engine.golf.holes import find_course, load_all_courses
from polygolf.engine.golf.play import HolePlay
from polygolf.engine.physics.jit import compile_kernels
from polygolf.game.caddie import preview_path
from polygolf.game.golfer_process import GolferProcess, question_for
from polygolf.game.shapes import CATALOGUE

SHAPE = CATALOGUE[2][1]  # the pentagon, the game's default ball


def hint_latency(courses) -> None:
    golfers = GolferProcess()
    try:
        print("hint latency (worker process, skill 1): hole, seconds")
        for k, hole in enumerate(find_course(courses, "meadow").holes):
            play = HolePlay(hole, SHAPE, "balanced")
            question = question_for(play, SHAPE, 1.0)
            play.close()
            started = time.perf_counter()
            golfers.ask(question).result()
            note = " (with the worker's start)" if k == 0 else ""
            print(f"  {hole.spec.name:<16} {time.perf_counter() - started:5.2f}{note}")
    finally:
        golfers.close()


def preview_cost(courses, preset: str) -> None:
    costs = []
    for name in ("meadow", "hazards"):
        for hole in find_course(courses, name).holes:
            play = HolePlay(hole, SHAPE, preset)
            ball = (play.ball.x, play.ball.y)
            for k in range(8):
                for length in (1.0, 2.5, 5.0):  # gentle to the strongest shot
                    a = k * math.pi / 4 + 0.1
                    started = time.perf_counter()
                    preview_path(play, SHAPE, ball, (length * math.cos(a), length * math.sin(a)))
                    costs.append((time.perf_counter() - started) * 1e3)
            play.close()
    costs.sort()
    print(f"preview at {preset}: {len(costs)} arrows, median {statistics.median(costs):.1f} ms, "
          f"90th percentile {costs[int(0.9 * len(costs))]:.1f} ms, worst {costs[-1]:.1f} ms")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--preset", action="append", default=None, help="preset(s) for the preview (fast, balanced)")
    args = parser.parse_args()
    courses = load_all_courses()[0]
    hint_latency(courses)
    compile_kernels()  # as the game does before its first screen (else the first preview loads them: 0.1 s)
    for preset in args.preset or ["fast", "balanced"]:
        preview_cost(courses, preset)


if __name__ == "__main__":
    main()
