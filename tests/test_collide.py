"""Separating axes and reference-face clipping on convex pieces."""

from __future__ import annotations

import math

import numpy as np
import pytest

from polygolf.engine.physics import polygon
from polygolf.engine.physics.collide import collide_polygons, separation
from polygolf.engine.physics.geometry import ConvexSet, ShapeTable
from polygolf.engine.physics.settings import GAP_TOLERANCE
from polygolf.engine.physics.toi import pair_reaches, reaches_wall, time_of_impact, toi_work


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


def _lowest_over_floor(verts, y, angle):
    c, s = math.cos(angle), math.sin(angle)
    return min(y + s * x + c * v for x, v in verts)


@pytest.mark.parametrize("sides", [3, 4, 7])
def test_the_gap_test_says_a_turning_body_reaches_a_floor_exactly_when_it_presses_into_it(sides):
    """A spinning polygon a little above a floor (gap 0.2-4 mm), moving on for a substep: the gap
    test must say it reaches the floor when it ends pressed in by more than the tolerance, and must
    not when every pose on the way (sampled finely) stays a millimetre clear. Conservative
    advancement crept along the turning bound, ran out of its steps and answered no for a triangle
    ending up to 3 mm in the floor (515 of 20 000 such cases)."""
    rng = np.random.default_rng(sides)
    outline = [(0.5 * math.cos(2 * math.pi * k / sides), 0.5 * math.sin(2 * math.pi * k / sides)) for k in range(sides)]
    body = ConvexSet.of([tuple(outline)], [tuple(polygon.edge_normals(outline))])
    floor = ConvexSet.of([tuple(box(5.0, 0.5))], [tuple(polygon.edge_normals(box(5.0, 0.5)))])
    floor_verts = floor.verts - np.array([0.0, 0.5])  # its top face at y = 0
    dt = 1.0 / 240.0
    pressed = clear = 0
    for _ in range(600):
        angle, gap = rng.uniform(0.0, 2 * math.pi), rng.uniform(2e-4, 0.004)
        vx, vy, spin = rng.uniform(-8.0, 8.0), rng.uniform(-1.0, 0.2), rng.uniform(-40.0, 40.0)
        y = gap - _lowest_over_floor(outline, 0.0, angle)
        reaches = reaches_wall(body.verts, body.normals, body.first, body.reach, 0.0, y, angle, vx, vy, spin, dt,
                               floor_verts, floor.normals, 0, 4, toi_work(max(sides, 4)))
        if _lowest_over_floor(outline, y + vy * dt, angle + spin * dt) < -GAP_TOLERANCE - 1e-9:
            pressed += 1
            assert reaches
        elif min(_lowest_over_floor(outline, y + vy * dt * t, angle + spin * dt * t)
                 for t in np.linspace(0.0, 1.0, 2001)) > 0.001:
            clear += 1
            assert not reaches
    assert pressed > 50 and clear > 50  # both kinds were asked about


def test_the_gap_test_between_two_bodies_says_they_reach_when_they_end_pressed_in():
    """The same for two turning triangles (`pair_reaches`, both moving on)."""
    outline = [(0.5 * math.cos(2 * math.pi * k / 3), 0.5 * math.sin(2 * math.pi * k / 3)) for k in range(3)]
    body = ConvexSet.of([tuple(outline)], [tuple(polygon.edge_normals(outline))])
    slab = box(3.0, 0.5)
    block = ConvexSet.of([tuple(slab)], [tuple(polygon.edge_normals(slab))])
    rng = np.random.default_rng(5)
    dt, pressed = 1.0 / 240.0, 0
    for _ in range(600):
        angle, gap = rng.uniform(0.0, 2 * math.pi), rng.uniform(2e-4, 0.004)
        vel_a = np.array([rng.uniform(-8.0, 8.0), rng.uniform(-1.0, 0.2), rng.uniform(-40.0, 40.0)])
        vel_b = np.array([rng.uniform(-1.0, 1.0), 0.0, 0.0])
        pose_a = np.array([0.0, gap - _lowest_over_floor(outline, 0.0, angle), angle])
        pose_b = np.array([0.0, -0.5, 0.0])  # the block's top face at y = 0, sliding under the triangle
        ends_in = _lowest_over_floor(outline, pose_a[1] + vel_a[1] * dt, angle + vel_a[2] * dt) < -GAP_TOLERANCE - 1e-9
        if not ends_in:
            continue
        pressed += 1
        assert pair_reaches(body.verts, body.normals, body.first, body.reach, 0.5, pose_a, vel_a, block.verts,
                            block.normals, block.first, block.reach, 3.05, pose_b, vel_b, dt, gap, False, False,
                            toi_work(4))
    assert pressed > 50


def test_time_of_impact_s_quick_answers_are_the_advancement_s_own():
    """Before advancing, `time_of_impact` answers NO_HIT where the piece's bounding circle, or the
    piece itself (its separations asked in its own frame), stays beyond a face of the wall farther
    than the motion can close: each answer must be the one the advancement alone gives, for a
    hexagon and a star's pieces moving and turning about a slanted and a square wall piece, for
    continuous collision's target and the gap test's (and both kinds of answer must come up)."""
    from polygolf.engine.physics.settings import GAP_TOLERANCE
    from polygolf.engine.physics.toi import _NOWHERE, NO_HIT, _advance, stays_clear, wall_out_of_reach

    rng = np.random.default_rng(5)
    walls = [box(1.5, 0.1), [(0.4, 0.3), (1.8, 0.3), (0.4, 1.6)]]
    wall = ConvexSet.of(walls, [polygon.edge_normals(w) for w in walls])
    pieces = [polygon.regular_polygon(6, 0.3), *polygon.convex_pieces(polygon.star_polygon(5, 2, 0.35))]
    body = ConvexSet.of(pieces, [polygon.edge_normals(p) for p in pieces])
    work = toi_work(6)
    quick, advanced, hits, let_go = 0, 0, 0, 0
    for _ in range(3000):
        i, g = int(rng.integers(len(pieces))), int(rng.integers(len(walls)))
        s, e, ws, we = body.first[i], body.first[i + 1], wall.first[g], wall.first[g + 1]
        start = np.array([rng.uniform(-2.0, 2.0), rng.uniform(-0.5, 2.0), rng.uniform(-3.2, 3.2)])
        end = start + np.array([*rng.normal(0.0, 0.15, 2), rng.normal(0.0, 0.3)])
        for target, tolerance, allowance in ((0.005, 0.00125, 0.005), (-1e-4, 5e-5, 0.0)):
            got = time_of_impact(body.verts, body.normals, s, e, body.reach[i], start, end, wall.verts, wall.normals,
                                 ws, we, target, tolerance, allowance, work)
            rates = np.empty(len(work[2]))  # (the advancement writes the piece's faces' rates after the wall's)
            wall_out_of_reach(body.reach[i], start, end, wall.verts, wall.normals, ws, we, target, tolerance, rates)
            alone = _advance(body.verts, body.normals, s, e, start, end, wall.verts, wall.normals, ws, we, _NOWHERE,
                             _NOWHERE, True, rates, abs(end[2] - start[2]) * body.reach[i], target, tolerance,
                             allowance, rates, False, work)
            # (The sweep's stop short of the wall stands only where the piece would go on to touch it.)
            if alone < 1.0 and target > 0.0 and stays_clear(body.verts, body.normals, s, e, start, end, wall.verts,
                                                              wall.normals, ws, we, _NOWHERE, _NOWHERE, -GAP_TOLERANCE,
                                                              alone, np.empty(3)):
                alone, let_go = NO_HIT, let_go + 1
            assert got == alone
            quick += got == NO_HIT
            hits += got < 1.0
            advanced += 1
    assert quick > 500 and hits > 100 and let_go > 0  # every answer (let go: 3 of the 6 000)


def _point_edges(points: tuple, polygon_: tuple) -> float:
    """The least distance from the points (x, y: (sample, point)) to the polygon's edges (x, y: (sample,
    vertex) or (vertex,) for one that stands still), over every sample."""
    px, py = points
    ax, ay = np.broadcast_to(polygon_[0], px.shape[:1] + polygon_[0].shape[-1:]), \
        np.broadcast_to(polygon_[1], px.shape[:1] + polygon_[1].shape[-1:])
    bx, by = np.roll(ax, -1, axis=-1), np.roll(ay, -1, axis=-1)
    ex, ey = (bx - ax)[:, None, :], (by - ay)[:, None, :]
    dx, dy = px[:, :, None] - ax[:, None, :], py[:, :, None] - ay[:, None, :]
    t = np.clip((dx * ex + dy * ey) / (ex * ex + ey * ey), 0.0, 1.0)
    return float(np.hypot(dx - t * ex, dy - t * ey).min())


@pytest.mark.parametrize("clearance", [0.01, -1e-4])
def test_stays_clear_is_never_wrong_and_exact_along_a_wall_face(clearance):
    """`toi.stays_clear` against the motion sampled at 20 001 poses, for a hexagon and a star's pieces
    moving and turning (up to two turns a substep) about a slanted and a square wall piece: where it
    says clear, the pieces' separation (their distance apart, or less their overlap) stays beyond the
    clearance at every pose; where a wall face keeps every sampled vertex beyond the clearance by more
    than a sampling step's travel, it says clear (exact along a face: the bottom of each vertex's
    circle); and both answers come up."""
    from polygolf.engine.physics.toi import stays_clear

    rng = np.random.default_rng(11)
    walls = [box(1.5, 0.1), [(0.4, 0.3), (1.8, 0.3), (0.4, 1.6)]]
    wall = ConvexSet.of(walls, [polygon.edge_normals(w) for w in walls])
    pieces = [polygon.regular_polygon(6, 0.3), *polygon.convex_pieces(polygon.star_polygon(5, 2, 0.35))]
    body = ConvexSet.of(pieces, [polygon.edge_normals(p) for p in pieces])
    ts = np.linspace(0.0, 1.0, 20001)
    said = {True: 0, False: 0}
    for _ in range(300):
        i, g = int(rng.integers(len(pieces))), int(rng.integers(len(walls)))
        s, e, ws, we = body.first[i], body.first[i + 1], wall.first[g], wall.first[g + 1]
        start = np.array([rng.uniform(-1.0, 2.5), rng.uniform(0.2, 1.2), rng.uniform(-3.2, 3.2)])
        end = start + np.array([*rng.normal(0.0, 0.3, 2), rng.normal(0.0, 4.0)])
        poses = start + ts[:, None] * (end - start)  # (sample, x y angle)
        c, sn = np.cos(poses[:, 2:]), np.sin(poses[:, 2:])
        lx, ly, mx, my = body.verts[s:e, 0], body.verts[s:e, 1], body.normals[s:e, 0], body.normals[s:e, 1]
        x, y = poses[:, :1] + c * lx - sn * ly, poses[:, 1:2] + sn * lx + c * ly  # (sample, vertex)
        nx_, ny_ = c * mx - sn * my, sn * mx + c * my  # the piece's faces' normals
        wx, wy = wall.verts[ws:we, 0], wall.verts[ws:we, 1]
        nx, ny = wall.normals[ws:we, 0], wall.normals[ws:we, 1]
        beyond_wall = ((x[:, :, None] - wx) * nx + (y[:, :, None] - wy) * ny).min(axis=1)  # (sample, wall face)
        beyond_piece = ((wx[None, None, :] - x[:, :, None]) * nx_[:, :, None]
                        + (wy[None, None, :] - y[:, :, None]) * ny_[:, :, None]).min(axis=2)  # (sample, face)
        apart = np.maximum(beyond_wall.max(axis=1), beyond_piece.max(axis=1))  # (separating axes' best)
        between = (np.hypot(*(end[:2] - start[:2])) + abs(end[2] - start[2]) * body.reach[i]) / (len(ts) - 1)
        clear = stays_clear(body.verts, body.normals, s, e, start, end, wall.verts, wall.normals, ws, we, np.zeros(3),
                            np.zeros(3), clearance, 0.0, np.empty(3))
        if clear and clearance < 0.0:  # (overlapping or not, no axis separates them more than the best face)
            assert apart.min() > clearance - 1e-9
        if clear and clearance > 0.0:  # (apart: the least of the vertex-to-edge distances either way)
            assert apart.min() > 0.0
            assert min(_point_edges((x, y), (wx, wy)), _point_edges((np.broadcast_to(wx, x.shape[:1] + wx.shape),
                                                                     np.broadcast_to(wy, x.shape[:1] + wy.shape)),
                                                                    (x, y))) > clearance - 1e-9
        if beyond_wall.min(axis=0).max() > clearance + between:
            assert clear
        said[bool(clear)] += 1
    assert said[True] > 30 and said[False] > 30


def _posed(piece: ConvexSet, s: int, e: int, poses: np.ndarray) -> tuple:
    """A piece's vertices and faces' normals at each pose (sample, vertex)."""
    c, sn = np.cos(poses[:, 2:]), np.sin(poses[:, 2:])
    lx, ly, mx, my = piece.verts[s:e, 0], piece.verts[s:e, 1], piece.normals[s:e, 0], piece.normals[s:e, 1]
    return (poses[:, :1] + c * lx - sn * ly, poses[:, 1:2] + sn * lx + c * ly, c * mx - sn * my, sn * mx + c * my)


def _beyond(faces: tuple, others: tuple) -> np.ndarray:
    """(sample, face): how far every vertex of `others` lies beyond each face of `faces` (both `_posed`)."""
    x, y, nx, ny = faces
    ox, oy = others[0], others[1]
    return ((ox[:, None, :] - x[:, :, None]) * nx[:, :, None] + (oy[:, None, :] - y[:, :, None]) * ny[:, :, None]
            ).min(axis=2)


@pytest.mark.parametrize("clearance", [0.01, -1e-4])
@pytest.mark.parametrize("turning", ["both", "one", "neither"])
def test_stays_clear_of_two_moving_pieces_is_never_wrong(clearance, turning):
    """`toi.stays_clear` for two body pieces that both move (a ball passing another that rolls, or a
    windmill's turning arm), against their motions sampled at 20 001 poses, for hexagons, a star's
    pieces and an arm, moving and turning about each other: where it says clear, the best separating
    axis keeps them beyond the clearance at every pose (and apart, by the vertex-to-edge distances,
    for a positive one); where one of them does not turn, an axis of it that keeps every sampled
    vertex of the other beyond the clearance by more than a sampling step's travel makes it say
    clear (exact, seen from that piece); and both answers come up."""
    from polygolf.engine.physics.toi import stays_clear

    rng = np.random.default_rng({"both": 21, "one": 22, "neither": 23}[turning])
    shapes = [polygon.regular_polygon(6, 0.3), *polygon.convex_pieces(polygon.star_polygon(5, 2, 0.35)),
              box(1.0, 0.15), polygon.regular_polygon(3, 0.2)]
    body = ConvexSet.of(shapes, [polygon.edge_normals(p) for p in shapes])
    ts = np.linspace(0.0, 1.0, 20001)
    said = {True: 0, False: 0}
    for _ in range(200):
        i, j = (int(k) for k in rng.integers(len(shapes), size=2))
        sa, ea, sb, eb = body.first[i], body.first[i + 1], body.first[j], body.first[j + 1]
        start_b = np.array([0.0, 0.0, rng.uniform(-3.2, 3.2)])
        bearing = rng.uniform(-3.2, 3.2)
        reach = body.reach[i] + body.reach[j]
        start_a = np.array([*(rng.uniform(0.6, 1.6) * reach * np.array([math.cos(bearing), math.sin(bearing)])),
                            rng.uniform(-3.2, 3.2)])
        turns = {"both": (1.0, 1.0), "one": (1.0, 0.0) if rng.random() < 0.5 else (0.0, 1.0), "neither": (0.0, 0.0)}
        end_a = start_a + np.array([*rng.normal(0.0, 0.4, 2), turns[turning][0] * rng.normal(0.0, 3.0)])
        end_b = start_b + np.array([*rng.normal(0.0, 0.4, 2), turns[turning][1] * rng.normal(0.0, 3.0)])
        poses_a, poses_b = start_a + ts[:, None] * (end_a - start_a), start_b + ts[:, None] * (end_b - start_b)
        a, b = _posed(body, sa, ea, poses_a), _posed(body, sb, eb, poses_b)
        beyond_b, beyond_a = _beyond(b, a), _beyond(a, b)  # (sample, face): along B's faces, along A's
        apart = np.maximum(beyond_b.max(axis=1), beyond_a.max(axis=1))
        clear = stays_clear(body.verts, body.normals, sa, ea, start_a, end_a, body.verts, body.normals, sb, eb,
                            start_b, end_b, clearance, 0.0, np.empty(3))
        if clear:
            assert apart.min() > clearance - 1e-9
        if clear and clearance > 0.0:
            assert min(_point_edges(a[:2], b[:2]), _point_edges(b[:2], a[:2])) > clearance - 1e-9
        between = (np.hypot(*(end_a[:2] - start_a[:2] - end_b[:2] + start_b[:2]))
                   + abs(end_a[2] - start_a[2]) * body.reach[i] + abs(end_b[2] - start_b[2]) * body.reach[j]) \
            / (len(ts) - 1)
        # Seen from a piece that does not turn, its faces are still axes: exact along each.
        if end_b[2] == start_b[2] and beyond_b.min(axis=0).max() > clearance + between:
            assert clear
        if end_a[2] == start_a[2] and beyond_a.min(axis=0).max() > clearance + between:
            assert clear
        said[bool(clear)] += 1
    assert said[True] > 20 and said[False] > 20


def test_wall_pieces_a_body_stays_clear_of_are_passed_over_with_the_same_rows():
    """`bodies_wall_contacts` skips the near pieces its bounding circle stays more than the margin
    clear of, and those with a face the whole body lies more than the margin beyond (asked in the
    body's frame): its rows must be those of `wall_contacts` asked about every near piece, for a
    hexagon and a star ({5/2}: two convex pieces) anywhere about slanted and square wall pieces."""
    from polygolf.engine.physics.collide import BODY, ROW, bodies_wall_contacts, wall_contacts
    from polygolf.engine.physics.geometry import ShapeTable, pose_piece

    rng = np.random.default_rng(12)
    pieces = [box(2.0, 0.1), [(1.0, 0.5), (2.5, 0.5), (1.0, 2.0)], [(-2.5, 0.4), (-1.5, 0.4), (-1.5, 1.4), (-2.5, 1.4)]]
    wall = ConvexSet.of(pieces, [polygon.edge_normals(p) for p in pieces])
    flags = np.zeros(len(wall.verts), dtype=np.bool_)
    walls = (wall.verts, wall.normals, wall.first, flags, np.zeros(len(wall.verts), dtype=np.int8))
    star = polygon.star_polygon(5, 2, 0.45)
    shapes = [polygon.regular_polygon(6, 0.45), star]
    table = ShapeTable.of([ConvexSet.of(list(polygon.convex_pieces(s)), [polygon.edge_normals(p)
                                        for p in polygon.convex_pieces(s)]) for s in shapes])
    lv, ln, first, reach, body_first = (table.pieces.verts, table.pieces.normals, table.pieces.first,
                                        table.pieces.reach, table.body_first)
    radius = np.array([polygon.bounding_radius(s) for s in shapes])
    every = np.arange(len(pieces), dtype=np.int64)
    dt, margin, touched, apart = 1.0 / 240.0, 0.01, 0, 0
    for _ in range(400):
        q = int(rng.integers(2))
        state = np.array([rng.uniform(-3.0, 3.0), rng.uniform(-0.8, 2.2), rng.uniform(-3.2, 3.2),
                          *rng.normal(0.0, 3.0, 2), rng.normal(0.0, 5.0)])
        batch = bodies_wall_contacts(lv, ln, first, reach, body_first, np.array([q]), radius, state[None, :],
                                     np.zeros(1, dtype=np.bool_), np.array([0, len(pieces)]), every, walls, dt,
                                     margin)
        p0, p1 = body_first[q], body_first[q + 1]
        v0, v1 = first[p0], first[p1]
        verts, normals = np.zeros((len(lv), 2)), np.zeros((len(lv), 2))
        pose_piece(lv, ln, v0, v1, state[0], state[1], state[2], verts[v0:v1], normals[v0:v1])
        out = np.empty((2 * (p1 - p0) * len(pieces), ROW))
        made = wall_contacts(verts, normals, lv, ln, first[p0:p1 + 1], reach[p0:p1], *state, dt, False, walls, every,
                             every, margin, out, np.empty((3, 3)), toi_work(6))
        assert np.array_equal(batch[:, :BODY], out[:made, :BODY])
        touched += made > 0
        apart += made == 0
    assert touched > 20 and apart > 20  # both kinds of pose were tried


def test_body_pairs_one_stays_clear_of_are_passed_over_with_the_same_rows():
    """`bodies_pair_contacts` passes over a pair when one body's bounding circle stays more than the
    margin clear of every piece of the other: its rows must be those of `collide_sets` asked about
    every pair within reach, for hexagons, stars ({5/2}: two pieces) and a long box, at random
    poses about each other; and the pass must be taken (pairs within reach but clear of each other)."""
    from polygolf.engine.physics.collide import BODY, NO_HIDDEN, NO_SEAMS, ROW, bodies_pair_contacts, collide_sets
    from polygolf.engine.physics.geometry import pose_piece

    rng = np.random.default_rng(7)
    shapes = [polygon.regular_polygon(6, 0.45), polygon.star_polygon(5, 2, 0.45), box(0.9, 0.15)]
    table = ShapeTable.of([ConvexSet.of(list(polygon.convex_pieces(s)), [polygon.edge_normals(p)
                                        for p in polygon.convex_pieces(s)]) for s in shapes])
    lv, ln, first, body_first = table.pieces.verts, table.pieces.normals, table.pieces.first, table.body_first
    radius = np.array([polygon.bounding_radius(s) for s in shapes])
    margin, touched, clear_within_reach = 0.01, 0, 0
    for _ in range(600):
        a, b = (int(k) for k in rng.choice(3, size=2, replace=False))
        poses = np.zeros((3, 3))
        poses[a] = 0.0, 0.0, rng.uniform(-3.2, 3.2)
        distance, bearing = rng.uniform(0.0, radius[a] + radius[b] + margin), rng.uniform(-3.2, 3.2)
        poses[b] = distance * math.cos(bearing), distance * math.sin(bearing), rng.uniform(-3.2, 3.2)
        pair = np.array([[a, b]], dtype=np.int64)
        rows, _, pairs, _ = bodies_pair_contacts(lv, ln, first, body_first, pair, poses, radius, margin)
        verts, normals = np.zeros((len(lv), 2)), np.zeros((len(lv), 2))
        for q in (a, b):
            v0, v1 = first[body_first[q]], first[body_first[q + 1]]
            pose_piece(lv, ln, v0, v1, *poses[q], verts[v0:v1], normals[v0:v1])
        a0, a1, b0, b1 = body_first[a], body_first[a + 1], body_first[b], body_first[b + 1]
        out = np.empty((2 * (a1 - a0) * (b1 - b0), ROW))
        made = collide_sets(verts, normals, first[a0:a1 + 1], verts, normals, first[b0:b1 + 1],
                            np.arange(b1 - b0, dtype=np.int64), NO_SEAMS, NO_HIDDEN, False, margin, False, out,
                            np.empty((3, 3)))
        assert np.array_equal(rows[:, :BODY], out[:made, :BODY])
        assert len(pairs) == (made > 0)
        touched += made > 0
        clear_within_reach += made == 0
    assert touched > 50 and clear_within_reach > 50  # both kinds of pose were tried


def test_a_length_compared_with_a_bound_is_judged_as_the_exact_one_would_be():
    """`toi.length_near` takes the cheaper square root of the sum of squares for `math.hypot` only
    away from the bounds its caller compares it with: on either side of the bound, in the band
    round it, at extremes of size and with no motion, every comparison comes out as the exact one's,
    and in the band the value is the exact one."""
    from polygolf.engine.physics.jit import COMPILED
    from polygolf.engine.physics.toi import length_near

    hypot = np.hypot if COMPILED else math.hypot  # compiled, math.hypot is the C library's (as numpy's)
    rng = np.random.default_rng(11)
    cases = []
    for _ in range(4000):
        x, y = rng.normal(size=2) * 10.0 ** rng.integers(-160, 150)
        plus, more = abs(rng.normal()) * rng.integers(0, 2), abs(rng.normal()) * rng.integers(0, 2)
        exact = hypot(x, y) + plus + more
        for bound in (exact, np.nextafter(exact, np.inf), np.nextafter(exact, -np.inf), exact * (1 + 1e-9),
                      exact * (1 - 1e-7), exact * 2.0, 0.0, math.inf):
            cases.append((x, y, plus, more, bound, exact))
    cases += [(0.0, 0.0, 0.0, 0.0, 0.0, 0.0), (3.0, 4.0, 0.0, 0.0, 5.0, 5.0), (1e-200, 1e-200, 0.0, 0.0, 1e-200,
                                                                                   hypot(1e-200, 1e-200))]
    for x, y, plus, more, bound, exact in cases:
        quick = length_near(x, y, plus, more, bound, bound)
        assert length_near(x, y, plus, more, bound, exact) == exact  # near the second bound: exact too
        assert (quick < bound) == (exact < bound) and (quick >= bound) == (exact >= bound), (x, y, plus, more, bound)
        if abs(exact - bound) <= 1e-7 * abs(bound):
            assert quick == exact


def test_a_shape_table_holds_each_body_s_pieces_in_order_whatever_the_mix():
    """Bodies of one, two and three pieces, repeated and mixed (a search's thousand balls share one
    set): body k's pieces, vertices, normals and reaches are its own set's, in order; none, an empty table."""
    square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    triangle = [(0.0, 0.0), (2.0, 0.0), (0.0, 3.0)]
    hexagon = [(math.cos(k * math.pi / 3), math.sin(k * math.pi / 3)) for k in range(6)]
    kinds = [ConvexSet.of(pieces, [polygon.edge_normals(p) for p in pieces])
             for pieces in ([hexagon], [square, triangle], [triangle, hexagon, square])]
    bodies = [kinds[k % 3] for k in (0, 1, 2, 2, 0, 0, 1, 2, 1, 0)] + [kinds[0]] * 40
    table = ShapeTable.of(bodies)
    joined = table.pieces
    assert len(table.body_first) == len(bodies) + 1 and joined.first[-1] == len(joined.verts)
    assert np.array_equal(joined.every_piece, np.arange(len(joined)))
    for k, own in enumerate(bodies):
        pieces = range(table.body_first[k], table.body_first[k + 1])
        assert len(pieces) == len(own)
        for j, p in enumerate(pieces):
            rows, own_rows = slice(joined.first[p], joined.first[p + 1]), slice(own.first[j], own.first[j + 1])
            assert np.array_equal(joined.verts[rows], own.verts[own_rows])
            assert np.array_equal(joined.normals[rows], own.normals[own_rows])
            assert joined.reach[p] == own.reach[j]
    empty = ShapeTable.of([])
    assert len(empty.pieces) == 0 and empty.body_first.tolist() == [0] and empty.pieces.verts.shape == (0, 2)
