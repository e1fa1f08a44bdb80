"""Separating axes and reference-face clipping on convex pieces."""

from __future__ import annotations

import numpy as np
import pytest

from polygolf.engine.physics import polygon
from polygolf.engine.physics.collide import collide_polygons, separation
from polygolf.engine.physics.geometry import ConvexSet
from polygolf.engine.physics.toi import time_of_impact, toi_work


def at(verts, dx=0.0, dy=0.0):
    verts = [(x + dx, y + dy) for x, y in verts]
    return verts, list(polygon.edge_normals(verts))


def box(hx, hy):
    return [(-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy)]


def test_face_to_face_gives_two_points_with_the_overlap():
    a, na = at(box(1.0, 1.0))
    b, nb = at(box(0.5, 0.5), dx=1.4)  # overlaps by 0.1 along x
    normal, points = collide_polygons(a, na, b, nb, margin=0.01)
    assert normal == pytest.approx((1.0, 0.0))
    assert len(points) == 2
    assert [p.separation for p in points] == pytest.approx([-0.1, -0.1])
    assert sorted(p.y for p in points) == pytest.approx([-0.5, 0.5])
    assert len({p.feature for p in points}) == 2


def test_vertex_into_face_gives_one_point_at_the_vertex():
    diamond = polygon.regular_polygon(4, 0.5)  # a vertex points at -x
    a, na = at(box(1.0, 1.0))
    b, nb = at(diamond, dx=1.45)
    normal, points = collide_polygons(a, na, b, nb, margin=0.01)
    assert normal == pytest.approx((1.0, 0.0))
    assert len(points) == 1
    assert points[0].separation == pytest.approx(-0.05)
    assert (points[0].clip_x, points[0].clip_y) == pytest.approx((0.95, 0.0))


def test_apart_beyond_the_margin_is_no_contact_and_normal_points_a_to_b():
    a, na = at(box(1.0, 1.0))
    b, nb = at(box(0.5, 0.5), dx=1.52)
    assert collide_polygons(a, na, b, nb, margin=0.01) is None
    assert separation(a, na, b, nb) == pytest.approx(0.02)
    normal, _ = collide_polygons(b, nb, a, na, margin=0.05)
    assert normal == pytest.approx((-1.0, 0.0))


def test_time_of_impact_head_on_and_miss():
    square = tuple(box(0.1, 0.1))
    normals = tuple(polygon.edge_normals(square))
    wall = tuple(box(0.025, 2.0))
    wall_normals = tuple(polygon.edge_normals(wall))
    reach = 0.1 * 2**0.5
    # From x=2 to x=-2 in one step: touches (within 0.005) when the face reaches x = 0.025 + 0.005.
    piece, walls = ConvexSet.of([square], [normals]), ConvexSet.of([wall], [wall_normals])

    def toi(start, end):
        return time_of_impact(piece.verts, piece.normals, 0, 4, reach, np.array(start), np.array(end), walls.verts,
                              walls.normals, 0, 4, 0.005, 0.001, 0.005, toi_work(4))

    t = toi((2.0, 0.0, 0.0), (-2.0, 0.0, 0.0))
    assert 2.0 - 4.0 * t - 0.1 == pytest.approx(0.03, abs=0.0011)
    # Passing above the wall's end: no impact.
    assert toi((2.0, 3.0, 0.0), (-2.0, 3.0, 0.0)) >= 1.0
