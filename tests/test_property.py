"""Property test: any ball, any shot, in a closed box. Never NaN, kinetic energy never rises,
never out of the box."""

from __future__ import annotations

import math

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from polygolf.engine.loading.scene import Scene, build_scene
from polygolf.engine.physics.settings import MAX_SHOT_SPEED

ROOM_W, ROOM_H = 6.0, 4.0

shapes = st.one_of(
    st.builds(lambda n: {"regular": n}, st.integers(3, 12)),
    st.builds(lambda pq: {"star": list(pq)}, st.sampled_from([(5, 2), (7, 2), (7, 3), (8, 3)])),
    st.builds(lambda seed, n: {"random": {"seed": seed, "vertices": n}}, st.integers(0, 10_000), st.integers(3, 10)),
)


def room_scene(shape: dict, radius: float, angle: float, speed: float, heading: float, spin: float,
               restitution: float, friction: float) -> Scene:
    t = 0.5
    walls = [
        {"box": {"center": [-t, ROOM_H / 2], "half": [t, ROOM_H / 2 + 2 * t]}},
        {"box": {"center": [ROOM_W + t, ROOM_H / 2], "half": [t, ROOM_H / 2 + 2 * t]}},
        {"box": {"center": [ROOM_W / 2, -t], "half": [ROOM_W / 2 + 2 * t, t]}},
        {"box": {"center": [ROOM_W / 2, ROOM_H + t], "half": [ROOM_W / 2 + 2 * t, t]}},
    ]
    body = {
        "name": "ball", "shape": {**shape, "radius": radius}, "angle": angle,
        "position": [ROOM_W / 2, ROOM_H / 2],
        "velocity": [speed * math.cos(heading), speed * math.sin(heading)], "spin": spin,
        "restitution": restitution, "friction": friction,
    }
    return Scene.model_validate({"name": "property-room", "bodies": [body], "walls": walls})


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    shape=shapes,
    radius=st.floats(0.1, 0.6),
    angle=st.floats(0, 360),
    speed=st.floats(0, MAX_SHOT_SPEED),
    heading=st.floats(0, 2 * math.pi),
    spin=st.floats(-30, 30),
    restitution=st.floats(0, 1),
    friction=st.floats(0, 1),
    preset=st.sampled_from(["fast", "balanced", "accurate"]),
)
def test_any_shot_in_a_closed_box_is_sane(shape, radius, angle, speed, heading, spin, restitution, friction, preset):
    scene = room_scene(shape, radius, angle, speed, heading, spin, restitution, friction)
    with build_scene(scene, preset) as sim:
        ball = sim.body("ball")
        import esper

        from polygolf.engine.components import Collider

        outline = esper.component_for_entity(next(iter(sim.names)), Collider).outline
        e0 = sim.kinetic_energy()
        for _ in range(90):
            sim.step()
            c, s = math.cos(ball.angle), math.sin(ball.angle)
            for x, y in outline:
                wx, wy = ball.x + c * x - s * y, ball.y + s * x + c * y
                assert -0.02 < wx < ROOM_W + 0.02 and -0.02 < wy < ROOM_H + 0.02, "left the box"
        assert not sim.metrics.nan
        assert sim.metrics.max_energy_rise <= 1e-9 * max(e0, 1e-12)
        assert sim.metrics.max_energy <= e0 * (1 + 1e-9) + 1e-15
