"""Game time from a fixed-timestep accumulator, and the poses drawn between physics frames."""

from __future__ import annotations

import math

import pytest

from polygolf.engine.physics.settings import FRAME_DT
from polygolf.game.timing import MAX_CATCH_UP, FixedStep, Poses, blend


@pytest.mark.parametrize("fps", [20, 35, 60, 144, 240])
def test_any_frame_rate_steps_sixty_physics_frames_a_second(fps):
    clock = FixedStep()
    stepped = sum(clock.advance(1 / fps) for _ in range(fps * 3))
    assert stepped == 180
    assert 0.0 <= clock.alpha < 1.0


def test_leftover_time_is_the_drawing_alpha():
    clock = FixedStep()
    assert clock.advance(FRAME_DT * 2.25) == 2
    assert clock.alpha == pytest.approx(0.25)
    assert clock.advance(FRAME_DT * 0.5) == 0
    assert clock.alpha == pytest.approx(0.75)


def test_a_stall_is_cut_to_the_catch_up_cap():
    clock = FixedStep()
    assert clock.advance(5.0) == round(MAX_CATCH_UP / FRAME_DT)
    assert clock.advance(-1.0) == 0  # a clock going backwards adds nothing


def test_blend_interpolates_position_and_turns_the_short_way():
    x, y, angle = blend((0.0, 0.0, math.pi - 0.1), (0.4, -0.2, -math.pi + 0.1), 0.5)
    assert (x, y) == pytest.approx((0.2, -0.1))
    assert math.remainder(angle - math.pi, math.tau) == pytest.approx(0.0, abs=1e-12)  # through pi, not zero


def test_a_jump_is_drawn_where_the_body_landed():
    poses = Poses((10.0, 0.0, 0.0))
    poses.moved_to((2.0, 3.0, 0.0))  # put back after water: no slide across the course
    assert poses.at(0.3) == (2.0, 3.0, 0.0)
