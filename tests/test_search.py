"""The search golfer: route distances, shots it chooses played for real, proofs of every shipped hole,
and `polygolf par` / `validate --prove`."""

from __future__ import annotations

import json
import math
import random
import shutil
from pathlib import Path

import pytest

from polygolf.engine.golf.golfer import _segment_distance, golfer_for
from polygolf.engine.golf.holes import load_all_courses, load_hole_file
from polygolf.engine.golf.layout import point_clearance
from polygolf.engine.golf.play import HolePlay
from polygolf.engine.golf.search import (
    PROOF_SHAPES,
    RouteMap,
    SearchGolfer,
    Shot,
    estimate_par,
    play_out,
    prove_hole,
    spoil,
)
from polygolf.engine.golf.shots import simulate_shots
from polygolf.engine.loading.paths import HOLES_DIR
from polygolf.game.cli import main

HEXAGON = PROOF_SHAPES[0]


def _holes() -> dict[str, object]:
    courses = load_all_courses()[0]
    return {f"{c.id}:{n + 1}": h for c in courses if c.id != "collision-test" for n, h in enumerate(c.playable)}


HOLES = _holes()


def test_route_distance_is_the_walk_round_the_walls() -> None:
    straight, dog_leg = HOLES["meadow:1"], HOLES["meadow:2"]
    route = RouteMap(straight.layout, straight.library.ball.radius)
    tee, cup = straight.layout.tee, straight.layout.cup
    assert route(*cup) < 0.4  # within the grid's step
    assert route(*tee) == pytest.approx(math.dist(tee, cup), abs=0.3)  # a clear line: as the crow flies
    bent = RouteMap(dog_leg.layout, dog_leg.library.ball.radius)
    tee, cup = dog_leg.layout.tee, dog_leg.layout.cup
    # Round the corner: the legs of the L (one tile each way, less what the inner corner saves), not the diagonal.
    assert bent(*tee) > 1.15 * math.dist(tee, cup)
    assert bent(*tee) < sum(math.dist(a, b) for a, b in zip(dog_leg.layout.route, dog_leg.layout.route[1:]))


def test_no_route_node_inside_a_wall() -> None:
    hole = HOLES["meadow:9"]
    route = RouteMap(hole.layout, hole.library.ball.radius)
    free = route.points[route.free]
    assert len(free) > 100
    radius = hole.library.ball.radius
    assert all(point_clearance(hole.layout, x, y) >= 0.6 * radius for x, y in free[::5])
    blocked = route.points[~route.free]
    on_green = [(x, y) for x, y in blocked if any(a <= x <= c and b <= y <= d for a, b, c, d in hole.layout.floor)]
    assert all(point_clearance(hole.layout, x, y) < 0.6 * radius + 1e-9 for x, y in on_green[::5])


def test_chosen_shot_played_for_real_ends_where_the_search_said() -> None:
    """The search's verdict is the game's physics: the shots it chose, played one by one on the
    hole's own world, end bit for bit where the search saw them end."""
    hole = HOLES["meadow:2"]
    golfer = SearchGolfer(hole, HEXAGON, "fast", "quick")
    run = play_out(golfer)
    assert run.sunk and run.strokes <= hole.spec.par
    play = HolePlay(hole, HEXAGON, "fast")
    try:
        for shot, result in zip(run.shots, run.results):
            assert (play.ball.x, play.ball.y) == shot.start
            assert play.shoot((shot.start[0] + shot.grab[0], shot.start[1] + shot.grab[1]), shot.arrow)
            play.step()
            frames = 1
            while not (play.ball_at_rest or play.state.holed) and frames < 60 * 20:
                play.step()
                frames += 1
            assert play.state.holed == result.holed
            if not result.holed:
                assert (play.ball.x, play.ball.y, play.ball.angle) == (*result.rest, result.angle)
        assert play.state.holed and play.state.score == run.strokes
    finally:
        play.close()


def test_it_banks_when_the_straight_line_is_blocked() -> None:
    """Sandbox's warm-up has no clear line from tee to cup; the golfer sinks it in one off a wall."""
    hole = HOLES["sandbox:1"]
    assert not golfer_for(hole).clear(hole.layout.tee, hole.layout.cup)
    choice = SearchGolfer(hole, HEXAGON, "fast", "quick").search(hole.layout.tee)
    assert choice.result.holed
    path = simulate_shots(hole, [choice.shot], "fast", shape=HEXAGON, path=True)[0].path
    headings = [math.atan2(b[1] - a[1], b[0] - a[0]) for a, b in zip(path, path[1:]) if math.dist(a, b) > 1e-3]
    turns = [abs(math.remainder(b - a, math.tau)) for a, b in zip(headings, headings[1:])]
    assert max(turns) > math.radians(30)  # a bounce, not a curve


@pytest.mark.parametrize("name", ["sandbox:1", "meadow:4", "hazards:6"])
def test_the_planners_clearance_is_every_edges_distance_measured(name: str) -> None:
    """`clear` measures only the edges near the segment; its answer is that of measuring every wall
    and water edge, also for segments that pass an edge at the clearance give or take a hair."""
    golfer = golfer_for(HOLES[name])
    rng = random.Random(7)
    x0, y0, x1, y1 = golfer._edge_boxes[:, 0].min(), golfer._edge_boxes[:, 1].min(), \
        golfer._edge_boxes[:, 2].max(), golfer._edge_boxes[:, 3].max()
    segments = []
    for _ in range(300):
        a = (rng.uniform(x0, x1), rng.uniform(y0, y1))
        segments.append((a, (a[0] + rng.gauss(0.0, 2.0), a[1] + rng.gauss(0.0, 2.0))))
    # Parallel to an edge, off it by the clearance, give or take 1e-12 to 1e-3.
    for u, v in rng.sample(golfer.edges, min(60, len(golfer.edges))):
        length = math.dist(u, v)
        nx, ny = (v[1] - u[1]) / length, (u[0] - v[0]) / length
        off = golfer.clearance + rng.choice((-1.0, 1.0)) * 10.0 ** rng.uniform(-12.0, -3.0)
        segments.append(((u[0] + nx * off, u[1] + ny * off), (v[0] + nx * off, v[1] + ny * off)))
    answers = [golfer.clear(a, b) for a, b in segments]
    assert answers == [all(_segment_distance(a, b, u, v) >= golfer.clearance for u, v in golfer.edges)
                       for a, b in segments]
    assert 0 < sum(answers) < len(answers)  # both answers come up


def test_a_holes_planner_is_built_once_and_a_reloaded_hole_gets_its_own() -> None:
    hole = HOLES["meadow:4"]
    assert golfer_for(hole) is golfer_for(hole)
    again = load_hole_file(hole.path)
    assert golfer_for(again) is not golfer_for(hole)
    assert golfer_for(again).plan(again.layout.tee) == golfer_for(hole).plan(hole.layout.tee)


def test_a_loose_golfer_weighs_its_best_shots_as_it_would_play_them() -> None:
    """At skill 0.5 the golfer takes, of its best shots, the one that fares best played loosely:
    over 12 seeds from Water Carry's tee its shots (spoiled alike) cost less in all than the exact
    best spoiled the same way; at skill 1 it is the exact best."""
    hole = HOLES["hazards:2"]
    start = hole.layout.tee
    exact, loose = [], []
    for k in range(12):
        best = SearchGolfer(hole, HEXAGON, "fast", "normal", seed=k).search(start).shot
        exact.append(spoil(best, 0.5, random.Random(k)))
        loose.append(SearchGolfer(hole, HEXAGON, "fast", "normal", seed=k).aim(start, skill=0.5, rng=random.Random(k)))
    assert SearchGolfer(hole, HEXAGON, "fast", "normal", seed=0).aim(start) == \
        SearchGolfer(hole, HEXAGON, "fast", "normal", seed=0).search(start).shot
    judge = SearchGolfer(hole, HEXAGON, "fast", "normal")
    cost = {name: sum(judge.cost(r) for r in simulate_shots(hole, shots, "fast", shape=HEXAGON, max_seconds=20.0))
            for name, shots in (("exact", exact), ("loose", loose))}
    assert cost["loose"] < 0.95 * cost["exact"]


def test_skill_spoils_the_aim_and_exact_skill_does_not() -> None:
    shot = Shot((1.0, 2.0), (3.0, 0.0), (0.0, 0.1), 0.3)
    assert spoil(shot, 1.0, random.Random(1)) == shot
    wild = [spoil(shot, 0.0, random.Random(seed)) for seed in range(200)]
    headings = [math.degrees(math.atan2(s.arrow[1], s.arrow[0])) for s in wild]
    assert 4.0 < (sum(h * h for h in headings) / len(headings)) ** 0.5 < 10.0  # about 7 degrees astray
    assert spoil(shot, 0.0, random.Random(5)) == spoil(shot, 0.0, random.Random(5))


def test_estimated_par_is_the_median_plus_a_human_stroke() -> None:
    assert estimate_par([1, 1, 2], 10) == 2
    assert estimate_par([3, 4, 5], 10) == 5
    assert estimate_par([3, None, None], 10) == 11


@pytest.mark.parametrize("name", sorted(HOLES))
def test_every_shipped_hole_is_sunk_and_its_par_is_within_one(name: str) -> None:
    hole = HOLES[name]
    proof = prove_hole(hole, shapes=[HEXAGON], effort="normal", knobs="fast")
    assert proof.sunk, f"{name}: not sunk in {hole.library.max_strokes} strokes"
    assert abs(proof.estimated_par - hole.spec.par) <= 1, f"{name}: par {hole.spec.par}, estimate {proof.estimated_par}"


def test_par_command_json(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["par", "meadow:1", "--json", "--jobs", "1"]) == 0
    rows = json.loads(capsys.readouterr().out)
    assert [r["hole"] for r in rows] == ["straight"]
    row = rows[0]
    assert {"hole", "name", "par", "estimated_par", "best_strokes", "sunk"} <= set(row)
    assert row["sunk"] is True and row["best_strokes"] == 1 and row["par"] == 2


def test_a_wrong_par_is_a_warning(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    shutil.copy(HOLES_DIR / "tiles.yaml", tmp_path / "tiles.yaml")
    text = (HOLES_DIR / "straight.yaml").read_text().replace("par: 2", "par: 7")
    assert "par: 7" in text
    hole_file = tmp_path / "far.yaml"
    hole_file.write_text(text)
    assert load_hole_file(hole_file).spec.par == 7
    assert main(["par", str(hole_file), "--jobs", "1"]) == 1
    out = capsys.readouterr()
    assert "straight" not in out.err and "par 7 is more than 1 from the estimated par 2" in out.err
    assert main(["validate", "--prove", str(hole_file)]) == 0  # a warning, not an error
    err = capsys.readouterr().err.strip().splitlines()
    line = next(n for n, text in enumerate(text.splitlines(), 1) if text.startswith("par:"))
    assert err == [f"{hole_file}:{line}: par: warning: par 7 is more than 1 from the estimated par 2"]


def test_par_refuses_what_is_not_a_hole(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["par", "nowhere"]) == 2
    assert "no course 'nowhere'" in capsys.readouterr().err
    assert main(["par", "meadow:42"]) == 2
    assert "meadow has holes 1 to 9" in capsys.readouterr().err
    with pytest.raises(SystemExit) as exit_:
        main(["par", "meadow", "--jobs", "0"])
    assert exit_.value.code == 2
