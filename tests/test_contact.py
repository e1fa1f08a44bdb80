"""The contact table (physics.contact): contact rows grouped into planes and reduced to two points
against hand-worked cases, materials, keys and NGS geometry, warm starting by key, and the
narrowphase's table for a star landing on two tips."""

from __future__ import annotations

import math

import esper
import numpy as np
import pytest

from polygolf.engine.assembly.assemble import make_body, make_collider
from polygolf.engine.components import Material, Wall
from polygolf.engine.physics import polygon
from polygolf.engine.physics.body import ANGLE as B_ANGLE
from polygolf.engine.physics.body import COLUMNS, Body, BodyStore
from polygolf.engine.physics.body import X as B_X
from polygolf.engine.physics.body import Y as B_Y
from polygolf.engine.physics.collide import (
    BODY,
    CLIP_X,
    CLIP_Y,
    FACE_X,
    FACE_Y,
    FEATURE,
    NX,
    NY,
    PIECE_A,
    PIECE_B,
    REF_IS_A,
    ROW,
    SEP,
    X,
    Y,
)
from polygolf.engine.physics.contact import (
    K_FEATURE,
    K_OTHER,
    K_OWN,
    K_PIECE,
    KEY_COLUMNS,
    M_NX,
    M_NY,
    P_APPROACH,
    P_FRICTION,
    P_LFX,
    P_LFY,
    P_LNX,
    P_LNY,
    P_LQX,
    P_LQY,
    P_NORMAL_IMPULSE,
    P_RESTITUTION,
    P_SEP,
    P_TANGENT_IMPULSE,
    P_X,
    POINT_COLUMNS,
    SAME_NORMAL_COS,
    ContactPoint,
    Manifold,
    build_contacts,
    carry_impulses,
    table_of,
)
from polygolf.engine.physics.settings import RESTITUTION_THRESHOLD
from polygolf.engine.systems.narrowphase import NarrowphaseProcessor

from .helpers import resources as context

DOWN = (0.0, -1.0)


def turned(degrees: float) -> tuple[float, float]:
    """DOWN turned by `degrees`."""
    a = math.radians(degrees)
    return math.sin(a), -math.cos(a)


def contact_rows(*points: dict) -> np.ndarray:
    """Contact rows (collide.ROW columns) from dicts of x, sep, normal, feature, pieces, ..."""
    out = np.zeros((len(points), ROW))
    for r, p in enumerate(points):
        out[r, X], out[r, Y], out[r, SEP] = p.get("x", 0.0), p.get("y", 0.0), p.get("sep", -0.001)
        out[r, NX], out[r, NY] = p.get("normal", DOWN)
        out[r, FEATURE], out[r, PIECE_A], out[r, PIECE_B] = p.get("feature", r), p.get("a", 0), p.get("b", 0)
        out[r, REF_IS_A] = p.get("ref_is_a", 1.0)
        out[r, CLIP_X], out[r, CLIP_Y] = p.get("clip", (0.0, 0.0))
        out[r, FACE_X], out[r, FACE_Y] = p.get("face", (0.0, 0.0))
    return out


STATE = np.zeros((2, len(COLUMNS)))  # two bodies at the origin; the static world is row 2
STATIC = np.zeros(len(COLUMNS))


def build(rows: np.ndarray, groups=((1, -1),), counts=None, materials=None, wall_materials=None, ngs=False,
          deepest=0.0, state=STATE):
    """`build_contacts` for groups of (entity A, entity B) taking `counts` rows each (all in one group by
    default), walls first: body row 0 against row 1, or against the static world (row 2; wall pieces
    0, 1, 2 are walls 10, 11, 12, each its only piece)."""
    counts = counts or [len(rows)]
    first = np.concatenate(([0], np.cumsum(counts))).astype(np.int64)
    materials = np.ones((len(groups), 4)) if materials is None else np.array(materials, dtype=np.float64)
    walls = [g for g, (_, eb) in enumerate(groups) if eb == -1]
    pairs = [g for g, (_, eb) in enumerate(groups) if eb != -1]
    assert walls == list(range(len(walls))), "walls first"
    wall_rows = rows[:first[len(walls)]].copy()
    for q in walls:
        wall_rows[first[q]:first[q + 1], BODY] = q
    pair_rows = rows[first[len(walls)]:].copy()
    pair_first = first[len(walls):] - first[len(walls)]
    return build_contacts(
        wall_rows, np.array([groups[q][0] for q in walls], dtype=np.int64), np.zeros(len(walls), dtype=np.int64),
        materials[walls, :2].copy(), np.ones((3, 2)) if wall_materials is None else np.array(wall_materials),
        np.array([10, 11, 12], dtype=np.int64), np.zeros(3, dtype=np.int64), pair_rows, pair_first,
        np.array([groups[g] for g in pairs], dtype=np.int64).reshape(-1, 2),
        np.array([(0, 1) for _ in pairs], dtype=np.int64).reshape(-1, 2), materials[pairs].reshape(-1, 4), state,
        STATIC, ngs, deepest)


def test_planes_take_their_first_points_normal_and_keep_the_order_they_come_in():
    assert math.cos(math.radians(1.5)) >= SAME_NORMAL_COS > math.cos(math.radians(3.0))
    rows = contact_rows({"x": 0.0}, {"x": 0.1, "normal": turned(1.5)}, {"x": 0.2, "normal": turned(3.0)},
                        {"x": 0.3, "normal": turned(-1.0)})
    ents, pair, normals, first, points, keys, _ = build(rows)
    # The third point is 1.5° from the second but 3° from the first plane's normal: a plane of its own.
    assert first.tolist() == [0, 2, 3]
    assert points[:, P_X].tolist() == [0.3, 0.0, 0.2]  # the fourth joined the first plane, which spans 0 to 0.3
    assert normals[:, M_NX:M_NY + 1].tolist() == [list(DOWN), list(turned(3.0))]
    assert ents.tolist() == [[1, -1], [1, -1]] and pair.tolist() == [[0, 2], [0, 2]]


def test_a_plane_keeps_the_two_points_that_span_it_the_deepest_breaking_ties():
    # Normal DOWN: the tangent is (-1, 0), so the least tangent position is the largest x.
    rows = contact_rows({"x": 0.1, "sep": -0.009}, {"x": 0.5, "sep": -0.001}, {"x": -0.5, "sep": -0.002},
                        {"x": 0.5, "sep": -0.004}, {"x": -0.5, "sep": -0.003}, {"x": -0.5, "sep": -0.003})
    *_, first, points, keys, deepest = build(rows)
    assert first.tolist() == [0, 2]
    assert points[:, P_X].tolist() == [0.5, -0.5]
    assert points[:, P_SEP].tolist() == [-0.004, -0.003]
    assert keys[:, K_FEATURE].tolist() == [3, 4]  # of two equal points, the first
    assert deepest == 0.004  # of the points kept: the deepest one (x = 0.1) was dropped


def test_a_plane_of_points_at_one_tangent_position_keeps_the_deepest_alone():
    rows = contact_rows({"x": 0.2, "sep": -0.001}, {"x": 0.2, "sep": -0.005}, {"x": 0.2, "sep": -0.005},
                        {"x": 0.2, "sep": -0.002})
    *_, first, points, keys, _ = build(rows)
    assert first.tolist() == [0, 1]
    assert keys[:, K_FEATURE].tolist() == [1]


def test_two_points_or_fewer_stay_as_they_come():
    rows = contact_rows({"x": -0.5, "sep": -0.001}, {"x": 0.5, "sep": -0.002})
    *_, first, points, _, _ = build(rows)
    assert points[:, P_X].tolist() == [-0.5, 0.5]


def test_materials_multiply_and_keys_name_the_wall_or_the_other_body():
    rows = contact_rows({"b": 1, "a": 2, "feature": 77}, {"b": 3, "a": 1, "feature": 5})
    ents, pair, _, first, points, keys, _ = build(
        rows, groups=((1, -1), (1, 2)), counts=[1, 1], materials=[(0.9, 0.25, 7.0, 7.0), (0.5, 0.5, 0.4, 0.8)],
        wall_materials=[(1.0, 1.0), (0.5, 0.8), (1.0, 1.0)])
    assert points[:, P_RESTITUTION].tolist() == [0.9 * 0.5, 0.5 * 0.4]
    assert points[:, P_FRICTION].tolist() == [0.25 * 0.8, 0.5 * 0.8]
    assert keys.tolist() == [[11, 0, 2, 77], [2, 3, 1, 5]]  # (wall 11, its piece 0) / (body 2, its piece 3)
    assert ents.tolist() == [[1, -1], [1, 2]] and pair.tolist() == [[0, 2], [0, 1]]


def test_deepest_overlap_is_kept_if_no_point_is_deeper():
    rows = contact_rows({"sep": -0.001})
    assert build(rows, deepest=0.01)[-1] == 0.01
    assert build(rows, deepest=0.0)[-1] == 0.001


def test_ngs_geometry_is_the_faces_in_their_bodies_frames():
    state = STATE.copy()
    state[0, B_X], state[0, B_Y], state[0, B_ANGLE] = 1.0, 2.0, 0.3
    rows = contact_rows({"normal": (0.6, -0.8), "face": (0.5, 0.25), "clip": (1.5, 1.0), "ref_is_a": 0.0},
                        {"normal": (0.0, 1.0), "face": (1.5, 2.5), "clip": (0.25, 0.75), "ref_is_a": 1.0})
    *_, points, _, _ = build(rows, groups=((1, -1), (1, 2)), counts=[1, 1], ngs=True, state=state)
    c, s = math.cos(0.3), math.sin(0.3)

    def local(x: float, y: float) -> list[float]:
        return pytest.approx([c * x + s * y, -s * x + c * y], abs=1e-15)

    # A wall's face (the reference): the static world's frame is the world's; the ball's corner in its own.
    assert points[0, P_LNX:P_LNY + 1].tolist() == [-0.6, 0.8] and points[0, P_LFX:P_LFY + 1].tolist() == [0.5, 0.25]
    assert points[0, P_LQX:P_LQY + 1].tolist() == local(0.5, -1.0)
    # A's face against body B (row 1, at the origin).
    assert points[1, P_LNX:P_LNY + 1].tolist() == local(0.0, 1.0)
    assert points[1, P_LFX:P_LFY + 1].tolist() == local(0.5, 0.5)
    assert points[1, P_LQX:P_LQY + 1].tolist() == [0.25, 0.75]
    *_, points, _, _ = build(rows, groups=((1, -1), (1, 2)), counts=[1, 1], ngs=False, state=state)
    assert not points[:, P_LNX:P_LQY + 1].any()


def old_table(*points: tuple) -> tuple[np.ndarray, ...]:
    """A last substep's table, one manifold a point: (entity A, key, normal impulse, tangent impulse, approach)."""
    ents = np.array([(ea, -1) for ea, *_ in points], dtype=np.int64).reshape(-1, 2)
    first = np.arange(len(points) + 1, dtype=np.int64)
    keys = np.array([key for _, key, *_ in points], dtype=np.int64).reshape(-1, KEY_COLUMNS)
    rows = np.zeros((len(points), POINT_COLUMNS))
    for p, (*_, normal, tangent, approach) in enumerate(points):
        rows[p, P_NORMAL_IMPULSE], rows[p, P_TANGENT_IMPULSE], rows[p, P_APPROACH] = normal, tangent, approach
    return ents, first, keys, rows


def test_impulses_carry_over_by_entity_and_key_from_resting_points_only():
    old = old_table((1, (10, 0, 0, 5), 1.0, 0.1, 0.0),  # resting: carried
                    (1, (10, 0, 1, 5), 2.0, 0.0, -1.0),  # an impact: its impulse stays with it
                    (1, (10, 0, 2, 5), 0.0, 0.0, 0.0),  # no impulse
                    (1, (10, 0, 3, 5), 0.0, -0.5, -RESTITUTION_THRESHOLD),  # friction alone, just resting: carried
                    (2, (10, 0, 4, 5), 3.0, 0.0, 0.0),  # another body's
                    (1, (10, 0, 4, 5), 4.0, 0.0, 0.0),  # twice: the last one counts
                    (1, (10, 0, 4, 5), 5.0, 0.0, 0.0))
    new_keys = np.array([(10, 0, own, 5) for own in (3, 2, 1, 0, 4)] + [(10, 0, 0, 6), (11, 0, 0, 5)], dtype=np.int64)
    ents = np.array([(1, -1)], dtype=np.int64)
    first = np.array([0, len(new_keys)], dtype=np.int64)
    points = np.zeros((len(new_keys), POINT_COLUMNS))
    assert carry_impulses(*old, ents, first, new_keys, points, RESTITUTION_THRESHOLD) == 3
    assert points[:, P_NORMAL_IMPULSE].tolist() == [0.0, 0.0, 0.0, 1.0, 5.0, 0.0, 0.0]
    assert points[:, P_TANGENT_IMPULSE].tolist() == [-0.5, 0.0, 0.0, 0.1, 0.0, 0.0, 0.0]


def test_table_of_hand_made_manifolds_reads_back_as_the_same_manifolds():
    ground, box, top = Body(x=0.0, y=0.0), Body.dynamic(0.0, 0.5, 1.0, 0.2), Body.dynamic(0.0, 1.5, 1.0, 0.2)
    store = BodyStore()
    store.gather([(4, box), (7, top)])
    made = [Manifold(4, -1, box, ground, 0.0, -1.0, [
                ContactPoint(x=-0.5, y=0.0, separation=-0.01, key=(9, 0, 1, 2), restitution=0.5, friction=0.3,
                             normal_impulse=0.25, approach_speed=-2.0, local_clip=(0.1, 0.2)),
                ContactPoint(x=0.5, y=0.0, separation=-0.02, key=(9, 0, 1, 3), restitution=0.5, friction=0.3,
                             ref_is_a=False)]),
            Manifold(4, 7, box, top, 0.0, 1.0, [ContactPoint(x=0.0, y=1.0, separation=0.0, key=(1, 2, 3),
                                                             restitution=0.1, friction=0.2, tangent_impulse=1.0)])]
    table = table_of(made, store, ground)
    assert table.pair.tolist() == [[0, 2], [0, 1]]
    assert table.manifolds() == made


def test_a_star_landing_on_two_tips_is_one_two_point_manifold_in_the_table(world):
    star = polygon.normalise(polygon.star_polygon(5, 2, 0.5))[0]
    tip_x = min(x for x, _ in star)
    ctx = context(walls=[(((-2.0, -5.0), (0.0, -5.0), (0.0, 5.0), (-2.0, 5.0)), Material(0.5, 0.5), ())])
    wall_ent = esper.get_component(Wall)[0][0]
    other = esper.create_entity(make_body(star, (5.0, 5.0), 1.0, 0.0), make_collider(star, Material(0.7, 0.9)))
    body = make_body(star, (-tip_x - 0.001, 0.0), 1.0, 0.0)
    ent = esper.create_entity(body, make_collider(star, Material(0.7, 0.9)))
    ctx.candidates.walls = {ent: np.array([0])}  # the wall's only piece
    esper.add_processor(NarrowphaseProcessor(ctx))
    esper.process()
    table = ctx.contacts.table
    assert len(table) == 1 and table.first.tolist() == [0, 2]
    assert table.ents.tolist() == [[ent, -1]]
    assert table.pair.tolist() == [[ctx.bodies.rows[ent], len(ctx.bodies.state)]] and other in ctx.bodies.rows
    assert table.keys[:, K_OTHER].tolist() == [wall_ent] * 2 and table.keys[:, K_PIECE].tolist() == [0, 0]
    assert table.keys[0, K_OWN] != table.keys[1, K_OWN]  # two tips: two pieces of the star
    assert table.points[:, P_RESTITUTION].tolist() == [0.7 * 0.5] * 2
    assert table.points[:, P_FRICTION].tolist() == [0.9 * 0.5] * 2
    assert ctx.contacts.touching == {ent, -1} and ctx.contacts.count == 2
    # An impact's points are not warm-started; a resting contact's are.
    table.points[:, P_NORMAL_IMPULSE] = 1.0, 2.0
    table.points[:, P_APPROACH] = -1.0, 0.0
    esper.process()
    assert ctx.contacts.table.points[:, P_NORMAL_IMPULSE].tolist() == [0.0, 2.0]
