"""The broadphase grid answers like a brute-force search, and neither huge items nor huge queries
make it slow or hungry."""

from __future__ import annotations

import math
import time

import numpy as np
from hypothesis import example, given, settings
from hypothesis import strategies as st

from polygolf.engine.loading.scene import Scene, build_scene
from polygolf.engine.physics.body import ASLEEP, COLUMNS, INV_MASS, SPIN, X0, Y0, X, Y
from polygolf.engine.physics.grid import (
    PAIR_FAT_MARGIN,
    BoxGrid,
    FatBoxes,
    FatPairs,
    bodies_near,
    body_pairs,
    box_pairs,
    by_entity,
    no_fat_pairs,
)

coord = st.floats(-3000, 3000, allow_nan=False)
size = st.floats(0.01, 2000, allow_nan=False)
boxes = st.builds(lambda x, y, w, h: (x, y, x + w, y + h), coord, coord, size, size)


def _overlaps(a, b) -> bool:
    return a[0] <= b[2] and b[0] <= a[2] and a[1] <= b[3] and b[1] <= a[3]


@settings(max_examples=200, deadline=None)
@given(st.lists(boxes, min_size=1, max_size=30), st.lists(boxes, min_size=1, max_size=5),
       st.floats(0.05, 50.0), st.lists(st.booleans(), min_size=30, max_size=30))
def test_queries_and_pairs_match_brute_force(items, queries, cell, active):
    grid = BoxGrid(np.array(items), cell)
    for query in queries:
        found = grid.query(query).tolist()
        assert found == sorted(i for i, box in enumerate(items) if _overlaps(query, box))
    # The bodies' lookup (`bodies_near`): a body at each query's centre, half its width wide, the
    # second at rest (not looked up).
    state = np.zeros((len(queries), len(COLUMNS)))
    state[:, INV_MASS] = 1.0
    state[1:2, ASLEEP] = 1.0
    state[:, X] = [(q[0] + q[2]) / 2 for q in queries]
    state[:, Y] = [(q[1] + q[3]) / 2 for q in queries]
    radius = np.array([(q[2] - q[0]) / 2 for q in queries])
    _check_bodies_near(items, grid, FatBoxes(), state, radius, 0.0, resting=1)
    _check_box_pairs(items, active)


@settings(max_examples=100, deadline=None)
@given(st.lists(st.builds(lambda x, y, w, h: (x, y, x + w, y + h), st.floats(-20, 20), st.floats(-20, 20),
                          st.floats(0.0, 3.0), st.floats(0.0, 3.0)), min_size=40, max_size=160),
       st.lists(st.booleans(), min_size=160, max_size=160))
def test_pairs_of_a_crowd_match_brute_force(items, active):
    """A crowd is paired through a grid of cells as large as its largest box, not by the sweep."""
    _check_box_pairs(items, active)


@settings(max_examples=100, deadline=None)
@given(st.lists(st.tuples(st.floats(-5, 5), st.floats(-5, 5), st.floats(-1, 1), st.floats(-1, 1), st.floats(0.1, 1.0),
                          st.sampled_from(["awake", "asleep", "kinematic", "turning"])), min_size=1, max_size=60),
       st.booleans())
def test_pairs_with_a_kinematic_body_alone_are_those_of_every_pair(bodies, turning_is_active):
    """`body_pairs` without the pairs of two dynamic bodies (continuous collision, when none of them
    can step far) gives exactly the pairs of every pair that hold a kinematic and a dynamic body."""
    state = np.zeros((len(bodies), len(COLUMNS)))
    for k, (x, y, dx, dy, _, kind) in enumerate(bodies):
        state[k, X0], state[k, Y0], state[k, X], state[k, Y] = x, y, x + dx, y + dy
        state[k, INV_MASS] = 0.0 if kind in ("kinematic", "turning") else 1.0
        state[k, ASLEEP] = kind == "asleep"
        state[k, SPIN] = 2.0 if kind == "turning" else 0.0
    rows, radius = np.arange(len(bodies)), np.array([b[4] for b in bodies])
    dynamic = state[:, INV_MASS] != 0.0
    for swept in (True, False):
        every = body_pairs(state, rows, radius, 0.01, swept, True, turning_is_active, True, no_fat_pairs()).tolist()
        alone = body_pairs(state, rows, radius, 0.01, swept, True, turning_is_active, False, no_fat_pairs()).tolist()
        assert alone == [[i, j] for i, j in every if dynamic[i] != dynamic[j]]


@settings(max_examples=60, deadline=None)
@given(st.lists(st.builds(lambda x, y, w, h: (x, y, x + w, y + h), st.floats(-5, 5), st.floats(-5, 5),
                          st.floats(0.0, 2.0), st.floats(0.0, 2.0)), min_size=1, max_size=60),
       st.lists(st.tuples(st.floats(-0.3, 0.3), st.floats(-0.3, 0.3)), min_size=1, max_size=30),
       st.floats(0.05, 1.0))
def test_walls_kept_in_fat_boxes_are_the_grids_answer_as_bodies_move(items, steps, size):
    """Three bodies wander (each step up to 0.3 m, so some stay inside their fat boxes and some leave
    them); a crowd of up to 60 boxes (more than a fat box keeps). Every answer, kept or asked for,
    is the brute-force one, in order."""
    grid = BoxGrid(np.array(items), 1.0)
    fat_boxes = FatBoxes()
    state = np.zeros((3, len(COLUMNS)))
    state[:, INV_MASS] = 1.0
    radius = np.array([size, 0.5 * size, 2.0 * size])
    for dx, dy in steps:
        state[:, X] += [dx, -dy, 0.5 * dx]
        state[:, Y] += [dy, dx, -0.5 * dy]
        _check_bodies_near(items, grid, fat_boxes, state, radius, 0.01)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.floats(-3, 3), st.floats(-3, 3), st.floats(0.05, 0.6)), min_size=2, max_size=80),
       st.lists(st.tuples(st.integers(0, 79), st.floats(-0.3, 0.3), st.floats(-0.3, 0.3),
                          st.sampled_from(["move", "sleep", "wake", "vanish"])), min_size=1, max_size=40))
@example([(0.0, 0.0, 0.1), (1.0, 0.0, 0.1)], [(0, 0.3, 0.0, "move")] * 3)  # out of its fat box, onto the other
def test_pairs_kept_in_fat_boxes_are_every_pair_as_bodies_move(bodies, moves):
    """A crowd of up to 80 bodies, one moved (by up to 0.3 m: inside its fat box or out of it), put
    to sleep, woken or sent to infinity or NaN at a time: the pairs picked from those kept between
    substeps (`FatPairs`) are, every time, the pairs searched for afresh, in order; and room runs
    short with 80 bodies in a 6 m square (they are kept anyway once it is given)."""
    state = np.zeros((len(bodies), len(COLUMNS)))
    state[:, INV_MASS] = 1.0
    state[:, X], state[:, Y] = [b[0] for b in bodies], [b[1] for b in bodies]
    rows, radius = np.arange(len(bodies)), np.array([b[2] for b in bodies])
    fat_pairs = FatPairs()
    fat_pairs.pairs = fat_pairs.of(state, rows)[1][:2]  # little room: the first rebuilds do not fit
    for which, dx, dy, how in [(0, 0.0, 0.0, "move"), *moves]:
        k = which % len(bodies)
        if how == "move":
            state[k, X] += dx
            state[k, Y] += dy
        elif how == "vanish":
            state[k, X] = math.inf if dx > 0 else math.nan
        else:
            state[k, ASLEEP] = how == "sleep"
        kept = fat_pairs.of(state, rows)
        fresh = body_pairs(state, rows, radius, 0.01, False, True, False, True, no_fat_pairs()).tolist()
        assert body_pairs(state, rows, radius, 0.01, False, True, False, True, kept).tolist() == fresh
        if how == "vanish":
            state[k, X] = 0.0
    fat, _, count = fat_pairs.of(state, rows)
    assert not fat_pairs.outgrown()  # room given
    if count[0] >= 0:  # the boxes kept are the bodies' grown by the margin (or larger, from before)
        assert (fat[:, 2] - fat[:, 0] >= 2 * (radius + 0.01 + PAIR_FAT_MARGIN) - 1e-9).all()


def test_fat_pairs_start_again_for_other_bodies():
    """Kept pairs are for one set of rows of one state: another state or other rows start again."""
    state = np.zeros((3, len(COLUMNS)))
    state[:, INV_MASS] = 1.0
    rows = np.arange(3)
    fat_pairs = FatPairs()
    fat, _, count = fat_pairs.of(state, rows)
    body_pairs(state, rows, np.full(3, 0.1), 0.01, False, True, False, True, (fat, fat_pairs.pairs, count))
    assert count[0] == 3  # all three at one spot
    assert fat_pairs.of(state, rows)[2][0] == 3
    assert fat_pairs.of(state.copy(), rows)[2][0] == -1
    assert fat_pairs.of(state, rows.copy())[2][0] == -1


@settings(max_examples=100, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 39), st.integers(0, 39)), max_size=80), st.permutations(range(40)))
def test_pairs_by_entity_come_sorted_whatever_order_the_bodies_are_listed_in(pairs, order):
    """Entities listed ascending (esper's usual order) are in order already; any other order is
    sorted: the same pairs of entities, (smaller, larger), ascending."""
    pairs = sorted({(min(i, j), max(i, j)) for i, j in pairs if i != j})
    for ents in (np.arange(100, 140), 100 + np.array(order)):
        got = by_entity(np.array(pairs, dtype=np.int64).reshape(-1, 2), ents.astype(np.int64)).tolist()
        assert got == sorted(sorted((int(ents[i]), int(ents[j]))) for i, j in pairs)


def _check_box_pairs(items: list, active: list[bool]) -> None:
    """`box_pairs` of these boxes (the first len(items) flags of `active`) against brute force."""
    flags = np.array(active[:len(items)])
    expected = sorted((i, j) for i in range(len(items)) for j in range(i + 1, len(items))
                      if _overlaps(items[i], items[j]) and (flags[i] or flags[j]))
    assert [tuple(p) for p in box_pairs(np.array(items), flags).tolist()] == expected


def _check_bodies_near(items: list, grid: BoxGrid, fat_boxes: FatBoxes, state: np.ndarray, radius: np.ndarray,
                       margin: float, resting: int = -1) -> None:
    """`bodies_near` for every row of `state` (row `resting` is at rest: not looked up) against brute force."""
    n, walls = len(state), len(items)
    near, first = np.empty(n, dtype=np.int64), np.empty(n + 1, dtype=np.int64)
    found, count = bodies_near(state, np.arange(n, dtype=np.int64), radius, margin, grid.arrays,
                               fat_boxes.of(state, walls), np.zeros(walls, dtype=np.bool_),
                               np.empty(walls, dtype=np.int64), near, first, np.empty(1, dtype=np.int64))
    answers = {near[k]: found[first[k]:first[k + 1]].tolist() for k in range(count)}
    for q in range(n):
        r = radius[q] + margin
        square = (state[q, X] - r, state[q, Y] - r, state[q, X] + r, state[q, Y] + r)
        expected = [] if q == resting else [i for i, box in enumerate(items) if _overlaps(square, box)]
        assert answers.get(q, []) == expected


def test_boxes_beyond_the_grid_and_not_numbers_are_answered_too():
    grid = BoxGrid(np.array([[0.0, 0.0, 1.0, 1.0], [5.0, 5.0, 6.0, 6.0]]), 1.0)
    assert grid.query((-math.inf, -math.inf, math.inf, math.inf)).tolist() == [0, 1]
    assert grid.query((-100.0, -100.0, 0.5, 0.5)).tolist() == [0]
    assert grid.query((100.0, 100.0, 200.0, 200.0)).tolist() == []
    assert grid.query((math.nan, math.nan, math.nan, math.nan)).tolist() == []
    assert BoxGrid(np.zeros((0, 4)), 1.0).query((0.0, 0.0, 1.0, 1.0)).tolist() == []


def test_a_kilometre_wall_and_a_fast_body_stay_cheap():
    scene = Scene.model_validate({
        "name": "huge", "bodies": [{"name": "ball", "shape": {"regular": 5, "radius": 0.3},
                                    "position": [0.0, 2.0], "velocity": [1000.0, -1000.0]}],
        "walls": [{"box": {"center": [0.0, -1000.0], "half": [1000.0, 1000.0]}},
                  {"box": {"center": [0.0, 1000.0], "half": [1000.0, 1.0]}}],
    })
    started = time.perf_counter()
    with build_scene(scene, "fast") as sim:
        sim.run(2.0)
        ball = sim.body("ball")
        assert ball.y > 0.0  # the floor held
    assert time.perf_counter() - started < 10.0


def test_a_query_s_answer_is_sorted_however_many_it_holds():
    """`_sort_few` (insertion for a few, heapsort past 16, in place: it makes no array) sorts the
    values of a range as numpy does and leaves the rest."""
    from polygolf.engine.physics.grid import _sort_few

    rng = np.random.default_rng(5)
    for count in (0, 1, 2, 15, 16, 17, 18, 40, 301):
        for start in (0, 3):
            values = rng.permutation(1000)[:count + 8].astype(np.int64)
            expected = np.concatenate([values[:start], np.sort(values[start:start + count]), values[start + count:]])
            _sort_few(values, start, start + count)
            assert np.array_equal(values, expected), (count, start)


def test_a_crowd_with_more_pairs_than_first_room_for_still_pairs_every_two():
    """Sixty boxes heaped on each other: 1770 pairs, more than the grid's pair search first makes
    room for (four a box), so it must start again with more."""
    items = [(0.01 * k, 0.0, 1.0 + 0.01 * k, 1.0) for k in range(60)]
    _check_box_pairs(items, [True] * 60)
    assert len(box_pairs(np.array(items), np.ones(60, dtype=np.bool_))) == 60 * 59 // 2
