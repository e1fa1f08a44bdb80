"""Each system alone: a world holding just that processor and hand-made components."""

from __future__ import annotations

import math

import esper
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from polygolf.engine.assembly.assemble import make_body, make_collider
from polygolf.engine.components import Body, Drag, Material
from polygolf.engine.loading.scene import Scene, build_scene
from polygolf.engine.physics import polygon
from polygolf.engine.physics.body import ANGLE, ANGLE0, ASLEEP, COLUMNS, INV_MASS, X0, Y0, X, Y
from polygolf.engine.physics.contact import P_NORMAL_IMPULSE, P_TANGENT_IMPULSE, ContactPoint, Manifold, table_of
from polygolf.engine.physics.settings import LINEAR_SLOP, TIME_TO_REST, TOI_TARGET
from polygolf.engine.systems.broadphase import BroadphaseProcessor, pick
from polygolf.engine.systems.ccd import CCDProcessor, _dynamic_pairs_may_step_far, _together
from polygolf.engine.systems.drag import DragProcessor
from polygolf.engine.systems.gravity import GravityProcessor
from polygolf.engine.systems.integrate import IntegrateProcessor
from polygolf.engine.systems.narrowphase import NarrowphaseProcessor
from polygolf.engine.systems.resolve import ResolveProcessor
from polygolf.engine.systems.restitution import RestitutionProcessor
from polygolf.engine.systems.spin import SpinProcessor

from .helpers import resources as context

SQUARE = polygon.normalise(polygon.regular_polygon(4, 0.5))[0]



def box(cx, cy, hx, hy):
    return [(cx - hx, cy - hy), (cx + hx, cy - hy), (cx + hx, cy + hy), (cx - hx, cy + hy)]


BOUNCY = Material(0.5, 0.0)


def ball(x=0.0, y=0.0, outline=SQUARE, angle=math.pi / 4, material=BOUNCY, **state):
    body = make_body(outline, (x, y), 1.0, angle)
    for key, value in state.items():
        setattr(body, key, value)
    return body, make_collider(outline, material)


def test_integrate_moves_by_velocity_and_skips_resting_bodies(world):
    ctx = context()
    moving = Body.dynamic(0.0, 0.0, 1.0, 1.0, vx=3.0, vy=-1.0)
    resting = Body.dynamic(5.0, 5.0, 1.0, 1.0, vx=3.0, asleep=True)
    esper.create_entity(moving)
    esper.create_entity(resting)
    esper.add_processor(IntegrateProcessor(ctx))
    esper.process()
    assert (moving.x, moving.y) == pytest.approx((3.0 * ctx.config.dt, -1.0 * ctx.config.dt))
    assert (resting.x, resting.y) == (5.0, 5.0)


def test_integrate_puts_a_still_damped_body_to_rest_and_leaves_a_coasting_one(world):
    ctx = context()
    still = Body.dynamic(0.0, 0.0, 1.0, 1.0, vx=0.001)
    coasting = Body.dynamic(9.0, 0.0, 1.0, 1.0, vx=0.001)  # no drag, touching nothing: keeps going
    esper.create_entity(still, Drag(linear=0.5))
    esper.create_entity(coasting)
    esper.add_processor(IntegrateProcessor(ctx))
    for _ in range(int(TIME_TO_REST / ctx.config.dt) + 2):
        esper.process()
    assert still.asleep and still.vx == 0.0
    assert not coasting.asleep and coasting.vx == 0.001


def test_spin_turns_by_angular_velocity(world):
    ctx = context()
    body = Body.dynamic(0.0, 0.0, 1.0, 1.0, spin=2.0)
    esper.create_entity(body)
    esper.add_processor(SpinProcessor(ctx))
    esper.process()
    assert body.angle == pytest.approx(2.0 * ctx.config.dt)


def test_drag_is_exact_exponential_decay(world):
    ctx = context()
    body = Body.dynamic(0.0, 0.0, 1.0, 1.0, vx=10.0, spin=4.0)
    esper.create_entity(body, Drag(linear=0.7, angular=1.5))
    esper.add_processor(DragProcessor(ctx))
    for _ in range(60 * ctx.config.knobs.substeps):
        esper.process()
    assert body.vx == pytest.approx(10.0 * math.exp(-0.7), rel=1e-12)
    assert body.spin == pytest.approx(4.0 * math.exp(-1.5), rel=1e-12)


def test_gravity_adds_constant_acceleration(world):
    ctx = context()
    ctx.config.gravity = (1.0, -2.0)
    body = Body.dynamic(0.0, 0.0, 1.0, 1.0)
    esper.create_entity(body)
    esper.add_processor(GravityProcessor(ctx))
    for _ in range(10):
        esper.process()
    assert (body.vx, body.vy) == pytest.approx((10 * ctx.config.dt, -20 * ctx.config.dt))


def test_broadphase_pairs_only_neighbours(world):
    walls = [box(0.0, 0.0, 0.5, 0.5), box(20.0, 0.0, 0.5, 0.5)]
    ctx = context(walls=walls)
    near_wall, near_wall_col = ball(0.95, 0.0)
    far, far_col = ball(10.0, 10.0)
    pair_a, pair_a_col = ball(-5.0, -5.0)
    pair_b, pair_b_col = ball(-5.6, -5.0)
    asleep_a, asleep_a_col = ball(30.0, 30.0, asleep=True)
    asleep_b, asleep_b_col = ball(30.5, 30.0, asleep=True)
    e_near = esper.create_entity(near_wall, near_wall_col)
    esper.create_entity(far, far_col)
    ea = esper.create_entity(pair_a, pair_a_col)
    eb = esper.create_entity(pair_b, pair_b_col)
    esper.create_entity(asleep_a, asleep_a_col)
    esper.create_entity(asleep_b, asleep_b_col)
    esper.add_processor(BroadphaseProcessor(ctx))
    esper.process()
    assert list(ctx.candidates.walls) == [e_near]
    assert ctx.statics.owner[ctx.candidates.walls[e_near]].tolist() == [1]  # the first wall only
    assert ctx.candidates.pairs == [(min(ea, eb), max(ea, eb))]  # resting pairs and far bodies: none


def test_narrowphase_square_face_gives_one_two_point_manifold(world):
    ctx = context(walls=[box(-1.0, 0.0, 1.0, 5.0)])
    half = 0.5 / math.sqrt(2.0)
    body, col = ball(half - 0.002, 0.0)  # 2 mm into the wall
    ent = esper.create_entity(body, col)
    ctx.candidates.walls = {ent: np.array([0])}  # the first wall's only piece
    esper.add_processor(NarrowphaseProcessor(ctx))
    esper.process()
    assert len(ctx.contacts.manifolds) == 1
    m = ctx.contacts.manifolds[0]
    assert (m.nx, m.ny) == pytest.approx((-1.0, 0.0))  # from the ball to the wall
    assert len(m.points) == 2
    assert [p.separation for p in m.points] == pytest.approx([-0.002, -0.002])
    assert sorted(p.y for p in m.points) == pytest.approx([-half, half])


def test_narrowphase_merges_a_star_landing_on_two_tips(world):
    star = polygon.normalise(polygon.star_polygon(5, 2, 0.5))[0]
    tip_x = min(x for x, _ in star)
    ctx = context(walls=[box(-1.0, 0.0, 1.0, 5.0)])
    body, col = ball(-tip_x - 0.001, 0.0, outline=star, angle=0.0)
    assert len(col.shape) > 1  # non-convex: the two tips are in different pieces
    ent = esper.create_entity(body, col)
    ctx.candidates.walls = {ent: np.array([0])}  # the first wall's only piece
    esper.add_processor(NarrowphaseProcessor(ctx))
    esper.process()
    assert len(ctx.contacts.manifolds) == 1, "the two tips must form one manifold"
    m = ctx.contacts.manifolds[0]
    assert len(m.points) == 2
    ys = sorted(p.y for p in m.points)
    assert ys[0] == pytest.approx(-ys[1])


def test_narrowphase_carries_impulses_of_persisting_points(world):
    ctx = context(walls=[box(-1.0, 0.0, 1.0, 5.0)])
    body, col = ball(0.5 / math.sqrt(2.0) - 0.002, 0.0)
    ent = esper.create_entity(body, col)
    ctx.candidates.walls = {ent: np.array([0])}  # the first wall's only piece
    esper.add_processor(NarrowphaseProcessor(ctx))
    esper.process()
    ctx.contacts.table.points[:, P_NORMAL_IMPULSE] = 1.5  # as if the solver had pushed there
    ctx.contacts.table.points[:, P_TANGENT_IMPULSE] = -0.25
    esper.process()
    assert [(p.normal_impulse, p.tangent_impulse) for p in ctx.contacts.manifolds[0].points] == [(1.5, -0.25)] * 2


def one_point_manifold(body, px, py, nx, ny, static, separation=0.0, restitution=0.5, friction=0.0, **solved):
    point = ContactPoint(x=px, y=py, separation=separation, key=(0,), restitution=restitution, friction=friction,
                         **solved)
    return Manifold(entity_a=1, entity_b=-1, body_a=body, body_b=static, nx=nx, ny=ny, points=[point])


def hand_made(ctx, *manifolds):
    """The contact table of hand-made manifolds between the world's bodies and its static stand-in."""
    ctx.bodies.gather(esper.get_component(Body))
    return table_of(manifolds, ctx.bodies, ctx.statics.body)


def test_resolve_stops_the_approach_of_a_central_hit(world):
    ctx = context()
    body = Body.dynamic(0.0, 0.0, 2.0, 0.5, vx=-3.0, vy=1.0)
    esper.create_entity(body)
    ctx.contacts.table = hand_made(ctx, one_point_manifold(body, -0.5, 0.0, -1.0, 0.0, ctx.statics.body))
    esper.add_processor(ResolveProcessor(ctx))
    esper.process()
    assert body.vx == pytest.approx(0.0, abs=1e-12)  # plastic: restitution is another processor
    assert body.vy == 1.0 and body.spin == 0.0  # no friction, no lever arm


def test_resolve_friction_is_clamped_by_coulomb(world):
    ctx = context(effects={"friction"})
    body = Body.dynamic(0.0, 0.0, 1.0, 1e9, vx=-1.0, vy=5.0)  # huge inertia: a point mass
    esper.create_entity(body)
    ctx.contacts.table = hand_made(ctx, one_point_manifold(body, -0.5, 0.0, -1.0, 0.0, ctx.statics.body,
                                                           friction=0.5))
    esper.add_processor(ResolveProcessor(ctx))
    esper.process()
    # Normal impulse 1.0 stops vx; friction can take at most 0.5 of the 5.0 sideways.
    assert body.vx == pytest.approx(0.0, abs=1e-9)
    assert body.vy == pytest.approx(4.5, rel=1e-6)


def test_resolve_split_impulse_moves_position_but_not_velocity(world):
    ctx = context()
    body = Body.dynamic(0.0, 0.0, 1.0, 1.0)
    esper.create_entity(body)
    ctx.contacts.table = hand_made(ctx, one_point_manifold(body, -0.5, 0.0, -1.0, 0.0, ctx.statics.body,
                                                           separation=-0.05))
    esper.add_processor(ResolveProcessor(ctx))
    esper.process()
    assert body.x > 0.0  # pushed out of the wall
    assert (body.vx, body.vy, body.spin) == (0.0, 0.0, 0.0)  # and no energy added


def test_restitution_repeats_e_times_the_compression_impulse(world):
    ctx = context()
    body = Body.dynamic(0.0, 0.0, 2.0, 0.5, vx=0.0)
    esper.create_entity(body)
    # What stopped a 4 m/s approach of a 2 kg body.
    m = one_point_manifold(body, -0.5, 0.0, -1.0, 0.0, ctx.statics.body, restitution=0.6, normal_impulse=8.0,
                           approach_speed=-4.0, ra_x=-0.5)
    ctx.contacts.table = hand_made(ctx, m)
    esper.add_processor(RestitutionProcessor(ctx))
    esper.process()
    assert body.vx == pytest.approx(0.6 * 4.0)
    assert ctx.stats.bounces == 1
    assert ctx.contacts.manifolds[0].points[0].normal_impulse == 0.0  # nothing of the impact is warm-started


def test_ccd_stops_a_body_at_its_time_of_impact(world):
    ctx = context(walls=[box(0.0, 0.0, 0.025, 2.0)])
    body, col = ball(-3.0, 0.0)  # moved from x=+2 to x=-3 in one substep: through the wall
    body.scratch.x0, body.scratch.y0, body.scratch.angle0 = 2.0, 0.0, body.angle
    esper.create_entity(body, col)
    esper.add_processor(CCDProcessor(ctx))
    esper.process()
    half = 0.5 / math.sqrt(2.0)
    assert body.x - half - 0.025 == pytest.approx(TOI_TARGET, abs=0.3 * TOI_TARGET)
    assert ctx.stats.toi_hits == 1


@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(st.floats(-1e4, 1e4), st.floats(-1e4, 1e4), st.floats(-50, 50), st.floats(-0.3, 0.3),
                          st.floats(-0.3, 0.3), st.floats(-0.5, 0.5), st.floats(0.05, 1.0), st.floats(0.1, 1.0)),
                min_size=2, max_size=12), st.booleans())
def test_no_two_dynamic_bodies_step_far_while_the_quick_bound_says_so(bodies, sweep_all):
    """Continuous collision skips looking for pairs of dynamic bodies when twice the longest step is
    below half the thinnest width (the slop, when it sweeps all: a game's balls); then no pair steps
    that far relative to the other (the test `toi.body_pair_hits` makes, with the exact length),
    wherever the bodies are."""
    state = np.zeros((len(bodies), len(COLUMNS)))
    for k, (x, y, a, dx, dy, da, _, _) in enumerate(bodies):
        state[k, X0], state[k, Y0], state[k, ANGLE0] = x, y, a
        state[k, X], state[k, Y], state[k, ANGLE] = x + dx, y + dy, a + da
        state[k, INV_MASS] = 1.0
    radius, thickness = np.array([b[6] for b in bodies]), np.array([b[7] * b[6] for b in bodies])
    rows = np.arange(len(bodies))

    def relative_step(i: int, j: int) -> float:
        a, b = state[i], state[j]
        return (math.hypot(a[X] - a[X0] - b[X] + b[X0], a[Y] - a[Y0] - b[Y] + b[Y0])
                + abs(a[ANGLE] - a[ANGLE0]) * radius[i] + abs(b[ANGLE] - b[ANGLE0]) * radius[j])

    far = [relative_step(i, j) >= (LINEAR_SLOP if sweep_all else 0.5 * min(thickness[i], thickness[j]))
           for i in range(len(bodies)) for j in range(i + 1, len(bodies))]
    if not _dynamic_pairs_may_step_far(state, rows, radius, thickness, sweep_all):
        assert not any(far)


def test_a_slow_pile_skips_the_search_for_pairs_and_a_fast_pair_does_not():
    """Pentagons 0.36 m wide stepping 2 cm a substep (a pile at 5 m/s, 4 substeps): no pair needs
    sweeping, so none is looked for; one of them stepping 10 cm might, so every pair is."""
    state = np.zeros((3, len(COLUMNS)))
    state[:, INV_MASS] = 1.0
    state[:, X0] = state[:, Y0] = [0.0, 1.0, 2.0]
    state[:, X], state[:, Y] = state[:, X0] + 0.02, state[:, Y0]
    rows, radius, thickness = np.arange(3), np.full(3, 0.2), np.full(3, 0.36)
    assert not _dynamic_pairs_may_step_far(state, rows, radius, thickness, False)
    assert _dynamic_pairs_may_step_far(state, rows, radius, thickness, True)  # a game's balls: beyond the slop
    state[1, X] += 0.08
    assert _dynamic_pairs_may_step_far(state, rows, radius, thickness, False)


def test_touching_balls_go_back_together_and_others_alone():
    """Of two players' balls touching at the substep's start, one put back to a wall's impact takes
    the other back with it (else it would be driven into); a ball apart, or asleep, keeps its own."""
    state = np.zeros((4, len(COLUMNS)))
    state[:, INV_MASS] = 1.0
    state[:, X0] = [0.0, 0.9, 3.0, 3.9]  # radius 0.45: 0 and 1 touch, 2 and 3 touch
    state[3, ASLEEP] = 1.0
    rows, radius = np.arange(4), np.full(4, 0.45)
    pairs = np.array([[0, 1], [1, 2], [2, 3]], dtype=np.int64)
    hits = np.array([1.0, 0.3, 0.6, 1.0])
    _together(state, rows, radius, pairs, hits)
    assert hits.tolist() == [0.3, 0.3, 0.6, 1.0]


def test_pick_with_no_room_for_the_walls_it_finds_grows_from_where_it_stopped():
    """The broadphase's kernel (`pick`) given room for one wall piece grows its array on from the
    body that did not fit (`grid.grow_near`) and finds what it finds with room to spare: three
    balls among small blocks within their margins, one by the first (it fits), four by the others
    (the second does not)."""
    walls = [{"box": {"center": [3.0 * b + 0.38 * i, 0.38 * j], "half": [0.1, 0.1]}}
             for b in range(3) for i in (-1, 1) for j in (-1, 1) if b or (i, j) == (1, 1)]
    balls = [{"name": f"ball-{b}", "shape": {"regular": 6, "radius": 0.3}, "position": [3.0 * b, 0.0],
              "velocity": [1.0, 0.5]} for b in range(3)]
    with build_scene(Scene.model_validate({"name": "blocks", "bodies": balls, "walls": walls}), "balanced") as sim:
        proc = next(p for p in sim.processors if isinstance(p, BroadphaseProcessor))
        inputs = proc.inputs()
        state, res = sim.res.bodies.state, sim.res
        fat = res.fat_boxes.of(state, len(res.statics.grid))
        roomy, _ = pick(state, res.shapes.packed, res.statics.packed, fat, inputs, np.empty(4096, dtype=np.int64))
        roomy = [a.copy() for a in roomy]
        tight, grown = pick(state, res.shapes.packed, res.statics.packed, fat, inputs, np.empty(1, dtype=np.int64))
    assert len(grown) > 1 and len(roomy[0]) == 3 and roomy[1].tolist() == [0, 1, 5, 9]
    assert all(np.array_equal(a, b) for a, b in zip(roomy, tight, strict=True))
