"""Many shots at once (`golf.shots.simulate_shots`): each ball of the shared world ends exactly where
the same shot played alone ends, and the results report drops, time and water penalties."""

from __future__ import annotations

import gc
import math

import pytest

from polygolf.engine.golf.golfer import golfer_for
from polygolf.engine.golf.holes import find_course, load_all_courses
from polygolf.engine.golf.play import HolePlay
from polygolf.engine.golf.shots import Shot, fan, simulate_shots
from polygolf.engine.golf.world import DEFAULT_BALL
from polygolf.engine.loading.scene import ShapeSpec
from polygolf.engine.physics.jit import compile_kernels
from polygolf.engine.physics.settings import LINEAR_SLOP

STAR = ShapeSpec(star=(5, 2), radius=1.0)


@pytest.fixture(scope="module")
def courses():
    return load_all_courses()[0]


def _alone(hole, shape, shot: Shot, preset: str):
    play = HolePlay(hole, shape, preset)
    try:
        play.place_ball(*shot.start)
        play.shoot((shot.start[0] + shot.grab[0], shot.start[1] + shot.grab[1]), shot.arrow)
        for _ in range(1200):
            play.step()
            if play.ball_at_rest or play.state.finished:
                break
        return (play.ball.x, play.ball.y), play.state.holed, play.state.penalties
    finally:
        play.close()


# gauntlet, pinball; bunker lane, ice rink and the slide, where balls of one batch cross different
# surfaces at once (each ball's drag is scaled by the surface under it alone)
@pytest.mark.parametrize(("course", "number"), [("hazards", 9), ("meadow", 8), ("hazards", 1), ("hazards", 3),
                                                ("hazards", 8)])
def test_each_shot_of_a_batch_ends_bit_for_bit_as_played_alone(courses, course, number):
    hole = find_course(courses, course).holes[number - 1]
    tee = hole.layout.tee
    shots = [Shot(tee, (4.0 * math.cos(a), 4.0 * math.sin(a)), grab=(0.1 * math.sin(3 * a), 0.0))
             for a in (0.0, 0.4, 1.3, 2.9, 4.4, 5.9)]
    batch = simulate_shots(hole, shots, "fast", shape=STAR)
    for shot, result in zip(shots, batch):
        rest, holed, penalties = _alone(hole, STAR, shot, "fast")
        assert (result.rest, result.holed, result.penalties) == (rest, holed, penalties)


def test_a_ball_the_windmill_meets_ends_as_alone_beside_a_faster_ball(courses):
    """The windmill's arm meets a slow ball at its tip while another ball of the batch crosses the
    hole: the arm and the ball make the same impact as when the ball is alone. (With a second ball
    the arm's row came first in the store, its pair was swept with A and B swapped, and the ball
    ended 2·10⁻¹⁵ m away from where it ends alone.)"""
    hole = find_course(courses, "hazards").holes[5]  # Windmill
    outline, pivot, _ = hole.layout.windmills[0]
    arm = max(math.hypot(x, y) for x, y in outline)
    hexagon = ShapeSpec(regular=6, radius=1.0)
    for angle in (7 * math.pi / 6, 4 * math.pi / 3, 3 * math.pi / 2):
        start = (pivot[0] + arm * math.cos(angle), pivot[1] + arm * math.sin(angle))
        nudge = Shot(start, (0.05 * math.cos(angle), 0.05 * math.sin(angle)))
        result, _ = simulate_shots(hole, [nudge, Shot(hole.layout.tee, (3.0, 0.3))], "fast", shape=hexagon)
        assert (result.rest, result.holed, result.penalties) == _alone(hole, hexagon, nudge, "fast")


def test_balls_of_a_fan_that_meet_the_arm_together_end_as_each_alone(courses):
    """Two shots at the windmill, both balls on its arm in the same frames: each ends as when alone.
    (The arm counted the other ball as something that might halt it, and passed a push from one ball
    on to the next: the second shot ended 2 m away from where it ends alone.)"""
    windmill = find_course(courses, "hazards").holes[5]
    a = Shot((3.0, 3.0), (2.9313856079563725, -0.6379486009595522))
    b = Shot((3.0, 3.0), (2.866009467376818, -0.8865606199840186))
    alone = simulate_shots(windmill, [a], "fast")[0]
    beside = simulate_shots(windmill, [b, a], "fast")[1]
    assert (beside.rest, beside.angle, beside.seconds) == (alone.rest, alone.angle, alone.seconds)
    assert alone.rest == _alone(windmill, DEFAULT_BALL, a, "fast")[0]


def test_a_ball_heading_for_a_wall_it_does_not_lie_against_stalls_no_windmill(courses):
    """QA: on the Gauntlet a fast star met the windmill's arm 15 cm from a wall; the stall test posed
    the arm at the impact but the ball where its step ended, counted the ball as lying against the
    wall, and stalled the windmill for the substep, for every ball of the fan: a shot beside it
    ended 11 m from where it ends alone. Both are now posed at the impact."""
    hole = find_course(courses, "hazards").holes[8]  # The Gauntlet
    star = ShapeSpec(star=(8, 3), radius=hole.library.ball.radius)
    a = Shot((12.513236267723691, 1.733500463599217), (-2.817615080821704, 1.0300705103662087),
             (0.0923041139766051, 0.19825339704624473), 3.784485760103234)
    b = Shot((5.535675765194628, 4.035494887690328), (4.567220573270582, -2.0348209344052695),
             (-0.03289586625495772, 0.16617068132120294), 3.9042976931596676)
    windmills = [0.14489217581844213]
    alone = simulate_shots(hole, [a], "fast", shape=star, max_seconds=8.0, windmills=windmills)[0]
    beside = simulate_shots(hole, [a, b], "fast", shape=star, max_seconds=8.0, windmills=windmills)[0]
    assert (beside.rest, beside.angle, beside.seconds) == (alone.rest, alone.angle, alone.seconds)


def test_a_planned_putt_drops_and_says_when(courses):
    hole = find_course(courses, "meadow").holes[0]  # Straight: the cup is in line with the tee
    origin, arrow = golfer_for(hole).plan(hole.layout.tee)
    result, miss = simulate_shots(hole, [Shot(origin, arrow), Shot(origin, (-arrow[0], -arrow[1]))], shape=STAR)
    assert result.holed and result.rest == hole.layout.cup and 1.0 < result.seconds < 20.0
    assert not miss.holed and math.dist(miss.rest, hole.layout.cup) > 5.0


def test_water_costs_a_penalty_and_the_ball_goes_back(courses):
    hole = find_course(courses, "hazards").holes[1]  # Water Carry
    tee = hole.layout.tee
    results = simulate_shots(hole, fan(tee, 16, [1.5, 3.0]), "fast", shape=STAR, path=True)
    wet = [r for r in results if r.penalties]
    assert wet, "no shot of the fan found the water"
    for r in wet:
        assert r.penalties == 1 and r.rest == tee  # put back where it last rested: the tee
        assert len(r.path) == round(r.seconds * 60)


def test_water_never_puts_a_ball_back_onto_another(courses):
    """Hot seat: a ball shot from the tee into the water while another ball now lies on the tee goes
    to the nearest free drop spot instead (it went back onto it: 434 mm of overlap in the fuzz)."""
    hole = find_course(courses, "hazards").holes[1]  # Water Carry
    tee = hole.layout.tee
    shots = fan(tee, 16, [1.5, 3.0])
    wet = next(s for s, r in zip(shots, simulate_shots(hole, shots, "fast", shape=STAR)) if r.penalties)
    play = HolePlay(hole, STAR, "fast", players=2)
    try:
        length = math.hypot(*wet.arrow)
        play.turn = 1
        play.place_ball(tee[0] - 1.5 * wet.arrow[0] / length, tee[1] - 1.5 * wet.arrow[1] / length)  # out of the way
        play.turn = 0
        play.place_ball(*tee)  # player 1's ball rests on the tee: its spot to go back to
        assert play.shoot(tee, wet.arrow)
        while math.dist((play.ball.x, play.ball.y), tee) < 1.5:
            play.step()
        play.turn = 1
        play.place_ball(*tee)  # player 2's ball now lies there
        play.turn = 0
        for _ in range(600):
            play.step()
            if play.all_at_rest:
                break
        first, second = play.players[0].body, play.players[1].body
        assert play.players[0].state.penalties == 1
        assert math.dist((first.x, first.y), (second.x, second.y)) >= 2 * play.collider.radius
        assert play.sim.metrics.max_penetration <= LINEAR_SLOP
    finally:
        play.close()


def test_a_closed_world_goes_at_once_and_leaves_the_collector_nothing(courses):
    """A world's run of stages and its resources must not hold each other: a search builds and drops
    a world per fan of shots, and what such a cycle keeps (every ball's handles) waited for the
    collector's slowest pass, up to 40 ms in the middle of a search."""
    compile_kernels()  # (loading a kernel leaves numba's own garbage)
    hole = find_course(courses, "hazards").holes[8]  # pinball: bumpers and a windmill
    shots = fan(hole.layout.tee, 8, [2.0])
    for path in (False, True):
        simulate_shots(hole, shots, "fast", shape=STAR, max_seconds=0.5, path=path)
        gc.collect()
        simulate_shots(hole, shots, "fast", shape=STAR, max_seconds=0.5, path=path)
        assert gc.collect() == 0, path


def test_the_collector_rests_only_while_a_fan_is_simulated(courses, monkeypatch):
    """`simulate_shots` turns the cyclic collector off while it runs (its objects all live until it
    returns) and leaves it as it found it, also when it fails."""
    from polygolf.engine.golf import shots as shots_module

    hole = find_course(courses, "meadow").holes[0]
    inside = []
    real_assemble = shots_module.assemble

    def spying(*args, **kwargs):
        inside.append(gc.isenabled())
        return real_assemble(*args, **kwargs)

    monkeypatch.setattr(shots_module, "assemble", spying)
    try:
        for enabled in (True, False):
            gc.enable() if enabled else gc.disable()
            results = simulate_shots(hole, fan(hole.layout.tee, 4, [1.0]), "fast", max_seconds=0.2)
            assert len(results) == 4 and gc.isenabled() is enabled
        gc.enable()

        def failing(*args, **kwargs):
            raise RuntimeError("no world")

        monkeypatch.setattr(shots_module, "assemble", failing)
        with pytest.raises(RuntimeError, match="no world"):
            simulate_shots(hole, fan(hole.layout.tee, 4, [1.0]), "fast")
        assert gc.isenabled()
    finally:
        gc.enable()
    assert inside == [False, False]
