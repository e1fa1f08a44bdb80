"""Exact mass properties, checked against textbook closed forms and against independent sums."""

from __future__ import annotations

import math

import pytest

from polygolf.engine.physics import polygon
from polygolf.engine.physics.mass import mass_properties


def test_rectangle_matches_textbook_inertia():
    w, h, rho = 3.0, 0.5, 2.0
    props = mass_properties([(-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2)], rho)
    assert props.mass == pytest.approx(rho * w * h)
    assert props.inertia == pytest.approx(props.mass * (w * w + h * h) / 12.0)


def test_regular_polygon_matches_closed_form_not_the_circle_approximation():
    # I = m R² (1 + 2 cos²(π/n)) / 6 for a regular n-gon of circumradius R.
    for n in range(3, 13):
        verts = polygon.regular_polygon(n, 0.7)
        props = mass_properties(verts)
        expected = props.mass * 0.49 * (1 + 2 * math.cos(math.pi / n) ** 2) / 6.0
        assert props.inertia == pytest.approx(expected, rel=1e-12)
        assert props.inertia != pytest.approx(0.5 * props.mass * 0.49, rel=1e-3)  # the seed's shortcut


def test_triangle_centroid_and_inertia():
    a, b, c = (0.0, 0.0), (4.0, 0.0), (0.0, 3.0)
    props = mass_properties([a, b, c])
    assert props.centroid == pytest.approx((4 / 3, 1.0))
    # Right triangle about its centroid: m (a² + b²) / 18.
    assert props.inertia == pytest.approx(props.area * (16 + 9) / 18)


def test_non_convex_equals_sum_of_its_pieces_by_parallel_axis():
    for outline in (polygon.star_polygon(5, 2, 1.0), polygon.star_polygon(8, 3, 0.4),
                    polygon.normalise(polygon.random_polygon(11, 9, 1.0))[0]):
        whole = mass_properties(outline, 3.0)
        cx, cy = whole.centroid
        total_mass, total_inertia = 0.0, 0.0
        for piece in polygon.convex_pieces(outline):
            part = mass_properties(piece, 3.0)
            px, py = part.centroid
            total_mass += part.mass
            total_inertia += part.inertia + part.mass * ((px - cx) ** 2 + (py - cy) ** 2)
        assert whole.mass == pytest.approx(total_mass, rel=1e-12)
        assert whole.inertia == pytest.approx(total_inertia, rel=1e-12)


def test_far_from_origin_keeps_precision():
    square = [(x + 1e6, y + 1e6) for x, y in polygon.regular_polygon(4, 1.0)]
    props = mass_properties(square)
    assert props.centroid == pytest.approx((1e6, 1e6), abs=1e-6)
    assert props.inertia == pytest.approx(props.mass * 2.0 / 6.0, rel=1e-9)


def test_clockwise_outline_is_refused():
    with pytest.raises(ValueError):
        mass_properties(list(reversed(polygon.regular_polygon(4, 1.0))))
