"""Sequential impulses on contact manifolds (Catto, GDC 2006; box2d-lite and Box2D v2.4).

Per substep, island by island:
1. prepare: lever arms, effective masses, and the approach speed of every point *before* solving.
2. warm start: re-apply last substep's impulses of persisting points.
3. velocity sweeps, repeated: Coulomb friction clamped to the current normal impulse, then the
   normal constraint vn >= 0 with accumulated-impulse clamping; a two-point manifold is solved as one
   2x2 complementarity problem (the block solver) so a flat face gets two equal impulses.
4. Position error is removed without touching velocities: split impulses (pseudo-velocities that move
   positions only) or non-linear Gauss-Seidel on positions. Neither adds kinetic energy.
5. `apply_restitution`: Poisson's hypothesis - the restitution phase repeats e times the compression
   impulse. With a converged compression phase the energy after impact can only fall:
   KE+ = KE_c + e²·W <= KE_c + W = KE- (W = ½PᵀAP, the energy the compression took).

`solve` runs steps 1-4 in that order for one substep, as box2d-lite's `Arbiter::PreStep` and
`ApplyImpulse` do for its world; the restitution phase is its own stage. Normals point from body A to
body B; a negative normal velocity is approach.

The work is one compiled kernel (`solve_contacts`) over the substep's `contact.ContactTable`, whose
manifold and point rows it reads and writes in place, and a packed copy of the bodies' rows (the
store's and the static world's), whose pose, velocity and pseudo-velocity `solve` writes back.
"""

from __future__ import annotations

import math

import numpy as np

from polygolf.engine.physics import body
from polygolf.engine.physics.body import Body, BodyStore
from polygolf.engine.physics.collide import CLIPPED_LOW
from polygolf.engine.physics.contact import (
    K_FEATURE,
    M_K11,
    M_K12,
    M_K22,
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
    P_NORMAL_MASS,
    P_PUSH_IMPULSE,
    P_RA_X,
    P_RA_Y,
    P_RB_X,
    P_RB_Y,
    P_REF_IS_A,
    P_RESTITUTION,
    P_SEP,
    P_TANGENT_IMPULSE,
    P_TANGENT_MASS,
    P_X,
    P_Y,
    ContactPoint,
    ContactTable,
    Manifold,
    table_of,
)
from polygolf.engine.physics.jit import counted_kernel, kernel, leaf_kernel, warm_up
from polygolf.engine.physics.motion import root as _root
from polygolf.engine.physics.presets import Knobs
from polygolf.engine.physics.settings import BLOCK_MAX_CONDITION, LINEAR_SLOP, MAX_CORRECTION, POSITION_BETA

# Columns of a body row: pose, velocity, mass properties, split-impulse pseudo-velocity (the first
# SOLVER_COLUMNS of a `body.BodyStore` row). A velocity and its pseudo-velocity are three columns
# each in the same order, so one function serves both.
B_X, B_Y, B_ANGLE, B_VX, B_VY, B_SPIN, B_MASS, B_INERTIA, B_INV_MASS, B_INV_INERTIA, B_PUSH_X, B_PUSH_Y, \
    B_PUSH_SPIN = body.X, body.Y, body.ANGLE, body.VX, body.VY, body.SPIN, body.MASS, body.INERTIA, body.INV_MASS, \
    body.INV_INERTIA, body.PUSH_X, body.PUSH_Y, body.PUSH_SPIN
B_ENERGY0 = body.ENERGY0  # (past the solver's columns: a store row's, read by the bounce's cap)
# Position correction, as `solve_contacts` takes it.
SPLIT, NGS, NO_CORRECTION = 0, 1, 2
_CORRECTIONS = {"split": SPLIT, "ngs": NGS, "none": NO_CORRECTION}


# --- small pieces --------------------------------------------------------------------------------

@leaf_kernel
def _max(a: float, b: float) -> float:
    """Python's max(a, b): the first unless the second is larger (so max(-0.0, 0.0) is -0.0)."""
    return b if b > a else a


@leaf_kernel
def _min(a: float, b: float) -> float:
    """Python's min(a, b): the first unless the second is smaller."""
    return b if b < a else a


@leaf_kernel
def _relative_velocity(bodies: np.ndarray, a: int, b: int, col: int, rax: float, ray: float, rbx: float,
                       rby: float) -> tuple[float, float]:
    """Velocity of B's point rb relative to A's point ra; `col` = B_VX for velocities, B_PUSH_X for
    split-impulse pseudo-velocities."""
    return (bodies[b, col] - bodies[b, col + 2] * rby - bodies[a, col] + bodies[a, col + 2] * ray,
            bodies[b, col + 1] + bodies[b, col + 2] * rbx - bodies[a, col + 1] - bodies[a, col + 2] * rax)


@leaf_kernel
def _apply(bodies: np.ndarray, a: int, b: int, col: int, px: float, py: float, rax: float, ray: float, rbx: float,
           rby: float) -> None:
    """Apply impulse P at a point: -P to A, +P to B (to velocities or pseudo-velocities, by `col`)."""
    bodies[a, col] -= bodies[a, B_INV_MASS] * px
    bodies[a, col + 1] -= bodies[a, B_INV_MASS] * py
    bodies[a, col + 2] -= bodies[a, B_INV_INERTIA] * (rax * py - ray * px)
    bodies[b, col] += bodies[b, B_INV_MASS] * px
    bodies[b, col + 1] += bodies[b, B_INV_MASS] * py
    bodies[b, col + 2] += bodies[b, B_INV_INERTIA] * (rbx * py - rby * px)


@leaf_kernel
def _push_target(separation: float, sink: float, dt: float, beta: float, slop: float, max_push: float) -> float:
    """The pseudo-velocity that removes `beta` of the overlap beyond `slop`, and all of what the
    point will sink beyond it this substep as the bodies turn (`sink`, `_turning_sinks`), in dt (at
    most `max_push` in all)."""
    over = _max(-(separation + slop), 0.0)
    deeper = _max(-(separation - sink + slop), 0.0) - over
    return _min(beta * over + deeper, max_push) / dt


@leaf_kernel
def _turning_sinks(bodies: np.ndarray, normals: np.ndarray, pair: np.ndarray, first: np.ndarray,
                   points: np.ndarray, keys: np.ndarray, order: np.ndarray, s: int, e: int, dt: float,
                   sink: np.ndarray) -> None:
    """How far each point's incident vertex will sink behind the reference face in dt through the
    bodies' turning alone, which the velocity solve does not see: it stops approach at the point,
    the first derivative of the separation, while a face turning about its body's centre sweeps
    into a corner at its second, s'' = -wR^2 n.(p - cR) + 2 wR n_perp.(vI - vR + wI x rI) -
    wI^2 n.rI (n the reference face's normal turning with it, p the vertex, rI = p - cI); the sink
    is -s'' dt^2 / 2 where that is positive. (A thin bar pivoting on a post at 50 rad/s sank 1.5-3.5 mm
    a substep, held at five times that by the fifth a substep the push removes.) A point clipped
    at a side plane of the reference face is not a vertex that stays put on its body: none."""
    for t in range(s, e):
        k = order[t]
        a, b = pair[k, 0], pair[k, 1]
        for p in range(first[k], first[k + 1]):
            sink[p] = 0.0
            if keys[p, K_FEATURE] % 256 >= CLIPPED_LOW:
                continue
            if points[p, P_REF_IS_A] != 0.0:
                ref, inc, nx, ny = a, b, normals[k, M_NX], normals[k, M_NY]
                rrx, rry, rix, riy = points[p, P_RA_X], points[p, P_RA_Y], points[p, P_RB_X], points[p, P_RB_Y]
            else:
                ref, inc, nx, ny = b, a, -normals[k, M_NX], -normals[k, M_NY]
                rrx, rry, rix, riy = points[p, P_RB_X], points[p, P_RB_Y], points[p, P_RA_X], points[p, P_RA_Y]
            half = 0.5 * points[p, P_SEP]  # the point lies halfway between the face and the vertex
            rrx, rry, rix, riy = rrx + half * nx, rry + half * ny, rix + half * nx, riy + half * ny
            wr, wi = bodies[ref, B_SPIN], bodies[inc, B_SPIN]
            if wr == 0.0 and wi == 0.0:
                continue
            ux = bodies[inc, B_VX] - wi * riy - bodies[ref, B_VX]
            uy = bodies[inc, B_VY] + wi * rix - bodies[ref, B_VY]
            curve = -wr * wr * (nx * rrx + ny * rry) + 2.0 * wr * (nx * uy - ny * ux) - wi * wi * (nx * rix + ny * riy)
            if curve < 0.0:
                sink[p] = -0.5 * curve * dt * dt


@leaf_kernel
def _kinetic_energy(bodies: np.ndarray, k: int) -> float:
    if not bodies[k, B_INV_MASS] > 0.0:
        return 0.0
    vx, vy, spin = bodies[k, B_VX], bodies[k, B_VY], bodies[k, B_SPIN]
    return 0.5 * (bodies[k, B_MASS] * (vx * vx + vy * vy) + bodies[k, B_INERTIA] * spin * spin)


@leaf_kernel
def _island_energy(bodies: np.ndarray, dynamic: np.ndarray, n: int) -> float:
    """The kinetic energy of the island's dynamic bodies, added left to right in their order (a
    plain sum, the same on every Python)."""
    energy = 0.0
    for j in range(n):
        energy += _kinetic_energy(bodies, dynamic[j])
    return energy


@leaf_kernel
def _save_velocities(bodies: np.ndarray, dynamic: np.ndarray, n: int, saved: np.ndarray) -> float:
    """The island's velocities into `saved` (for `_restore_velocities`); returns its kinetic energy."""
    for j in range(n):
        saved[j, 0], saved[j, 1], saved[j, 2] = bodies[dynamic[j], B_VX], bodies[dynamic[j], B_VY], \
            bodies[dynamic[j], B_SPIN]
    return _island_energy(bodies, dynamic, n)


@leaf_kernel
def _restore_velocities(bodies: np.ndarray, dynamic: np.ndarray, n: int, saved: np.ndarray) -> None:
    for j in range(n):
        bodies[dynamic[j], B_VX], bodies[dynamic[j], B_VY], bodies[dynamic[j], B_SPIN] = \
            saved[j, 0], saved[j, 1], saved[j, 2]


@leaf_kernel
def solve_block(k11: float, k12: float, k22: float, b1: float, b2: float, a1: float, a2: float
                ) -> tuple[float, float]:
    """Solve the two-point LCP  w = K x + b,  x >= 0,  w >= 0,  x·w = 0  by enumerating its four cases.

    `b` is the velocity with the current impulses `a` removed (b = vn - bias - K·a); returns x, the
    new accumulated impulses, or keeps `a` if rounding leaves no case satisfied (K is positive
    definite here, so the exact problem always has one solution).
    """
    det = k11 * k22 - k12 * k12
    x1 = -(k22 * b1 - k12 * b2) / det
    x2 = -(k11 * b2 - k12 * b1) / det
    if x1 >= 0.0 and x2 >= 0.0:
        return x1, x2
    x1 = -b1 / k11
    if x1 >= 0.0 and k12 * x1 + b2 >= 0.0:
        return x1, 0.0
    x2 = -b2 / k22
    if x2 >= 0.0 and k12 * x2 + b1 >= 0.0:
        return 0.0, x2
    if b1 >= 0.0 and b2 >= 0.0:
        return 0.0, 0.0
    return a1, a2


# --- islands and the shock chain ------------------------------------------------------------------

@kernel
def _islands(bodies: np.ndarray, pair: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The manifolds in groups that share no dynamic body (union-find): `order` lists manifold rows
    island by island, each island in the original order, islands in the order their first manifold
    comes; island i is order[start[i]:start[i + 1]]. Islands do not interact, so each is solved on
    its own: a decision about one (the cold restart) never touches another, and a body solves the
    same alone as beside others it never meets."""
    n_bodies, n_manifolds = bodies.shape[0], pair.shape[0]
    parent = np.arange(n_bodies)
    for k in range(n_manifolds):
        a, b = pair[k, 0], pair[k, 1]
        if bodies[a, B_INV_MASS] > 0.0 and bodies[b, B_INV_MASS] > 0.0:
            parent[_root(parent, b)] = _root(parent, a)
    # A manifold with no dynamic body is an island of its own (key n_bodies + k).
    label = np.full(n_bodies + n_manifolds, -1, dtype=np.int64)
    island = np.empty(n_manifolds, dtype=np.int64)
    count = 0
    for k in range(n_manifolds):
        a, b = pair[k, 0], pair[k, 1]
        if bodies[a, B_INV_MASS] > 0.0:
            key = _root(parent, a)
        elif bodies[b, B_INV_MASS] > 0.0:
            key = _root(parent, b)
        else:
            key = n_bodies + k
        if label[key] < 0:
            label[key] = count
            count += 1
        island[k] = label[key]
    start = np.zeros(count + 1, dtype=np.int64)
    for k in range(n_manifolds):
        start[island[k] + 1] += 1
    for i in range(count):
        start[i + 1] += start[i]
    fill = start[:count].copy()
    order = np.empty(n_manifolds, dtype=np.int64)
    for k in range(n_manifolds):
        order[fill[island[k]]] = k
        fill[island[k]] += 1
    return order, start


@kernel
def _levels(bodies: np.ndarray, pair: np.ndarray) -> np.ndarray:
    """Each dynamic body's distance from the ground (a wall or a windmill) in contacts: 1 = touches
    the ground; -1 where no chain of contacts reaches it."""
    n_bodies, n_manifolds = bodies.shape[0], pair.shape[0]
    level = np.full(n_bodies, -1, dtype=np.int64)
    links = np.zeros(n_bodies + 1, dtype=np.int64)
    queue = np.empty(n_bodies, dtype=np.int64)
    tail = 0
    for k in range(n_manifolds):  # every manifold the narrowphase kept is solved as touching
        a, b = pair[k, 0], pair[k, 1]
        ma, mb = bodies[a, B_INV_MASS], bodies[b, B_INV_MASS]
        grounded = -1
        if ma == 0.0 and mb > 0.0:
            grounded = b
        elif mb == 0.0 and ma > 0.0:
            grounded = a
        elif ma > 0.0 and mb > 0.0:
            links[a + 1] += 1
            links[b + 1] += 1
        if grounded >= 0 and level[grounded] < 0:
            level[grounded] = 1
            queue[tail] = grounded
            tail += 1
    for i in range(n_bodies):
        links[i + 1] += links[i]
    fill = links[:n_bodies].copy()
    other = np.empty(links[n_bodies], dtype=np.int64)
    for k in range(n_manifolds):
        a, b = pair[k, 0], pair[k, 1]
        if bodies[a, B_INV_MASS] > 0.0 and bodies[b, B_INV_MASS] > 0.0:
            other[fill[a]] = b
            fill[a] += 1
            other[fill[b]] = a
            fill[b] += 1
    head = 0
    while head < tail:  # breadth first: every body gets its least distance
        key = queue[head]
        head += 1
        for j in range(links[key], links[key + 1]):
            if level[other[j]] < 0:
                level[other[j]] = level[key] + 1
                queue[tail] = other[j]
                tail += 1
    return level


@kernel
def _shock_chain(bodies: np.ndarray, pair: np.ndarray, level: np.ndarray, order: np.ndarray, s: int, e: int,
                 chain: np.ndarray, a_grounded: np.ndarray) -> int:
    """Touching contacts of one island between bodies at different distances from the ground (at 0),
    nearest the ground first (then in island order), into `chain`, each with whether its A is the body
    nearer the ground; returns how many. None unless some dynamic body touches another and, through
    it, the ground (a free pile, or a ball alone on a wall, needs none)."""
    links = grounds = False
    for t in range(s, e):
        ma, mb = bodies[pair[order[t], 0], B_INV_MASS], bodies[pair[order[t], 1], B_INV_MASS]
        if (ma == 0.0 and mb > 0.0) or (mb == 0.0 and ma > 0.0):
            grounds = True
        elif ma > 0.0 and mb > 0.0:
            links = True
    if not links or not grounds:
        return 0  # no body between another and the ground: nothing to propagate
    n = 0
    nearest = np.empty(e - s, dtype=np.int64)
    deepest = 0
    for t in range(s, e):
        k = order[t]
        a, b = pair[k, 0], pair[k, 1]
        da = 0 if bodies[a, B_INV_MASS] == 0.0 else level[a]
        db = 0 if bodies[b, B_INV_MASS] == 0.0 else level[b]
        if da >= 0 and db >= 0 and da != db:
            chain[n], a_grounded[n], nearest[n] = k, da < db, min(da, db)
            deepest = max(deepest, nearest[n])
            n += 1
    # A stable counting sort by distance keeps island order among equals.
    count = np.zeros(deepest + 2, dtype=np.int64)
    for c in range(n):
        count[nearest[c] + 1] += 1
    for d in range(deepest + 1):
        count[d + 1] += count[d]
    sorted_chain, sorted_grounded = chain[:n].copy(), a_grounded[:n].copy()
    for c in range(n):
        chain[count[nearest[c]]] = sorted_chain[c]
        a_grounded[count[nearest[c]]] = sorted_grounded[c]
        count[nearest[c]] += 1
    return n


@leaf_kernel
def _propagate_shock(bodies: np.ndarray, normals: np.ndarray, pair: np.ndarray, first: np.ndarray,
                     points: np.ndarray, sink: np.ndarray, chain: np.ndarray, a_grounded: np.ndarray, n: int,
                     pushes: bool, dt: float, beta: float, slop: float, max_push: float) -> None:
    """Shock propagation (Guendelman, Bridson and Fedkiw 2003), after the Gauss-Seidel sweeps: from
    the ground outwards, each body nearer the ground is taken as immovable and the farther one alone
    is stopped from closing on it. Sequential impulses converge slowly when a heavy body presses a
    light one against a wall (the light one is squeezed into the wall); this pass lets the wall's
    resistance reach the heavy body through the light one. It only ever stops an approach, so a
    converged solve is left as it is.

    With `pushes` it acts on the split-impulse pseudo-velocities instead (the overlap's push
    targets), so an overlap already made is pushed out on the far body's side."""
    col = B_PUSH_X if pushes else B_VX
    for c in range(n):
        k, grounded = chain[c], a_grounded[c]
        a, b = pair[k, 0], pair[k, 1]
        free = b if grounded else a
        sign = 1.0 if grounded else -1.0  # an impulse along n pushes B away from A
        nx, ny = normals[k, M_NX], normals[k, M_NY]
        for p in range(first[k], first[k + 1]):
            rax, ray, rbx, rby = points[p, P_RA_X], points[p, P_RA_Y], points[p, P_RB_X], points[p, P_RB_Y]
            dvx, dvy = _relative_velocity(bodies, a, b, col, rax, ray, rbx, rby)
            vn = dvx * nx + dvy * ny
            target = _push_target(points[p, P_SEP], sink[p], dt, beta, slop, max_push) if pushes else 0.0
            if vn >= target:
                continue
            rx, ry = (rbx, rby) if grounded else (rax, ray)
            rn = rx * ny - ry * nx
            k_free = bodies[free, B_INV_MASS] + bodies[free, B_INV_INERTIA] * rn * rn
            lam = sign * (target - vn) / k_free
            px, py = lam * nx, lam * ny
            bodies[free, col] += bodies[free, B_INV_MASS] * px
            bodies[free, col + 1] += bodies[free, B_INV_MASS] * py
            bodies[free, col + 2] += bodies[free, B_INV_INERTIA] * (rx * py - ry * px)


# --- one island's stages --------------------------------------------------------------------------

@leaf_kernel
def _prepare(bodies: np.ndarray, normals: np.ndarray, pair: np.ndarray, first: np.ndarray, block: np.ndarray,
             points: np.ndarray, order: np.ndarray, s: int, e: int, max_condition: float) -> None:
    """Lever arms, effective masses and approach speeds; the block matrix of two-point manifolds,
    and whether it is well enough conditioned to be solved as a block."""
    for t in range(s, e):
        k = order[t]
        a, b = pair[k, 0], pair[k, 1]
        nx, ny = normals[k, M_NX], normals[k, M_NY]
        ma, mb = bodies[a, B_INV_MASS], bodies[b, B_INV_MASS]
        ia, ib = bodies[a, B_INV_INERTIA], bodies[b, B_INV_INERTIA]
        for p in range(first[k], first[k + 1]):
            rax, ray = points[p, P_X] - bodies[a, B_X], points[p, P_Y] - bodies[a, B_Y]
            rbx, rby = points[p, P_X] - bodies[b, B_X], points[p, P_Y] - bodies[b, B_Y]
            points[p, P_RA_X], points[p, P_RA_Y], points[p, P_RB_X], points[p, P_RB_Y] = rax, ray, rbx, rby
            rna = rax * ny - ray * nx
            rnb = rbx * ny - rby * nx
            kn = ma + mb + ia * rna * rna + ib * rnb * rnb
            points[p, P_NORMAL_MASS] = 1.0 / kn if kn > 0.0 else 0.0
            # Tangent t = (ny, -nx); r x t = -(r . n).
            rta = -(rax * nx + ray * ny)
            rtb = -(rbx * nx + rby * ny)
            kt = ma + mb + ia * rta * rta + ib * rtb * rtb
            points[p, P_TANGENT_MASS] = 1.0 / kt if kt > 0.0 else 0.0
            dvx, dvy = _relative_velocity(bodies, a, b, B_VX, rax, ray, rbx, rby)
            points[p, P_APPROACH] = dvx * nx + dvy * ny
        block[k] = False
        if first[k + 1] - first[k] == 2:
            p1, p2 = first[k], first[k] + 1
            rn1a = points[p1, P_RA_X] * ny - points[p1, P_RA_Y] * nx
            rn1b = points[p1, P_RB_X] * ny - points[p1, P_RB_Y] * nx
            rn2a = points[p2, P_RA_X] * ny - points[p2, P_RA_Y] * nx
            rn2b = points[p2, P_RB_X] * ny - points[p2, P_RB_Y] * nx
            k11 = ma + mb + ia * rn1a * rn1a + ib * rn1b * rn1b
            k22 = ma + mb + ia * rn2a * rn2a + ib * rn2b * rn2b
            k12 = ma + mb + ia * rn1a * rn2a + ib * rn1b * rn2b
            normals[k, M_K11], normals[k, M_K12], normals[k, M_K22] = k11, k12, k22
            det = k11 * k22 - k12 * k12
            block[k] = k11 * k11 < max_condition * det


@leaf_kernel
def _warm_start(bodies: np.ndarray, normals: np.ndarray, pair: np.ndarray, first: np.ndarray, points: np.ndarray,
                order: np.ndarray, s: int, e: int) -> None:
    """Re-apply the impulses carried over from last substep."""
    for t in range(s, e):
        k = order[t]
        nx, ny = normals[k, M_NX], normals[k, M_NY]
        for p in range(first[k], first[k + 1]):
            jn, jt = points[p, P_NORMAL_IMPULSE], points[p, P_TANGENT_IMPULSE]
            if jn != 0.0 or jt != 0.0:
                _apply(bodies, pair[k, 0], pair[k, 1], B_VX, jn * nx + jt * ny, jn * ny - jt * nx, points[p, P_RA_X],
                       points[p, P_RA_Y], points[p, P_RB_X], points[p, P_RB_Y])


@leaf_kernel
def _normal_block(bodies: np.ndarray, a: int, b: int, col: int, nx: float, ny: float, manifold: np.ndarray,
                  points: np.ndarray, p1: int, impulse: int, t1: float, t2: float) -> None:
    """A two-point manifold's normal impulses as one 2x2 complementarity problem, driving the
    (pseudo-)velocity along the normal at each point to its target (0 for velocities)."""
    p2 = p1 + 1
    dv1x, dv1y = _relative_velocity(bodies, a, b, col, points[p1, P_RA_X], points[p1, P_RA_Y], points[p1, P_RB_X],
                                    points[p1, P_RB_Y])
    dv2x, dv2y = _relative_velocity(bodies, a, b, col, points[p2, P_RA_X], points[p2, P_RA_Y], points[p2, P_RB_X],
                                    points[p2, P_RB_Y])
    k11, k12, k22 = manifold[M_K11], manifold[M_K12], manifold[M_K22]
    a1, a2 = points[p1, impulse], points[p2, impulse]
    b1 = dv1x * nx + dv1y * ny - t1 - (k11 * a1 + k12 * a2)
    b2 = dv2x * nx + dv2y * ny - t2 - (k12 * a1 + k22 * a2)
    x1, x2 = solve_block(k11, k12, k22, b1, b2, a1, a2)
    d1, d2 = x1 - a1, x2 - a2
    points[p1, impulse], points[p2, impulse] = x1, x2
    _apply(bodies, a, b, col, d1 * nx, d1 * ny, points[p1, P_RA_X], points[p1, P_RA_Y], points[p1, P_RB_X],
           points[p1, P_RB_Y])
    _apply(bodies, a, b, col, d2 * nx, d2 * ny, points[p2, P_RA_X], points[p2, P_RA_Y], points[p2, P_RB_X],
           points[p2, P_RB_Y])


@leaf_kernel
def _normal_point(bodies: np.ndarray, a: int, b: int, col: int, nx: float, ny: float, points: np.ndarray, p: int,
                  impulse: int, target: float) -> None:
    """One point's normal impulse, accumulated and clamped at zero, driving the (pseudo-)velocity
    along the normal to `target`."""
    rax, ray, rbx, rby = points[p, P_RA_X], points[p, P_RA_Y], points[p, P_RB_X], points[p, P_RB_Y]
    dvx, dvy = _relative_velocity(bodies, a, b, col, rax, ray, rbx, rby)
    lam = -points[p, P_NORMAL_MASS] * (dvx * nx + dvy * ny - target)
    new = _max(points[p, impulse] + lam, 0.0)
    lam = new - points[p, impulse]
    points[p, impulse] = new
    _apply(bodies, a, b, col, lam * nx, lam * ny, rax, ray, rbx, rby)


@leaf_kernel
def _solve_velocities(bodies: np.ndarray, normals: np.ndarray, pair: np.ndarray, first: np.ndarray,
                      block: np.ndarray, points: np.ndarray, order: np.ndarray, s: int, e: int,
                      friction: bool) -> None:
    """One Gauss-Seidel sweep over the island's manifolds."""
    for t in range(s, e):
        k = order[t]
        a, b = pair[k, 0], pair[k, 1]
        nx, ny = normals[k, M_NX], normals[k, M_NY]
        tx, ty = ny, -nx
        if friction:
            for p in range(first[k], first[k + 1]):
                limit = points[p, P_FRICTION] * points[p, P_NORMAL_IMPULSE]
                if limit <= 0.0 and points[p, P_TANGENT_IMPULSE] == 0.0:
                    continue
                rax, ray, rbx, rby = points[p, P_RA_X], points[p, P_RA_Y], points[p, P_RB_X], points[p, P_RB_Y]
                dvx, dvy = _relative_velocity(bodies, a, b, B_VX, rax, ray, rbx, rby)
                lam = -points[p, P_TANGENT_MASS] * (dvx * tx + dvy * ty)
                new = _min(_max(points[p, P_TANGENT_IMPULSE] + lam, -limit), limit)
                lam = new - points[p, P_TANGENT_IMPULSE]
                points[p, P_TANGENT_IMPULSE] = new
                _apply(bodies, a, b, B_VX, lam * tx, lam * ty, rax, ray, rbx, rby)
        if block[k]:
            _normal_block(bodies, a, b, B_VX, nx, ny, normals[k], points, first[k], P_NORMAL_IMPULSE, 0.0, 0.0)
        else:
            for p in range(first[k], first[k + 1]):
                _normal_point(bodies, a, b, B_VX, nx, ny, points, p, P_NORMAL_IMPULSE, 0.0)


@leaf_kernel
def _solve_split(bodies: np.ndarray, normals: np.ndarray, pair: np.ndarray, first: np.ndarray, block: np.ndarray,
                 points: np.ndarray, sink: np.ndarray, order: np.ndarray, s: int, e: int, dt: float, beta: float,
                 slop: float, max_push: float) -> None:
    """One sweep of split impulses: pseudo-velocities that will remove `beta` of the overlap beyond
    `slop` this substep, and what turning will sink beyond it (`_turning_sinks`). They move
    positions only and are thrown away afterwards."""
    for t in range(s, e):
        k = order[t]
        a, b = pair[k, 0], pair[k, 1]
        nx, ny = normals[k, M_NX], normals[k, M_NY]
        if block[k]:
            p1, p2 = first[k], first[k] + 1
            t1 = _push_target(points[p1, P_SEP], sink[p1], dt, beta, slop, max_push)
            t2 = _push_target(points[p2, P_SEP], sink[p2], dt, beta, slop, max_push)
            if t1 == 0.0 and t2 == 0.0 and points[p1, P_PUSH_IMPULSE] == 0.0 and points[p2, P_PUSH_IMPULSE] == 0.0:
                continue
            _normal_block(bodies, a, b, B_PUSH_X, nx, ny, normals[k], points, p1, P_PUSH_IMPULSE, t1, t2)
            continue
        for p in range(first[k], first[k + 1]):
            target = _push_target(points[p, P_SEP], sink[p], dt, beta, slop, max_push)
            if target == 0.0 and points[p, P_PUSH_IMPULSE] == 0.0:
                continue
            _normal_point(bodies, a, b, B_PUSH_X, nx, ny, points, p, P_PUSH_IMPULSE, target)


@leaf_kernel
def _solve_ngs(bodies: np.ndarray, pair: np.ndarray, first: np.ndarray, points: np.ndarray, order: np.ndarray,
               s: int, e: int, beta: float, slop: float, max_correction: float) -> None:
    """One sweep of non-linear Gauss-Seidel (Box2D v2's position solver): re-measure each point's
    separation at the current poses and move the bodies directly."""
    for t in range(s, e):
        k = order[t]
        a, b = pair[k, 0], pair[k, 1]
        ma, mb = bodies[a, B_INV_MASS], bodies[b, B_INV_MASS]
        ia, ib = bodies[a, B_INV_INERTIA], bodies[b, B_INV_INERTIA]
        for p in range(first[k], first[k + 1]):
            ref_is_a = points[p, P_REF_IS_A] != 0.0
            ref, inc = (a, b) if ref_is_a else (b, a)
            cr, sr = math.cos(bodies[ref, B_ANGLE]), math.sin(bodies[ref, B_ANGLE])
            ci, si = math.cos(bodies[inc, B_ANGLE]), math.sin(bodies[inc, B_ANGLE])
            lnx, lny = points[p, P_LNX], points[p, P_LNY]
            nx, ny = cr * lnx - sr * lny, sr * lnx + cr * lny
            fx, fy = points[p, P_LFX], points[p, P_LFY]
            face_x, face_y = bodies[ref, B_X] + cr * fx - sr * fy, bodies[ref, B_Y] + sr * fx + cr * fy
            qx, qy = points[p, P_LQX], points[p, P_LQY]
            clip_x, clip_y = bodies[inc, B_X] + ci * qx - si * qy, bodies[inc, B_Y] + si * qx + ci * qy
            sep = (clip_x - face_x) * nx + (clip_y - face_y) * ny
            correction = _min(_max(beta * (sep + slop), -max_correction), 0.0)
            if correction == 0.0:
                continue
            if not ref_is_a:
                nx, ny = -nx, -ny  # normal from A to B
            rax, ray = clip_x - bodies[a, B_X], clip_y - bodies[a, B_Y]
            rbx, rby = clip_x - bodies[b, B_X], clip_y - bodies[b, B_Y]
            rna = rax * ny - ray * nx
            rnb = rbx * ny - rby * nx
            kn = ma + mb + ia * rna * rna + ib * rnb * rnb
            if kn <= 0.0:
                continue
            lam = -correction / kn
            px, py = lam * nx, lam * ny
            bodies[a, B_X] -= ma * px
            bodies[a, B_Y] -= ma * py
            bodies[a, B_ANGLE] -= ia * (rax * py - ray * px)
            bodies[b, B_X] += mb * px
            bodies[b, B_Y] += mb * py
            bodies[b, B_ANGLE] += ib * (rbx * py - rby * px)


@kernel
def solve_contacts(bodies: np.ndarray, normals: np.ndarray, pair: np.ndarray, first: np.ndarray, block: np.ndarray,
                   points: np.ndarray, keys: np.ndarray, warm: bool, iterations: int, position_iterations: int,
                   correction: int, dt: float, friction: bool, beta: float, slop: float, max_push: float,
                   max_condition: float) -> int:
    """One substep's contact solve over packed arrays, island by island: velocities, then position
    error removed without touching them. Returns how many islands threw their warm start away for a
    cold solve.

    Rows: `bodies` (B_ columns), `normals` (M_ columns) and `pair` (body rows of A and B) per
    manifold, manifold k's points are rows first[k]:first[k + 1] of `points` (P_ columns) and of
    `keys` (K_ columns: which point is clipped, `_turning_sinks`); `block` per manifold is written.
    Bodies, manifolds and points are updated in place."""
    order, start = _islands(bodies, pair)
    level = _levels(bodies, pair)
    n_bodies, n_manifolds = bodies.shape[0], pair.shape[0]
    seen = np.full(n_bodies, -1, dtype=np.int64)
    dynamic = np.empty(n_bodies, dtype=np.int64)
    saved = np.empty((n_bodies, 3))
    chain = np.empty(n_manifolds, dtype=np.int64)
    a_grounded = np.empty(n_manifolds, dtype=np.bool_)
    sink = np.zeros(len(points))
    cold_restarts = 0
    for i in range(len(start) - 1):
        s, e = start[i], start[i + 1]
        # The island's dynamic bodies, in the order they first come.
        n_dynamic = 0
        for t in range(s, e):
            for side in range(2):
                body = pair[order[t], side]
                if bodies[body, B_INV_MASS] > 0.0 and seen[body] != i:
                    seen[body] = i
                    dynamic[n_dynamic] = body
                    n_dynamic += 1
        _prepare(bodies, normals, pair, first, block, points, order, s, e, max_condition)
        if warm:
            before = _save_velocities(bodies, dynamic, n_dynamic, saved)
            _warm_start(bodies, normals, pair, first, points, order, s, e)
            for _ in range(iterations):
                _solve_velocities(bodies, normals, pair, first, block, points, order, s, e, friction)
            if _island_energy(bodies, dynamic, n_dynamic) > before * (1.0 + 1e-12):
                # A contact solve without restitution can only take energy away; a cold Gauss-Seidel
                # sweep never adds any, but last substep's impulses re-applied to contacts that are
                # now opening can. Fall back to the cold solve.
                cold_restarts += 1
                _restore_velocities(bodies, dynamic, n_dynamic, saved)
                for t in range(s, e):
                    for p in range(first[order[t]], first[order[t] + 1]):
                        points[p, P_NORMAL_IMPULSE] = points[p, P_TANGENT_IMPULSE] = 0.0
                for _ in range(iterations):
                    _solve_velocities(bodies, normals, pair, first, block, points, order, s, e, friction)
        else:
            for _ in range(iterations):
                _solve_velocities(bodies, normals, pair, first, block, points, order, s, e, friction)

        n_chain = _shock_chain(bodies, pair, level, order, s, e, chain, a_grounded)
        if n_chain:
            # Taking the nearer body as immovable stops the farther one from closing on it however the
            # nearer one moves: one driven from its support, fast, would drive the farther one with it
            # (QA: a light body pinched between a heavy one and a wall gave it energy, +40 % in a
            # substep). The pass is kept only if it took no energy in.
            before = _save_velocities(bodies, dynamic, n_dynamic, saved)
            _propagate_shock(bodies, normals, pair, first, points, sink, chain, a_grounded, n_chain, False, 0.0, 0.0,
                             0.0, 0.0)
            if _island_energy(bodies, dynamic, n_dynamic) > before * (1.0 + 1e-12):
                _restore_velocities(bodies, dynamic, n_dynamic, saved)
        if correction == SPLIT:
            _turning_sinks(bodies, normals, pair, first, points, keys, order, s, e, dt, sink)
            for _ in range(position_iterations):
                _solve_split(bodies, normals, pair, first, block, points, sink, order, s, e, dt, beta, slop, max_push)
            if n_chain:
                _propagate_shock(bodies, normals, pair, first, points, sink, chain, a_grounded, n_chain, dt > 0.0, dt,
                                 beta, slop, max_push)
            for j in range(n_dynamic):  # move by the pseudo-velocity for dt, then forget it
                body = dynamic[j]
                bodies[body, B_X] += bodies[body, B_PUSH_X] * dt
                bodies[body, B_Y] += bodies[body, B_PUSH_Y] * dt
                bodies[body, B_ANGLE] += bodies[body, B_PUSH_SPIN] * dt
                bodies[body, B_PUSH_X] = bodies[body, B_PUSH_Y] = bodies[body, B_PUSH_SPIN] = 0.0
        elif correction == NGS:
            for _ in range(position_iterations):
                _solve_ngs(bodies, pair, first, points, order, s, e, beta, slop, max_push)
    return cold_restarts


# --- the adapters ---------------------------------------------------------------------------------

def solve(table: ContactTable, knobs: Knobs, dt: float, friction: bool) -> int:
    """One substep's contact solve (`solve_contacts` on the table, in place: its points' impulses,
    lever arms, masses and approach speeds, its manifolds' block data; the bodies' pose, velocity
    and pseudo-velocity). Returns how many islands threw their warm start away for a cold solve."""
    if not len(table):
        return 0
    return solve_table(table.store.state, table.static._row, table.arrays, *solve_knobs(knobs), float(dt),
                       bool(friction))


def solve_knobs(knobs: Knobs) -> tuple[bool, int, int, int]:
    """The knobs `solve_table` follows: warm start, iterations, position iterations, correction."""
    return (bool(knobs.warm_start), int(knobs.iterations), int(knobs.position_iterations),
            _CORRECTIONS[knobs.position_correction])


@counted_kernel
def solve_table(state: np.ndarray, static: np.ndarray, table: tuple, warm: bool, iterations: int,
                position_iterations: int, correction: int, dt: float, friction: bool) -> int:
    """`solve_contacts` on a table's columns (`ContactTable.arrays`), the rows of a store's `state`
    and the static world's row (a table's body rows: the static world is the row after the
    store's). Only the rows the table names are copied in, in the order they first come (a fan of a
    thousand shots has a few touching a wall), and their pose, velocity and pseudo-velocity
    written back; the solve reads no body by its number, so this is the solve of every row."""
    _, pair, normals, block, first, points, keys = table
    n = state.shape[0]
    slot = np.full(n + 1, -1, dtype=np.int64)  # each named row's row in `bodies`
    named = np.empty(2 * len(pair), dtype=np.int64)
    local = np.empty_like(pair)
    count = 0
    for k in range(len(pair)):
        for side in range(2):
            row = pair[k, side]
            if slot[row] < 0:
                slot[row] = count
                named[count] = row
                count += 1
            local[k, side] = slot[row]
    bodies = np.empty((count, body.SOLVER_COLUMNS))
    for j in range(count):
        source = state[named[j]] if named[j] < n else static
        for c in range(body.SOLVER_COLUMNS):
            bodies[j, c] = source[c]
        if named[j] < n:
            state[named[j], B_ENERGY0] = _kinetic_energy(state, named[j])  # (what restitution may not exceed)
    cold_restarts = solve_contacts(bodies, normals, local, first, block, points, keys, warm, iterations,
                                   position_iterations, correction, dt, friction, POSITION_BETA, LINEAR_SLOP,
                                   MAX_CORRECTION, BLOCK_MAX_CONDITION)
    for j in range(count):
        row = state[named[j]] if named[j] < n else static
        for c in range(body.X, body.SPIN + 1):
            row[c] = bodies[j, c]
        for c in range(body.PUSH_X, body.PUSH_SPIN + 1):
            row[c] = bodies[j, c]
    return cold_restarts


@leaf_kernel
def restitute(state: np.ndarray, static: np.ndarray, table: tuple, threshold: float) -> int:
    """`apply_restitution` on a table's columns (`ContactTable.arrays`) and its bodies' rows, in place.
    (A leaf: on most substeps no point bounces, and that is asked without counting a reference to
    each of the table's arrays; `_scaled_bounces` does the rest.)"""
    _, pair, normals, _, first, points, _ = table
    if not _any_bounce(points, 0, first[pair.shape[0]], threshold):
        return 0
    return _scaled_bounces(state, static, pair, normals, first, points, threshold)


@leaf_kernel
def _bounce(state: np.ndarray, static: np.ndarray, pair: np.ndarray, normals: np.ndarray, first: np.ndarray,
            points: np.ndarray, threshold: float, scale: np.ndarray) -> int:
    """Every bouncing point's bounce, scaled by its body's `scale` (the static world's row is the one
    after `state`'s); returns how many bounced. (A leaf: the two body rows it takes a manifold cost
    nothing.)"""
    n = state.shape[0]
    bounced = 0
    for k in range(pair.shape[0]):
        nx, ny = normals[k, M_NX], normals[k, M_NY]
        a = static if pair[k, 0] == n else state[pair[k, 0]]
        b = static if pair[k, 1] == n else state[pair[k, 1]]
        s = scale[pair[k, 0]] if pair[k, 0] < n else scale[pair[k, 1]]
        for p in range(first[k], first[k + 1]):
            if not _bounces(points, p, threshold):
                continue
            e = points[p, P_RESTITUTION] * s
            jn, jt = e * points[p, P_NORMAL_IMPULSE], e * points[p, P_TANGENT_IMPULSE]
            px, py = jn * nx + jt * ny, jn * ny - jt * nx
            a[B_VX] -= a[B_INV_MASS] * px
            a[B_VY] -= a[B_INV_MASS] * py
            a[B_SPIN] -= a[B_INV_INERTIA] * (points[p, P_RA_X] * py - points[p, P_RA_Y] * px)
            b[B_VX] += b[B_INV_MASS] * px
            b[B_VY] += b[B_INV_MASS] * py
            b[B_SPIN] += b[B_INV_INERTIA] * (points[p, P_RB_X] * py - points[p, P_RB_Y] * px)
            # The impact is over: nothing of it should be warm-started into the next substep.
            points[p, P_NORMAL_IMPULSE] = points[p, P_TANGENT_IMPULSE] = 0.0
            bounced += 1
    return bounced


@leaf_kernel
def _bounces(points: np.ndarray, p: int, threshold: float) -> bool:
    """Whether point p bounces: it was approaching faster than `threshold` and took an impulse."""
    return points[p, P_APPROACH] < -threshold and points[p, P_NORMAL_IMPULSE] > 0.0 and points[p, P_RESTITUTION] > 0.0


@counted_kernel
def _scaled_bounces(state: np.ndarray, static: np.ndarray, pair: np.ndarray, normals: np.ndarray,
                    first: np.ndarray, points: np.ndarray, threshold: float) -> int:
    """The bounces (`_bounce`) of a table some point of which bounces, each body's scaled. Poisson's
    bounce gives every point e times its compression impulse again, point by point; where points push against each
    other (a body pinched in a notch or a groove) their large, nearly cancelling impulses given
    again can leave the bodies with more kinetic energy than before the impact. So in each island
    (bodies joined by this substep's contacts, which only pass energy between them or take it away)
    with a bounce, the bounces are scaled back, as little as they must be, until the island has no
    more kinetic energy than before the substep's contact solve (`B_ENERGY0`): the energy after is
    quadratic in the scale. An island with a kinematic body (a windmill, which may well add energy)
    is left as it is. Unscaled, a bounce is the same floats as before this cap."""
    n = state.shape[0]
    group = np.arange(n)  # union-find over the body rows (the static world, row n, joins nothing)
    for k in range(pair.shape[0]):
        a, b = pair[k, 0], pair[k, 1]
        if a < n and b < n:
            ra, rb = _root(group, a), _root(group, b)
            group[max(ra, rb)] = min(ra, rb)
    bouncing = np.zeros(n, dtype=np.bool_)  # by island root
    change = np.zeros((n, 3))  # each body's velocity change by its bounces
    for k in range(pair.shape[0]):
        nx, ny = normals[k, M_NX], normals[k, M_NY]
        a, b = pair[k, 0], pair[k, 1]
        for p in range(first[k], first[k + 1]):
            if not _bounces(points, p, threshold):
                continue
            bouncing[_root(group, a if a < n else b)] = True
            e = points[p, P_RESTITUTION]
            jn, jt = e * points[p, P_NORMAL_IMPULSE], e * points[p, P_TANGENT_IMPULSE]
            px, py = jn * nx + jt * ny, jn * ny - jt * nx
            if a < n:
                change[a, 0] -= state[a, B_INV_MASS] * px
                change[a, 1] -= state[a, B_INV_MASS] * py
                change[a, 2] -= state[a, B_INV_INERTIA] * (points[p, P_RA_X] * py - points[p, P_RA_Y] * px)
            if b < n:
                change[b, 0] += state[b, B_INV_MASS] * px
                change[b, 1] += state[b, B_INV_MASS] * py
                change[b, 2] += state[b, B_INV_INERTIA] * (points[p, P_RB_X] * py - points[p, P_RB_Y] * px)
    # Per island: energy(s) = quad s^2 + lin s + now; it may not end above `before`.
    quad, lin, now, before = np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n)
    driven = np.zeros(n, dtype=np.bool_)
    touched = np.zeros(n, dtype=np.bool_)
    for k in range(pair.shape[0]):
        for side in range(2):
            j = pair[k, side]
            if j >= n or touched[j]:
                continue
            touched[j] = True
            root = _root(group, j)
            if not bouncing[root]:
                continue
            if state[j, B_INV_MASS] == 0.0:
                driven[root] = True  # a kinematic body
                continue
            m, inertia = state[j, B_MASS], state[j, B_INERTIA] if state[j, B_INV_INERTIA] > 0.0 else 0.0
            vx, vy, w = state[j, B_VX], state[j, B_VY], state[j, B_SPIN]
            dx, dy, dw = change[j, 0], change[j, 1], change[j, 2]
            quad[root] += 0.5 * (m * (dx * dx + dy * dy) + inertia * dw * dw)
            lin[root] += m * (vx * dx + vy * dy) + inertia * w * dw
            now[root] += 0.5 * (m * (vx * vx + vy * vy) + inertia * w * w)
            before[root] += state[j, B_ENERGY0]
    scale = np.ones(n)
    for j in range(n):
        if not touched[j]:
            continue
        root = _root(group, j)
        if not bouncing[root] or driven[root] or \
                quad[root] + lin[root] + now[root] <= before[root] * (1.0 + 1e-9) + 1e-12:
            continue
        # The largest s in [0, 1] with quad s^2 + lin s + now <= before (0 if even none is).
        room = lin[root] * lin[root] - 4.0 * quad[root] * (now[root] - before[root])
        s = (-lin[root] + math.sqrt(room)) / (2.0 * quad[root]) if room >= 0.0 and quad[root] > 0.0 else 0.0
        scale[j] = min(1.0, max(0.0, s))
    return _bounce(state, static, pair, normals, first, points, threshold, scale)


@leaf_kernel
def _any_bounce(points: np.ndarray, start: int, stop: int, threshold: float) -> bool:
    for p in range(start, stop):
        if _bounces(points, p, threshold):
            return True
    return False


def apply_restitution(table: ContactTable, threshold: float) -> int:
    """Poisson restitution: every point that was approaching faster than `threshold` gets e times
    its compression impulse again. Returns how many points bounced. Runs after `solve`, on the
    bodies' rows themselves (a point resting is passed over in the kernel)."""
    return restitute(table.store.state, table.static._row, table.arrays, threshold)


@warm_up("contact solver")
def _warm() -> None:
    ground = Body(x=0.0, y=0.0)
    box = Body.dynamic(0.0, 0.5, 1.0, 1.0 / 6.0, vy=-1.0)
    top = Body.dynamic(0.0, 1.5, 1.0, 1.0 / 6.0, vy=-1.0)
    store = BodyStore()
    store.gather([(1, box), (2, top)])

    def point(x: float, y: float, separation: float, key: int) -> ContactPoint:
        return ContactPoint(x=x, y=y, separation=separation, key=(key,), restitution=0.5, friction=0.5,
                            local_normal=(0.0, 1.0), local_face=(x, 0.0), local_clip=(x, -0.5))

    for correction in ("split", "ngs"):
        manifolds = [Manifold(1, -1, box, ground, 0.0, -1.0, [point(-0.5, 0.0, -0.01, 0), point(0.5, 0.0, -0.01, 1)]),
                     Manifold(1, 2, box, top, 0.0, 1.0, [point(0.0, 1.0, -0.01, 2)])]
        table = table_of(manifolds, store, ground)
        solve(table, Knobs(position_correction=correction), 1.0 / 240.0, True)
        apply_restitution(table, 0.05)
    solve_block(2.0, 1.0, 2.0, -1.0, -1.0, 0.0, 0.0)
