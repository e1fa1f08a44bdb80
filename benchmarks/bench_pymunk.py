"""PolyGolf against pymunk (Chipmunk2D) on equal work, in one process (a benchmark script, not a test).

    python benchmarks/bench_pymunk.py [--repeats 5] [--preset balanced] [--skip-1000] [--shots 1000]
                                      [--only {100,1000,ball,shots}]

Equal work: the same bodies, walls, materials and start, stepped in 1/60 s frames of the preset's
substeps, each substep with the preset's velocity iterations (pymunk's `iterations`). pymunk has no
split impulses, continuous collision or rolling drag, so PolyGolf does a little more per step; both
engines skip sleeping. Engines are run interleaved, repeat after repeat (after one round not counted;
the garbage collector runs before each timing, outside it), and each figure is the median over
repeats of the time per frame (wall clock, one core) after a first frame, timed on its own and shown
apart ("first frame": PolyGolf packs what its run of stages holds, Chipmunk builds its spatial index).

Scenarios: 100 and 1000 pentagons moving in a closed box; one ball bouncing round Meadow's Obstacle
Field (elastic, no drag, so it never stops); K shots at once on that hole (PolyGolf: `simulate_shots`,
balls that meet walls but not each other; pymunk: K balls filtered from each other), reported as
ball-frames per second: PolyGolf's the median of `--repeats` fans (after one not counted), each timed
whole with its world's building, pymunk's the median of half as many runs (one takes seconds).
"""

from __future__ import annotations

import argparse
import gc
import math
import statistics
import sys
import time
from pathlib import Path

import pymunk

sys.path.insert(0, str(Path(__file__).parent))
from bench_physics import pentagons_in_a_box  # noqa: E402

from polygolf.engine.golf.scenes import find_hole  # noqa: E402
from polygolf.engine.golf.shots import Shot, simulate_shots  # noqa: E402
from polygolf.engine.loading.scene import Scene, ShapeSpec, build_scene  # noqa: E402
from polygolf.engine.physics.jit import compile_kernels  # noqa: E402
from polygolf.engine.physics.polygon import convex_pieces  # noqa: E402
from polygolf.engine.physics.presets import PRESETS  # noqa: E402
from polygolf.engine.physics.settings import FRAME_DT, SHOT_POWER  # noqa: E402

HOLE = "meadow:4"  # Obstacle Field


def pymunk_space(scene: Scene, iterations: int, collide_bodies: bool = True) -> pymunk.Space:
    """The scene in pymunk: polygons as convex pieces, the same density, restitution and friction."""
    space = pymunk.Space()
    space.iterations = iterations
    space.gravity = tuple(scene.gravity)
    for wall in scene.walls:
        for piece in convex_pieces(wall.outline()):
            shape = pymunk.Poly(space.static_body, piece)
            shape.elasticity, shape.friction = wall.restitution, wall.friction
            space.add(shape)
    for spec in scene.bodies:
        outline = spec.shape.outline()
        pieces = convex_pieces(outline)
        body = pymunk.Body()
        body.position = tuple(spec.position)
        body.angle = math.radians(spec.angle)
        body.velocity = tuple(spec.velocity)
        body.angular_velocity = spec.spin
        shapes = []
        for piece in pieces:
            shape = pymunk.Poly(body, piece)
            shape.density = spec.density
            shape.elasticity, shape.friction = spec.restitution, spec.friction
            if not collide_bodies:
                shape.filter = pymunk.ShapeFilter(group=1)  # same group: never each other
            shapes.append(shape)
        space.add(body, *shapes)
    return space


def time_pymunk(space: pymunk.Space, frames: int, substeps: int) -> tuple[float, float]:
    """(the first frame, the mean of the `frames` frames after it), in seconds."""
    dt = FRAME_DT / substeps
    gc.collect()  # (neither engine pays for the other's garbage)
    start = time.perf_counter()
    for _ in range(substeps):
        space.step(dt)
    first = time.perf_counter() - start
    start = time.perf_counter()
    for _ in range(frames * substeps):
        space.step(dt)
    return first, (time.perf_counter() - start) / frames


def time_polygolf(scene: Scene, frames: int, preset: str) -> tuple[float, float]:
    """(the first frame, the mean of the `frames` frames after it), in seconds."""
    with build_scene(scene, preset) as sim:
        gc.collect()
        start = time.perf_counter()
        sim.step(1, measure=False)
        first = time.perf_counter() - start
        start = time.perf_counter()
        sim.step(frames, measure=False)
        return first, (time.perf_counter() - start) / frames


def ball_on_hole(collide_bodies: bool = True, count: int = 1, speed: float = 12.0) -> Scene:
    """Balls bouncing round the Obstacle Field's walls: elastic, frictionless, no drag."""
    hole = find_hole(HOLE, Path.cwd())
    walls = [{"polygon": [list(v) for v in outline], "restitution": 1.0, "friction": 0.0}
             for outline in hole.layout.wall_outlines()]
    tee = hole.layout.tee
    bodies = [{"name": f"ball-{k}", "shape": {"regular": 6, "radius": hole.library.ball.radius},
               "position": list(tee), "velocity": [speed * math.cos(2 * math.pi * k / count),
                                                   speed * math.sin(2 * math.pi * k / count)],
               "spin": 2.0, "restitution": 1.0, "friction": 0.0} for k in range(count)]
    return Scene.model_validate({"name": "ball-on-hole", "bodies": bodies, "walls": walls,
                                 "collide_bodies": collide_bodies})


def polygolf_shots(count: int, preset: str, seconds: float) -> float:
    """PolyGolf's ball-frames per second for `count` shots fanned from the tee for `seconds`, the
    fan's world built and stepped until every ball rests (or the time is up)."""
    hole = find_hole(HOLE, Path.cwd())
    tee = hole.layout.tee
    shots = [Shot(tee, (2.4 * math.cos(2 * math.pi * k / count), 2.4 * math.sin(2 * math.pi * k / count)))
             for k in range(count)]
    gc.collect()
    start = time.perf_counter()
    results = simulate_shots(hole, shots, preset, shape=ShapeSpec(regular=6, radius=1.0), max_seconds=seconds)
    return sum(r.seconds for r in results) / FRAME_DT / (time.perf_counter() - start)


def pymunk_shots(count: int, preset: str, seconds: float) -> float:
    """pymunk's ball-frames per second for the same balls, filtered from each other, at the shots'
    launch speed, for `seconds`."""
    scene = ball_on_hole(collide_bodies=False, count=count, speed=2.4 * SHOT_POWER)
    space = pymunk_space(scene, PRESETS[preset].iterations, collide_bodies=False)
    frames = round(seconds / FRAME_DT)
    first, rest = time_pymunk(space, frames - 1, PRESETS[preset].substeps)
    return count * frames / (first + rest * (frames - 1))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--preset", choices=list(PRESETS), default="balanced")
    parser.add_argument("--skip-1000", action="store_true", help="leave out the 1000-pentagon box")
    parser.add_argument("--shots", type=int, default=1000, help="shots at once (default 1000)")
    parser.add_argument("--only", choices=["100", "1000", "ball", "shots"],
                        help="one scenario alone (to compare two versions run after each other)")
    args = parser.parse_args()
    knobs = PRESETS[args.preset]
    print(f"kernels compiled or loaded in {compile_kernels():.1f} s (not timed below)")
    print(f"pymunk {pymunk.version} (Chipmunk2D {pymunk.chipmunk_version}); PolyGolf preset {args.preset}: "
          f"{knobs.substeps} substeps x {knobs.iterations} iterations; median of {args.repeats} repeats")

    scenarios = [("100", "100 pentagons in a box", lambda: pentagons_in_a_box(100), 30),
                 ("1000", "1000 pentagons in a box", lambda: pentagons_in_a_box(1000), 5),
                 ("ball", "one ball on Obstacle Field", ball_on_hole, 120)]
    scenarios = [(label, make(), frames) for key, label, make, frames in scenarios
                 if (args.only or key) == key and not (key == "1000" and args.skip_1000)]
    print(f"{'scenario':<30}{'PolyGolf':>14}{'pymunk':>14}{'ratio':>9}{'first frame':>24}")
    for label, scene, frames in scenarios:
        ours, theirs = [], []
        for repeat in range(args.repeats + 1):  # the first round is not counted: caches and the CPU warm up
            mine = time_polygolf(scene, frames, args.preset)
            other = time_pymunk(pymunk_space(scene, knobs.iterations), frames, knobs.substeps)
            if repeat:
                ours.append(mine)
                theirs.append(other)
        a, b = statistics.median(t for _, t in ours), statistics.median(t for _, t in theirs)
        a1, b1 = statistics.median(f for f, _ in ours), statistics.median(f for f, _ in theirs)
        print(f"{label:<30}{a * 1e6:>11.0f} us{b * 1e6:>11.0f} us{a / b:>8.1f}x{a1 * 1e6:>11.0f} /{b1 * 1e6:>7.0f} us",
              flush=True)

    # A fan takes some 70 ms and pymunk's run of the same balls some 4 s: PolyGolf's figure is the
    # median of `--repeats` fans (after one not counted, as above), pymunk's of half as many runs.
    if args.only not in (None, "shots"):
        return
    ours = statistics.median([polygolf_shots(args.shots, args.preset, 3.0) for _ in range(args.repeats + 1)][1:])
    theirs = statistics.median(pymunk_shots(args.shots, args.preset, 3.0) for _ in range(max(1, args.repeats // 2)))
    ahead = f"{theirs / ours:.1f}x" if theirs >= ours else f"PolyGolf {ours / theirs:.1f}x faster"
    print(f"{f'{args.shots} shots at once (3 s)':<30}{ours:>11.0f} bf/s{theirs:>9.0f} bf/s  {ahead}"
          "  (ball-frames per second; a ratio as above: time per ball-frame, PolyGolf's over pymunk's)")


if __name__ == "__main__":
    main()
