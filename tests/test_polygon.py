"""Polygon generation, validation, normalisation and convex decomposition."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from polygolf.engine.physics import polygon
from polygolf.engine.physics.polygon import PolygonError


@pytest.mark.parametrize("sides", range(3, 13))
def test_regular_polygon_has_equal_sides_on_its_circle(sides):
    verts = polygon.regular_polygon(sides, 0.5)
    assert len(verts) == sides
    assert all(math.hypot(x, y) == pytest.approx(0.5) for x, y in verts)
    edges = [math.dist(verts[i], verts[(i + 1) % sides]) for i in range(sides)]
    assert edges == pytest.approx([2 * 0.5 * math.sin(math.pi / sides)] * sides)
    assert polygon.signed_area(verts) == pytest.approx(0.5 * sides * 0.25 * math.sin(2 * math.pi / sides))


@pytest.mark.parametrize(("p", "q"), [(5, 2), (7, 2), (7, 3), (8, 3), (9, 4), (6, 2)])
def test_star_outline_is_simple_and_its_notches_lie_on_the_chords(p, q):
    verts = polygon.star_polygon(p, q, 1.0)
    assert len(verts) == 2 * p
    assert polygon.is_simple(verts) and polygon.signed_area(verts) > 0
    assert not polygon.is_convex(verts)
    # The notch between tips 0 and 1 is where chord (tip 0 -> tip q) crosses chord (tip 1 -> tip 1-q).
    tip = [(math.cos(2 * math.pi * k / p), math.sin(2 * math.pi * k / p)) for k in range(p)]
    a, b = tip[0], tip[q % p]
    c, d = tip[1], tip[(1 - q) % p]
    den = (a[0] - b[0]) * (c[1] - d[1]) - (a[1] - b[1]) * (c[0] - d[0])
    t = ((a[0] - c[0]) * (c[1] - d[1]) - (a[1] - c[1]) * (c[0] - d[0])) / den
    crossing = (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
    assert verts[1] == pytest.approx(crossing)


def test_star_five_two_inner_radius_is_golden():
    verts = polygon.star_polygon(5, 2, 1.0)
    golden = (1 + math.sqrt(5)) / 2
    assert math.hypot(*verts[1]) == pytest.approx(1 / golden**2)


@given(seed=st.integers(0, 2**31), n=st.integers(3, 24), radius=st.floats(0.05, 5.0))
def test_random_polygons_are_simple_ccw_and_far_from_degenerate(seed, n, radius):
    verts = polygon.random_polygon(seed, n, radius)
    assert len(verts) == n
    assert polygon.is_simple(verts)
    assert polygon.signed_area(verts) > 0.05 * radius * radius
    assert polygon.bounding_radius(verts) == pytest.approx(radius)
    assert polygon.random_polygon(seed, n, radius) == verts  # seeded: the same every time


def test_normalise_makes_ccw_and_centres_on_the_centroid():
    clockwise_l = [(0, 0), (0, 2), (1, 2), (1, 1), (2, 1), (2, 0)]
    verts, centre = polygon.normalise(clockwise_l)
    assert polygon.signed_area(verts) == pytest.approx(3.0)
    # L of three unit squares: centroid at (5/6, 5/6).
    assert centre == pytest.approx((5 / 6, 5 / 6))
    assert polygon.centroid(verts) == pytest.approx((0.0, 0.0), abs=1e-12)


@pytest.mark.parametrize("far", [0.0, 1000.0, 100_000.0])
def test_zero_area_is_judged_at_the_polygons_own_size_wherever_it_lies(far):
    """A half-square-metre triangle is one 100 km out too (it was refused as "zero area" there);
    a flat one is refused everywhere."""
    verts, centre = polygon.normalise([(far, far), (far - 1.0, far), (far, far - 1.0)])
    assert polygon.signed_area(verts) == pytest.approx(0.5, rel=1e-6) and centre == pytest.approx((far - 1 / 3,) * 2)
    with pytest.raises(PolygonError, match="zero area"):
        polygon.normalise([(far, far), (far + 1.0, far + 1.0), (far + 2.0, far + 2.0)])


def test_normalise_drops_collinear_vertices():
    verts, _ = polygon.normalise([(0, 0), (1, 0), (2, 0), (2, 2), (0, 2)])
    assert len(verts) == 4


@pytest.mark.parametrize(
    ("vertices", "message"),
    [
        ([(0, 0), (1, 0)], "at least 3"),
        ([(0, 0), (1, 0), (2, 0)], "zero area"),
        ([(0, 0), (4, 0), (0, 3), (3, 3)], "cross"),
        ([(0, 0), (1, 1), (1, 0), (0, 1)], "cross"),  # a symmetric bowtie: its halves' areas cancel (QA)
        ([(0, 0), (1, 0), (1, 0), (0, 1)], "repeated"),
        ([(0, 0), (1, 0), (math.nan, 1)], "finite"),
        ([(0, 0), (1,), (0, 1)], "pairs"),
    ],
)
def test_bad_outlines_are_refused_with_the_reason(vertices, message):
    with pytest.raises(PolygonError, match=message):
        polygon.normalise(vertices)


def _pieces_ok(outline):
    pieces = polygon.convex_pieces(outline)
    assert all(polygon.is_convex(p) and polygon.signed_area(p) > 0 for p in pieces)
    assert sum(polygon.signed_area(p) for p in pieces) == pytest.approx(polygon.signed_area(outline))
    return pieces


@pytest.mark.parametrize(("p", "q"), [(5, 2), (7, 2), (7, 3), (8, 3)])
def test_stars_split_into_convex_pieces_covering_their_area(p, q):
    pieces = _pieces_ok(polygon.star_polygon(p, q, 1.0))
    assert len(pieces) <= 2 * p  # Hertel-Mehlhorn: within 4x of the optimum p + 1


@given(seed=st.integers(0, 10_000), n=st.integers(3, 16))
def test_random_polygons_split_into_convex_pieces(seed, n):
    _pieces_ok(polygon.normalise(polygon.random_polygon(seed, n, 1.0))[0])


def test_convex_outline_is_its_own_piece():
    square = polygon.regular_polygon(4, 1.0)
    assert polygon.convex_pieces(square) == [square]


@given(radius=st.floats(0.01, 10.0), pq=st.sampled_from([(5, 2), (7, 2), (7, 3), (8, 3), (9, 4)]))
def test_stars_of_any_size_validate(radius, pq):
    """A star's outline has several edges on one chord; rounding must not make them 'cross'."""
    assert polygon.is_simple(polygon.star_polygon(*pq, radius))
    polygon.normalise(polygon.star_polygon(*pq, radius))


def test_star_seven_three_at_an_awkward_radius_is_simple():
    assert polygon.is_simple(polygon.star_polygon(7, 3, 0.14576153822865226))  # found by hypothesis
