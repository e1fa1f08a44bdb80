"""Random shots on every shipped hole, reporting the deepest overlap each leaves (a measurement, not a
test): the figure behind "static walls and windmills never press a ball deep into anything".

    python benchmarks/fuzz_overlaps.py [--shots 60] [--preset balanced] [--seed 7] [--players 2]

Each shot: a random shape, a random direction and power (arrow 0.5-6 m), grabbed anywhere on the ball,
followed until the balls rest (at most 10 s); overlap is measured after every substep. With
`--players N` every player's ball is on the green (side by side on the tee) and each plays one such
shot in turn, so balls knock into each other too.
"""

from __future__ import annotations

import argparse
import math
import random
import time

from polygolf.engine.golf.holes import load_all_courses
from polygolf.engine.golf.play import HolePlay
from polygolf.engine.loading.scene import ShapeSpec

SHAPES = [ShapeSpec(regular=n, radius=1.0) for n in (3, 4, 5, 6, 8)] + [
    ShapeSpec(star=(5, 2), radius=1.0), ShapeSpec(star=(7, 3), radius=1.0)]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--shots", type=int, default=60, help="shots per hole")
    parser.add_argument("--preset", default="balanced")
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--players", type=int, default=1, help="balls on the green, each shot in turn")
    args = parser.parse_args()
    rng = random.Random(args.seed)
    holes = [h for course in load_all_courses()[0] for h in course.playable]
    worst, deep, total, started = 0.0, [], 0, time.perf_counter()
    for hole in holes:
        for _ in range(args.shots):
            play = HolePlay(hole, rng.choice(SHAPES), args.preset, players=args.players)
            try:
                for turn in range(args.players):
                    play.turn = turn
                    if play.state.finished:
                        continue
                    r = play.collider.radius
                    a, power = rng.uniform(0, 2 * math.pi), rng.uniform(0.5, 6.0)
                    grab = (play.ball.x + rng.uniform(-r, r), play.ball.y + rng.uniform(-r, r))
                    play.shoot(grab, (power * math.cos(a), power * math.sin(a)))
                    for _ in range(600):
                        play.sim.step(1, measure=True)
                        if play.all_at_rest:
                            break
                overlap = play.sim.metrics.max_penetration
            finally:
                play.close()
            total += 1
            worst = max(worst, overlap)
            if overlap > 0.011:
                deep.append((hole.id, overlap))
    seconds = time.perf_counter() - started
    print(f"{args.preset}, {args.players} player(s): {total * args.players} shots on {len(holes)} holes "
          f"in {seconds:.0f} s; "
          f"worst overlap {worst * 1000:.1f} mm; over 11 mm: {len(deep)}; "
          f"over 5 cm: {sum(1 for _, o in deep if o > 0.05)}")
    for hole_id, overlap in sorted(deep, key=lambda d: -d[1])[:10]:
        print(f"  {hole_id}: {overlap * 1000:.1f} mm")


if __name__ == "__main__":
    main()
