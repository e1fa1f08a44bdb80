"""The hard cases of the physics core, each a scene in content/scenes, each checked against physics
(closed-form impulses, conservation laws, invariants) at every preset."""

from __future__ import annotations

import math

import pytest

from .conftest import PRESET_NAMES
from .helpers import scene_sim, step_until

ENERGY_TOLERANCE = 1e-9  # relative rise of kinetic energy over one substep that counts as none


def world_vertices(body, outline):
    c, s = math.cos(body.angle), math.sin(body.angle)
    return [(body.x + c * x - s * y, body.y + s * x + c * y) for x, y in outline]


def outline_of(sim, name="ball"):
    import esper

    from polygolf.engine.components import Collider

    esper.switch_world(sim.world)
    ent = next(e for e, n in sim.names.items() if n == name)
    return esper.component_for_entity(ent, Collider).outline


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_flat_face_rebounds_at_half_speed_without_spin(preset):
    with scene_sim("flat-wall", preset) as sim:
        sim.run(1.0)
        ball = sim.body("ball")
        assert ball.vx == pytest.approx(5.0, rel=0.01)
        assert abs(ball.vy) < 1e-9
        assert abs(ball.spin) < 1e-6
        assert sim.metrics.max_energy_rise <= ENERGY_TOLERANCE * sim.metrics.initial_energy


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_off_centre_vertex_hit_matches_closed_form_impulse(preset):
    e, v0, side, density = 0.5, -10.0, 0.5 * math.sqrt(2.0), 1.0
    mass = density * side * side
    inertia = mass * side * side / 6.0  # square about its centre
    with scene_sim("vertex-hit", preset) as sim:
        ball = sim.body("ball")
        # The corner that strikes is the leftmost; without spin the pose at impact is the initial one.
        corner = min(world_vertices(ball, outline_of(sim)), key=lambda p: p[0])
        rx, ry = corner[0] - ball.x, corner[1] - ball.y
        step_until(sim, lambda: sim.res.stats.bounces >= 1, max_frames=120)
        nx, ny = 1.0, 0.0  # wall normal, towards the ball
        r_cross_n = rx * ny - ry * nx
        vn = v0 * nx
        j = -(1.0 + e) * vn / (1.0 / mass + r_cross_n**2 / inertia)
        expected_v = v0 + j * nx / mass
        expected_spin = r_cross_n * j / inertia
        assert ball.vx == pytest.approx(expected_v, rel=0.02)
        assert ball.spin == pytest.approx(expected_spin, rel=0.02)
        assert abs(ball.vy) < 1e-9


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_corner_triangle_stays_inside_loses_energy_and_rests_shallow(preset):
    radius, room = 0.5, 6.0
    with scene_sim("corner", preset) as sim:
        ball = sim.body("ball")
        outline = outline_of(sim)
        deepest_outside = 0.0
        for _ in range(20 * 60):
            sim.step()
            for x, y in world_vertices(ball, outline):
                deepest_outside = max(deepest_outside, -x, x - room, -y, y - room)
            if ball.asleep:
                break
        assert ball.asleep, "the triangle never came to rest"
        assert deepest_outside < 0.02 * radius  # never left the room, not even by 2 % of its radius
        assert sim.metrics.max_energy_rise <= ENERGY_TOLERANCE * sim.metrics.initial_energy
        resting_overlap = max(0.0, *(max(-x, x - room, -y, y - room) for x, y in world_vertices(ball, outline)))
        assert resting_overlap <= 0.02 * radius


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_fast_spin_with_friction_never_gains_energy(preset):
    with scene_sim("fast-spin", preset) as sim:
        before = sim.kinetic_energy()
        step_until(sim, lambda: sim.res.stats.bounces >= 1, max_frames=120)
        sim.run(1.0)
        assert sim.metrics.max_energy_rise <= ENERGY_TOLERANCE * before
        assert sim.kinetic_energy() < before
        assert sim.metrics.max_energy <= before * (1 + ENERGY_TOLERANCE)


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_thin_wall_is_never_passed_at_200_mps(preset):
    with scene_sim("thin-wall", preset) as sim:
        ball = sim.body("ball")
        for _ in range(60):
            sim.step()
            assert ball.x > 0.025, f"ball centre reached x={ball.x:.3f}, through the wall"
        assert ball.vx > 0.0  # it bounced back
        assert sim.metrics.max_penetration < 0.025


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_star_lands_flat_on_two_tips_without_energy_gain_or_spin(preset):
    e, v0 = 0.8, -8.0
    with scene_sim("star-landing", preset) as sim:
        before = sim.kinetic_energy()
        sim.run(1.0)
        star = sim.body("star")
        assert sim.res.stats.bounces >= 1
        assert abs(star.spin) < 1e-6
        assert star.vx == pytest.approx(-e * v0, rel=0.01)
        assert abs(star.vy) < 1e-9
        assert sim.metrics.max_energy <= before * (1 + ENERGY_TOLERANCE)


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_resting_contact_settles_without_jitter_and_stays(preset):
    with scene_sim("resting-contact", preset) as sim:
        ball = sim.body("ball")
        path, last_moving = [], 0
        for frame in range(10 * 60):
            sim.step()
            path.append((ball.x, ball.y))
            if math.hypot(ball.vx, ball.vy) > 0.05:
                last_moving = frame
            if ball.asleep:
                break
        assert ball.asleep, "never came to rest"
        # From the end of its real motion it creeps less than 5 mm and sleeps within half a second:
        # a jittering contact would keep it moving, or push it about.
        settle = path[last_moving:]
        assert max(math.dist(p, path[-1]) for p in settle) < 0.005
        assert len(settle) / 60.0 < 0.5
        pose = (ball.x, ball.y, ball.angle)
        for _ in range(3 * 60):
            sim.step()
            assert ball.asleep
        assert (ball.x, ball.y, ball.angle) == pose
        # It rests against both walls: the corner is at the origin, the walls along the axes.
        xs, ys = zip(*world_vertices(ball, outline_of(sim)))
        assert -0.01 <= min(xs) <= 0.011 and -0.01 <= min(ys) <= 0.011


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_long_roll_follows_exponential_drag(preset):
    v0, w0, k, ka = math.hypot(12.0, 5.0), 4.0, 0.7, 1.5
    with scene_sim("long-roll", preset) as sim:
        sim.run(1.0)
        ball = sim.body("ball")
        assert math.hypot(ball.vx, ball.vy) == pytest.approx(v0 * math.exp(-k), rel=0.005)
        assert ball.spin == pytest.approx(w0 * math.exp(-ka), rel=0.005)
        assert sim.system_names == ["integrate", "spin", "drag"]  # nothing can touch it


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_light_ball_against_heavy_block_conserves_momentum(preset):
    with scene_sim("mass-ratio", preset) as sim:
        ball, block = sim.body("ball"), sim.body("block")
        assert block.mass / ball.mass == pytest.approx(1000.0)
        p0 = (ball.mass * ball.vx + block.mass * block.vx, ball.mass * ball.vy + block.mass * block.vy)
        v1 = ball.vx
        sim.run(2.0)
        p1 = (ball.mass * ball.vx + block.mass * block.vx, ball.mass * ball.vy + block.mass * block.vy)
        assert p1[0] == pytest.approx(p0[0], rel=1e-9)
        assert abs(p1[1]) < 1e-9 * abs(p0[0])
        m1, m2, e = ball.mass, block.mass, 0.5 * 1.0
        assert ball.vx == pytest.approx((m1 - e * m2) / (m1 + m2) * v1, rel=0.01)
        assert block.vx == pytest.approx((1 + e) * m1 / (m1 + m2) * v1, rel=0.01)
        assert sim.metrics.max_energy_rise <= ENERGY_TOLERANCE * sim.metrics.initial_energy
        assert not sim.metrics.nan


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_far_from_origin_gives_the_flat_face_result(preset):
    with scene_sim("flat-wall", preset) as near, scene_sim("far-from-origin", preset) as far:
        near.run(1.0)
        far.run(1.0)
        a, b = near.body("ball"), far.body("ball")
        assert b.vx == pytest.approx(a.vx, rel=0.01)
        assert b.vx == pytest.approx(5.0, rel=0.01)
        assert abs(b.spin) < 1e-6
        assert b.x - 10000.0 == pytest.approx(a.x, abs=0.01)


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_deep_overlap_is_pushed_out_without_gaining_speed(preset):
    half = 0.5 / math.sqrt(2.0)
    with scene_sim("deep-overlap", preset) as sim:
        ball = sim.body("ball")
        assert half - ball.x == pytest.approx(0.05, abs=1e-4)  # starts 5 cm into the wall
        sim.run(0.5)
        assert half - ball.x <= 0.0055  # out to within the linear slop
        assert (ball.vx, ball.vy, ball.spin) == (0.0, 0.0, 0.0)  # position correction adds no energy
        assert sim.metrics.max_energy == 0.0


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_a_light_body_pinched_elastically_between_a_heavy_one_and_a_wall_gains_no_energy(preset):
    """QA's elastic box (everything restitution 1, friction 0): shock propagation took the light body,
    held by the wall, as immovable while it was driven off it at 17 m/s, and stopped the heavy one
    from closing on it by driving it along: +40 % kinetic energy in one substep at fast."""
    with scene_sim("elastic-pinch", preset) as sim:
        sim.run(2.0)
        assert sim.metrics.max_energy <= sim.metrics.initial_energy * (1.0 + ENERGY_TOLERANCE)
        assert not sim.metrics.nan
