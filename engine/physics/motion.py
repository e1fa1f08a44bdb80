"""Free motion of every body of a world, one kernel call a stage: semi-implicit Euler's position half
with rest detection, orientation, constant accelerations and drag. Each kernel walks the rows of a
`body.BodyStore` state array (`body.COLUMNS`), skipping bodies at rest."""

from __future__ import annotations

import math

import numpy as np

from polygolf.engine.physics.body import (
    ANGLE,
    ANGLE0,
    ASLEEP,
    COLUMNS,
    DRAG_SCALE,
    INERTIA,
    INV_MASS,
    LAG,
    MASS,
    MOVED_FOR,
    SPIN,
    STILL_TIME,
    VX,
    VY,
    X0,
    Y0,
    X,
    Y,
)
from polygolf.engine.physics.geometry import norm
from polygolf.engine.physics.jit import inlined_leaf, leaf_kernel, warm_up


@leaf_kernel
def _mark_start(state: np.ndarray, k: int) -> None:
    state[k, X0] = state[k, X]
    state[k, Y0] = state[k, Y]
    state[k, ANGLE0] = state[k, ANGLE]


@leaf_kernel
def put_to_rest(state: np.ndarray, k: int) -> None:
    """Body row k at rest where it is: no velocity, no motion owed (`Body.rest`, for kernels)."""
    state[k, ASLEEP] = 1.0
    state[k, VX] = state[k, VY] = state[k, SPIN] = 0.0
    _mark_start(state, k)


@leaf_kernel
def advance(state: np.ndarray, settles: np.ndarray, dt: float, still_step: float, still_turn: float,
            speed_cap: float, time_to_rest: float) -> None:
    """x += v·dt for every awake body (plus the time continuous collision owes it), after putting to
    rest each dynamic body that `settles` (touching something, or slowed by drag) and has moved less
    than `still_step` and turned less than `still_turn` a substep, below `speed_cap`, for
    `time_to_rest` seconds: each body alone (`integrate` puts bodies that touch each other to rest
    together: `hold_islands`)."""
    count_still(state, settles, dt, still_step, still_turn, speed_cap)
    move(state, settles, dt, time_to_rest, settles, False)


@leaf_kernel
def count_still(state: np.ndarray, settles: np.ndarray, dt: float, still_step: float, still_turn: float,
                speed_cap: float) -> None:
    """Each awake dynamic body that `settles`: its still time grows by dt while it moves less than
    `still_step` and turns less than `still_turn` a substep, below `speed_cap`; else it begins again."""
    for k in range(state.shape[0]):
        if state[k, ASLEEP] != 0.0 or state[k, INV_MASS] == 0.0 or not settles[k]:
            continue
        dx, dy = state[k, X] - state[k, X0], state[k, Y] - state[k, Y0]
        vx, vy = state[k, VX], state[k, VY]
        if (dx * dx + dy * dy < still_step * still_step and abs(state[k, ANGLE] - state[k, ANGLE0]) < still_turn
                and vx * vx + vy * vy < speed_cap * speed_cap):
            state[k, STILL_TIME] += dt
        else:
            state[k, STILL_TIME] = 0.0


@inlined_leaf
def _ready(state: np.ndarray, settles: np.ndarray, k: int, time_to_rest: float) -> bool:
    """Whether awake body row k has been still long enough to rest (`count_still` has counted)."""
    return state[k, INV_MASS] > 0.0 and settles[k] and state[k, STILL_TIME] >= time_to_rest


@leaf_kernel
def hold_islands(state: np.ndarray, settles: np.ndarray, touching: np.ndarray, lookup: np.ndarray,
                 time_to_rest: float, island: np.ndarray, held: np.ndarray) -> bool:
    """Bodies that touch each other (the contact table's entity pairs `touching`; `lookup`: entity
    -> row) rest together, as Box2D's islands sleep: held[k] says body row k is still long enough
    but a dynamic body it touches, directly or through others, is not yet. (Each alone, the first
    to sleep was woken by a still neighbour, and three balls at rest in a row never slept.)
    `island`: room for a row a body. Returns whether any two dynamic bodies touch and any body is
    ready to rest (else `held` is left as it was: nobody is held; a crowd in motion costs one pass)."""
    ready = False
    for k in range(len(island)):
        if state[k, ASLEEP] == 0.0 and _ready(state, settles, k, time_to_rest):
            ready = True
            break
    if not ready:
        return False  # (nobody would rest this substep: nobody to hold)
    joined = False
    for g in range(touching.shape[0]):
        ea, eb = touching[g, 0], touching[g, 1]
        if not (0 <= ea < len(lookup) and 0 <= eb < len(lookup)):
            continue
        a, b = lookup[ea], lookup[eb]
        if a < 0 or b < 0 or state[a, INV_MASS] == 0.0 or state[b, INV_MASS] == 0.0:
            continue
        if not joined:
            for k in range(len(island)):
                island[k] = k
            joined = True
        a, b = root(island, a), root(island, b)
        if a != b:
            island[max(a, b)] = min(a, b)
    if not joined:
        return False
    for k in range(len(held)):
        held[k] = False
    for k in range(len(island)):  # an island holds on while any awake dynamic body in it is not ready
        if state[k, ASLEEP] == 0.0 and state[k, INV_MASS] > 0.0 and not _ready(state, settles, k, time_to_rest):
            held[root(island, k)] = True
    for k in range(len(island)):
        held[k] = held[root(island, k)]
    return True


@leaf_kernel
def root(parent: np.ndarray, key: int) -> int:
    """Union-find: the root of `key`'s set in `parent` (each entry its parent; a root its own),
    halving the path on the way (the islands here and the solver's)."""
    while parent[key] != key:
        parent[key] = parent[parent[key]]
        key = parent[key]
    return key


@leaf_kernel
def move(state: np.ndarray, settles: np.ndarray, dt: float, time_to_rest: float, held: np.ndarray,
         holding: bool) -> None:
    """Each awake body still long enough (`count_still`), unless `holding` and held[k]
    (`hold_islands`), put to rest; every other awake body x += v·dt (plus what it is owed)."""
    for k in range(state.shape[0]):
        if state[k, ASLEEP] != 0.0:
            continue
        if _ready(state, settles, k, time_to_rest) and not (holding and held[k]):
            put_to_rest(state, k)
            continue
        _mark_start(state, k)
        step = dt
        lag = state[k, LAG]
        if lag:
            # Continuous collision stopped the body early last substep; it now moves on with its new
            # velocity for the time it lost, so impacts do not slow the clock: at most a substep's
            # time, so a body stopped again and again (pressed into a row of balls) does not save up
            # substep after substep of motion and then jump that far at once.
            lag = min(lag, dt)
            step += lag
            state[k, ANGLE] += state[k, SPIN] * lag
            state[k, LAG] = 0.0
        state[k, MOVED_FOR] = step
        state[k, X] += state[k, VX] * step
        state[k, Y] += state[k, VY] * step


@leaf_kernel
def turn(state: np.ndarray, dt: float) -> None:
    """angle += ω·dt for every awake body that spins."""
    for k in range(state.shape[0]):
        if state[k, SPIN] and state[k, ASLEEP] == 0.0:
            state[k, ANGLE] += state[k, SPIN] * dt


@leaf_kernel
def accelerate(state: np.ndarray, rows: np.ndarray, pushes: np.ndarray, which: np.ndarray, dt: float) -> None:
    """v += a·dt for each awake dynamic body of `rows`, with a = pushes[which[q]] (x, y), or none
    where which[q] < 0: gravity (one push for every body), the slope each ball is on."""
    for q in range(rows.shape[0]):
        k, p = rows[q], which[q]
        if p >= 0 and state[k, INV_MASS] > 0.0 and state[k, ASLEEP] == 0.0:
            state[k, VX] += pushes[p, 0] * dt
            state[k, VY] += pushes[p, 1] * dt


@leaf_kernel
def take_scale(state: np.ndarray, rows: np.ndarray, scales: np.ndarray, which: np.ndarray) -> None:
    """The drag scale of each body of `rows` is scales[which[q]] (the surface it is on), where
    which[q] >= 0."""
    for q in range(rows.shape[0]):
        if which[q] >= 0:
            state[rows[q], DRAG_SCALE] = scales[which[q]]


@leaf_kernel
def decay(value: float, rate: float, resistance: float, dt: float) -> float:
    """Magnitude after dt under d|v|/dt = -rate·|v| - resistance, solved exactly; never below zero.

    |v|(dt) = (|v| + c/k)·exp(-k·dt) - c/k, or |v| - c·dt when k = 0."""
    return _decayed(value, rate, resistance, dt, math.exp(-rate * dt) if rate > 0.0 else 1.0)


@inlined_leaf
def _decayed(value: float, rate: float, resistance: float, dt: float, shrink: float) -> float:
    """`decay` given shrink = exp(-rate·dt) (worked out by the caller, who may have it already)."""
    if rate > 0.0:
        after = (value + resistance / rate) * shrink - resistance / rate
    else:
        after = value - resistance * dt
    return after if after > 0.0 else 0.0


@leaf_kernel
def drag(state: np.ndarray, rows: np.ndarray, rates: np.ndarray, dt: float) -> None:
    """Drag on each awake dynamic body of `rows`: `rates` per row are (linear, angular, rolling,
    rolling_angular), each times the body's `drag_scale`, which is then reset to 1. (Balls on one
    green share their rates: each exp(-rate·dt) is worked out when the rate differs from the last
    body's, not once a body.)"""
    linear_rate, linear_shrink, angular_rate, angular_shrink = math.nan, 1.0, math.nan, 1.0
    for q in range(rows.shape[0]):
        k = rows[q]
        if state[k, ASLEEP] != 0.0 or state[k, INV_MASS] == 0.0:
            continue
        scale = state[k, DRAG_SCALE]
        state[k, DRAG_SCALE] = 1.0
        linear, angular, rolling, rolling_angular = rates[q, 0], rates[q, 1], rates[q, 2], rates[q, 3]
        if linear or rolling:
            vx, vy = state[k, VX], state[k, VY]
            speed = norm(vx, vy)
            if speed > 0.0:
                rate = linear * scale
                if rate != linear_rate and rate > 0.0:
                    linear_rate, linear_shrink = rate, math.exp(-rate * dt)
                factor = _decayed(speed, rate, rolling * scale, dt, linear_shrink) / speed
                state[k, VX] = vx * factor
                state[k, VY] = vy * factor
        spin = state[k, SPIN]
        if (angular or rolling_angular) and spin:
            rate = angular * scale
            if rate != angular_rate and rate > 0.0:
                angular_rate, angular_shrink = rate, math.exp(-rate * dt)
            turned = _decayed(abs(spin), rate, rolling_angular * scale, dt, angular_shrink)
            state[k, SPIN] = math.copysign(turned, spin)


# Squared distances within this factor of a cup's squared radius are decided by the exact distance
# (math.hypot, within an ulp; the sum of squares, within a few): far wider than either can be off.
_NEARLY = 1.0 + 1e-9


@inlined_leaf
def cup_under(state: np.ndarray, k: int, cups: np.ndarray) -> int:
    """The first cup (x, y, radius, max_speed) the centre of body row k is over slowly enough to
    drop in, or -1: at most `max_speed` over the centre, falling linearly to zero at the rim."""
    for c in range(cups.shape[0]):
        dx, dy = state[k, X] - cups[c, 0], state[k, Y] - cups[c, 1]
        if not dx * dx + dy * dy < cups[c, 2] * cups[c, 2] * _NEARLY:
            continue  # well outside: no need of the exact distance
        distance = math.hypot(dx, dy)
        if distance < cups[c, 2]:
            share = 1.0 - distance / cups[c, 2]
            if math.hypot(state[k, VX], state[k, VY]) < cups[c, 3] * (share if share > 0.0 else 0.0):
                return c
    return -1


@leaf_kernel
def kinetic_energy(state: np.ndarray) -> tuple[float, bool]:
    """The bodies' kinetic energy (summed in row order) and whether every pose and energy is finite."""
    total, finite = 0.0, True
    for k in range(state.shape[0]):
        e = 0.0
        if state[k, INV_MASS] > 0.0:
            vx, vy, spin = state[k, VX], state[k, VY], state[k, SPIN]
            e = 0.5 * (state[k, MASS] * (vx * vx + vy * vy) + state[k, INERTIA] * spin * spin)
        if not (math.isfinite(e) and math.isfinite(state[k, X]) and math.isfinite(state[k, Y])
                and math.isfinite(state[k, ANGLE])):
            finite = False
        total += e
    return total, finite


@inlined_leaf
def pose_at(state: np.ndarray, k: int, t: float) -> tuple[float, float, float]:
    """Body row k's pose (x, y, angle) at fraction t of its motion this substep, as the integrator
    moves it: linearly in position and angle."""
    return (state[k, X0] + t * (state[k, X] - state[k, X0]), state[k, Y0] + t * (state[k, Y] - state[k, Y0]),
            state[k, ANGLE0] + t * (state[k, ANGLE] - state[k, ANGLE0]))


@leaf_kernel
def rewind(state: np.ndarray, rows: np.ndarray, hits: np.ndarray) -> int:
    """Each body q of `rows` with hits[q] < 1 goes back to that fraction of its motion this substep
    (continuous collision's time of impact). A dynamic body owes the rest of its motion's time
    (`lag`, made up in the next substep); a kinematic one (a stalled windmill) stands still for the
    solve and owes nothing. Returns how many went back."""
    count = 0
    for q in range(rows.shape[0]):
        t = hits[q]
        if not t < 1.0:
            continue
        k = rows[q]
        state[k, X], state[k, Y], state[k, ANGLE] = pose_at(state, k, t)
        if state[k, INV_MASS] != 0.0:
            state[k, LAG] = (1.0 - t) * state[k, MOVED_FOR]
        else:
            state[k, SPIN] = 0.0
        count += 1
    return count


@leaf_kernel
def wake_pairs(state: np.ndarray, pairs: np.ndarray) -> None:
    """Pair by pair, in order: if either body is at rest, wake both (a body that touches a moving one
    is moving again). Their still time goes on from the lesser of the two: from zero where one was
    moving, but where one was awake and still, from its time, so that bodies come to rest against
    each other fall asleep together (begun again from zero pair by pair, the clocks of three balls
    at rest in a row never ran out together: they never slept)."""
    for g in range(pairs.shape[0]):
        a, b = pairs[g, 0], pairs[g, 1]
        if state[a, ASLEEP] != 0.0 or state[b, ASLEEP] != 0.0:
            state[a, ASLEEP] = state[b, ASLEEP] = 0.0
            state[a, STILL_TIME] = state[b, STILL_TIME] = min(state[a, STILL_TIME], state[b, STILL_TIME])


@leaf_kernel
def mark_touching(settles: np.ndarray, ents: np.ndarray, lookup: np.ndarray) -> None:
    """settles[lookup[entity]] = True for every entity of a contact table's pairs (`ents`) that has a
    row (the static world, -1, has none)."""
    for g in range(ents.shape[0]):
        for side in range(2):
            ent = ents[g, side]
            if 0 <= ent < len(lookup) and lookup[ent] >= 0:
                settles[lookup[ent]] = True


@leaf_kernel
def came_to_rest(state: np.ndarray, rows: np.ndarray, was_asleep: np.ndarray, out: np.ndarray) -> int:
    """The bodies of `rows` (indices into it, into `out`) at rest now that were not when `was_asleep`
    was last updated (it is, here). Returns how many."""
    count = 0
    for q in range(rows.shape[0]):
        asleep = state[rows[q], ASLEEP] != 0.0
        if asleep and not was_asleep[q]:
            out[count] = q
            count += 1
        was_asleep[q] = asleep
    return count


@warm_up("motion")
def _warm() -> None:
    state = np.zeros((2, len(COLUMNS)))
    state[:, INV_MASS] = 1.0
    state[:, VX] = 1.0
    state[:, SPIN] = 1.0
    state[:, DRAG_SCALE] = 1.0
    rows = np.arange(2, dtype=np.int64)
    advance(state, np.ones(2, dtype=np.bool_), 0.01, 0.001, 0.001, 0.1, 0.25)
    hold_islands(state, np.ones(2, dtype=np.bool_), np.array([[0, 1]], dtype=np.int64), np.arange(2, dtype=np.int64),
                 0.25, np.empty(2, dtype=np.int64), np.zeros(2, dtype=np.bool_))
    turn(state, 0.01)
    accelerate(state, rows, np.array([[1.0, 0.0]]), np.zeros(2, dtype=np.int64), 0.01)
    take_scale(state, rows, np.array([0.5]), np.array([0, -1], dtype=np.int64))
    drag(state, rows, np.array([[0.1, 0.1, 0.5, 0.5], [0.0, 0.0, 0.5, 0.5]]), 0.01)
    kinetic_energy(state)
    came_to_rest(state, rows, np.zeros(2, dtype=np.bool_), np.empty(2, dtype=np.int64))
    rewind(state, rows, np.array([0.5, 1.0]))
    wake_pairs(state, np.array([[0, 1]], dtype=np.int64))
    mark_touching(np.zeros(2, dtype=np.bool_), np.array([[1, -1]], dtype=np.int64), np.array([-1, 0], dtype=np.int64))
