"""Bodies in arrays (`physics.body`): a `Body` is a handle on a row of its world's state array, and
the free-motion kernels (`physics.motion`, `geometry.first_area`) step every row at once, checked
against closed forms and against the scalar definitions they replace."""

from __future__ import annotations

import math

import esper
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from polygolf.engine.components.hazards import Region
from polygolf.engine.physics import motion
from polygolf.engine.physics.body import (
    ANGLE,
    ASLEEP,
    COLUMNS,
    DRAG_SCALE,
    INV_MASS,
    LAG,
    SPIN,
    STILL_TIME,
    VX,
    VY,
    Body,
    BodyStore,
    Selection,
    X,
    Y,
)
from polygolf.engine.physics.geometry import Areas, first_area
from polygolf.engine.physics.settings import REST_ANGULAR, REST_LINEAR, REST_SPEED_CAP, TIME_TO_REST

DT = 1.0 / 240.0


def rows(n: int = 1, **values: float) -> np.ndarray:
    """A state array of n awake dynamic bodies (unit mass and inertia) at the origin."""
    state = np.zeros((n, len(COLUMNS)))
    state[:, INV_MASS] = 1.0
    state[:, COLUMNS.index("mass")] = state[:, COLUMNS.index("inertia")] = 1.0
    state[:, COLUMNS.index("inv_inertia")] = 1.0
    state[:, DRAG_SCALE] = 1.0
    for name, value in values.items():
        state[:, COLUMNS.index(name)] = value
    return state


# --- handles and the store -----------------------------------------------------------------------

def test_a_handle_reads_and_writes_its_row():
    body = Body.dynamic(1.0, 2.0, 4.0, 8.0, vx=3.0, spin=0.5)
    assert (body.x, body.y, body.vx, body.spin, body.inv_mass, body.inv_inertia) == (1.0, 2.0, 3.0, 0.5, 0.25, 0.125)
    assert type(body.x) is float and body.asleep is False
    assert (body.scratch.x0, body.scratch.y0) == (1.0, 2.0)  # its motion starts where it was made
    body.vy = -1.0
    body.scratch.lag = 0.01
    assert body._row[VY] == -1.0 and body._row[LAG] == 0.01
    assert body.kinetic_energy() == pytest.approx(0.5 * 4.0 * (9.0 + 1.0) + 0.5 * 8.0 * 0.25)
    body.rest()
    assert body.asleep and (body.vx, body.vy, body.spin) == (0.0, 0.0, 0.0)


def test_bodies_made_at_once_are_the_bodies_made_one_by_one_on_rows_of_one_array():
    made = [(1.0, -2.0, 0.3, 4.0, 5.0, -6.0, 2.0, 0.5, 0.5, 2.0, False), (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0,
                                                                        1.0, True)]
    together = Body.on_rows([Body.row(*values) for values in made])
    for body, values in zip(together, made):
        alone = Body(*values)
        assert body._row.tolist() == alone._row.tolist() and body.asleep == values[-1]
    assert together[0]._row.base is together[1]._row.base is not None  # one array, a row each
    together[1].x = 9.0
    assert (together[0].x, together[1].x) == (1.0, 9.0)
    assert Body.on_rows([]) == []


def test_gathering_moves_every_body_into_one_array_and_keeps_its_values():
    esper.switch_world("bodies-test")
    try:
        a, b = Body.dynamic(1.0, 0.0, 1.0, 1.0, vx=2.0), Body(x=5.0, y=6.0, spin=1.5)
        ea, eb = esper.create_entity(a), esper.create_entity(b)
        store = BodyStore()
        state = store.gather(esper.get_component(Body))
        assert state.shape == (2, len(COLUMNS))
        assert state[store.rows[ea], VX] == 2.0 and state[store.rows[eb], SPIN] == 1.5
        assert store.gather(esper.get_component(Body)) is state  # nothing changed: the same array
        state[store.rows[ea], X] = 7.0  # a kernel's write is the handle's value, and back
        b.vy = 3.0
        assert a.x == 7.0 and state[store.rows[eb], VY] == 3.0
        esper.delete_entity(ea, immediate=True)
        again = store.gather(esper.get_component(Body))
        assert again is not state and again.shape == (1, len(COLUMNS)) and again[0, Y] == 6.0
        assert a.x == 7.0  # a body that left keeps its last values
        b.x = -1.0
        assert again[store.rows[eb], X] == -1.0 and state[store.rows.get(ea, 0), X] == 7.0
    finally:
        esper.switch_world("default")
        esper.delete_world("bodies-test")


def test_a_selection_follows_the_store():
    esper.switch_world("bodies-test")
    try:
        ents = [esper.create_entity(Body(x=float(k), y=0.0), *(("tag",) if k % 2 else ())) for k in range(5)]
        store, chosen = BodyStore(), Selection()
        state = store.gather(esper.get_component(Body))
        picked = chosen.of(store, esper.get_components(Body, str))
        assert sorted(state[picked, X].tolist()) == [1.0, 3.0]
        esper.delete_entity(ents[0], immediate=True)
        state = store.gather(esper.get_component(Body))
        assert sorted(state[chosen.of(store, esper.get_components(Body, str)), X].tolist()) == [1.0, 3.0]
    finally:
        esper.switch_world("default")
        esper.delete_world("bodies-test")


# --- free motion -----------------------------------------------------------------------------------

def test_advance_moves_by_velocity_and_makes_up_the_lag():
    state = rows(2, vx=2.0, vy=-1.0, spin=3.0)
    state[1, LAG] = 0.5 * DT
    state[1, ASLEEP] = 0.0
    motion.advance(state, np.zeros(2, dtype=np.bool_), DT, 1e-9, 1e-9, 0.1, 0.25)
    assert (state[0, X], state[0, Y], state[0, ANGLE]) == (2.0 * DT, -DT, 0.0)
    assert state[1, X] == pytest.approx(2.0 * 1.5 * DT) and state[1, ANGLE] == pytest.approx(3.0 * 0.5 * DT)
    assert state[1, LAG] == 0.0


def test_advance_puts_a_settling_body_to_rest_after_time_to_rest_and_no_sooner():
    state = rows(3, vx=0.5 * REST_LINEAR)  # slow: moves less than REST_LINEAR·dt a substep
    state[2, VX] = 2.0 * REST_SPEED_CAP  # touching but too fast: never
    settles = np.array([True, False, True])  # the middle one coasts freely: never
    still, substeps = 0.0, 0  # still time adds up a substep at a time, as the kernel adds it
    while still < TIME_TO_REST:
        still += DT
        substeps += 1
    for _ in range(substeps):
        assert not state[0, ASLEEP]
        motion.advance(state, settles, DT, REST_LINEAR * DT, REST_ANGULAR * DT, REST_SPEED_CAP, TIME_TO_REST)
    assert state[0, ASLEEP] and state[0, VX] == 0.0
    assert not state[1, ASLEEP] and not state[2, ASLEEP]


def test_a_body_woken_by_a_touching_one_goes_on_from_the_lesser_still_time():
    """Moving into a sleeper: both begin again from zero. Still beside it (come to rest against it a
    moment later): both go on from the still one's time, so the two sleep together and a row of
    balls at rest falls asleep (from zero pair by pair, three in a row never did)."""
    state = rows(4)
    state[:, STILL_TIME] = 0.0, TIME_TO_REST, 0.5 * TIME_TO_REST, TIME_TO_REST
    state[[1, 3], ASLEEP] = 1.0
    motion.wake_pairs(state, np.array([[0, 1], [2, 3]], dtype=np.int64))
    assert not state[:, ASLEEP].any()
    assert state[:, STILL_TIME].tolist() == [0.0, 0.0, 0.5 * TIME_TO_REST, 0.5 * TIME_TO_REST]


def test_bodies_touching_each_other_rest_together_when_all_are_still_long_enough():
    """Rows 0-1-2 touch in a chain (2 through 1), row 3 touches only a wall (the static world, -1)
    and row 4 is a kinematic arm touching 3: an island is held while any of its dynamic bodies is
    not ready, and a kinematic body or a wall joins nobody."""
    state = rows(5, vx=0.0)
    state[4, INV_MASS] = 0.0
    settles = np.ones(5, dtype=np.bool_)
    state[:, STILL_TIME] = TIME_TO_REST, TIME_TO_REST, 0.5 * TIME_TO_REST, TIME_TO_REST, 0.0
    touching = np.array([[10, 11], [11, 12], [13, -1], [13, 14]], dtype=np.int64)
    lookup = np.array([-1] * 10 + [0, 1, 2, 3, 4], dtype=np.int64)
    island, held = np.empty(5, dtype=np.int64), np.zeros(5, dtype=np.bool_)
    assert motion.hold_islands(state, settles, touching, lookup, TIME_TO_REST, island, held)
    assert held.tolist() == [True, True, True, False, False]
    motion.move(state, settles, DT, TIME_TO_REST, held, True)
    assert state[:, ASLEEP].tolist() == [0.0, 0.0, 0.0, 1.0, 0.0]
    state[2, STILL_TIME] = TIME_TO_REST  # the last of the chain ready too: the three rest at once
    assert motion.hold_islands(state, settles, touching, lookup, TIME_TO_REST, island, held)
    motion.move(state, settles, DT, TIME_TO_REST, held, True)
    assert state[:, ASLEEP].tolist() == [1.0, 1.0, 1.0, 1.0, 0.0]
    assert not motion.hold_islands(state, settles, touching[2:3], lookup, TIME_TO_REST, island, held)


def test_drag_follows_the_closed_form_and_uses_the_surface_scale_once():
    state = rows(2, vx=3.0, vy=4.0, spin=-2.0)
    state[1, DRAG_SCALE] = 5.0
    rates = np.array([[0.4, 1.0, 1.2, 2.0]] * 2)
    motion.drag(state, np.arange(2, dtype=np.int64), rates, DT)
    speed = (5.0 + 1.2 / 0.4) * math.exp(-0.4 * DT) - 1.2 / 0.4
    assert math.hypot(state[0, VX], state[0, VY]) == pytest.approx(speed, rel=1e-12)
    assert state[0, VX] / state[0, VY] == pytest.approx(0.75)  # direction kept
    assert state[0, SPIN] == pytest.approx(-((2.0 + 2.0) * math.exp(-DT) - 2.0), rel=1e-12)
    sand = (5.0 + 6.0 / 2.0) * math.exp(-2.0 * DT) - 6.0 / 2.0  # every rate five times
    assert math.hypot(state[1, VX], state[1, VY]) == pytest.approx(sand, rel=1e-12)
    assert state[1, DRAG_SCALE] == 1.0  # reset: the surface says so again next substep if still on it


def test_drag_of_a_speed_whose_square_overflows_is_still_the_closed_form():
    # Drag takes the speed as the root of the sum of squares only where the squares are normal
    # numbers: here they overflow, and the root of infinity would turn the velocity into NaN.
    state = rows(1, vx=3e160, vy=4e160)
    motion.drag(state, np.zeros(1, dtype=np.int64), np.array([[0.4, 0.0, 0.0, 0.0]]), DT)
    assert np.isfinite(state[0, [VX, VY]]).all()
    assert state[0, VX] == pytest.approx(3e160 * math.exp(-0.4 * DT), rel=1e-12)
    assert state[0, VY] == pytest.approx(4e160 * math.exp(-0.4 * DT), rel=1e-12)


def test_drag_never_reverses_a_body():
    state = rows(1, vx=1e-4, spin=1e-4)
    motion.drag(state, np.zeros(1, dtype=np.int64), np.array([[0.0, 0.0, 5.0, 5.0]]), DT)
    assert (state[0, VX], state[0, SPIN]) == (0.0, 0.0)


def test_accelerate_skips_resting_and_kinematic_bodies():
    state = rows(3)
    state[1, ASLEEP] = 1.0
    state[2, INV_MASS] = 0.0
    motion.accelerate(state, np.arange(3, dtype=np.int64), np.array([[2.0, -1.0]]), np.zeros(3, dtype=np.int64), 0.5)
    assert state[:, VX].tolist() == [1.0, 0.0, 0.0] and state[:, VY].tolist() == [-0.5, 0.0, 0.0]


def test_the_cup_catches_a_slow_ball_and_lets_a_fast_one_or_one_at_the_rim_pass():
    state = rows(4)
    state[:, X] = [0.1, 0.1, 0.3, 5.0]
    state[:, VX] = [1.0, 3.5, 0.1, 0.0]
    cups = np.array([[0.0, 0.0, 0.3, 4.0]])
    # over the centre the cap is 4 m/s, 0.1 m out of 0.3 it is 4·(1 - 1/3) = 2.67 m/s, at the rim 0
    assert [motion.cup_under(state, k, cups) for k in range(4)] == [0, -1, -1, -1]


def test_kinetic_energy_sums_every_dynamic_body_and_notices_nan():
    state = rows(3, vx=2.0, spin=1.0)
    state[2, INV_MASS] = 0.0  # kinematic: no energy of its own
    energy, finite = motion.kinetic_energy(state)
    assert energy == pytest.approx(2 * (0.5 * 4.0 + 0.5 * 1.0)) and finite
    state[1, Y] = math.nan
    assert not motion.kinetic_energy(state)[1]


coordinates = st.floats(-3.0, 3.0, allow_nan=False)


@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(coordinates, coordinates), min_size=3, max_size=9), coordinates, coordinates)
def test_an_area_holds_a_point_exactly_when_the_region_does(outline, x, y):
    xs, ys = zip(*outline)
    region = Region(tuple(outline), (min(xs), min(ys), max(xs), max(ys)))
    areas = Areas.of([region.outline], [region.aabb])
    state = rows(1, x=x, y=y)
    out = np.empty(1, dtype=np.int64)
    first_area(state, np.zeros(1, dtype=np.int64), areas.verts, areas.first, areas.boxes, out)
    assert (out[0] == 0) == region.contains(x, y)


def test_the_first_area_that_holds_a_body_is_taken_and_resting_bodies_are_not_looked_at():
    square = [(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)]
    inner = [(0.5, 0.5), (1.5, 0.5), (1.5, 1.5), (0.5, 1.5)]
    areas = Areas.of([inner, square], [(0.5, 0.5, 1.5, 1.5), (0.0, 0.0, 2.0, 2.0)])
    state = rows(4)
    state[:, X] = [1.0, 0.2, 3.0, 1.0]
    state[:, Y] = 1.0
    state[3, ASLEEP] = 1.0
    out = np.empty(4, dtype=np.int64)
    first_area(state, np.arange(4, dtype=np.int64), areas.verts, areas.first, areas.boxes, out)
    assert out.tolist() == [0, 1, -1, -1]
