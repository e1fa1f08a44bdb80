"""Physics where golf is played, at every preset: a ball that never touches is never hit, seams
between flush walls are not felt, bodies come to rest touching rather than hovering, and a shot along
a real rail of a real hole keeps its line. Each case is a named scene in content/scenes/."""

from __future__ import annotations

import math
import os
import random

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from polygolf.engine.loading.scene import Scene, build_scene
from polygolf.engine.physics.motion import decay
from polygolf.engine.physics.seams import covered_features
from polygolf.engine.physics.settings import LINEAR_SLOP

from .conftest import PRESET_NAMES
from .helpers import scene_sim

APOTHEM = 0.35 * math.cos(math.pi / 6)  # the hexagon's flat face from its centre


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_a_ball_passing_2mm_above_a_corner_is_untouched(preset):
    with scene_sim("ghost-corner", preset) as sim:
        sim.run(1.0)
        ball = sim.body("ball")
        assert (ball.vx, ball.vy, ball.spin) == pytest.approx((8.0, 0.0, 0.0), abs=1e-9)
        assert ball.x == pytest.approx(7.0, abs=1e-6)  # and on time


@pytest.mark.parametrize("preset", PRESET_NAMES)
@pytest.mark.parametrize("gap", [0.0, 0.0005, 0.004])
def test_grazing_a_corner_level_or_just_above_is_no_hit(preset, gap):
    scene = Scene.model_validate({
        "name": "graze", "walls": [{"box": {"center": [1.0, -0.5], "half": [1.0, 0.5]}}],
        "bodies": [{"name": "ball", "shape": {"regular": 6, "radius": 0.35}, "position": [-1.0, APOTHEM + gap],
                    "velocity": [8.0, 0.0], "restitution": 0.6, "friction": 0.3}]})
    with build_scene(scene, preset) as sim:
        sim.run(1.0)
        ball = sim.body("ball")
        assert (ball.vx, ball.vy, ball.spin) == pytest.approx((8.0, 0.0, 0.0), abs=1e-9)


@pytest.mark.parametrize("preset", PRESET_NAMES)
@pytest.mark.parametrize("sides", [3, 8, 12])
def test_a_block_with_a_notch_beneath_is_as_flat_on_top_as_a_box(preset, sides):
    """The notch splits the block into three pieces, the top face on a 5.7° sliver whose two inner
    edges meet the others' at an acute angle: the probe 0.1 mm outside those edges left the sliver
    1 mm from their ends, they were taken for faces, and a ball sliding level over the far corner
    left it at (22.3, 4.2) m/s spinning -15.8 rad/s."""
    radius = 0.2
    notched = [[0, -1], [1.8, -1], [2, -0.2], [2.2, -1], [4, -1], [4, 0], [0, 0]]
    scene = Scene.model_validate({
        "name": "notched", "walls": [{"polygon": notched}],
        "bodies": [{"name": "ball", "shape": {"regular": sides, "radius": radius}, "angle": _flat_bottomed(sides),
                    "position": [-0.5, radius * math.cos(math.pi / sides)], "velocity": [25.0, 0.0],
                    "restitution": 0.6, "friction": 0.5}]})
    with build_scene(scene, preset) as sim:
        sim.run(0.3)
        ball = sim.body("ball")
        assert ball.x > 4.5 and (ball.vx, ball.vy, ball.spin) == pytest.approx((25.0, 0.0, 0.0), abs=1e-9)


def _flat_bottomed(sides: int) -> float:
    """The angle (degrees) that puts a face of a regular polygon at its bottom."""
    return (270.0 - 180.0 / sides) % (360.0 / sides)


@pytest.mark.parametrize("preset", PRESET_NAMES)
@pytest.mark.parametrize("sides", [3, 4, 5, 7, 8, 12])
@pytest.mark.parametrize("gap", [0.0, 0.00005, 0.0005, 0.004])
def test_every_flat_bottomed_polygon_grazing_a_corner_is_no_hit(preset, sides, gap):
    """As above for triangles to dodecagons, level with the box or up to 4 mm above it. (A square level
    with the box was stopped 5 mm short of the corner, then, counted as touching, stopped again with
    its vertex on the corner, where the contact took the box's side for its normal and threw it back;
    a dodecagon at `accurate` came within the gap tolerance of the corner by a discrete step, and a
    contact that near was kept without asking whether the motion would press it in.)"""
    radius = 0.35
    scene = Scene.model_validate({
        "name": "graze", "walls": [{"box": {"center": [1.0, -0.5], "half": [1.0, 0.5]}}],
        "bodies": [{"name": "ball", "shape": {"regular": sides, "radius": radius}, "angle": _flat_bottomed(sides),
                    "position": [-1.0, radius * math.cos(math.pi / sides) + gap], "velocity": [8.0, 0.0],
                    "restitution": 0.6, "friction": 0.3}]})
    with build_scene(scene, preset) as sim:
        sim.run(1.0)
        ball = sim.body("ball")
        assert (ball.vx, ball.vy, ball.spin) == pytest.approx((8.0, 0.0, 0.0), abs=1e-9)


@pytest.mark.parametrize("preset", PRESET_NAMES)
@pytest.mark.parametrize(("sides", "gap", "speed"), [(6, 0.001, 10.0), (6, 0.002, 25.0), (5, 0.002, 20.0),
                                                     (3, 0.001, 25.0), (6, 0.001, 1000.0)])
def test_a_ball_passing_just_above_a_diamond_s_top_corner_is_untouched(preset, sides, gap, speed):
    """A flat-bottomed ball a millimetre or two above a box turned 45°, at up to the fastest shot and
    far beyond. (The gap test's advancement crept along by the general bound, a step of about the
    gap a time, and ran out of steps: counted as an impact, it struck the ball off the corner.)"""
    radius = 0.35
    corner = 0.5 * math.sqrt(2.0)
    scene = Scene.model_validate({
        "name": "diamond", "walls": [{"box": {"center": [0.0, 0.0], "half": [0.5, 0.5], "angle": 45}}],
        "bodies": [{"name": "ball", "shape": {"regular": sides, "radius": radius}, "angle": _flat_bottomed(sides),
                    "position": [-3.0, corner + radius * math.cos(math.pi / sides) + gap],
                    "velocity": [speed, 0.0], "restitution": 0.6, "friction": 0.3}]})
    with build_scene(scene, preset) as sim:
        sim.run(0.5)
        ball = sim.body("ball")
        assert ball.x > 1.0  # past the corner
        assert (ball.vx, ball.vy, ball.spin) == pytest.approx((speed, 0.0, 0.0), abs=1e-9)


@pytest.mark.parametrize("preset", PRESET_NAMES)
@pytest.mark.parametrize("spin", [30.0, -30.0, 200.0])
def test_a_spinning_star_whose_tips_pass_a_millimetre_above_a_floor_is_untouched(preset, spin):
    """A star {5/2} at the fastest shot's spin (and far beyond) skimming a floor, untouched and on time.
    (Its turn bounds how fast a tip can close on the floor, a step of a few hundredths of the substep
    each: the steps ran out before the substep did, and the floor struck it. Until stop 27 each tip
    that swung within the sweep's target was put back there: at 200 rad/s the star was 1.2 m behind
    after 0.5 s at balanced, 3.1 m at fast.)"""
    scene = Scene.model_validate({
        "name": "spin", "walls": [{"box": {"center": [0.0, -0.5], "half": [1000.0, 0.5]}}],
        "bodies": [{"name": "ball", "shape": {"star": [5, 2], "radius": 0.5}, "position": [0.0, 0.501],
                    "velocity": [10.0, 0.0], "spin": spin, "restitution": 0.6, "friction": 0.3}]})
    with build_scene(scene, preset) as sim:
        sim.run(0.5)
        ball = sim.body("ball")
        assert (ball.vx, ball.vy, ball.spin) == pytest.approx((10.0, 0.0, spin), abs=1e-9)
        assert ball.x == pytest.approx(5.0, abs=1e-6)


@settings(max_examples=int(os.environ.get("POLYGOLF_PROPERTY_EXAMPLES", "60")), deadline=None)
@given(shape=st.sampled_from([{"regular": n} for n in (3, 4, 5, 8)]
                             + [{"star": s} for s in ([5, 2], [7, 3], [7, 2], [9, 4])]
                             + [{"random": {"seed": seed, "vertices": 9}} for seed in (1, 2, 3)]),
       radius=st.floats(0.1, 0.5), speed=st.floats(0.5, 25.0), spin=st.floats(-200.0, 200.0),
       gap=st.floats(0.0005, 0.01), boxes=st.integers(1, 4), ceiling=st.booleans(),
       preset=st.sampled_from(PRESET_NAMES))
def test_random_spinning_shapes_skimming_random_seamed_rails_are_untouched_and_on_time(shape, radius, speed, spin, gap,
                                                                                          boxes, ceiling, preset):
    """A shape spinning along a rail of flush boxes (a floor, or a ceiling), its tips' circle `gap`
    clear of it: it never touches the rail, so it keeps its velocity and spin, and is where it would
    be in mid-green. (Until stop 27 a tip swinging within the sweep's 5 mm target was put back there.)"""
    from polygolf.engine.loading.scene import ShapeSpec
    from polygolf.engine.physics.polygon import bounding_radius

    reach = bounding_radius(ShapeSpec(**shape, radius=radius).outline())
    side = -1.0 if ceiling else 1.0
    walls = [{"box": {"center": [2.0 * k + 1.0, -0.5 * side], "half": [1.0, 0.5]}} for k in range(boxes)]
    scene = Scene.model_validate({"name": "skim", "walls": walls, "bodies": [
        {"name": "ball", "shape": {**shape, "radius": radius}, "position": [0.0, side * (reach + gap)],
         "velocity": [speed, 0.0], "spin": spin, "restitution": 0.6, "friction": 0.5}]})
    seconds = round(60.0 * min(0.5, 2.0 * boxes / speed)) / 60.0
    with build_scene(scene, preset) as sim:
        sim.run(seconds)
        ball = sim.body("ball")
        assert (ball.vx, ball.vy, ball.spin) == pytest.approx((speed, 0.0, spin), abs=1e-9)
        assert ball.x == pytest.approx(speed * seconds, abs=1e-6)


@settings(max_examples=int(os.environ.get("POLYGOLF_PROPERTY_EXAMPLES", "60")), deadline=None)
@given(shape=st.sampled_from([{"regular": n} for n in (3, 5, 8)] + [{"star": s} for s in ([5, 2], [7, 3], [9, 4])]
                             + [{"random": {"seed": seed, "vertices": 9}} for seed in (1, 2, 3)]),
       radius=st.floats(0.1, 0.5), speed=st.floats(2.0, 25.0), spin=st.floats(-200.0, 200.0),
       side=st.floats(5.0, 85.0), backwards=st.booleans(), gap=st.floats(0.0005, 0.005),
       preset=st.sampled_from(PRESET_NAMES))
def test_random_spinning_shapes_passing_a_corner_without_touching_it_are_untouched_and_on_time(
        shape, radius, speed, spin, side, backwards, gap, preset):
    """A shape spinning past a box's corner on a slant, the circle of its tips `gap` clear of the
    corner (the nearest the box comes to its path): untouched, and where it would be in mid-green
    at every frame. (Until stop 27 a sweep put it back wherever a tip came within 5 mm: 18-44 mm
    behind for a frame.)"""
    from polygolf.engine.loading.scene import ShapeSpec
    from polygolf.engine.physics.polygon import bounding_radius

    reach = bounding_radius(ShapeSpec(**shape, radius=radius).outline()) + gap
    normal = (math.cos(math.radians(side)), math.sin(math.radians(side)))  # corner to the path, up and right
    way = (normal[1], -normal[0]) if backwards else (-normal[1], normal[0])
    start = (reach * normal[0] - way[0] * speed * 0.3, reach * normal[1] - way[1] * speed * 0.3)
    scene = Scene.model_validate({"name": "corner", "walls": [{"box": {"center": [-1.0, -1.0], "half": [1.0, 1.0]}}],
                                  "bodies": [{"name": "ball", "shape": {**shape, "radius": radius},
                                              "position": list(start), "velocity": [way[0] * speed, way[1] * speed],
                                              "spin": spin, "restitution": 0.6, "friction": 0.5}]})
    with build_scene(scene, preset) as sim:
        ball = sim.body("ball")
        for frame in range(1, 37):
            sim.step()
            assert (ball.x, ball.y) == pytest.approx((start[0] + way[0] * speed * frame / 60,
                                                      start[1] + way[1] * speed * frame / 60), abs=1e-6)
        assert (ball.vx, ball.vy, ball.spin) == pytest.approx((way[0] * speed, way[1] * speed, spin), abs=1e-9)


@pytest.mark.parametrize("preset", PRESET_NAMES)
@pytest.mark.parametrize(("shape", "spin", "gap"), [({"regular": 6}, 0.0, 0.001), ({"star": [5, 2]}, 30.0, 0.001),
                                                    ({"star": [7, 3]}, -30.0, 0.0005)])
def test_a_ball_passing_a_resting_ball_without_touching_it_is_untouched_and_on_time(preset, shape, spin, gap):
    """A small ball at the fastest shot skims past a resting one, its tips' circle `gap` clear of the
    other's: neither is touched, and the one passing is where it would be in mid-green. (Until stop
    27 the sweep put it back wherever a tip came within its 5 mm target: 18 mm behind at fast.)"""
    from polygolf.engine.loading.scene import ShapeSpec
    from polygolf.engine.physics.polygon import bounding_radius

    outline = ShapeSpec(**shape, radius=0.1).outline()
    reach = bounding_radius(outline) if spin else -min(y for _, y in outline)  # below its centre, at any turn
    still = max(y for _, y in ShapeSpec(regular=6, radius=0.3).outline())  # the resting ball's top
    scene = Scene.model_validate({"name": "pass", "bodies": [
        {"name": "ball", "shape": {**shape, "radius": 0.1}, "position": [-1.0, still + reach + gap],
         "velocity": [25.0, 0.0], "spin": spin, "restitution": 0.6, "friction": 0.5},
        {"name": "other", "shape": {"regular": 6, "radius": 0.3}, "position": [0.0, 0.0], "restitution": 0.6,
         "friction": 0.5}]})
    with build_scene(scene, preset) as sim:
        ball, other = sim.body("ball"), sim.body("other")
        for frame in range(1, 6):  # (a body put back makes its time up a substep later: look at every frame)
            sim.step()
            assert ball.x == pytest.approx(-1.0 + 25.0 * frame / 60, abs=1e-6)
        assert (ball.vx, ball.vy, ball.spin) == pytest.approx((25.0, 0.0, spin), abs=1e-9)
        assert (other.x, other.y, other.vx, other.vy, other.spin) == (0.0, 0.0, 0.0, 0.0, 0.0)


@pytest.mark.parametrize("preset", PRESET_NAMES)
@pytest.mark.parametrize(("shape", "spin", "other_velocity", "other_spin"), [
    ({"regular": 6}, 0.0, (0.0, 0.0), 200.0),  # past a ball spinning where it stands
    ({"star": [7, 3]}, -60.0, (25.0, 0.0), -20.0),  # alongside one rolling as fast
    ({"star": [5, 2]}, 30.0, (-20.0, 0.0), 50.0),  # past one coming the other way
])
@pytest.mark.parametrize("gap", [0.002, 0.0005])
def test_a_ball_passing_a_moving_ball_without_touching_it_leaves_both_untouched_and_on_time(
        preset, shape, spin, other_velocity, other_spin, gap):
    """Two balls that both move, their bounding circles `gap` apart where they pass (the other one
    turning a vertex to the top then): neither is touched, and both are where they would be alone.
    (Until stop 28 only a pass by a resting ball was asked whether it sinks in: at fast, passing a
    ball spinning at 200 rad/s, the hexagon was put back up to 218 mm.)"""
    from polygolf.engine.loading.scene import ShapeSpec
    from polygolf.engine.physics.polygon import bounding_radius

    outline, other = ShapeSpec(**shape, radius=0.1).outline(), ShapeSpec(regular=6, radius=0.3).outline()
    reach = bounding_radius(outline) if spin else -min(y for _, y in outline)  # below its centre, at any turn
    meet = 0.04  # s: when they pass, a vertex of the other at its top
    vertex = math.atan2(other[0][1], other[0][0])
    start = (-25.0 * meet, bounding_radius(other) + reach + gap)
    other_start = (-other_velocity[0] * meet, 0.0)
    scene = Scene.model_validate({"name": "pass", "bodies": [
        {"name": "ball", "shape": {**shape, "radius": 0.1}, "position": list(start), "velocity": [25.0, 0.0],
         "spin": spin, "restitution": 0.6, "friction": 0.5},
        {"name": "other", "shape": {"regular": 6, "radius": 0.3}, "position": list(other_start),
         "velocity": list(other_velocity), "spin": other_spin,
         "angle": math.degrees(math.pi / 2 - vertex - other_spin * meet), "restitution": 0.6, "friction": 0.5}]})
    with build_scene(scene, preset) as sim:
        ball, other_ball = sim.body("ball"), sim.body("other")
        for frame in range(1, 8):  # (a body put back makes its time up a substep later: look at every frame)
            sim.step()
            assert (ball.x, ball.y) == pytest.approx((start[0] + 25.0 * frame / 60, start[1]), abs=1e-6)
            assert (other_ball.x, other_ball.y) == pytest.approx(
                (other_start[0] + other_velocity[0] * frame / 60, 0.0), abs=1e-6)
        assert (ball.vx, ball.vy, ball.spin) == pytest.approx((25.0, 0.0, spin), abs=1e-9)
        assert (other_ball.vx, other_ball.vy, other_ball.spin) == pytest.approx((*other_velocity, other_spin), abs=1e-9)


@pytest.mark.parametrize("preset", PRESET_NAMES)
@pytest.mark.parametrize(("shape", "spin"), [({"regular": 6}, 0.0), ({"star": [5, 2]}, 30.0), ({"regular": 3}, -10.0)])
@pytest.mark.parametrize(("turning", "speed"), [(1.5, 25.0), (3.0, 3.0), (-2.0, 10.0)])
def test_a_ball_passing_a_turning_windmill_s_tip_without_touching_it_is_untouched_and_on_time(
        preset, shape, spin, turning, speed):
    """A ball rolling past a windmill, its bounding circle half a millimetre outside the circle the
    arm's tip turns on, the tip passing as it does: untouched and on time. (Until stop 28 a ball and
    a turning arm were swept by the advancement alone: the hexagon was put back up to 132 mm.)"""
    from polygolf.engine.assembly.assemble import assemble
    from polygolf.engine.assembly.spec import DynamicPart, KinematicPart, WorldSpec
    from polygolf.engine.components import Material, Windmill
    from polygolf.engine.loading.scene import ShapeSpec
    from polygolf.engine.physics.polygon import bounding_radius

    outline = ShapeSpec(**shape, radius=0.1).outline()
    arm = ((-0.15, -0.15), (2.0, -0.15), (2.0, 0.15), (-0.15, 0.15))
    x = math.hypot(2.0, 0.15) + bounding_radius(outline) + 0.0005
    meet = 0.05  # s: when the ball passes level with the pivot, the arm pointing at it
    ball = DynamicPart("ball", outline, (x, -speed * meet), 1.0, Material(0.6, 0.3), 0.0, (0.0, speed), spin)
    mill = KinematicPart("windmill", arm, (0.0, 0.0), turning, angle=-turning * meet, extras=(Windmill(turning),))
    with assemble(WorldSpec("windmill-pass", [ball], [], [mill]), preset) as sim:
        ball = sim.body("ball")
        for frame in range(1, 13):
            sim.step()
            assert (ball.x, ball.y) == pytest.approx((x, speed * (frame / 60 - meet)), abs=1e-6)
        assert (ball.vx, ball.vy, ball.spin) == pytest.approx((0.0, speed, spin), abs=1e-9)


def _box(x0: float, y0: float, x1: float, y1: float) -> tuple[list, list]:
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)], [(0.0, -1.0), (1.0, 0.0), (0.0, 1.0), (-1.0, 0.0)]


def _internal_edges(*boxes: tuple[float, float, float, float]) -> list[frozenset[int]]:
    pieces, normals = zip(*(_box(*b) for b in boxes))
    return covered_features(pieces, normals, lambda i: range(len(pieces)))[0]


def test_an_edge_is_internal_only_where_other_pieces_cover_all_of_it():
    """(Edges: 0 bottom, 1 right, 2 top, 3 left.) A side wall four tiles long whose tiles' border
    walls meet it at its quarter points is a face between them; a face covered end to end, by one
    piece or two side by side (flush, or 50 µm apart), is internal; one bare for a centimetre at an
    end is a face."""
    side = (17.85, -0.15, 18.15, 24.15)
    crossings = [(15.8, y - 0.15, 18.15, y + 0.15) for y in (6.0, 12.0, 18.0)]
    assert 3 not in _internal_edges(side, *crossings)[0]
    assert _internal_edges((0.0, 0.0, 1.0, 1.0), (1.0, -1.0, 2.0, 2.0))[0] == {1}
    assert _internal_edges((0.0, 0.0, 1.0, 1.0), (1.0, 0.0, 2.0, 0.4), (1.0, 0.4, 2.0, 1.0))[0] == {1}
    assert _internal_edges((0.0, 0.0, 1.0, 1.0), (1.0, 0.0, 2.0, 0.4), (1.0, 0.40005, 2.0, 1.0))[0] == {1}
    assert 1 not in _internal_edges((0.0, 0.0, 1.0, 1.0), (1.0, 0.01, 2.0, 2.0))[0]


def test_a_vertex_is_hidden_only_on_a_flat_or_reflex_stretch_of_the_walls():
    """Two boxes side by side: the corners where they meet on top lie on a flat stretch (hidden),
    the outer ones are corners; an L of two boxes hides its inner corner; a ridge of 165 degrees
    with another wall beside it is a corner (16 sampled directions took such a ridge for flat)."""
    pieces, normals = zip(_box(0.0, 0.0, 1.0, 1.0), _box(1.0, 0.0, 2.0, 1.0))
    hidden = covered_features(pieces, normals, lambda i: range(2))[1]
    assert hidden[0] == {1, 2} and hidden[1] == {0, 3}
    pieces, normals = zip(_box(0.0, 0.0, 2.0, 1.0), _box(0.0, 1.0, 1.0, 2.0))
    assert 2 not in covered_features(pieces, normals, lambda i: range(2))[1][0]  # (2, 1): a corner
    slope = math.tan(math.radians(7.5))
    ridge = [(-2.0, -2.0 * slope - 1.0), (2.0, -2.0 * slope - 1.0), (2.0, -2.0 * slope), (0.0, 0.0),
             (-2.0, -2.0 * slope)]
    ridge_normals = [(0.0, -1.0), (1.0, 0.0), (math.sin(math.radians(7.5)), math.cos(math.radians(7.5))),
                     (-math.sin(math.radians(7.5)), math.cos(math.radians(7.5))), (-1.0, 0.0)]
    beside, beside_normals = _box(2.0, -3.0, 3.0, -2.0)
    hidden = covered_features([ridge, beside], [ridge_normals, beside_normals], lambda i: range(2))[1]
    assert 3 not in hidden[0]
    pieces, normals = zip(_box(0.0, 0.0, 2.0, 1.0), _box(1.0, 1.0, 2.0, 2.0))  # an L: (1, 1) is inside its bend
    assert 0 in covered_features(pieces, normals, lambda i: range(2))[1][1]


def test_only_an_inside_corner_of_the_walls_is_reflex():
    """Reflex: the solid round the vertex fills more than half the turn (the inside of an L, where
    the free space is a wedge); the flat seam on top of two boxes and the outer corners are not."""
    pieces, normals = zip(_box(0.0, 0.0, 1.0, 1.0), _box(1.0, 0.0, 2.0, 1.0))
    assert covered_features(pieces, normals, lambda i: range(2))[2] == [frozenset(), frozenset()]
    pieces, normals = zip(_box(0.0, 0.0, 2.0, 1.0), _box(1.0, 1.0, 2.0, 2.0))  # an L: (1, 1) is inside its bend
    assert covered_features(pieces, normals, lambda i: range(2))[2] == [frozenset(), frozenset({0})]


_NEEDLE = [[-0.20751622794521576, -0.007464149099062448], [0.4150324558904316, 0.0],
           [-0.20751622794521576, 0.007464149099062448]]


@pytest.mark.parametrize("preset", PRESET_NAMES)
@pytest.mark.parametrize("thickness", [0.006, 0.05])
@pytest.mark.parametrize("one_polygon", [False, True])
def test_a_needle_sliding_into_a_v_stays_in_it(preset, thickness, one_polygon):
    """QA: a needle (0.62 m x 15 mm) shot at 25 m/s lands on one leg of a 90 degree V, slides down
    it into the corner, its tip sunk in that leg and so just beyond the other leg's covered edge:
    neither leg's contact stopped it, and it went through the other leg at 19.8 m/s (walls 6 mm to
    5 cm, fast and balanced). The V as two quads sharing the bisector, or as one wall polygon."""
    s, length = math.sqrt(0.5), 2.5
    back = [0.0, -thickness / s]
    legs = [[[0.0, 0.0], [-length * s, length * s], [-length * s - thickness * s, length * s - thickness * s], back],
            [back, [length * s + thickness * s, length * s - thickness * s], [length * s, length * s], [0.0, 0.0]]]
    if one_polygon:
        legs = [[back, legs[1][1], legs[1][2], [0.0, 0.0], legs[0][1], legs[0][2]]]
    scene = Scene.model_validate({
        "name": "needle-v", "walls": [{"polygon": leg, "restitution": 0.5, "friction": 0.5} for leg in legs],
        "bodies": [{"name": "ball", "shape": {"vertices": _NEEDLE}, "position": [0.5212529727001292, 1.264939856272095],
                    "angle": math.degrees(5.015888941599809), "velocity": [-3.2789757074877706, -24.784033535921974],
                    "spin": -21.775639528630325, "restitution": 0.0, "friction": 0.0}]})
    with build_scene(scene, preset) as sim:
        ball = sim.body("ball")
        for _ in range(30):
            sim.step()
            # the centroid never more than the slop behind either leg's inner face
            assert min(s * (ball.x + ball.y), s * (ball.y - ball.x)) > -LINEAR_SLOP
        assert math.hypot(ball.vx, ball.vy) < 1.0  # (it came to a stop in the V: 14 m/s through it before)


@pytest.mark.parametrize("preset", PRESET_NAMES)
@pytest.mark.parametrize("shape, diagonal", [({"regular": 4}, "up"), ({"regular": 6}, "down"),
                                             ({"star": [8, 3]}, "up")])
def test_a_shape_sunk_on_a_rail_of_flush_triangles_slides_on_time(preset, shape, diagonal):
    """QA: a rail of 0.5 x 0.2 m blocks, each split along a diagonal into two triangles; a shape
    lying on it sunk 1 mm, frictionless, sliding at 25 m/s. Near each block's end its sunk corner
    passed from the upper triangle into the lower one across their diagonal (a covered face), and
    the sweep put it back there: a square 157 mm behind at fast, 74 mm at balanced; a hexagon 23 mm
    at accurate."""
    shape = dict(shape, radius=0.2)
    angle = -90.0 + 180.0 / shape.get("regular", 8)
    walls = []
    for k in range(20):
        x0, x1 = -0.5 + 0.5 * k, 0.5 * k
        block = [[x0, -0.2], [x1, -0.2], [x1, 0.0], [x0, 0.0]]
        halves = ([block[0], block[1], block[2]], [block[0], block[2], block[3]]) if diagonal == "up" else \
            ([block[0], block[1], block[3]], [block[1], block[2], block[3]])
        walls += [{"polygon": half, "restitution": 1.0, "friction": 0.0} for half in halves]
    _assert_slides_on_time(preset, shape, angle, 0.001, 25.0, walls, 0.6, 0.0)


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_a_square_rests_on_a_ridge_beside_another_wall_without_sinking(preset):
    slope = math.tan(math.radians(7.5))
    ridge = [[-2.0, -2.0 * slope - 1.0], [2.0, -2.0 * slope - 1.0], [2.0, -2.0 * slope], [0.0, 0.0],
             [-2.0, -2.0 * slope]]
    scene = Scene.model_validate({
        "name": "ridge", "gravity": [0.0, -9.81],
        "walls": [{"polygon": ridge}, {"box": {"center": [2.5, -2.0 * slope - 0.5], "half": [0.5, 0.5]}}],
        "bodies": [{"name": "square", "shape": {"regular": 4, "radius": 0.35}, "angle": 45, "position": [0.0, 0.26],
                    "restitution": 0.0, "friction": 0.8}]})
    with build_scene(scene, preset) as sim:
        sim.run(2.0)
        assert sim.body("square").y == pytest.approx(0.35 * math.cos(math.pi / 4), abs=LINEAR_SLOP)


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_a_ball_shot_at_a_long_side_wall_between_its_crossings_bounces_back(preset):
    """Random nine's seed 99 made such a column (hole 8): shots at the side wall went through it and
    off the course, its whole inner face taken for a seam."""
    walls = [{"polygon": [[17.85, -0.15], [18.15, -0.15], [18.15, 24.15], [17.85, 24.15]]}]
    walls += [{"box": {"center": [16.975, y], "half": [1.175, 0.15]}} for y in (6.0, 12.0, 18.0)]
    bodies = [{"name": f"ball-{k}", "shape": {"regular": 6, "radius": 0.3}, "position": [15.0, y],
               "velocity": [20.0, 3.0 - k], "restitution": 0.5, "friction": 0.3}
              for k, y in enumerate((3.0, 9.0, 15.0, 21.0))]
    scene = Scene.model_validate({"name": "long-side", "walls": walls, "bodies": bodies, "collide_bodies": False})
    with build_scene(scene, preset) as sim:
        sim.run(0.5)
        for name, ball in sim.bodies():
            assert ball.x < 17.85 and ball.vx < 0.0, name


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_a_frictionless_slide_across_flush_boxes_keeps_its_speed(preset):
    with scene_sim("seam-slide", preset) as sim:
        sim.run(1.0)  # three seams crossed (x = 2, 4, 6)
        ball = sim.body("ball")
        assert ball.x > 6.2
        assert (ball.vx, ball.vy, ball.spin) == pytest.approx((6.0, 0.0, 0.0), abs=1e-9)
        assert sim.metrics.max_penetration <= LINEAR_SLOP + 1e-3


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_a_body_dropped_8mm_rests_touching_the_floor(preset):
    with scene_sim("hover-drop", preset) as sim:
        sim.run(1.5)
        ball = sim.body("ball")
        gap = ball.y - 0.2 * math.sqrt(0.5)  # the square's bottom face above the floor's top (y = 0)
        assert ball.asleep
        assert -LINEAR_SLOP <= gap <= LINEAR_SLOP, gap


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_the_dog_leg_rail_shot_keeps_its_line_past_the_seam(preset):
    with scene_sim("dog-leg-rail", preset) as sim:
        sim.run(1.6)
        ball = sim.body("ball")
        assert ball.x > 12.15  # past the flush corner at x = 11.85 and the rail's end
        assert (ball.vy, ball.spin) == pytest.approx((0.0, 0.0), abs=1e-9)
        assert ball.y == pytest.approx(5.85 - APOTHEM, abs=1e-6)
        # Only the green slows it: the exact drag law (linear 0.4/s, rolling 1.2 m/s²) over 1.6 s.
        assert ball.vx == pytest.approx(decay(10.0, 0.4, 1.2, 1.6), rel=1e-9)


@settings(max_examples=int(os.environ.get("POLYGOLF_PROPERTY_EXAMPLES", "60")), deadline=None)
@given(shape=st.sampled_from([{"regular": n} for n in (3, 4, 5, 6, 8, 12)] + [{"star": [5, 2]}, {"star": [7, 3]}]),
       radius=st.floats(0.1, 0.5), angle=st.floats(0, 360), speed=st.floats(1.0, 25.0),
       height=st.floats(0.0005, 0.3), boxes=st.integers(2, 5), preset=st.sampled_from(PRESET_NAMES))
def test_random_shapes_past_random_corners_above_random_seamed_rails_are_untouched(shape, radius, angle, speed,
                                                                                     height, boxes, preset):
    """A shape flying level over a seamed row of boxes, `height` above it at its lowest, never touches
    it: whatever its outline, angle and speed, it keeps its velocity."""
    from polygolf.engine.loading.scene import ShapeSpec
    from polygolf.engine.physics.polygon import normalise

    outline = ShapeSpec(**shape, radius=radius).outline()
    turned = normalise([(x * math.cos(math.radians(angle)) - y * math.sin(math.radians(angle)),
                         x * math.sin(math.radians(angle)) + y * math.cos(math.radians(angle))) for x, y in outline])[0]
    lowest = min(y for _, y in turned)
    walls = [{"box": {"center": [2.0 * k + 1.0, -0.5], "half": [1.0, 0.5]}} for k in range(boxes)]
    scene = Scene.model_validate({"name": "fly", "walls": walls, "bodies": [
        {"name": "ball", "shape": {**shape, "radius": radius}, "angle": angle, "position": [-1.0, height - lowest],
         "velocity": [speed, 0.0], "restitution": 0.6, "friction": 0.5}]})
    with build_scene(scene, preset) as sim:
        sim.run(2.0 * boxes / speed + 0.1)
        ball = sim.body("ball")
        assert (ball.vx, ball.vy, ball.spin) == pytest.approx((speed, 0.0, 0.0), abs=1e-9)


@settings(max_examples=int(os.environ.get("POLYGOLF_PROPERTY_EXAMPLES", "60")), deadline=None)
@given(sides=st.sampled_from([3, 4, 5, 6, 8, 12]), radius=st.floats(0.1, 0.5), speed=st.floats(0.5, 25.0),
       widths=st.lists(st.floats(0.3, 3.0), min_size=2, max_size=6), preset=st.sampled_from(PRESET_NAMES),
       ceiling=st.booleans())
def test_random_shapes_sliding_along_random_seamed_rails_keep_their_speed(sides, radius, speed, widths, preset,
                                                                          ceiling):
    """A regular polygon with a face flat on a rail of flush boxes of random widths (a floor, or a
    ceiling it slides under), moving along it: nothing presses it into the rail, so no seam may
    change its velocity or turn it."""
    from polygolf.engine.loading.scene import ShapeSpec
    from polygolf.engine.physics.polygon import edge_normals

    nx, ny = edge_normals(ShapeSpec(regular=sides, radius=radius).outline())[0]
    turn = -90.0 - math.degrees(math.atan2(ny, nx))  # turns that face's normal straight down
    scene_angle = turn if not ceiling else turn + 180.0
    apothem = radius * math.cos(math.pi / sides)
    edges = [0.0]
    for w in widths:
        edges.append(edges[-1] + w)
    side = 1.0 if not ceiling else -1.0
    walls = [{"box": {"center": [(a + b) / 2, -0.5 * side], "half": [(b - a) / 2, 0.5]}}
             for a, b in zip(edges, edges[1:])]
    scene = Scene.model_validate({"name": "slide", "walls": walls, "bodies": [
        {"name": "ball", "shape": {"regular": sides, "radius": radius}, "angle": scene_angle,
         "position": [radius, side * apothem], "velocity": [speed, 0.0], "restitution": 0.6, "friction": 0.8}]})
    with build_scene(scene, preset) as sim:
        sim.run(min(1.0, (edges[-1] - 2 * radius) / speed))
        ball = sim.body("ball")
        assert (ball.vx, ball.vy, ball.spin) == pytest.approx((speed, 0.0, 0.0), abs=1e-9)


def _one_d(m1: float, m2: float, v1: float, v2: float, e: float) -> tuple[float, float]:
    """Velocities after a central 1-D impact with restitution e."""
    p, closing = m1 * v1 + m2 * v2, v1 - v2
    return (p - m2 * e * closing) / (m1 + m2), (p + m1 * e * closing) / (m1 + m2)


@pytest.mark.parametrize("preset", PRESET_NAMES)
@pytest.mark.parametrize("name", ["body-tunnel", "plate-tunnel"])
def test_fast_bodies_never_pass_through_each_other(preset, name):
    with scene_sim(name, preset) as sim:
        (na, a), (nb, b) = sim.bodies()
        before = (a.mass, b.mass, a.vx, b.vx)
        sim.run(0.2)
        assert a.x < b.x, f"{na} passed through {nb}"
        expected = _one_d(*before, e=0.25)
        assert (a.vx, b.vx) == pytest.approx(expected, rel=1e-6)
        assert sim.metrics.max_energy <= sim.metrics.initial_energy * (1.0 + 1e-12)


def test_a_windmill_that_would_crush_the_ball_against_a_wall_is_refused(tmp_path):
    import shutil

    from polygolf.engine.golf.holes import load_hole
    from polygolf.engine.loading.course import load_library
    from polygolf.engine.loading.paths import HOLES_DIR
    from polygolf.engine.loading.yamlsource import ContentError

    tiles = (HOLES_DIR / "tiles.yaml").read_text().replace("half: [1.9, 0.18]", "half: [2.3, 0.18]")
    (tmp_path / "tiles.yaml").write_text(tiles)
    shutil.copy(HOLES_DIR / "windmill.yaml", tmp_path / "windmill.yaml")
    with pytest.raises(ContentError, match=r"windmill.yaml:\d+: tiles\[1\]\.pattern: a windmill's sweep comes "
                                           r"within 0\.54 m of a wall: the ball \(0\.9 m across\) needs 0\.91 m"):
        load_hole(tmp_path / "windmill.yaml", load_library(tmp_path / "tiles.yaml"))


def test_water_never_puts_the_ball_back_in_a_windmills_sweep():
    from polygolf.engine.components import Water

    water = Water(keep_out=((10.0, 3.0, 2.4),), fallback=(3.0, 3.0))
    assert water.put_back(11.0, 3.5) == (3.0, 3.0)  # in the sweep: the tee instead
    assert water.put_back(6.0, 3.0) == (6.0, 3.0)  # clear of it: where it last rested


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_a_ball_wedged_in_a_v_groove_comes_to_rest(preset):
    with scene_sim("v-groove", preset) as sim:
        sim.run(4.0)
        ball = sim.body("ball")
        y = ball.y
        sim.run(1.0)
        assert ball.asleep and ball.y == y  # no creep
        assert sim.metrics.max_penetration <= LINEAR_SLOP + 0.01


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_a_heavy_block_squeezes_a_small_square_out_instead_of_into_the_wall(preset):
    """Before shock propagation: 129, 131 and 69 mm of overlap (fast, balanced, accurate)."""
    with scene_sim("heavy-crush", preset) as sim:
        ball, block = sim.body("ball"), sim.body("block")
        assert block.mass / ball.mass > 3000
        energy = sim.metrics.initial_energy
        sim.run(2.0)
        assert sim.metrics.max_penetration <= LINEAR_SLOP
        assert abs(ball.y) > 0.3  # out of the block's way, along the wall (x = -1.0)
        assert ball.x - 0.1 * math.sqrt(0.5) > -1.0 - LINEAR_SLOP  # its face (a square turned flat)
        assert sim.kinetic_energy() < 0.05 * energy  # inelastic materials: the block is stopped, nothing gained
        assert sim.metrics.max_energy_rise <= 1e-6 * energy


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_a_heavy_piston_stops_at_a_square_it_cannot_squeeze_out(preset):
    """Before shock propagation: 128, 130 and 33 mm of overlap (fast, balanced, accurate)."""
    with scene_sim("piston-crush", preset) as sim:
        piston = sim.body("piston")
        sim.run(2.0)
        assert sim.metrics.max_penetration <= LINEAR_SLOP
        assert piston.x - 0.6 > -1.0 + 0.1 * math.sqrt(2.0) - LINEAR_SLOP  # short of the end wall by the square
        assert abs(piston.vx) < 0.1


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_a_ball_passing_2mm_above_a_free_block_touches_neither(preset):
    """The gap test between bodies. Before it: at accurate the ball left at (3.84, 2.65) m/s spinning
    -15.4 rad/s, and knocked the block away."""
    with scene_sim("ghost-pass", preset) as sim:
        ball, block = sim.body("ball"), sim.body("block")
        sim.run(0.5)
        assert ball.x > 1.5  # past the block's far corner
        assert (ball.vx, ball.vy, ball.spin) == pytest.approx((8.0, 0.0, 0.0), abs=1e-9)
        assert (block.vx, block.vy, block.spin) == pytest.approx((0.0, 0.0, 0.0), abs=1e-9)


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_a_body_dropped_8mm_onto_another_rests_touching_it(preset):
    """Before the gap test between bodies it stayed 8.0 mm up, on the contact margin."""
    with scene_sim("stack-drop", preset) as sim:
        sim.run(1.5)
        bottom, top = sim.body("bottom"), sim.body("top")
        gap = top.y - bottom.y - 2 * 0.2 * math.sqrt(0.5)
        assert top.asleep and bottom.asleep
        assert -LINEAR_SLOP <= gap <= LINEAR_SLOP, gap


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_two_boxes_stacked_on_a_floor_rest_where_they_are(preset):
    """Resting contacts under gravity close by g·dt every substep (0.08 m/s at fast): bounced as
    impacts, they lifted the pair the whole contact margin (10 mm) off the floor and walked it
    sideways, never at rest. Equal boxes, restitution 0.2, friction 0.6."""
    half = 0.5 * math.sqrt(0.5)
    box = {"shape": {"regular": 4, "radius": 0.5}, "angle": 45.0, "restitution": 0.2, "friction": 0.6}
    scene = Scene.model_validate({"name": "two-boxes", "gravity": [0.0, -9.81],
                                  "walls": [{"box": {"center": [0.0, -0.5], "half": [10.0, 0.5]}}],
                                  "bodies": [{"name": "bottom", "position": [0.0, half], **box},
                                             {"name": "top", "position": [0.0, 3 * half + 0.001], **box}]})
    with build_scene(scene, preset) as sim:
        sim.run(5.0)
        bottom, top = sim.body("bottom"), sim.body("top")
        assert bottom.asleep and top.asleep
        assert abs(bottom.y - half) <= LINEAR_SLOP and abs(top.y - bottom.y - 2 * half) <= LINEAR_SLOP
        assert abs(bottom.x) < 1e-3 and abs(top.x) < 1e-3


def _pinch_world(preset: str):
    """A windmill arm (2.15 m, turning at 1.5 rad/s) whose tip passes 0.49 m from a wall, and a
    hexagon ball 0.78 m across flat against that wall in its path: a gap the content rules refuse."""
    from polygolf.engine.assembly.assemble import assemble
    from polygolf.engine.assembly.spec import DynamicPart, KinematicPart, WallPart, WorldSpec
    from polygolf.engine.components import Material, Windmill

    hexagon = tuple((0.45 * math.cos(k * math.pi / 3), 0.45 * math.sin(k * math.pi / 3)) for k in range(6))
    arm = ((-0.15, -0.15), (2.0, -0.15), (2.0, 0.15), (-0.15, 0.15))
    wall = ((-3.0, 2.5), (3.0, 2.5), (3.0, 3.0), (-3.0, 3.0))
    ball = DynamicPart("ball", hexagon, (0.0, 2.5 - 0.45 * math.sqrt(0.75)), 1.0, Material(0.6, 0.3), top_speed=25.0)
    return assemble(WorldSpec("pinch", [ball], [WallPart(wall, Material())],
                              [KinematicPart("windmill", arm, (0.0, 0.0), 1.5, extras=(Windmill(1.5),))]), preset)


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_a_windmill_never_crushes_a_ball_against_a_wall(preset):
    """Before the stall: 19.3 mm of overlap at fast. Now the arm either stalls at the ball (it stops
    short of it for as long as the ball lies there) or the ball is squeezed out along the wall."""
    import esper

    from polygolf.engine.components import Body, Windmill

    sim = _pinch_world(preset)
    try:
        ball = sim.body("ball")
        esper.switch_world(sim.world)
        arm = next(body for _, (body, _) in esper.get_components(Body, Windmill))
        sim.run(4.0)
        assert sim.metrics.max_penetration <= LINEAR_SLOP
        squeezed = abs(ball.x) > 1.0
        stalled = arm.angle < 1.5 * 4.0 - 1.0 and ball.y == pytest.approx(2.5 - 0.45 * math.sqrt(0.75), abs=LINEAR_SLOP)
        assert squeezed or stalled
    finally:
        sim.close()


@pytest.mark.parametrize("preset", PRESET_NAMES)
@pytest.mark.parametrize("seed", [249523, 11, 4242, 90210])
def test_an_elastic_rough_concave_shape_spinning_into_a_corner_gains_no_energy(preset, seed):
    """Restitution 1 and friction 1.2 on shape and walls (the issue's case: +2.5 % at fast once)."""
    rng = random.Random(seed)
    scene = Scene.model_validate({"name": "corner-energy", "bodies": [{
        "name": "ball", "shape": {"random": {"seed": seed, "vertices": rng.randint(6, 9)}, "radius": 0.4},
        "position": [1.0, 1.0], "velocity": [rng.uniform(-12, -2), rng.uniform(-12, -2)],
        "spin": rng.uniform(-30, 30), "restitution": 1.0, "friction": 1.2}],
        "walls": [{"box": {"center": [-0.5, 1.0], "half": [0.5, 3.0]}, "restitution": 1.0, "friction": 1.2},
                  {"box": {"center": [1.0, -0.5], "half": [3.0, 0.5]}, "restitution": 1.0, "friction": 1.2}]})
    with build_scene(scene, preset) as sim:
        sim.step(60)
        assert sim.metrics.max_energy <= sim.metrics.initial_energy * (1.0 + 1e-9)
        assert sim.metrics.max_penetration <= LINEAR_SLOP + 0.01


def _worst_overlap_of_full_power_shots(preset: str, players: int, hole_ids: tuple[str, ...]) -> float:
    """The deepest overlap when the first player's ball is struck at full power at the last one's,
    square, triangle and star, straight and grabbed off the line (spin), each followed to rest."""
    from polygolf.engine.golf.holes import load_all_courses
    from polygolf.engine.golf.play import HolePlay
    from polygolf.engine.loading.scene import ShapeSpec
    from polygolf.engine.physics.settings import MAX_SHOT_SPEED, SHOT_POWER

    holes = {h.id: h for c in load_all_courses()[0] for h in c.playable}
    full = MAX_SHOT_SPEED / SHOT_POWER
    worst = 0.0
    shapes = (ShapeSpec(regular=4, radius=1.0), ShapeSpec(regular=3, radius=1.0), ShapeSpec(star=(5, 2), radius=1.0))
    for shape in shapes:
        for hole_id in hole_ids:
            for off in (-0.2, 0.0, 0.2):
                play = HolePlay(holes[hole_id], shape, preset, players=players)
                try:
                    first, last = play.players[0].body, play.players[-1].body
                    dx, dy = last.x - first.x, last.y - first.y
                    d = math.hypot(dx, dy)
                    play.shoot((first.x - dy / d * off, first.y + dx / d * off), (full * dx / d, full * dy / d))
                    for _ in range(300):
                        play.sim.step(1, measure=True)
                        if play.all_at_rest:
                            break
                    worst = max(worst, play.sim.metrics.max_penetration)
                finally:
                    play.close()
    return worst


@pytest.mark.parametrize("preset", ["fast", "balanced"])
def test_a_full_power_shot_at_the_other_players_ball_never_sinks_into_it(preset):
    """Two players: the balls are swept against each other beyond the slop (`StepConfig.sweep_bodies`),
    so a ball struck straight at the other one stops at it instead of stepping a quarter of its
    width into it before the contact parts them (193 mm at fast, 82 at balanced, before)."""
    assert _worst_overlap_of_full_power_shots(preset, 2, ("straight", "pinball")) < 0.03


@pytest.mark.parametrize("preset", ["fast", "balanced"])
@pytest.mark.parametrize("players", [3, 4])
def test_a_row_of_balls_struck_at_full_power_never_sinks_into_itself(preset, players):
    """Three or four balls side by side on the tee, the first struck at full power along the row:
    each ball it drives meets the next at its time of impact, and one held back makes up at most a
    substep's motion (it saved up substep after substep while pressed, then jumped: up to 221 mm of
    overlap at fast with three players)."""
    assert _worst_overlap_of_full_power_shots(preset, players, ("straight", "corner-pocket")) < 0.03


def test_a_body_held_back_again_and_again_makes_up_one_substep_at_most():
    """Continuous collision owes a body the time it cut from its motion; held back at the start of
    three substeps running, it may move on for its own substep and one more, not four."""
    import numpy as np

    from polygolf.engine.physics.body import COLUMNS, INV_MASS, LAG, VX, X
    from polygolf.engine.physics.motion import advance, rewind

    state = np.zeros((1, len(COLUMNS)))
    state[0, INV_MASS], state[0, VX] = 1.0, 10.0
    dt, settles, rows = 1.0 / 240.0, np.zeros(1, dtype=np.bool_), np.zeros(1, dtype=np.int64)
    for _ in range(3):
        advance(state, settles, dt, 0.0, 0.0, 0.0, 1.0)
        rewind(state, rows, np.zeros(1))  # stopped where it started, every time
    assert state[0, X] == 0.0 and state[0, LAG] == pytest.approx(2 * dt)  # (one substep made up, its own lost)
    advance(state, settles, dt, 0.0, 0.0, 0.0, 1.0)
    assert state[0, X] == pytest.approx(10.0 * 2 * dt)


def _hull(points: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """The convex hull, counter-clockwise (Andrew's monotone chain)."""
    points = sorted(set(points))

    def cross(o, a, b) -> float:
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower: list[tuple[float, float]] = []
    upper: list[tuple[float, float]] = []
    for p in points:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(points):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def _seamed_floor(width: float, count: int) -> list[dict]:
    return [{"box": {"center": [-0.5 + (k + 0.5) * width, -0.5], "half": [width / 2, 0.5]}, "friction": 1.0}
            for k in range(count)]


@pytest.mark.parametrize("preset", PRESET_NAMES)
@pytest.mark.parametrize(("seed", "vertices"), [(1, 7), (17, 6), (5, 9)])
def test_a_random_shape_sliding_on_two_feet_over_seams_is_untouched(preset, seed, vertices):
    """QA: a random (non-convex) ball resting on two vertices of its hull, exactly on a floor of
    flush boxes 0.37 m wide, sliding at 25 m/s with nothing pressing it down, was kicked up at 1.9
    m/s and set spinning at a seam: one of its slanted faces, 7.7 mm above a box's hidden corner,
    was taken for the surface there. Nothing touches it harder than a graze, so it must keep its
    velocity and be where free flight puts it, on every hull edge it can stand on."""
    from polygolf.engine.loading.scene import ShapeSpec

    shape = {"random": {"seed": seed, "vertices": vertices}, "radius": 0.2}
    outline = ShapeSpec.model_validate(shape).outline()
    hull = _hull([tuple(p) for p in outline])
    for a, b in zip(hull, hull[1:] + hull[:1]):
        turn = -math.atan2(b[1] - a[1], b[0] - a[0])  # that hull edge along +x, the shape above it
        c, s = math.cos(turn), math.sin(turn)
        lowest = min(s * x + c * y for x, y in outline)
        scene = Scene.model_validate({"name": "feet", "gravity": [0.0, 0.0], "walls": _seamed_floor(0.37, 34),
                                      "bodies": [{"name": "ball", "shape": shape, "angle": math.degrees(turn),
                                                  "position": [0.0, -lowest], "velocity": [25.0, 0.0],
                                                  "restitution": 0.6, "friction": 0.3}]})
        with build_scene(scene, preset) as sim:
            sim.run(0.4)
            ball = sim.body("ball")
            assert (ball.vx, ball.vy, ball.spin) == pytest.approx((25.0, 0.0, 0.0), abs=1e-9), (a, b)
            assert (ball.x, ball.y) == pytest.approx((10.0, -lowest), abs=1e-9), (a, b)


@pytest.mark.parametrize("preset", PRESET_NAMES)
@pytest.mark.parametrize(("shape", "angle"), [({"regular": 3}, 30.0), ({"regular": 4}, 0.0), ({"star": [5, 2]}, 54.0)])
@pytest.mark.parametrize("sunk", [0.0, 0.5 * LINEAR_SLOP, 0.98 * LINEAR_SLOP])
def test_a_tip_pressed_into_a_floor_of_flush_boxes_slides_as_on_one_floor(preset, shape, angle, sunk):
    """A shape sliding on a tip at 25 m/s, `sunk` into the floor and pressed on into it (at 0.3
    m/s: the contact keeps it there, within the slop), over flush boxes 0.37 m wide: it met each
    next box's covered side face, and continuous collision put it back at every seam, 1.25 m
    behind after 0.4 s at balanced (README's known limitation until stop 30). Frictionless, so
    nothing but a seam could slow it: it must be where the same slide on one whole floor puts it,
    at the same speed."""
    shape = {**shape, "radius": 0.2}  # a tip straight down, 0.2 m below the centre
    ends = []
    for walls in (_seamed_floor(0.37, 34), [{"box": {"center": [5.79, -0.5], "half": [6.29, 0.5]}}]):
        scene = Scene.model_validate({"name": "tip", "gravity": [0.0, 0.0], "walls": walls, "bodies": [
            {"name": "ball", "shape": shape, "angle": angle, "position": [0.0, 0.2 - sunk], "velocity": [25.0, -0.3],
             "restitution": 0.0, "friction": 0.0}]})
        with build_scene(scene, preset) as sim:  # the ball's friction 0: every contact's is
            sim.run(0.4)
            ball = sim.body("ball")
            ends.append((ball.x, ball.y, ball.vx))
    seamed, whole = ends
    assert whole[0] == pytest.approx(10.0, abs=1e-9)  # the whole floor does not hold it back either
    assert seamed == pytest.approx(whole, abs=1e-6)


@pytest.mark.parametrize("preset", PRESET_NAMES)
@pytest.mark.parametrize(("sides", "angle", "height", "velocity", "spin"), [
    (6, 100.799, 0.24363, (21.358, -4.734), 3.405), (8, 229.994, 0.22768, (21.872, -2.709), -1.883),
    (4, 93.485, 0.23019, (22.053, -2.812), -2.387), (4, 41.677, 0.15723, (19.318, -1.992), -1.551)])
def test_a_landing_beside_a_seam_is_a_landing_on_one_floor(preset, sides, angle, height, velocity, spin):
    """Frictionless landings QA's sweep found held back by a seam of a floor of flush boxes 0.37 m
    wide (x = -0.13, 0.24, 0.61 ...): a tip about to land just beyond a seam would pass the first
    box's end before it sank and was still beyond the margin of the next, so no contact acted and
    continuous collision stopped the ball at the next box's hidden corner (a hexagon 25 mm behind
    at balanced, its bounce and spin lost); a corner sliding onto the next box was stopped at its
    covered face (a square 63 mm behind at fast); a point clipped at the seam took half of a landing
    tip's impulse (accurate). Each must land, bounce and slide as on one whole floor: on time and at
    the same speed and spin, its pose within a tenth of a millimetre and a milliradian (a face
    resting across a seam is held by two manifolds, one a box, not one of two points: the square
    at fast settles 0.04 mm deeper)."""
    ends = []
    for walls in (_seamed_floor(0.37, 34), [{"box": {"center": [5.79, -0.5], "half": [6.29, 0.5]}}]):
        scene = Scene.model_validate({"name": "landing", "gravity": [0.0, 0.0], "walls": walls, "bodies": [
            {"name": "ball", "shape": {"regular": sides, "radius": 0.2}, "angle": angle, "position": [0.0, height],
             "velocity": list(velocity), "spin": spin, "restitution": 0.0, "friction": 0.0}]})
        with build_scene(scene, preset) as sim:
            sim.run(0.4)
            ball = sim.body("ball")
            ends.append((ball.x, ball.y, ball.angle, ball.vx, ball.vy, ball.spin))
    seamed, whole = ends
    assert whole[0] == pytest.approx(0.4 * velocity[0], abs=1e-9)  # frictionless: on time on one floor
    assert seamed[0] == pytest.approx(whole[0], abs=1e-6)
    assert seamed[1] == pytest.approx(whole[1], abs=1e-4) and seamed[2] == pytest.approx(whole[2], abs=1e-3)
    assert seamed[3:] == pytest.approx(whole[3:], abs=1e-6)


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_a_pentagon_pressed_into_a_floor_with_a_seam_under_its_face_is_not_tipped(preset):
    """QA's random slides: a pentagon sliding at 5 m/s on one corner, its face slanting up over a
    seam and pressed 0.3 m/s into the floor, sank 5.2 mm (past the slop) in the first substep; the
    box beyond the seam then took the ball's slanted face as the reference, its own face's corner
    at the seam for the contact, the gap test dropped it, and the ball was tipped at 0.09 rad/s
    and lifted at 9 mm/s, where one floor holds both ends of the face."""
    ends = []
    for walls in ([{"box": {"center": [-0.5745, -0.5], "half": [0.5, 0.5]}},
                   {"box": {"center": [4.9255, -0.5], "half": [5.0, 0.5]}}],
                  [{"box": {"center": [4.4255, -0.5], "half": [5.5, 0.5]}}]):
        scene = Scene.model_validate({"name": "pressed", "gravity": [0.0, 0.0], "walls": walls, "bodies": [
            {"name": "ball", "shape": {"regular": 5, "radius": 0.16463}, "angle": 158.207,
             "position": [0.0, 0.13545], "velocity": [5.0, -0.3154], "restitution": 0.0, "friction": 0.0}]})
        with build_scene(scene, preset) as sim:
            sim.run(0.3)
            ball = sim.body("ball")
            ends.append((ball.x, ball.y, ball.angle, ball.vx, ball.vy, ball.spin))
    seamed, whole = ends
    assert whole[5] == pytest.approx(0.0, abs=1e-9)  # one floor: nothing tips it
    assert seamed == pytest.approx(whole, abs=1e-6)


@pytest.mark.parametrize("preset", PRESET_NAMES)
@pytest.mark.parametrize("seam", [0.09, 0.11, 0.15, 0.195])
def test_a_spinning_square_bounces_by_a_seam_as_off_one_floor(preset, seam):
    """QA: a square spinning at 10 rad/s, striking a floor at 25 m/s and 1 degree down, bounced
    nearly twice as high and lost its spin when a seam lay under it (balanced): the ball's face was
    the contact's reference against the next box's hidden corner, and the spin swung it shut. The
    floor is the same flat surface either way, so the bounce must be the one-piece floor's."""
    ends = []
    for walls in ([{"box": {"center": [seam - 2.0, -0.5], "half": [2.0, 0.5]}},
                   {"box": {"center": [seam + 6.0, -0.5], "half": [6.0, 0.5]}}],
                  [{"box": {"center": [seam + 2.0, -0.5], "half": [8.0, 0.5]}}]):
        scene = Scene.model_validate({"name": "spin-seam", "gravity": [0.0, 0.0], "walls": walls, "bodies": [
            {"name": "ball", "shape": {"regular": 4, "radius": 0.2}, "angle": 45.0,
             "position": [0.0, 0.14642135623730956],
             "velocity": [24.996192378909782, -0.4363101609320878], "spin": 10.0,
             "restitution": 0.6, "friction": 0.3}]})
        with build_scene(scene, preset) as sim:
            sim.run(0.1)
            ball = sim.body("ball")
            ends.append((ball.vx, ball.vy, ball.spin))
    seamed, whole = ends
    assert whole[1] > 0.3  # it bounced
    # Where the seam lies under the impact, two boxes share it: fast's two iterations leave the two
    # manifolds' shares a little unconverged (before the fix: 0.49 m/s and 3.6 rad/s off).
    speed, spin = (0.03, 0.3) if preset == "fast" else (2e-3, 2e-2)
    assert seamed[:2] == pytest.approx(whole[:2], abs=speed)
    assert seamed[2] == pytest.approx(whole[2], abs=spin)


@pytest.mark.parametrize("preset", PRESET_NAMES)
@pytest.mark.parametrize("gap", [0.0001, 0.001])
def test_a_star_passing_the_tip_of_a_wall_of_two_triangles_is_untouched(preset, gap):
    """QA: a star {5/2} passing 1 mm off the tip of an arrowhead wall (one outline, made of two
    triangles sharing an edge that ends at the tip) was struck across that shared edge: past the
    tip, clear of the upper triangle, the triangle's other faces alone made an overlap of 9 mm.
    It never touches the wall, so its velocity must not change and it must be on time."""
    from polygolf.engine.loading.scene import ShapeSpec

    outline = ShapeSpec(star=(5, 2), radius=0.2).outline()
    heading = math.radians(-20.0)
    ux, uy = math.cos(heading), math.sin(heading)
    # The star's centre passes the tip (the origin) on a line that keeps the star `gap` clear of it:
    # the tip's distance from the swept star is its distance from the line less the star's extent
    # across the motion on the tip's side.
    across = max(-uy * x + ux * y for x, y in outline)  # the star's reach to the right of its motion
    offset = across + gap  # the centre line passes this far left of the tip
    start = (-1.0 * ux - uy * offset, -1.0 * uy + ux * offset)
    velocity = (2.0 * ux, 2.0 * uy)
    scene = Scene.model_validate({"name": "arrow", "gravity": [0.0, 0.0], "bodies": [
        {"name": "ball", "shape": {"star": [5, 2], "radius": 0.2}, "position": list(start),
         "velocity": list(velocity), "restitution": 0.5, "friction": 0.3}],
        "walls": [{"polygon": [[0.0, 0.0], [-3.0, 0.8], [-2.0, 0.0], [-3.0, -0.8]]}]})
    with build_scene(scene, preset) as sim:
        sim.run(1.0)
        ball = sim.body("ball")
        assert (ball.vx, ball.vy, ball.spin) == pytest.approx((*velocity, 0.0), abs=1e-9)
        assert (ball.x, ball.y) == pytest.approx((start[0] + velocity[0], start[1] + velocity[1]), abs=1e-9)
        assert sim.metrics.max_penetration == 0.0


_GATE = [[5.85, 3.8], [6.15, 3.8], [6.15, 6.15], [5.85, 6.15]]
_CAP = [[5.0, 5.85], [7.0, 5.85], [7.0, 6.15], [5.0, 6.15]]  # a border wall over the gate's far end


@pytest.mark.parametrize("preset", PRESET_NAMES)
@pytest.mark.parametrize(("shape", "angle", "y", "spin"), [
    ({"regular": 8}, 145.16873701596188, 3.747499360549881, -30.0),
    ({"star": [5, 2]}, 20.0, 3.70, 30.0),
    ({"random": {"seed": 3, "vertices": 64}}, 200.0, 3.72, -30.0),
])
def test_a_wall_covered_at_its_far_end_strikes_as_the_wall_alone(preset, shape, angle, y, spin):
    """QA: a ball struck at the free corner of a gate wall whose far end (2.35 m off) lies in a border
    wall, as on narrow-gates, bounced as if the corner were on a flat stretch of wall (the border's
    hidden corner made the wall's face the reference): an octagon left at w = +0.44 rad/s, not -5.05;
    a random 64-gon was held 4.5 mm into the corner for two frames, then struck 23 mm deep. The
    border is never reached: the strike must be the gate's alone (to rounding: a piece of the 64-gon
    lying along the gate's face takes the wall's face as the reference beside the hidden corner)."""
    ends = []
    for walls in ([_GATE, _CAP], [_GATE]):
        scene = Scene.model_validate({
            "name": "gate", "gravity": [0.0, 0.0], "effects": ["restitution", "spin", "friction", "ccd"],
            "walls": [{"polygon": w, "restitution": 1.0, "friction": 1.0} for w in walls],
            "bodies": [{"name": "ball", "shape": dict(shape, radius=0.45), "angle": angle, "position": [5.0, y],
                        "velocity": [9.996599435104113, 0.26076758632186564], "spin": spin,
                        "restitution": 0.6, "friction": 0.3}]})
        with build_scene(scene, preset) as sim:
            sim.step(6)
            ball = sim.body("ball")
            ends.append((ball.x, ball.y, ball.vx, ball.vy, ball.spin, sim.metrics.max_penetration))
    capped, alone = ends
    assert capped == pytest.approx(alone, abs=1e-9)
    assert abs(alone[2] - 9.996599435104113) > 1.0  # (it was struck)


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_a_star_sliding_sunk_on_two_tips_over_narrow_flush_boxes_stays_on_time(preset):
    """QA: a star {8/3} on two tips, sunk 3.1 mm (within the slop), frictionless, sliding at 23.7 m/s
    over a row of flush boxes as narrow as 5 cm. At fast a tip passed a narrow box within a substep,
    and the box beyond it, joined to the floor the star lay by only through the narrow one, was not
    taken as the same floor: the sweep put the star back at its seam, up to 0.34 m behind."""

    xs = [-0.664498, -0.233748, 0.860717, 1.944998, 2.051393, 3.228858, 3.771594, 4.16763, 4.224993, 4.275034,
          5.085459, 5.185919, 5.849737, 5.926974, 6.571397, 6.680676, 7.001373, 8.149164, 8.424255, 8.615543,
          8.780635, 8.858597, 9.156113, 10.307508]
    depth, speed, angle = 0.4127146633127921, 23.709751227486993, -22.5
    shape = {"star": [8, 3], "radius": 0.36449810760716944}
    walls = [{"box": {"center": [(p + q) / 2, -depth / 2], "half": [(q - p) / 2, depth / 2]}, "restitution": 0.5,
              "friction": 0.0} for p, q in zip(xs, xs[1:])]
    _assert_slides_on_time(preset, shape, angle, 0.0031374671030305703, speed, walls, 0.6, 0.0)


def _assert_slides_on_time(preset: str, shape: dict, angle: float, sunk: float, speed: float, walls: list,
                           restitution: float, friction: float) -> None:
    """A ball of `shape` turned `angle` (degrees), its lowest point `sunk` below y = 0 (the top of
    `walls`), sliding along x at `speed`: where free motion puts it every frame for 0.3 s, its
    velocity and spin untouched."""
    from polygolf.engine.loading.scene import ShapeSpec

    a = math.radians(angle)
    lowest = min(math.sin(a) * x + math.cos(a) * y for x, y in ShapeSpec(**shape).outline())
    scene = Scene.model_validate({
        "name": "slide", "walls": walls,
        "bodies": [{"name": "ball", "shape": shape, "angle": angle, "position": [0.0, -lowest - sunk],
                    "velocity": [speed, 0.0], "restitution": restitution, "friction": friction}]})
    with build_scene(scene, preset) as sim:
        ball = sim.body("ball")
        for frame in range(1, 19):
            sim.step()
            assert ball.x == pytest.approx(speed * frame / 60.0, abs=1e-6), frame
        assert (ball.vx, ball.vy, ball.spin) == (speed, 0.0, 0.0)


@pytest.mark.parametrize("preset", PRESET_NAMES)
def test_a_star_tip_sunk_just_short_of_a_seam_lies_on_the_floor(preset):
    """QA: a star {8/3} on two tips, sunk 2.3 mm, sliding at 17.3 m/s over flush boxes. One tip lay
    2.1 mm short of a seam: nearer the covered side face of its box (and the star's own cut between
    two pieces, parallel to it) than the top, so the star was not seen lying on the floor, and the
    box after the next seam put it back 72 mm at fast (frame 18)."""

    xs = [-0.4666189878834811, -0.31386678469725265, 0.754718420414974, 1.6933858694225739, 1.8441128471287098,
          2.560265309552831, 3.667187888851384, 4.194288745318153, 4.982900984398106, 5.062260178425308,
          5.9477466594575485, 6.896567170155041, 7.404750813723904]
    depth, speed, angle, sunk = 0.35695849508392274, 17.29550878876301, 67.5, 0.0023223933999038326
    shape = {"star": [8, 3], "radius": 0.1666189878834811}
    walls = [{"box": {"center": [(p + q) / 2, -depth / 2], "half": [(q - p) / 2, depth / 2]}, "restitution": 1.0,
              "friction": 0.0} for p, q in zip(xs, xs[1:])]
    _assert_slides_on_time(preset, shape, angle, sunk, speed, walls, 0.0, 1.0)
