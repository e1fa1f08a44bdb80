"""The golf systems alone: shot input, cup capture, scoring, launcher."""

from __future__ import annotations

import math

import esper
import pytest

from polygolf.engine.assembly.assemble import make_body, make_collider
from polygolf.engine.components import Ball, Body, Collider, Cup, HoleState, Launcher, Material, ShotInput
from polygolf.engine.physics import polygon
from polygolf.engine.physics.settings import MAX_SHOT_SPEED, MAX_SHOT_SPIN, SHOT_POWER, SPIN_RATIO
from polygolf.engine.physics.shot import shot_velocity
from polygolf.engine.systems.cup import CupProcessor
from polygolf.engine.systems.launch import LaunchProcessor
from polygolf.engine.systems.scoring import ScoringProcessor
from polygolf.engine.systems.shot import ShotProcessor, push_resting

from .helpers import resources as ctx

SQUARE = polygon.normalise(polygon.regular_polygon(4, 0.45))[0]



def ball_entity(asleep=True, **state):
    body = make_body(SQUARE, (0.0, 0.0), 1.0)
    body.asleep = asleep
    for key, value in state.items():
        setattr(body, key, value)
    shot = ShotInput()
    ent = esper.create_entity(body, make_collider(SQUARE, Material()), shot, Ball(0.0, 0.0))
    return ent, body, shot


def test_shot_through_the_centre_is_straight_and_follows_the_arrow(world):
    esper.add_processor(ShotProcessor(ctx()))
    _, body, shot = ball_entity()
    shot.request((0.0, 0.0), (1.0, 0.5))
    esper.process()
    assert (body.vx, body.vy) == pytest.approx((SHOT_POWER * 1.0, SHOT_POWER * 0.5))
    assert body.spin == 0.0 and not body.asleep and shot.accepted == 1


def test_shot_is_refused_while_the_ball_moves(world):
    esper.add_processor(ShotProcessor(ctx()))
    _, body, shot = ball_entity(asleep=False, vx=2.0)
    shot.request((0.0, 0.0), (1.0, 0.0))
    esper.process()
    assert body.vx == 2.0 and shot.rejected == 1 and shot.accepted == 0


def test_the_push_moves_only_a_resting_body_and_says_how_fast():
    """`push_resting`, the shot stage's push and a fan's: a moving body is left as it is (None), a
    click gives nothing and leaves the body asleep (0.0), a shot wakes it with shot_velocity's
    velocity, turned by a push off its centre, and says its speed."""
    moving = make_body(SQUARE, (0.0, 0.0), 1.0, velocity=(0.3, 0.0))
    assert push_resting(moving, 0.45, (0.0, 0.0), (1.0, 0.0)) is None and moving.vx == 0.3
    resting = make_body(SQUARE, (1.0, 2.0), 1.0, asleep=True)
    assert push_resting(resting, 0.45, (1.0, 2.0), (0.0, 0.0)) == 0.0 and resting.asleep
    speed = push_resting(resting, 0.45, (1.0, 2.1), (0.6, 0.8))
    vx, vy, spin = shot_velocity(resting.mass, resting.inertia, 0.45, 1.0 - 1.0, 2.1 - 2.0, 0.6, 0.8)
    assert (resting.vx, resting.vy, resting.spin) == (vx, vy, spin) and spin < 0.0
    assert speed == math.hypot(vx, vy) == pytest.approx(SHOT_POWER) and not resting.asleep
    # Stopped but not yet asleep (no velocity at all) counts as resting too; a turn alone does not.
    still = make_body(SQUARE, (0.0, 0.0), 1.0)
    assert push_resting(still, 0.45, (0.0, 0.0), (1.0, 0.0)) == pytest.approx(SHOT_POWER)
    turning = make_body(SQUARE, (0.0, 0.0), 1.0, spin=0.5)
    assert push_resting(turning, 0.45, (0.0, 0.0), (1.0, 0.0)) is None and turning.vx == 0.0


def test_linear_and_angular_parts_are_capped_apart():
    props_mass, props_inertia = 0.405, 0.405 * 0.405 / 6  # a 0.636 m square: m, m·s²/6
    # A huge arrow: capped at the maximum speed.
    vx, vy, _ = shot_velocity(props_mass, props_inertia, 0.45, 0.0, 0.0, 100.0, 0.0)
    assert math.hypot(vx, vy) == pytest.approx(MAX_SHOT_SPEED)
    # A soft shot grabbed at the rim: the spin it would get (r×J/I) is cut to SPIN_RATIO·v/R.
    vx, vy, spin = shot_velocity(props_mass, props_inertia, 0.45, 0.0, 0.3, 0.2, 0.0)
    uncapped = (0.0 * 0.0 - 0.3 * props_mass * vx) / props_inertia
    assert abs(uncapped) > SPIN_RATIO * vx / 0.45
    assert spin == pytest.approx(-SPIN_RATIO * vx / 0.45)
    # A full shot grabbed at the rim: cut to the absolute cap.
    _, _, spin = shot_velocity(props_mass, props_inertia, 0.45, 0.0, 0.3, 5.0, 0.0)
    assert spin == pytest.approx(-MAX_SHOT_SPIN)


@pytest.mark.parametrize(("distance", "speed", "drops"), [
    (0.0, 3.9, True), (0.0, 4.1, False),  # over the centre: up to 4 m/s
    (0.275, 1.9, True), (0.275, 2.1, False),  # half way to the rim: up to 2 m/s
    (0.54, 0.01, True), (0.56, 0.0, False),  # at the rim: nothing drops, outside: never
])
def test_cup_cap_falls_linearly_from_centre_to_rim(world, distance, speed, drops):
    res = ctx()
    esper.add_processor(CupProcessor(res))
    esper.create_entity(Cup(0.0, 0.0, 0.55, 4.0))
    body = Body.dynamic(distance, 0.0, 1.0, 1.0, vx=0.0, vy=speed)
    esper.create_entity(body, Ball(0.0, 0.0))
    esper.process()
    holed = [ball for kind, ball, _ in res.events.fired if kind == "holed"]
    assert bool(holed) is drops
    if drops:
        assert body.asleep and (body.x, body.y) == (0.0, 0.0)


def _rolling_balls_and_cups(world_name: str, run: bool) -> tuple[list[int], list[Body], list]:
    """Three balls rolling towards two cups (the third too fast to drop) stepped 240 substeps, by a
    run of compiled stages (integrate and cup as one kernel call, up to 4 substeps at a time) or
    by the processors one at a time; the holed events, the balls and their `Ball.holed`."""
    from polygolf.engine.systems.integrate import IntegrateProcessor
    from polygolf.engine.systems.run import StageRun

    esper.switch_world(world_name)
    res = ctx()
    esper.create_entity(Cup(1.0, 0.0, 0.55, 4.0))
    esper.create_entity(Cup(0.0, 3.0, 0.55, 4.0))
    bodies = [Body.dynamic(0.0, 0.0, 1.0, 1.0, vx=1.5), Body.dynamic(0.0, 2.0, 1.0, 1.0, vy=0.8),
              Body.dynamic(-1.0, 0.0, 1.0, 1.0, vx=9.0)]
    ents = [esper.create_entity(body, Ball(0.0, 0.0)) for body in bodies]
    members = [IntegrateProcessor(res), CupProcessor(res)]
    if run:
        stage, done, short = StageRun(res, members), 0, 0
        while done < 240:
            ran = stage.process(min(4, 240 - done))
            short += ran < min(4, 240 - done)
            done += ran
        assert short == 2  # the run stops after the substep a ball drops in
    else:
        for _ in range(240):
            for member in members:
                member.process()
    holed = [ent for kind, ent, _ in res.events.fired if kind == "holed"]
    return holed, bodies, [esper.component_for_entity(ent, Ball).holed for ent in ents]


def test_the_cup_in_a_run_of_compiled_stages_drops_each_ball_once_as_alone():
    """The cup's kernel runs inside a run of substeps; the balls it drops are said holed when the run
    ends, once each, in the order they dropped, and lie where the cup alone would have put them."""
    try:
        holed, bodies, flags = _rolling_balls_and_cups("cup-run", run=True)
        alone_holed, alone_bodies, alone_flags = _rolling_balls_and_cups("cup-alone", run=False)
    finally:
        esper.switch_world("default")
        for name in ("cup-run", "cup-alone"):
            esper.delete_world(name)
    ents = sorted(holed)
    assert len(holed) == 2 and flags == [True, True, False] and holed == alone_holed and flags == alone_flags
    assert holed == ents  # 1.5 m/s drops 0.34 m from the centre, after 0.44 s; 0.8 m/s 0.44 m out, after 0.7 s
    assert [(b.x, b.y, b.asleep) for b in bodies[:2]] == [(1.0, 0.0, True), (0.0, 3.0, True)]
    assert [b._row.tolist() for b in bodies] == [b._row.tolist() for b in alone_bodies]
    assert bodies[2].x > 1.55 and not bodies[2].asleep  # over the first cup at 9 m/s: it rolls on


def test_scoring_counts_strokes_and_holes(world):
    res = ctx()
    esper.add_processor(ScoringProcessor(res))
    state = HoleState(par=3, max_strokes=10)
    ball = esper.create_entity(Body.dynamic(0.0, 0.0, 1.0, 1.0), Ball(0.0, 0.0), state)
    other = HoleState(par=3, max_strokes=10)
    second = esper.create_entity(Body.dynamic(5.0, 0.0, 1.0, 1.0), Ball(5.0, 0.0), other)
    res.events.emit("shot", second)
    for _ in range(2):
        res.events.emit("shot", ball)
    res.events.emit("penalty", ball, 2)
    res.events.emit("holed", ball)
    res.events.emit("shot", ball)  # after the hole is over: not counted
    esper.process()
    assert (state.strokes, state.penalties, state.score, state.holed) == (2, 2, 4, True)
    assert (other.strokes, other.penalties, other.holed) == (1, 0, False)  # each ball keeps its own score


def test_scoring_picks_the_ball_up_after_the_last_stroke(world):
    res = ctx()
    esper.add_processor(ScoringProcessor(res))
    state = HoleState(par=3, max_strokes=2)
    body = Body.dynamic(0.0, 0.0, 1.0, 1.0, vx=1.0)
    ent = esper.create_entity(body, Ball(0.0, 0.0), state, make_collider(SQUARE, Material()))
    res.events.emit("shot", ent)
    res.events.emit("shot", ent)
    esper.process()
    assert not state.picked_up and esper.has_component(ent, Collider)  # still rolling: it might drop
    body.asleep = True
    esper.process()
    assert state.picked_up and state.finished and state.score == 2
    assert not esper.has_component(ent, Collider)  # it left the green: nothing can hit it


def test_a_shot_marks_where_every_resting_ball_lies_for_the_water_to_put_it_back(world):
    """Another player's shot may knock a resting ball into the water: it goes back where it lay then,
    not to the spot it was last shot from."""
    esper.add_processor(ShotProcessor(ctx()))
    shooter, body, shot = ball_entity(asleep=True)
    other = make_body(SQUARE, (4.0, 1.5), 1.0, asleep=True)
    marker = Ball(1.0, 1.0)  # shot from (1, 1) earlier; it rests at (4, 1.5) now
    esper.create_entity(other, make_collider(SQUARE, Material()), marker)
    rolling = make_body(SQUARE, (7.0, 0.0), 1.0, velocity=(1.0, 0.0))
    still_rolling = Ball(6.0, 0.0)
    esper.create_entity(rolling, make_collider(SQUARE, Material()), still_rolling)
    shot.request((0.0, 0.0), (1.0, 0.0))
    esper.process()
    assert not body.asleep and (esper.component_for_entity(shooter, Ball).rest_x,
                                esper.component_for_entity(shooter, Ball).rest_y) == (0.0, 0.0)
    assert (marker.rest_x, marker.rest_y) == (4.0, 1.5)
    assert (still_rolling.rest_x, still_rolling.rest_y) == (6.0, 0.0)  # not resting: its spot stays


def test_a_hole_never_scores_beyond_the_pickup(world):
    """A last stroke into the water (or a restart while it rolls) adds a penalty: the ball is picked
    up at the limit, and the hole scores the limit."""
    res = ctx()
    esper.add_processor(ScoringProcessor(res))
    state = HoleState(par=3, max_strokes=10)
    body = Body.dynamic(0.0, 0.0, 1.0, 1.0, asleep=True)
    ent = esper.create_entity(body, Ball(0.0, 0.0), state, make_collider(SQUARE, Material()))
    for _ in range(10):
        res.events.emit("shot", ent)
    res.events.emit("penalty", ent, 1)
    esper.process()
    assert (state.strokes, state.penalties, state.score, state.picked_up) == (10, 1, 10, True)


def test_a_ball_knocked_into_the_cup_by_another_counts_the_putt_it_was_spared(world):
    res = ctx()
    esper.add_processor(ScoringProcessor(res))
    shooter_state, knocked_state = HoleState(par=2, max_strokes=10), HoleState(par=2, max_strokes=10)
    shooter = esper.create_entity(Body.dynamic(0.0, 0.0, 1.0, 1.0), Ball(0.0, 0.0), shooter_state)
    knocked = esper.create_entity(Body.dynamic(5.0, 0.0, 1.0, 1.0), Ball(5.0, 0.0), knocked_state)
    res.events.emit("shot", shooter)
    res.events.emit("holed", knocked)  # never shot: not a hole in none
    esper.process()
    assert (knocked_state.strokes, knocked_state.holed) == (1, True)
    res.events.emit("holed", shooter)  # its own shot: counted once
    esper.process()
    assert (shooter_state.strokes, shooter_state.holed) == (1, True)


def test_launcher_sends_the_ball_from_the_tee_again_and_again(world):
    context = ctx()
    esper.add_processor(LaunchProcessor(context))
    esper.create_entity(Launcher((7.0, 2.5), 1.0, (3.0, 3.0)))
    _, body, _ = ball_entity(asleep=True)
    esper.process()
    assert (body.x, body.y, body.vx, body.vy, body.asleep) == (3.0, 3.0, 7.0, 2.5, False)
    body.x, body.vx = 9.0, 0.0
    for _ in range(round(1.0 / context.config.dt) - 1):
        esper.process()
    assert body.x == 9.0
    esper.process()
    assert (body.x, body.vx) == (3.0, 7.0)


def test_the_launcher_sends_each_players_ball_from_its_own_spot():
    """Collision test with two players: both balls launched again and again, never onto each other."""
    from polygolf.engine.golf.holes import find_course, load_all_courses
    from polygolf.engine.golf.play import HolePlay
    from polygolf.engine.loading.scene import ShapeSpec

    hole = find_course(load_all_courses()[0], "collision-test").playable[0]
    play = HolePlay(hole, ShapeSpec(regular=5, radius=1.0), "fast", players=2)
    try:
        spots = [p.tee for p in play.players]
        assert spots[0] != spots[1]
        play.sim.step(1, measure=True)
        assert play.sim.metrics.max_penetration < 0.011
        play.sim.step(60 * 13, measure=True)  # two launches more
        assert play.sim.metrics.max_penetration < 0.05
    finally:
        play.close()
