"""Every hazard reads at a glance in every theme, by numbers: its colour is far from the green, the
checker's other green and the walls (and a bumper from the ball); the power ramp changes lightness,
so it reads without red-green vision."""

from __future__ import annotations

import math

import pytest

from polygolf.game.drawing import lightness
from polygolf.game.theme import FALLBACK, Theme, load_themes

THEMES, _ = load_themes()
HAZARD_COLOURS = ("sand_zone", "water", "ice", "slope", "bumper", "windmill")
SURROUNDINGS = ("green", "green_alt", "wall")
MIN_DISTANCE = 70.0  # RGB distance; the grass checker's two greens are 10 apart


def distance(theme: Theme, a: str, b: str) -> float:
    return math.dist(theme.rgba(a)[:3], theme.rgba(b)[:3])



def test_the_three_shipped_themes_load():
    assert {t.name for t in THEMES} == {"Grass", "Night", "Sand"}


@pytest.mark.parametrize("theme", [*THEMES, FALLBACK], ids=lambda t: t.name)
@pytest.mark.parametrize("hazard", HAZARD_COLOURS)
def test_every_hazard_colour_stands_out_from_the_green_and_the_walls(theme, hazard):
    for other in SURROUNDINGS:
        assert distance(theme, hazard, other) >= MIN_DISTANCE, (theme.name, hazard, other)


@pytest.mark.parametrize("theme", [*THEMES, FALLBACK], ids=lambda t: t.name)
def test_bumpers_windmills_and_obstacles_do_not_look_like_the_ball_or_each_other(theme):
    assert distance(theme, "bumper", "ball") >= MIN_DISTANCE
    assert distance(theme, "windmill", "ball") >= MIN_DISTANCE
    assert distance(theme, "sand_zone", "obstacle") >= MIN_DISTANCE  # a bunker is not a wall block
    assert distance(theme, "ice", "wall") >= MIN_DISTANCE


@pytest.mark.parametrize("theme", [*THEMES, FALLBACK], ids=lambda t: t.name)
def test_the_power_ramp_changes_lightness(theme):
    assert abs(lightness(theme.rgba("arrow")) - lightness(theme.rgba("arrow_strong"))) >= 0.3
