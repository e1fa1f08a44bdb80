"""Physics cost per 60 Hz frame, per preset (a benchmark script, not a test).

    python benchmarks/bench_physics.py [--repeats 5] [--frames 120] [--skip-1000]

Scenarios: one ball among 24 wall blocks (always moving: elastic, no drag); 100 and 1000 pentagons
in a closed box. Each frame is timed on its own; the figure is the median over frames and repeats,
after a warm-up. Ratios are against `fast` measured in the same process, on the same scenario.
"""

from __future__ import annotations

import argparse
import math
import random
import statistics
import time

from polygolf.engine.loading.scene import Scene, build_scene
from polygolf.engine.physics.jit import compile_kernels
from polygolf.engine.physics.presets import PRESETS


def one_ball_among_blocks() -> Scene:
    """A 12 x 8 m room (4 walls) holding 20 pillar blocks, and one square ball bouncing about."""
    walls = [
        {"box": {"center": [-0.5, 4.0], "half": [0.5, 5.0]}},
        {"box": {"center": [12.5, 4.0], "half": [0.5, 5.0]}},
        {"box": {"center": [6.0, -0.5], "half": [7.0, 0.5]}},
        {"box": {"center": [6.0, 8.5], "half": [7.0, 0.5]}},
    ]
    for i in range(5):
        for j in range(4):
            walls.append({"box": {"center": [1.5 + 2.25 * i, 1.0 + 2.0 * j], "half": [0.3, 0.3],
                                  "angle": 15.0 * (i + j)}})
    ball = {"name": "ball", "shape": {"regular": 5, "radius": 0.25}, "position": [2.6, 2.0],
            "velocity": [11.0, 7.0], "spin": 3.0, "restitution": 1.0, "friction": 0.0}
    return Scene.model_validate({"name": "one-ball-24-blocks", "bodies": [ball], "walls": walls})


def pentagons_in_a_box(count: int, seed: int = 1) -> Scene:
    rng = random.Random(seed)
    side = math.ceil(math.sqrt(count))
    spacing = 0.6
    size = side * spacing + 0.6
    walls = [
        {"box": {"center": [-0.5, size / 2], "half": [0.5, size / 2 + 1]}},
        {"box": {"center": [size + 0.5, size / 2], "half": [0.5, size / 2 + 1]}},
        {"box": {"center": [size / 2, -0.5], "half": [size / 2 + 1, 0.5]}},
        {"box": {"center": [size / 2, size + 0.5], "half": [size / 2 + 1, 0.5]}},
    ]
    bodies = []
    for k in range(count):
        i, j = divmod(k, side)
        bodies.append({
            "name": f"p{k}", "shape": {"regular": 5, "radius": 0.2},
            "position": [0.6 + i * spacing, 0.6 + j * spacing], "angle": rng.uniform(0, 72),
            "velocity": [rng.uniform(-3, 3), rng.uniform(-3, 3)], "spin": rng.uniform(-5, 5),
            "restitution": 0.5, "friction": 0.3,
        })
    return Scene.model_validate({"name": f"{count}-pentagons", "bodies": bodies, "walls": walls})


def frame_times(scene: Scene, preset: str, frames: int, warmup: int) -> list[float]:
    with build_scene(scene, preset) as sim:
        sim.step(warmup, measure=False)
        out = []
        for _ in range(frames):
            t0 = time.perf_counter()
            sim.step(1, measure=False)
            out.append(time.perf_counter() - t0)
        return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--frames", type=int, default=120)
    parser.add_argument("--skip-1000", action="store_true", help="leave out the slow 1000-body scenario")
    args = parser.parse_args()
    print(f"kernels compiled or loaded in {compile_kernels():.1f} s (not timed below)")

    scenarios = [("1 ball, 24 wall blocks", one_ball_among_blocks(), args.frames, args.repeats),
                 ("100 pentagons in a box", pentagons_in_a_box(100), max(30, args.frames // 2), args.repeats)]
    if not args.skip_1000:
        scenarios.append(("1000 pentagons in a box", pentagons_in_a_box(1000), 10, max(2, args.repeats // 2)))

    print(f"us per 60 Hz frame: median (ratio to fast) / mean / 95th percentile, {args.repeats} repeats")
    print(f"{'scenario':<26}" + "".join(f"{name:>30}" for name in PRESETS))
    for label, scene, frames, repeats in scenarios:
        stats = {}
        for name in PRESETS:
            samples = []
            for _ in range(repeats):
                samples += frame_times(scene, name, frames, warmup=10)
            samples = [s * 1e6 for s in samples]
            stats[name] = (statistics.median(samples), statistics.fmean(samples),
                           statistics.quantiles(samples, n=20)[-1])
        base = stats["fast"][0]
        print(f"{label:<26}" + "".join(f"{m:>10.0f} ({m / base:4.2f}x) / {mean:>5.0f} / {p95:>5.0f}"
                                       for m, mean, p95 in stats.values()), flush=True)


if __name__ == "__main__":
    main()
