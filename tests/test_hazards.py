"""Hazards: each system alone against its closed form, then bumper and windmill through the whole
contact pipeline, and every hole's pipeline holding exactly what the hole needs."""

from __future__ import annotations

import math

import esper
import pytest

from polygolf.engine.assembly.assemble import make_body, make_collider
from polygolf.engine.components import (
    Ball,
    Body,
    Bumper,
    Drag,
    HoleState,
    Ice,
    Material,
    Region,
    Sand,
    Slope,
    Water,
    Windmill,
)
from polygolf.engine.golf.holes import load_courses
from polygolf.engine.golf.play import HolePlay
from polygolf.engine.golf.world import hole_effects
from polygolf.engine.loading.scene import ShapeSpec
from polygolf.engine.physics import polygon
from polygolf.engine.systems.drag import DragProcessor
from polygolf.engine.systems.ice import IceProcessor
from polygolf.engine.systems.sand import SandProcessor
from polygolf.engine.systems.scoring import ScoringProcessor
from polygolf.engine.systems.slope import SlopeProcessor
from polygolf.engine.systems.water import WaterProcessor

from .helpers import pipeline, resources

SQUARE = polygon.normalise(polygon.regular_polygon(4, 0.45))[0]
BIG = ((-50.0, -50.0), (50.0, -50.0), (50.0, 50.0), (-50.0, 50.0))


def region(outline=BIG) -> Region:
    xs, ys = zip(*outline)
    return Region(tuple(outline), (min(xs), min(ys), max(xs), max(ys)))


def context(walls=(), effects=()):
    return resources(walls=walls, cell=3.0, effects=effects)


def rolling_ball(vx=6.0, drag=(0.4, 1.2), x=0.0, y=0.0):
    body = Body.dynamic(x, y, 1.0, 1.0, vx=vx)
    drag_c = Drag(linear=drag[0], rolling=drag[1])
    esper.create_entity(body, drag_c, Ball(x, y))
    return body


def run(seconds, ctx):
    for _ in range(round(seconds / ctx.config.dt)):
        esper.process()


def expected_speed(v0, k, c, t):
    """dv/dt = -k·v - c, until it stops."""
    return max(0.0, (v0 + c / k) * math.exp(-k * t) - c / k)


@pytest.mark.parametrize(("marker", "scale"), [(Sand(), 5.0), (Ice(), 0.08)])
def test_sand_and_ice_scale_the_green_drag(world, marker, scale):
    ctx = context()
    esper.create_entity(region(), marker)
    procs = {Sand: SandProcessor, Ice: IceProcessor}
    esper.add_processor(procs[type(marker)](ctx), priority=1)
    esper.add_processor(DragProcessor(ctx), priority=0)
    body = rolling_ball()
    run(0.5, ctx)
    assert body.vx == pytest.approx(expected_speed(6.0, 0.4 * scale, 1.2 * scale, 0.5), rel=0.01)


def test_drag_outside_a_bunker_is_the_green_alone(world):
    ctx = context()
    esper.create_entity(region(((10, 10), (12, 10), (12, 12), (10, 12))), Sand())
    esper.add_processor(SandProcessor(ctx), priority=1)
    esper.add_processor(DragProcessor(ctx), priority=0)
    body = rolling_ball(vx=3.0)
    run(0.5, ctx)
    assert body.vx == pytest.approx(expected_speed(3.0, 0.4, 1.2, 0.5), rel=0.01)


def test_slope_pushes_at_its_acceleration(world):
    ctx = context()
    esper.create_entity(region(), Slope((0.0, -2.0)))
    esper.add_processor(SlopeProcessor(ctx))
    body = rolling_ball(vx=1.0, drag=(0.0, 0.0))
    run(1.0, ctx)
    assert (body.vx, body.vy) == pytest.approx((1.0, -2.0), rel=1e-9)


def test_water_costs_a_stroke_and_returns_the_ball_to_its_last_rest(world):
    ctx = context()
    esper.create_entity(region(((2, -1), (4, -1), (4, 1), (2, 1))), Water())
    esper.add_processor(WaterProcessor(ctx), priority=1)
    esper.add_processor(ScoringProcessor(ctx), priority=0)
    body = rolling_ball(vx=0.0, drag=(0.0, 0.0))
    (ent, ball), = esper.get_component(Ball)
    state = HoleState(par=3, max_strokes=10)
    esper.add_component(ent, state)
    ball.rest_x, ball.rest_y = -1.0, 0.5
    body.x = 2.5  # rolled into the pond
    esper.process()
    assert (body.x, body.y, body.asleep) == (-1.0, 0.5, True)
    assert state.penalties == 1 and state.score == 1


def mini_world(effects, walls=(), ball_at=(0.0, 0.0), ball_v=(0.0, 0.0), restitution=0.5):
    ctx = context(walls, effects)
    body = make_body(SQUARE, ball_at, 1.0)
    body.vx, body.vy = ball_v
    esper.create_entity(body, make_collider(SQUARE, Material(restitution, 0.0)), Ball(*ball_at))
    return ctx, body


def test_bumper_returns_the_ball_faster_by_its_kick(world):
    kick, e, v0 = 2.5, 0.5, -6.0
    half = 0.45 / math.sqrt(2)
    wall = (((-2.0, -3.0), (0.0, -3.0), (0.0, 3.0), (-2.0, 3.0)), Material(1.0, 0.0), (Bumper(kick),))
    effects = {"spin", "restitution", "bumper", "ccd"}
    ctx, body = mini_world(effects, [wall], ball_at=(1.0, 0.0), ball_v=(v0, 0.0), restitution=e)
    body.angle = math.pi / 4  # face-on
    pipeline(ctx, effects, walls=True)
    run(0.5, ctx)
    assert body.x > half
    assert body.vx == pytest.approx(-e * v0 + kick, rel=0.01)  # once, though the face touches at two points
    assert abs(body.spin) < 1e-9
    assert esper.get_component(Bumper)[0][1].lit == 0.0  # the light went out after the hit


@pytest.mark.parametrize("bumper", [False, True])
def test_impacts_stage_reports_each_hit_once_with_its_approach_speed(world, bumper):
    """A wall (or bumper) struck at 2 m/s and then at 6 m/s: one impact each, of that speed and kind."""
    extra = (Bumper(1.0),) if bumper else ()
    wall = (((-2.0, -3.0), (0.0, -3.0), (0.0, 3.0), (-2.0, 3.0)), Material(1.0, 0.0), extra)
    effects = {"spin", "restitution", "ccd", "impacts"} | ({"bumper"} if bumper else set())
    heard = []
    for speed in (2.0, 6.0):
        esper.switch_world(f"impact-at-{speed}")  # each throw alone (the fixture deletes these worlds)
        ctx, body = mini_world(effects, [wall], ball_at=(1.0, 0.0), ball_v=(-speed, 0.0))
        body.angle = math.pi / 4  # face-on: two points, one impact
        pipeline(ctx, effects, walls=True)
        run(0.5, ctx)
        _, impacts = ctx.events.drain()
        assert len(impacts) == 1, impacts
        heard.append(impacts[0])
    assert [i.kind for i in heard] == ["bumper" if bumper else "wall"] * 2
    assert [i.speed for i in heard] == pytest.approx([2.0, 6.0], rel=0.02)
    assert heard[0].x == pytest.approx(0.0, abs=0.01)  # on the wall's face


def test_windmill_contact_reverses_the_relative_normal_velocity(world):
    """A ball at rest struck by a turning blade: after the impact the relative normal velocity at the
    contact point is -e times what it was (the blade is kinematic: infinite mass)."""
    e, speed = 0.6, 2.0
    effects = {"windmill", "spin", "restitution"}
    ctx, ball = mini_world(effects, ball_at=(1.5, 0.62), restitution=e)
    blade = polygon.normalise(((-2.3, -0.18), (2.3, -0.18), (2.3, 0.18), (-2.3, 0.18)))[0]
    mill = Body(x=0.0, y=0.0, spin=speed)
    esper.create_entity(mill, make_collider(blade, Material(1.0, 0.0)), Windmill(speed))
    procs = pipeline(ctx, effects, walls=False)
    by_name = {p.name: p for p in procs}
    before = None
    for _ in range(240):
        for proc in procs:
            proc.process()
            if proc.name == "resolve" and ctx.contacts.manifolds and before is None:
                m = ctx.contacts.manifolds[0]
                p = m.points[0]
                before = (m, p, p.approach_speed)
            if proc.name == "restitution" and before is not None:
                break
        if before is not None:
            break
    assert before is not None, "the blade never reached the ball"
    m, p, approach = before
    assert approach < -0.5  # the blade was closing on the ball
    a, b = m.body_a, m.body_b
    dvx = b.vx - b.spin * p.rb_y - a.vx + a.spin * p.ra_y
    dvy = b.vy + b.spin * p.rb_x - a.vy - a.spin * p.ra_x
    after = dvx * m.nx + dvy * m.ny
    assert after == pytest.approx(-e * approach, rel=0.02)
    assert mill.spin == speed  # nothing slows a kinematic windmill
    assert "windmill" in by_name


@pytest.fixture(scope="module")
def courses():
    return load_courses()


HAZARD_EFFECTS = {"sand", "water", "ice", "slope", "bumper", "windmill"}


def test_the_hazard_course_uses_every_hazard(courses):
    hazards = next(c for c in courses if c.name == "Hazards")
    assert len(hazards.playable) == 9
    used = set()
    for hole in hazards.playable:
        used |= set(hole_effects(hole)) & HAZARD_EFFECTS
    assert used == HAZARD_EFFECTS


def test_every_hole_holds_exactly_the_systems_it_needs(courses):
    core = ["shot", "integrate", "spin", "drag", "ccd", "broadphase", "narrowphase", "resolve", "impacts",
            "restitution", "cup", "scoring"]
    order = ["shot", "launch", "windmill", "integrate", "spin", "slope", "sand", "ice", "drag", "ccd", "broadphase",
             "narrowphase", "resolve", "impacts", "restitution", "bumper", "water", "cup", "scoring"]
    for course in courses:
        for hole in course.playable:
            world = HolePlay(hole, ShapeSpec(regular=5, radius=1.0))
            try:
                names = world.sim.system_names
                needed = set(core) | (set(hole_effects(hole)) & (HAZARD_EFFECTS | {"launch"}))
                if hole.spec.green is not None and not hole.spec.green.any:
                    needed.discard("drag")
                assert set(names) == needed, f"{hole.id}: {names}"
                assert names == [n for n in order if n in names], f"{hole.id}: order {names}"
                kinds = {k for k, _, _ in world.layout.zones} | ({"bumper"} if world.layout.bumpers else set()) | \
                    ({"windmill"} if world.layout.windmills else set())
                assert kinds == set(names) & HAZARD_EFFECTS, f"{hole.id}: hazards {kinds} vs systems {names}"
            finally:
                world.close()


def test_hazard_course_plays_end_to_end(courses):
    from polygolf.engine.golf.golfer import play_hole

    hazards = next(c for c in courses if c.name == "Hazards")
    for hole in hazards.playable:
        world = HolePlay(hole, ShapeSpec(star=(5, 2), radius=1.0))
        try:
            play_hole(world)
            assert world.state.finished, hole.id
        finally:
            world.close()
