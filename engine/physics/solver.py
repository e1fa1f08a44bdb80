"""Sequential impulses on contact manifolds (Catto, GDC 2006; box2d-lite and Box2D v2.4).

Per substep:
1. `prepare`: lever arms, effective masses, and the approach speed of every point *before* solving.
2. `warm_start`: re-apply last substep's impulses of persisting points.
3. `solve_velocities`, repeated: Coulomb friction clamped to the current normal impulse, then the
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
"""

from __future__ import annotations

import math

from polygolf.engine.physics.contact import Manifold
from polygolf.engine.physics.presets import Knobs
from polygolf.engine.physics.settings import BLOCK_MAX_CONDITION, LINEAR_SLOP, MAX_CORRECTION, POSITION_BETA


def islands(manifolds: list[Manifold]) -> list[list[Manifold]]:
    """The manifolds in groups that share no dynamic body (union-find), each in its original order.
    Groups do not interact, so each is solved on its own: a decision about one (the cold restart
    below) never touches another, and a body solves the same alone as beside others it never meets."""
    parent: dict[int, int] = {}

    def root(key: int) -> int:
        while parent.setdefault(key, key) != key:
            parent[key] = parent[parent[key]]
            key = parent[key]
        return key

    for m in manifolds:
        dynamic = [id(b) for b in (m.body_a, m.body_b) if b.inv_mass > 0.0]
        for other in dynamic[1:]:
            parent[root(other)] = root(dynamic[0])
    groups: dict[int, list[Manifold]] = {}
    for m in manifolds:
        anchor = next((id(b) for b in (m.body_a, m.body_b) if b.inv_mass > 0.0), id(m))
        groups.setdefault(root(anchor), []).append(m)
    return list(groups.values())


def solve(manifolds: list[Manifold], knobs: Knobs, dt: float, friction: bool) -> int:
    """One substep's contact solve, island by island. Returns how many islands threw their warm
    start away for a cold solve (see `solve_island`)."""
    groups = islands(manifolds)
    if len(groups) == 1:
        return int(solve_island(manifolds, knobs, dt, friction))
    return sum(solve_island(group, knobs, dt, friction) for group in groups)


def solve_island(manifolds: list[Manifold], knobs: Knobs, dt: float, friction: bool) -> bool:
    """Velocities, then position error removed without touching them. Returns True if the warm start
    was thrown away for a cold solve (see below)."""
    prepare(manifolds)
    cold_restart = False
    if knobs.warm_start:
        bodies = {id(b): b for m in manifolds for b in (m.body_a, m.body_b) if b.inv_mass > 0.0}.values()
        saved = [(b, b.vx, b.vy, b.spin) for b in bodies]
        before = sum(b.kinetic_energy() for b in bodies)
        warm_start(manifolds)
        _iterate(manifolds, knobs.iterations, friction)
        if sum(b.kinetic_energy() for b in bodies) > before * (1.0 + 1e-12):
            # A contact solve without restitution can only take energy away; a cold Gauss-Seidel
            # sweep never adds any, but last substep's impulses re-applied to contacts that are
            # now opening can. Fall back to the cold solve.
            cold_restart = True
            for b, vx, vy, spin in saved:
                b.vx, b.vy, b.spin = vx, vy, spin
            for m in manifolds:
                for p in m.points:
                    p.normal_impulse = p.tangent_impulse = 0.0
            _iterate(manifolds, knobs.iterations, friction)
    else:
        _iterate(manifolds, knobs.iterations, friction)

    chain = shock_chain(manifolds)
    if chain:
        propagate_shock(chain)
    if knobs.position_correction == "split":
        for _ in range(knobs.position_iterations):
            solve_split(manifolds, dt, POSITION_BETA, LINEAR_SLOP, MAX_CORRECTION)
        if chain:
            propagate_shock(chain, dt, POSITION_BETA, LINEAR_SLOP, MAX_CORRECTION)
        apply_pushes(manifolds, dt)
    elif knobs.position_correction == "ngs":
        for _ in range(knobs.position_iterations):
            solve_ngs(manifolds, POSITION_BETA, LINEAR_SLOP, MAX_CORRECTION)
    return cold_restart


def shock_chain(manifolds: list[Manifold]) -> list[tuple[Manifold, bool]]:
    """Touching contacts between bodies at different distances from the ground (a wall or a
    windmill, at 0), nearest the ground first, each with whether its A is the body nearer the ground.
    Distance is counted in contacts: 1 = touches the ground. Empty unless some dynamic body
    touches another and, through it, the ground (a free pile, or a ball alone on a wall, needs none)."""
    level: dict[int, int] = {}
    links: dict[int, list[Manifold]] = {}
    for m in manifolds:  # every manifold the narrowphase kept is solved as touching
        a, b = m.body_a, m.body_b
        if a.inv_mass == 0.0 and b.inv_mass > 0.0:
            level[id(b)] = 1
        elif b.inv_mass == 0.0 and a.inv_mass > 0.0:
            level[id(a)] = 1
        elif a.inv_mass > 0.0 and b.inv_mass > 0.0:
            links.setdefault(id(a), []).append(m)
            links.setdefault(id(b), []).append(m)
    if not links or not level:
        return []  # no body between another and the ground: nothing to propagate
    frontier = list(level)
    while frontier:
        nearer = []
        for key in frontier:
            for m in links.get(key, ()):
                other = id(m.body_b) if id(m.body_a) == key else id(m.body_a)
                if other not in level:
                    level[other] = level[key] + 1
                    nearer.append(other)
        frontier = nearer
    def depth(body) -> int | None:
        return 0 if body.inv_mass == 0.0 else level.get(id(body))

    chain = []
    for k, m in enumerate(manifolds):
        da, db = depth(m.body_a), depth(m.body_b)
        if da is not None and db is not None and da != db:
            chain.append((min(da, db), k, m, da < db))
    return [(m, a_nearer) for _, _, m, a_nearer in sorted(chain, key=lambda c: c[:2])]


def propagate_shock(chain: list[tuple[Manifold, bool]], dt: float = 0.0, beta: float = 0.0, slop: float = 0.0,
                    max_push: float = 0.0) -> None:
    """Shock propagation (Guendelman, Bridson and Fedkiw 2003), after the Gauss-Seidel sweeps: from
    the ground outwards, each body nearer the ground is taken as immovable and the farther one alone
    is stopped from closing on it. Sequential impulses converge slowly when a heavy body presses a
    light one against a wall (the light one is squeezed into the wall); this pass lets the wall's
    resistance reach the heavy body through the light one. It only ever stops an approach, so a
    converged solve is left as it is.

    With `dt` it acts on the split-impulse pseudo-velocities instead (the overlap's push targets),
    so an overlap already made is pushed out on the far body's side."""
    pushes = dt > 0.0
    for m, a_is_grounded in chain:
        free = m.body_b if a_is_grounded else m.body_a
        sign = 1.0 if a_is_grounded else -1.0  # an impulse along n pushes B away from A
        nx, ny = m.nx, m.ny
        for p in m.points:
            if pushes:
                vn = _push_velocity(m, p.ra_x, p.ra_y, p.rb_x, p.rb_y)
                target = min(beta * max(-(p.separation + slop), 0.0), max_push) / dt
            else:
                dvx, dvy = _relative_velocity(m, p.ra_x, p.ra_y, p.rb_x, p.rb_y)
                vn, target = dvx * nx + dvy * ny, 0.0
            if vn >= target:
                continue
            rx, ry = (p.rb_x, p.rb_y) if a_is_grounded else (p.ra_x, p.ra_y)
            rn = rx * ny - ry * nx
            k = free.inv_mass + free.inv_inertia * rn * rn
            lam = sign * (target - vn) / k
            px, py = lam * nx, lam * ny
            if pushes:
                s = free.scratch
                s.push_x += free.inv_mass * px
                s.push_y += free.inv_mass * py
                s.push_spin += free.inv_inertia * (rx * py - ry * px)
            else:
                free.vx += free.inv_mass * px
                free.vy += free.inv_mass * py
                free.spin += free.inv_inertia * (rx * py - ry * px)


def _iterate(manifolds: list[Manifold], iterations: int, friction: bool) -> None:
    for _ in range(iterations):
        solve_velocities(manifolds, friction)


def prepare(manifolds: list[Manifold]) -> None:
    for m in manifolds:
        a, b = m.body_a, m.body_b
        nx, ny = m.nx, m.ny
        ma, mb, ia, ib = a.inv_mass, b.inv_mass, a.inv_inertia, b.inv_inertia
        for p in m.points:
            rax, ray = p.x - a.x, p.y - a.y
            rbx, rby = p.x - b.x, p.y - b.y
            p.ra_x, p.ra_y, p.rb_x, p.rb_y = rax, ray, rbx, rby
            rna = rax * ny - ray * nx
            rnb = rbx * ny - rby * nx
            k = ma + mb + ia * rna * rna + ib * rnb * rnb
            p.normal_mass = 1.0 / k if k > 0.0 else 0.0
            # Tangent t = (ny, -nx); r x t = -(r . n).
            rta = -(rax * nx + ray * ny)
            rtb = -(rbx * nx + rby * ny)
            k = ma + mb + ia * rta * rta + ib * rtb * rtb
            p.tangent_mass = 1.0 / k if k > 0.0 else 0.0
            dvx = b.vx - b.spin * rby - a.vx + a.spin * ray
            dvy = b.vy + b.spin * rbx - a.vy - a.spin * rax
            p.approach_speed = dvx * nx + dvy * ny
        m.block = False
        if len(m.points) == 2:
            p1, p2 = m.points
            rn1a = p1.ra_x * ny - p1.ra_y * nx
            rn1b = p1.rb_x * ny - p1.rb_y * nx
            rn2a = p2.ra_x * ny - p2.ra_y * nx
            rn2b = p2.rb_x * ny - p2.rb_y * nx
            m.k11 = ma + mb + ia * rn1a * rn1a + ib * rn1b * rn1b
            m.k22 = ma + mb + ia * rn2a * rn2a + ib * rn2b * rn2b
            m.k12 = ma + mb + ia * rn1a * rn2a + ib * rn1b * rn2b
            det = m.k11 * m.k22 - m.k12 * m.k12
            m.block = m.k11 * m.k11 < BLOCK_MAX_CONDITION * det


def _apply(m: Manifold, px: float, py: float, rax: float, ray: float, rbx: float, rby: float) -> None:
    """Apply impulse P at a point: -P to A, +P to B."""
    a, b = m.body_a, m.body_b
    a.vx -= a.inv_mass * px
    a.vy -= a.inv_mass * py
    a.spin -= a.inv_inertia * (rax * py - ray * px)
    b.vx += b.inv_mass * px
    b.vy += b.inv_mass * py
    b.spin += b.inv_inertia * (rbx * py - rby * px)


def warm_start(manifolds: list[Manifold]) -> None:
    for m in manifolds:
        nx, ny = m.nx, m.ny
        for p in m.points:
            if p.normal_impulse or p.tangent_impulse:
                px = p.normal_impulse * nx + p.tangent_impulse * ny
                py = p.normal_impulse * ny - p.tangent_impulse * nx
                _apply(m, px, py, p.ra_x, p.ra_y, p.rb_x, p.rb_y)


def _relative_velocity(m: Manifold, rax: float, ray: float, rbx: float, rby: float) -> tuple[float, float]:
    a, b = m.body_a, m.body_b
    return (b.vx - b.spin * rby - a.vx + a.spin * ray,
            b.vy + b.spin * rbx - a.vy - a.spin * rax)


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


def solve_velocities(manifolds: list[Manifold], friction: bool) -> None:
    """One Gauss-Seidel sweep over every manifold."""
    for m in manifolds:
        nx, ny = m.nx, m.ny
        tx, ty = ny, -nx
        points = m.points
        if friction:
            for p in points:
                limit = p.friction * p.normal_impulse
                if limit <= 0.0 and p.tangent_impulse == 0.0:
                    continue
                dvx, dvy = _relative_velocity(m, p.ra_x, p.ra_y, p.rb_x, p.rb_y)
                lam = -p.tangent_mass * (dvx * tx + dvy * ty)
                new = min(max(p.tangent_impulse + lam, -limit), limit)
                lam = new - p.tangent_impulse
                p.tangent_impulse = new
                _apply(m, lam * tx, lam * ty, p.ra_x, p.ra_y, p.rb_x, p.rb_y)
        if m.block:
            p1, p2 = points
            dv1x, dv1y = _relative_velocity(m, p1.ra_x, p1.ra_y, p1.rb_x, p1.rb_y)
            dv2x, dv2y = _relative_velocity(m, p2.ra_x, p2.ra_y, p2.rb_x, p2.rb_y)
            a1, a2 = p1.normal_impulse, p2.normal_impulse
            b1 = dv1x * nx + dv1y * ny - (m.k11 * a1 + m.k12 * a2)
            b2 = dv2x * nx + dv2y * ny - (m.k12 * a1 + m.k22 * a2)
            x1, x2 = solve_block(m.k11, m.k12, m.k22, b1, b2, a1, a2)
            d1, d2 = x1 - a1, x2 - a2
            p1.normal_impulse, p2.normal_impulse = x1, x2
            _apply(m, d1 * nx, d1 * ny, p1.ra_x, p1.ra_y, p1.rb_x, p1.rb_y)
            _apply(m, d2 * nx, d2 * ny, p2.ra_x, p2.ra_y, p2.rb_x, p2.rb_y)
        else:
            for p in points:
                dvx, dvy = _relative_velocity(m, p.ra_x, p.ra_y, p.rb_x, p.rb_y)
                lam = -p.normal_mass * (dvx * nx + dvy * ny)
                new = max(p.normal_impulse + lam, 0.0)
                lam = new - p.normal_impulse
                p.normal_impulse = new
                _apply(m, lam * nx, lam * ny, p.ra_x, p.ra_y, p.rb_x, p.rb_y)


def apply_restitution(manifolds: list[Manifold], threshold: float) -> int:
    """Poisson restitution: every point that was approaching faster than `threshold` gets e times
    its compression impulse again. Returns how many points bounced."""
    bounced = 0
    for m in manifolds:
        nx, ny = m.nx, m.ny
        for p in m.points:
            if p.approach_speed >= -threshold or p.normal_impulse <= 0.0 or p.restitution <= 0.0:
                continue
            e = p.restitution
            jn, jt = e * p.normal_impulse, e * p.tangent_impulse
            _apply(m, jn * nx + jt * ny, jn * ny - jt * nx, p.ra_x, p.ra_y, p.rb_x, p.rb_y)
            # The impact is over: nothing of it should be warm-started into the next substep.
            p.normal_impulse = p.tangent_impulse = 0.0
            bounced += 1
    return bounced


# --- position correction -------------------------------------------------------------------------

def _push_velocity(m: Manifold, rax: float, ray: float, rbx: float, rby: float) -> float:
    a, b = m.body_a.scratch, m.body_b.scratch
    dvx = b.push_x - b.push_spin * rby - a.push_x + a.push_spin * ray
    dvy = b.push_y + b.push_spin * rbx - a.push_y - a.push_spin * rax
    return dvx * m.nx + dvy * m.ny


def _apply_push(m: Manifold, px: float, py: float, rax: float, ray: float, rbx: float, rby: float) -> None:
    a, b = m.body_a, m.body_b
    sa, sb = a.scratch, b.scratch
    sa.push_x -= a.inv_mass * px
    sa.push_y -= a.inv_mass * py
    sa.push_spin -= a.inv_inertia * (rax * py - ray * px)
    sb.push_x += b.inv_mass * px
    sb.push_y += b.inv_mass * py
    sb.push_spin += b.inv_inertia * (rbx * py - rby * px)


def solve_split(manifolds: list[Manifold], dt: float, beta: float, slop: float, max_push: float) -> None:
    """One sweep of split impulses: pseudo-velocities that will remove `beta` of the overlap beyond
    `slop` this substep. They move positions only and are thrown away afterwards."""
    for m in manifolds:
        nx, ny = m.nx, m.ny
        points = m.points
        if m.block:
            p1, p2 = points
            t1 = min(beta * max(-(p1.separation + slop), 0.0), max_push) / dt
            t2 = min(beta * max(-(p2.separation + slop), 0.0), max_push) / dt
            if t1 == 0.0 and t2 == 0.0 and p1.push_impulse == 0.0 and p2.push_impulse == 0.0:
                continue
            a1, a2 = p1.push_impulse, p2.push_impulse
            b1 = _push_velocity(m, p1.ra_x, p1.ra_y, p1.rb_x, p1.rb_y) - t1 - (m.k11 * a1 + m.k12 * a2)
            b2 = _push_velocity(m, p2.ra_x, p2.ra_y, p2.rb_x, p2.rb_y) - t2 - (m.k12 * a1 + m.k22 * a2)
            x1, x2 = solve_block(m.k11, m.k12, m.k22, b1, b2, a1, a2)
            d1, d2 = x1 - a1, x2 - a2
            p1.push_impulse, p2.push_impulse = x1, x2
            _apply_push(m, d1 * nx, d1 * ny, p1.ra_x, p1.ra_y, p1.rb_x, p1.rb_y)
            _apply_push(m, d2 * nx, d2 * ny, p2.ra_x, p2.ra_y, p2.rb_x, p2.rb_y)
            continue
        for p in points:
            target = min(beta * max(-(p.separation + slop), 0.0), max_push) / dt
            if target == 0.0 and p.push_impulse == 0.0:
                continue
            vn = _push_velocity(m, p.ra_x, p.ra_y, p.rb_x, p.rb_y)
            lam = -p.normal_mass * (vn - target)
            new = max(p.push_impulse + lam, 0.0)
            lam = new - p.push_impulse
            p.push_impulse = new
            _apply_push(m, lam * nx, lam * ny, p.ra_x, p.ra_y, p.rb_x, p.rb_y)


def apply_pushes(manifolds: list[Manifold], dt: float) -> None:
    """Move every body by its split-impulse pseudo-velocity for dt, then forget it."""
    moved = set()
    for m in manifolds:
        for body in (m.body_a, m.body_b):
            if body.inv_mass > 0.0 and id(body) not in moved:
                moved.add(id(body))
                s = body.scratch
                body.x += s.push_x * dt
                body.y += s.push_y * dt
                body.angle += s.push_spin * dt
                s.push_x = s.push_y = s.push_spin = 0.0


def solve_ngs(manifolds: list[Manifold], beta: float, slop: float, max_correction: float) -> float:
    """One sweep of non-linear Gauss-Seidel (Box2D v2's position solver): re-measure each point's
    separation at the current poses and move the bodies directly. Returns the worst separation seen."""
    worst = 0.0
    for m in manifolds:
        a, b = m.body_a, m.body_b
        ma, mb, ia, ib = a.inv_mass, b.inv_mass, a.inv_inertia, b.inv_inertia
        for p in m.points:
            ref, inc = (a, b) if p.ref_is_a else (b, a)
            cr, sr = math.cos(ref.angle), math.sin(ref.angle)
            ci, si = math.cos(inc.angle), math.sin(inc.angle)
            lnx, lny = p.local_normal
            nx, ny = cr * lnx - sr * lny, sr * lnx + cr * lny
            fx, fy = p.local_face
            face_x, face_y = ref.x + cr * fx - sr * fy, ref.y + sr * fx + cr * fy
            qx, qy = p.local_clip
            clip_x, clip_y = inc.x + ci * qx - si * qy, inc.y + si * qx + ci * qy
            sep = (clip_x - face_x) * nx + (clip_y - face_y) * ny
            worst = min(worst, sep)
            correction = min(max(beta * (sep + slop), -max_correction), 0.0)
            if correction == 0.0:
                continue
            if not p.ref_is_a:
                nx, ny = -nx, -ny  # normal from A to B
            rax, ray = clip_x - a.x, clip_y - a.y
            rbx, rby = clip_x - b.x, clip_y - b.y
            rna = rax * ny - ray * nx
            rnb = rbx * ny - rby * nx
            k = ma + mb + ia * rna * rna + ib * rnb * rnb
            if k <= 0.0:
                continue
            lam = -correction / k
            px, py = lam * nx, lam * ny
            a.x -= ma * px
            a.y -= ma * py
            a.angle -= ia * (rax * py - ray * px)
            b.x += mb * px
            b.y += mb * py
            b.angle += ib * (rbx * py - rby * px)
    return worst
