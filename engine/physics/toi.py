"""Time of impact of a moving convex piece against a static convex polygon (or another moving piece),
by conservative advancement.

Mirtich's conservative advancement: at time t the separating-axis distance d is a lower bound on the
true distance, and no point of the piece can close it faster than a bound mu, so the piece may safely
advance by (d - target)/mu. Each axis gets its own bound, the pieces' relative speed along it plus
what turning adds, max(0, -n.v) + |w|·R: a fixed axis (a wall's face) once, an axis that turns with
its piece as it points at each step (held fixed from then on, it still separates the two pieces'
projections, so it still bounds the distance from below). A head-on approach converges in one or two
steps, and pieces that pass each other or part are let go at once. The piece moves linearly in
position and angle over the substep, which is exactly what the integrator did.

Pieces are row ranges of `geometry.ConvexSet` arrays: a body's in its own frame (turned about its
origin), a wall's in world coordinates. A kernel returns the fraction of the motion, or NO_HIT.
"""

from __future__ import annotations

import math

import numpy as np

from polygolf.engine.physics.body import ANGLE, ANGLE0, ASLEEP, COLUMNS, INV_MASS, SPIN, VX, VY, X0, Y0, X, Y
from polygolf.engine.physics.geometry import ConvexSet, ShapeTable, face_line, norm, pose_piece, span_on_line
from polygolf.engine.physics.grid import BoxGrid, FatBoxes, look_up_walls, walls_near
from polygolf.engine.physics.jit import inlined_kernel, inlined_leaf, kernel, leaf_kernel, warm_up
from polygolf.engine.physics.seams import PROBE, REFLEX
from polygolf.engine.physics.settings import GAP_TOLERANCE

MAX_ITERATIONS = 24
NO_HIT = 2.0  # any fraction >= 1: the motion ends before an impact
_CLEARANCE = 1e-6  # m: beyond rounding, for the bounding circle's quick answer


@inlined_leaf
def _face_separations(verts: np.ndarray, normals: np.ndarray, others: np.ndarray, count: int, other_count: int,
                      seps: np.ndarray, at: int) -> None:
    """Separation of the first `other_count` rows of `others` from each of the first `count` faces,
    into seps[at:]."""
    for i in range(count):
        nx, ny = normals[i, 0], normals[i, 1]
        vx, vy = verts[i, 0], verts[i, 1]
        lowest = 1e300
        for j in range(other_count):
            d = (others[j, 0] - vx) * nx + (others[j, 1] - vy) * ny
            if d < lowest:
                lowest = d
        seps[at + i] = lowest


@inlined_leaf
def _separations(lva: np.ndarray, lna: np.ndarray, sa: int, ea: int, xa: float, ya: float, aa: float,
                 lvb: np.ndarray, lnb: np.ndarray, sb: int, eb: int, xb: float, yb: float, ab: float, b_posed: bool,
                 pa_v: np.ndarray, pa_n: np.ndarray, pb_v: np.ndarray, pb_n: np.ndarray, b_first: bool,
                 seps: np.ndarray) -> float:
    """Separation along every face of two pieces at their poses (a piece of B already `b_posed` is
    used as it is: a wall); B's faces first if `b_first`. Returns the largest."""
    na_, nb_ = ea - sa, eb - sb
    pose_piece(lva, lna, sa, ea, xa, ya, aa, pa_v, pa_n)
    if b_posed:
        for k in range(nb_):
            pb_v[k, 0], pb_v[k, 1] = lvb[sb + k, 0], lvb[sb + k, 1]
            pb_n[k, 0], pb_n[k, 1] = lnb[sb + k, 0], lnb[sb + k, 1]
    else:
        pose_piece(lvb, lnb, sb, eb, xb, yb, ab, pb_v, pb_n)
    if b_first:
        _face_separations(pb_v, pb_n, pa_v, nb_, na_, seps, 0)
        _face_separations(pa_v, pa_n, pb_v, na_, nb_, seps, nb_)
    else:
        _face_separations(pa_v, pa_n, pb_v, na_, nb_, seps, 0)
        _face_separations(pb_v, pb_n, pa_v, nb_, na_, seps, na_)
    best = -1e300
    for k in range(na_ + nb_):
        if seps[k] > best:
            best = seps[k]
    return best


@inlined_leaf
def _turning_rates(pa_n: np.ndarray, pb_n: np.ndarray, na_: int, nb_: int, d_x: float, d_y: float, turns: float,
                   b_posed: bool, rates: np.ndarray) -> None:
    """The rates of the axes that turn (A's faces; B's too unless B is a wall, whose own rates stay
    as the caller set them), from the faces' normals as posed now: an axis held fixed from now on
    still bounds the distance from below (it separates the two projections), and it closes no faster
    than the pieces' relative step along it, d·n (d = (d_x, d_y), A's step less B's), plus what
    turning adds (`turns`, each piece's turn at its bounding radius). Never more than the general
    bound |d| + turns, and far less for pieces that pass each other or part."""
    if b_posed:  # B's faces first, fixed (the wall's own rates)
        for i in range(na_):
            rates[nb_ + i] = max(0.0, pa_n[i, 0] * d_x + pa_n[i, 1] * d_y) + turns
    else:
        for i in range(na_):
            rates[i] = max(0.0, pa_n[i, 0] * d_x + pa_n[i, 1] * d_y) + turns
        for i in range(nb_):
            rates[na_ + i] = max(0.0, -(pb_n[i, 0] * d_x + pb_n[i, 1] * d_y)) + turns


@leaf_kernel
def _advance(lva: np.ndarray, lna: np.ndarray, sa: int, ea: int, start_a: np.ndarray, end_a: np.ndarray,
             lvb: np.ndarray, lnb: np.ndarray, sb: int, eb: int, start_b: np.ndarray, end_b: np.ndarray,
             b_posed: bool, rates: np.ndarray, turns: float, target: float, tolerance: float, allowance: float,
             at_start: np.ndarray, measured: bool, work: tuple, posed_at_start: bool = False,
             beside: float = math.inf) -> float:
    """Conservative advancement over t in [0, 1]: the first t at which the separating-axis distance
    comes within `target` (see time_of_impact for `allowance`), or NO_HIT. Axes: B's faces first
    when B is a wall (their rates given in `rates`), else A's. The axes that turn get their rates
    from where they point at each step (`_turning_rates`; `turns`: the bound on what the pieces'
    turning adds). `at_start`: the separations at t = 0 if already `measured` (the pieces are then
    posed again, for their normals, unless the scratch still holds them so: `posed_at_start`).
    `work`: scratch (`toi_work`). `beside`: the separation at t = 0 from pieces that are one surface
    with B (`time_of_impact`), counted as B's own for whether the pieces start within `target`.

    Should MAX_ITERATIONS steps not decide it (a fast spin beside a face, say), a sweep that stops
    bodies short of walls (`target` > 0) is given the t reached, where the body is still safely
    apart; a question whether the pieces would press into each other (`target` <= 0: the gap tests)
    is answered no, unless they are pressed in where the motion ends (asked once, after the first
    step): the contact is then made a substep later if they do, and a ball passing a corner is not
    struck by a step count. (A piece already within `target` is put back too when the
    steps run out: a star spinning past a rail a millimetre off falls behind, README; answered no
    there, three and four players' balls pressed together against a wall sank up to 11 cm into
    each other at fast, against 7 before.)"""
    na_, nb_ = ea - sa, eb - sb
    posed, seps = work[0], work[1]
    pa_v, pa_n, pb_v, pb_n = posed[0], posed[1], posed[2], posed[3]
    d_x = end_a[0] - start_a[0] - (end_b[0] - start_b[0])
    d_y = end_a[1] - start_a[1] - (end_b[1] - start_b[1])
    if measured:
        worst = -1e300
        for k in range(na_ + nb_):
            seps[k] = at_start[k]
            if seps[k] > worst:
                worst = seps[k]
        if not posed_at_start:
            pose_piece(lva, lna, sa, ea, start_a[0], start_a[1], start_a[2], pa_v, pa_n)
            if not b_posed:
                pose_piece(lvb, lnb, sb, eb, start_b[0], start_b[1], start_b[2], pb_v, pb_n)
    else:
        worst = _separations(lva, lna, sa, ea, start_a[0], start_a[1], start_a[2], lvb, lnb, sb, eb,
                             start_b[0], start_b[1], start_b[2], b_posed, pa_v, pa_n, pb_v, pb_n, b_posed, seps)
    # Already within `target` (sliding along the wall, or stopped there by the last impact): only
    # sinking `allowance` into it (deeper than it already is, if in it) counts, never just touching it.
    near = min(worst, beside)
    level = target if near >= target + tolerance else min(near, target, 0.0) - allowance
    t = 0.0
    ends_checked = False
    for _ in range(MAX_ITERATIONS):
        _turning_rates(pa_n, pb_n, na_, nb_, d_x, d_y, turns, b_posed, rates)
        # Any axis gives a safe step: its separation cannot fall to `level` sooner than this.
        step = -math.inf
        for k in range(na_ + nb_):
            rate = rates[k]
            if rate > 0.0:
                s = (seps[k] - level) / rate
            else:
                s = math.inf if seps[k] > level else 0.0
            if s > step:
                step = s
        t += step
        if t >= 1.0:
            return NO_HIT
        if target <= 0.0 and not ends_checked:
            # A yes-or-no question (the gap tests): pressed in deeper than `level` where the motion
            # ends, they reach it on the way (the separating axes are exact for convex pieces), so
            # the steps that would say when are not taken, nor can they run out first.
            ends_checked = True
            if _separations(lva, lna, sa, ea, end_a[0], end_a[1], end_a[2], lvb, lnb, sb, eb, end_b[0], end_b[1],
                            end_b[2], b_posed, pa_v, pa_n, pb_v, pb_n, b_posed, seps) < level:
                return t
        worst = _separations(lva, lna, sa, ea, start_a[0] + t * (end_a[0] - start_a[0]),
                             start_a[1] + t * (end_a[1] - start_a[1]), start_a[2] + t * (end_a[2] - start_a[2]),
                             lvb, lnb, sb, eb, start_b[0] + t * (end_b[0] - start_b[0]),
                             start_b[1] + t * (end_b[1] - start_b[1]), start_b[2] + t * (end_b[2] - start_b[2]),
                             b_posed, pa_v, pa_n, pb_v, pb_n, b_posed, seps)
        if worst < level + tolerance:
            return t
    return t if target > 0.0 else NO_HIT


_NOWHERE = np.zeros(3)


@kernel
def toi_work(vertices: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Scratch for the time of impact of pieces of at most `vertices` vertices, made once a kernel
    call rather than once a pair of pieces: both pieces posed (vertices and normals), a row per
    face for the separations, their rates and the separations at the start, and five motions
    (x, y, angle: two pieces' starts and ends, and `stays_clear`'s relative one)."""
    return (np.empty((4, vertices, 2)), np.empty(2 * vertices), np.empty(2 * vertices), np.empty(2 * vertices),
            np.empty((5, 3)))


@leaf_kernel
def widest(first: np.ndarray) -> int:
    """The most vertices of any piece of a set (rows `first`)."""
    most = 0
    for i in range(len(first) - 1):
        most = max(most, first[i + 1] - first[i])
    return most


@inlined_leaf
def wall_out_of_reach(reach: float, start: np.ndarray, end: np.ndarray, wv: np.ndarray, wn: np.ndarray, ws: int,
                      we: int, target: float, tolerance: float, rates: np.ndarray) -> bool:
    """`time_of_impact`'s quick answer: per unit of t, how fast the piece (bounding radius `reach`
    about the body's origin, moving start -> end) can approach each face of the wall piece (rows
    ws..we), into rates[0:]; and whether it stays beyond some face, farther than `target` and the
    tolerance, however fast it approaches it: then there is no impact, as the first advancement
    step would find (its step along that face's axis passes 1). (A loop and no call, so a caller
    in a hot loop pays no reference counts for it; see `jit`.)"""
    dx, dy = end[0] - start[0], end[1] - start[1]
    turn = abs(end[2] - start[2]) * reach
    clear = target + tolerance + _CLEARANCE
    beyond = False
    for k in range(we - ws):
        rates[k] = max(0.0, -(dx * wn[ws + k, 0] + dy * wn[ws + k, 1])) + turn
        beyond |= (start[0] - wv[ws + k, 0]) * wn[ws + k, 0] + (start[1] - wv[ws + k, 1]) * wn[ws + k, 1] - reach \
            - rates[k] > clear
    return beyond


@inlined_leaf
def separations_in_body_frame(lv: np.ndarray, s: int, e: int, x: float, y: float, c: float, sn: float,
                              wv: np.ndarray, wn: np.ndarray, ws: int, we: int, out: np.ndarray) -> None:
    """How far a body's piece (rows s..e of its own frame; the body at (x, y), turned by the angle
    whose cosine and sine are c, sn) lies beyond each face of a wall piece (rows ws..we), into
    out[0:]: each face's normal turned into the body's frame rather than the piece into the world,
    so the body need not be posed (the separations `_face_separations` finds of the posed piece, to
    rounding: a caller deciding by them leaves room for it)."""
    for k in range(ws, we):
        nx, ny = wn[k, 0], wn[k, 1]
        lx, ly = c * nx + sn * ny, c * ny - sn * nx
        lowest = math.inf
        for j in range(s, e):
            d = lv[j, 0] * lx + lv[j, 1] * ly
            if d < lowest:
                lowest = d
        out[k - ws] = (x - wv[k, 0]) * nx + (y - wv[k, 1]) * ny + lowest


@inlined_leaf
def wall_beyond_body_faces(lv: np.ndarray, ln: np.ndarray, s: int, e: int, x: float, y: float, c: float, sn: float,
                           wv: np.ndarray, ws: int, we: int, local: np.ndarray) -> float:
    """How far a wall piece (rows ws..we) lies beyond the nearest-to-separating face of a body's piece
    (rows s..e of its own frame; the body at (x, y), turned by the angle whose cosine and sine are
    c, sn): the largest over the piece's faces of the wall's least separation from it, the wall's
    vertices turned into the body's frame (into `local`) rather than the piece into the world (what
    `collide.max_separation` finds of the posed piece, to rounding: a caller deciding by it leaves
    room for it)."""
    for k in range(ws, we):
        dx, dy = wv[k, 0] - x, wv[k, 1] - y
        local[k - ws, 0], local[k - ws, 1] = c * dx + sn * dy, c * dy - sn * dx
    best = -math.inf
    for i in range(s, e):
        nx, ny, vx, vy = ln[i, 0], ln[i, 1], lv[i, 0], lv[i, 1]
        lowest = math.inf
        for k in range(we - ws):
            d = (local[k, 0] - vx) * nx + (local[k, 1] - vy) * ny
            if d < lowest:
                lowest = d
        if lowest > best:
            best = lowest
    return best


@leaf_kernel
def time_of_impact(lv: np.ndarray, ln: np.ndarray, s: int, e: int, reach: float, start: np.ndarray,
                   end: np.ndarray, wv: np.ndarray, wn: np.ndarray, ws: int, we: int, target: float, tolerance: float,
                   allowance: float, work: tuple, beside: float = math.inf) -> float:
    """Fraction of the motion start -> end (x, y, angle) at which the piece (rows s..e, body frame)
    first comes within `target` of the wall piece (rows ws..we, world), or NO_HIT.

    `reach` is the largest distance of the piece's vertices from the body origin. A piece already
    within `target` at the start (sliding along the wall, or stopped there by an impact the substep
    before) is stopped only if it would sink `allowance` into it (deeper than it already is, if in
    it): a corner swinging into the wall while another rests on it is caught, but sliding is not
    interrupted, nor is a piece stopped for touching a corner it passes level with a face (its
    vertex at the corner, the contact's normal could be either face's). `work`: scratch (`toi_work`).
    `beside`: how near the piece lies to walls this one carries on across a seam (`first_wall_hits`):
    within `target` of those, it is as if within `target` of this one."""
    dx, dy, da = end[0] - start[0], end[1] - start[1], end[2] - start[2]
    turn = abs(da) * reach  # largest distance any vertex moves by rotation over the whole motion
    general_rate = math.hypot(dx, dy) + turn
    if general_rate <= 0.0:
        return NO_HIT
    rates = work[2]
    if wall_out_of_reach(reach, start, end, wv, wn, ws, we, target, tolerance, rates):
        return NO_HIT
    # The same along the wall's faces with the piece itself in place of its bounding circle: the
    # advancement's first step along such a face passes 1 (its level is `target`, the face being
    # beyond it), which is its answer, NO_HIT.
    seps = work[1]
    separations_in_body_frame(lv, s, e, start[0], start[1], math.cos(start[2]), math.sin(start[2]), wv, wn, ws, we,
                              seps)
    clear = target + tolerance + _CLEARANCE
    beyond = False
    for k in range(we - ws):
        beyond |= seps[k] - rates[k] > clear
    if beyond:
        return NO_HIT
    # The piece's own faces turn with it: the advancement gives them their rates as they point.
    t = _advance(lv, ln, s, e, start, end, wv, wn, ws, we, _NOWHERE, _NOWHERE, True, rates, turn, target, tolerance,
                 allowance, rates, False, work, False, beside)
    # A sweep stops a piece short of the wall only if it would go on to sink into it (deeper than the
    # gap test's tolerance, beyond every face): a tip swinging past a rail within the target, and a
    # ball sliding level onto the next of two flush boxes, are let go (the advancement's bound for a
    # turn is the same at every point of the piece, and it knows no seams; `stays_clear` is exact).
    if t < 1.0 and target > 0.0 and stays_clear(lv, ln, s, e, start, end, wv, wn, ws, we, _NOWHERE, _NOWHERE,
                                                -GAP_TOLERANCE, t, work[4][4]):
        return NO_HIT
    return t


# `stays_clear` walks the rest of a motion in parts, first a quarter of it: a part that some axis
# clears is passed and the next one tried twice as long; one that none clears is tried half as long,
# down to CLEAR_FINEST of the rest (then the answer is no), at most CLEAR_STEPS tries in all.
CLEAR_FIRST = 0.25
CLEAR_FINEST = 1.0 / 4096.0
CLEAR_STEPS = 512


@leaf_kernel
def stays_clear(lva: np.ndarray, lna: np.ndarray, sa: int, ea: int, start_a: np.ndarray, end_a: np.ndarray,
                lvb: np.ndarray, lnb: np.ndarray, sb: int, eb: int, start_b: np.ndarray, end_b: np.ndarray,
                clearance: float, since: float, relative: np.ndarray) -> bool:
    """Whether piece A (rows sa..ea, body frame) and piece B (rows sb..eb: a body's, or a wall's in
    world coordinates with the motion `_NOWHERE` to `_NOWHERE`), each moving start -> end (x, y,
    angle, each linear in t), stay more than `clearance` apart from t = `since` to 1 (a negative
    clearance: never sink deeper than that into each other). `relative`: room for one motion's end.

    A piece that does not turn is a frame the other moves in as the integrator moves it, linearly in
    position and angle: seen from it, the question is that of a piece passing a still one, asked
    along the still piece's faces exactly (`_least_along`). Where both turn, every face gets the
    lower bound of `_least_beyond_face`. Either way the motion is walked part by part (see
    CLEAR_FIRST) where no axis clears all of it. An answer of no may be wrong (the caller then keeps
    the advancement's stop), yes never."""
    if start_b[2] == end_b[2]:  # B slides or stands: A as it moves relative to B, B where it starts
        for k in range(2):
            relative[k] = end_a[k] - (end_b[k] - start_b[k])
        relative[2] = end_a[2]
        return _walk_clear(lva, lna, sa, ea, start_a, relative, lvb, lnb, sb, eb, start_b, start_b, clearance, since)
    if start_a[2] == end_a[2]:  # A slides: the same from B's side
        for k in range(2):
            relative[k] = end_b[k] - (end_a[k] - start_a[k])
        relative[2] = end_b[2]
        return _walk_clear(lvb, lnb, sb, eb, start_b, relative, lva, lna, sa, ea, start_a, start_a, clearance, since)
    return _walk_clear(lva, lna, sa, ea, start_a, end_a, lvb, lnb, sb, eb, start_b, end_b, clearance, since)


@leaf_kernel
def _walk_clear(lva: np.ndarray, lna: np.ndarray, sa: int, ea: int, start_a: np.ndarray, end_a: np.ndarray,
                lvb: np.ndarray, lnb: np.ndarray, sb: int, eb: int, start_b: np.ndarray, end_b: np.ndarray,
                clearance: float, since: float) -> bool:
    """`stays_clear`'s walk: the whole rest along B's faces, then part by part along either's."""
    if _part_clear(lva, lna, sa, ea, start_a, end_a, lvb, lnb, sb, eb, start_b, end_b, clearance, since, 1.0, False):
        return True
    if not _part_clear(lva, lna, sa, ea, start_a, end_a, lvb, lnb, sb, eb, start_b, end_b, clearance, 1.0, 1.0, True):
        return False  # (sunk in where the motion ends: an impact, as a rule, asked about at once)
    t, width, finest = since, CLEAR_FIRST * (1.0 - since), CLEAR_FINEST * (1.0 - since)
    for _ in range(CLEAR_STEPS):
        last = t + width >= 1.0
        if last:
            width = 1.0 - t
        if _part_clear(lva, lna, sa, ea, start_a, end_a, lvb, lnb, sb, eb, start_b, end_b, clearance, t,
                       1.0 if last else t + width, True):
            if last:
                return True
            t += width
            width *= 2.0
        else:
            width *= 0.5
            if width < finest:
                return False
    return False


@leaf_kernel
def _part_clear(lva: np.ndarray, lna: np.ndarray, sa: int, ea: int, start_a: np.ndarray, end_a: np.ndarray,
                lvb: np.ndarray, lnb: np.ndarray, sb: int, eb: int, start_b: np.ndarray, end_b: np.ndarray,
                clearance: float, t0: float, t1: float, own_faces: bool) -> bool:
    """`stays_clear` over [t0, t1]: along a face of B (exact if B stands still), or (`own_faces`)
    of A, turning with it (`_least_beyond_face`)."""
    if _still(start_b, end_b):
        c, sn = math.cos(start_b[2]), math.sin(start_b[2])  # (1 and 0 for a wall: its rows as they are)
        for k in range(sb, eb):
            nx, ny = c * lnb[k, 0] - sn * lnb[k, 1], sn * lnb[k, 0] + c * lnb[k, 1]
            if _least_along(lva, sa, ea, start_a, end_a, nx, ny, _reach_along(lvb, sb, eb, start_b, c, sn, nx, ny),
                            t0, t1) > clearance:
                return True
    else:
        for k in range(sb, eb):
            if _least_beyond_face(lvb, lnb, k, start_b, end_b, lva, sa, ea, start_a, end_a, t0, t1) > clearance:
                return True
    if own_faces:
        for i in range(sa, ea):
            if _least_beyond_face(lva, lna, i, start_a, end_a, lvb, sb, eb, start_b, end_b, t0, t1) > clearance:
                return True
    return False


@inlined_leaf
def _least_beyond_face(lvx: np.ndarray, lnx: np.ndarray, i: int, start_x: np.ndarray, end_x: np.ndarray,
                       lvy: np.ndarray, ys: int, ye: int, start_y: np.ndarray, end_y: np.ndarray, t0: float,
                       t1: float) -> float:
    """A lower bound, over t in [t0, t1], of how far every vertex of piece Y (rows ys..ye) lies
    beyond face i of piece X, each moving start -> end: g(t) = q(t) . n_i - v_i . n_i, q the vertex
    seen from X (turned into X's frame). The lesser end, less what g'' allows between the ends,
    times (t1 - t0)^2 / 8. With s the vertex's offset from X's origin in the world, q = R(-a_X) s,
    so |q''| <= |s''| + 2 |w_X| |s'| + w_X^2 |s| (w: the turns), where |s''| = w_Y^2 |l| and
    |s'| <= |d| + |w_Y| |l| (l the vertex in Y's frame, d the step of Y's origin less X's); |s| is
    longest at an end if Y does not turn, else at most the origins' distance there plus |l|."""
    dxx, dxy, wx = end_x[0] - start_x[0], end_x[1] - start_x[1], end_x[2] - start_x[2]
    dyx, dyy, wy = end_y[0] - start_y[0], end_y[1] - start_y[1], end_y[2] - start_y[2]
    offset = lvx[i, 0] * lnx[i, 0] + lvx[i, 1] * lnx[i, 1]
    facing = math.atan2(lnx[i, 1], lnx[i, 0])
    u0x, u0y = math.cos(start_x[2] + wx * t0 + facing), math.sin(start_x[2] + wx * t0 + facing)
    u1x, u1y = math.cos(start_x[2] + wx * t1 + facing), math.sin(start_x[2] + wx * t1 + facing)
    p0x, p0y, p1x, p1y = start_x[0] + dxx * t0, start_x[1] + dxy * t0, start_x[0] + dxx * t1, start_x[1] + dxy * t1
    o0x, o0y, o1x, o1y = start_y[0] + dyx * t0, start_y[1] + dyy * t0, start_y[0] + dyx * t1, start_y[1] + dyy * t1
    c0, s0 = math.cos(start_y[2] + wy * t0), math.sin(start_y[2] + wy * t0)
    c1, s1 = math.cos(start_y[2] + wy * t1), math.sin(start_y[2] + wy * t1)
    step = math.hypot(dyx - dxx, dyy - dxy)
    apart = max(math.hypot(o0x - p0x, o0y - p0y), math.hypot(o1x - p1x, o1y - p1y))
    width = (t1 - t0) * (t1 - t0) / 8.0
    lowest = math.inf
    for k in range(ys, ye):
        w0x, w0y = o0x + c0 * lvy[k, 0] - s0 * lvy[k, 1], o0y + s0 * lvy[k, 0] + c0 * lvy[k, 1]
        w1x, w1y = o1x + c1 * lvy[k, 0] - s1 * lvy[k, 1], o1y + s1 * lvy[k, 0] + c1 * lvy[k, 1]
        g0 = (w0x - p0x) * u0x + (w0y - p0y) * u0y - offset
        g1 = (w1x - p1x) * u1x + (w1y - p1y) * u1y - offset
        if wy == 0.0:
            far = max(math.hypot(w0x - p0x, w0y - p0y), math.hypot(w1x - p1x, w1y - p1y))
            bend = 2.0 * abs(wx) * step
        else:
            arm = math.hypot(lvy[k, 0], lvy[k, 1])
            far = apart + arm
            bend = wy * wy * arm + 2.0 * abs(wx) * (step + abs(wy) * arm)
        lowest = min(lowest, min(g0, g1) - (bend + wx * wx * far) * width)
    return lowest


@inlined_leaf
def _reach_along(wv: np.ndarray, ws: int, we: int, at: np.ndarray, c: float, sn: float, nx: float, ny: float
                 ) -> float:
    """How far the still piece (rows ws..we, posed `at`; c, sn: its angle's cosine and sine) reaches
    along the axis (nx, ny)."""
    most = -math.inf
    for k in range(ws, we):
        x, y = at[0] + c * wv[k, 0] - sn * wv[k, 1], at[1] + sn * wv[k, 0] + c * wv[k, 1]
        most = max(most, x * nx + y * ny)
    return most


@inlined_leaf
def _least_along(lv: np.ndarray, s: int, e: int, start: np.ndarray, end: np.ndarray, nx: float, ny: float,
                 beyond: float, t0: float, t1: float) -> float:
    """The least, over t in [t0, t1], of how far every vertex of the piece (rows s..e, body frame;
    moving start -> end) lies along the fixed axis (nx, ny) beyond `beyond`. Exact: a vertex at
    distance r and polar angle phi from the body's origin lies at f(t) = a + b t + r cos(psi0 + w t)
    (a, b: the origin's start and step along the axis; w: the turn; psi0 = angle + phi - angle of
    the axis), whose least value is at an end or where f' = b - r w sin(psi) = 0 with cos(psi) < 0
    (the bottom of the vertex's circle, a turn apart from the next)."""
    dx, dy, turn = end[0] - start[0], end[1] - start[1], end[2] - start[2]
    a = start[0] * nx + start[1] * ny - beyond
    b = dx * nx + dy * ny
    facing = math.atan2(ny, nx)
    lowest = math.inf
    for j in range(s, e):
        r = math.hypot(lv[j, 0], lv[j, 1])
        psi0 = start[2] + math.atan2(lv[j, 1], lv[j, 0]) - facing
        low = min(a + b * t0 + r * math.cos(psi0 + turn * t0), a + b * t1 + r * math.cos(psi0 + turn * t1))
        if r > 0.0 and turn != 0.0 and abs(b) <= abs(r * turn):
            bottom = math.pi - math.asin(b / (r * turn))  # a psi where f' = 0, cos(psi) <= 0
            lo, hi = min(psi0 + turn * t0, psi0 + turn * t1), max(psi0 + turn * t0, psi0 + turn * t1)
            psi = bottom + 2.0 * math.pi * math.ceil((lo - bottom) / (2.0 * math.pi))
            while psi <= hi:
                low = min(low, a + b * ((psi - psi0) / turn) + r * math.cos(psi))
                psi += 2.0 * math.pi
        lowest = min(lowest, low)
    return lowest


@leaf_kernel
def pair_time_of_impact(lva: np.ndarray, lna: np.ndarray, sa: int, ea: int, reach_a: float, start_a: np.ndarray,
                        end_a: np.ndarray, lvb: np.ndarray, lnb: np.ndarray, sb: int, eb: int, reach_b: float,
                        start_b: np.ndarray, end_b: np.ndarray, target: float, tolerance: float, allowance: float,
                        at_start: np.ndarray, measured: bool, work: tuple, posed_at_start: bool = False) -> float:
    """The same for two pieces that both move (two bodies): every axis turns with its body, and takes
    the relative step along it, (dA - dB)·n, plus |ΔθA|·RA + |ΔθB|·RB (`_turning_rates`).
    `at_start`: the separations at the start poses, if already `measured` (and the scratch's posed
    pieces still those poses: `posed_at_start`)."""
    turns = abs(end_a[2] - start_a[2]) * reach_a + abs(end_b[2] - start_b[2]) * reach_b
    # No motion at all (the relative step's length plus the turns would be 0: a length is 0 only
    # for a step of 0, and neither can be negative).
    if end_a[0] - start_a[0] - end_b[0] + start_b[0] == 0.0 and end_a[1] - start_a[1] - end_b[1] + start_b[1] == 0.0 \
            and turns == 0.0:
        return NO_HIT
    t = _advance(lva, lna, sa, ea, start_a, end_a, lvb, lnb, sb, eb, start_b, end_b, False, work[2], turns, target,
                 tolerance, allowance, at_start, measured, work, posed_at_start)
    # As against a wall (`time_of_impact`): a ball passing another player's ball, resting or rolling,
    # or the tip of a turning windmill's arm, without sinking into it is not put back.
    if t < 1.0 and target > 0.0 and stays_clear(lva, lna, sa, ea, start_a, end_a, lvb, lnb, sb, eb, start_b, end_b,
                                                -GAP_TOLERANCE, t, work[4][4]):
        return NO_HIT
    return t


@inlined_leaf
def _still(start: np.ndarray, end: np.ndarray) -> bool:
    return start[0] == end[0] and start[1] == end[1] and start[2] == end[2]


@inlined_leaf
def length_near(x: float, y: float, plus: float, more: float, bound: float, other: float) -> float:
    """hypot(x, y) + plus + more, for a caller that compares it with `bound` and `other` (the same
    twice for one bound): within a millionth of either, exactly that; elsewhere with the square root
    of the sum of squares in place of `math.hypot`, which is within a few ulps of it (the comparisons
    come out the same) and costs several times less (`geometry.norm`, which takes the exact one where
    the squares leave the normal range)."""
    value = norm(x, y) + plus + more
    if abs(value - bound) > 1e-6 * abs(bound) and abs(value - other) > 1e-6 * abs(other):
        return value
    return math.hypot(x, y) + plus + more


@leaf_kernel
def first_wall_hits(lv: np.ndarray, ln: np.ndarray, first: np.ndarray, reach: np.ndarray, body_first: np.ndarray,
                    state: np.ndarray, rows: np.ndarray, radius: np.ndarray, least: float, grid: tuple,
                    fat_boxes: tuple, seen: np.ndarray, found: np.ndarray, wv: np.ndarray, wn: np.ndarray,
                    wfirst: np.ndarray, internal: np.ndarray, hidden: np.ndarray, target: float, tolerance: float,
                    allowance: float, far: float, out: np.ndarray, work: tuple, boxes: np.ndarray) -> tuple[bool, int]:
    """For each body q of `rows` (a `body.BodyStore` state, from its pose at the substep's start to
    its pose now; shape q of a `ShapeTable`, bounding radius radius[q]), the earliest impact of any
    of its pieces with the wall pieces its swept box meets in `grid` (the walls' `BoxGrid.arrays`,
    asked through the bodies' `grid.FatBoxes.arrays`),
    as a fraction of its motion; 1.0 if none, or if it is at rest, kinematic, or stepped less than
    `least` (the discrete contact handles small steps), into `out` (the caller's, kept between
    substeps).
    `seen` and `found`: the grid query's scratch, one row per wall piece; `work`: the time of
    impact's (`toi_work` for the widest piece of either set); `boxes`: room for two boxes (a
    leaf makes no array); all kept by the caller. Returns whether
    an awake body stepped `far` or more, and how many bodies hit.

    A body's step is its centre's path plus its turn at its bounding radius, compared with `least`
    and `far` only (`length_near`).

    A piece that carries on a face of another across a seam (`_level_beside`: flush boxes of a
    floor) is one surface with it: a body already within `target` of that other piece at the start
    is stopped by this one, as by the other, only if it would sink `allowance` into it (deeper than
    it already lies, if in it; counted to twice the target). A tip sliding on a floor of flush
    boxes meets each next box's covered side face: it was put back at every seam (a triangle sunk
    within the slop, at 25 m/s, 1.25 m behind after 0.4 s at balanced; a square landing flat on its
    corners by a seam at fast, 63 mm)."""
    out[:] = 1.0
    moved = False
    hits = 0
    box, wide = boxes[0], boxes[1]
    fat, walls = fat_boxes
    boxes = grid[0]
    start, end = work[4][0], work[4][1]
    for q in range(len(rows)):
        k = rows[q]
        if state[k, ASLEEP] != 0.0:
            continue
        x0, y0, a0, x1, y1, a1 = state[k, X0], state[k, Y0], state[k, ANGLE0], state[k, X], state[k, Y], state[k, ANGLE]
        dx, dy, turn = x1 - x0, y1 - y0, abs(a1 - a0) * radius[q]
        travel = length_near(dx, dy, turn, 0.0, least, far)
        moved |= travel >= far
        if state[k, INV_MASS] == 0.0 or travel < least:
            continue
        r = radius[q] + target
        box[0], box[1], box[2], box[3] = min(x0, x1) - r, min(y0, y1) - r, max(x0, x1) + r, max(y0, y1) + r
        count = walls_near(fat, walls, k, box, boxes, found)
        if count < 0:
            count = look_up_walls(grid, fat, walls, k, box, wide, seen, found, found)
        if count == 0:
            continue
        start[0], start[1], start[2] = x0, y0, a0
        end[0], end[1], end[2] = x1, y1, a1
        best = 1.0
        for n in range(count):
            w = found[n]
            beside = math.nan  # (asked once a piece, and only of a piece that stops the body)
            for i in range(body_first[q], body_first[q + 1]):
                if wall_out_of_reach(reach[i], start, end, wv, wn, wfirst[w], wfirst[w + 1], target, tolerance,
                                     work[2]):
                    continue  # the quick answer first, without the call
                t = time_of_impact(lv, ln, first[i], first[i + 1], reach[i], start, end, wv, wn, wfirst[w],
                                   wfirst[w + 1], target, tolerance, allowance, work)
                if t < 1.0 and _through_covered_face(lv, ln, first[i], first[i + 1], start, end, t, wv, wn, wfirst[w],
                                                     wfirst[w + 1], internal, hidden, work):
                    continue
                if t < 1.0:  # unless the piece carries on a surface the body lies by: then as that surface
                    if math.isnan(beside):
                        beside = max(_level_beside(lv, ln, first, body_first, q, start, wv, wn, wfirst, internal,
                                                   found, count, w, work), -2.0 * target)
                    if beside < target + tolerance:  # (else the same answer: the rule is not met)
                        t = time_of_impact(lv, ln, first[i], first[i + 1], reach[i], start, end, wv, wn, wfirst[w],
                                           wfirst[w + 1], target, tolerance, allowance, work, beside)
                if t < best:
                    best = t
        out[q] = best
        if best < 1.0:
            hits += 1
    return moved, hits


@inlined_leaf
def _through_covered_face(lv: np.ndarray, ln: np.ndarray, s: int, e: int, start: np.ndarray, end: np.ndarray,
                          t: float, wv: np.ndarray, wn: np.ndarray, ws: int, we: int, internal: np.ndarray,
                          hidden: np.ndarray, work: tuple) -> bool:
    """Whether the piece (rows s..e, body frame), where its motion start -> end brings it within the
    target of wall piece ws..we (fraction t), lies nearest that piece across a face another piece
    covers (`internal`, physics.seams), neither end of which is a reflex corner: it comes from
    inside the one that covers it, whose own time of impact answers for the solid (QA: a square sunk
    1 mm in a rail of flush triangles passed from each block's upper triangle into its lower one
    across their diagonal and was put back there, 157 mm behind at fast). At an inside corner
    (`hidden` marks seams.REFLEX) the covering piece answers only along its own faces: a needle
    sliding down one leg of a V, its tip sunk in it just past the other leg's covered edge, goes on
    into the other leg, which must stop it."""
    posed, seps = work[0], work[1]
    x, y, a = start[0] + t * (end[0] - start[0]), start[1] + t * (end[1] - start[1]), start[2] + t * (end[2] - start[2])
    _separations(lv, ln, s, e, x, y, a, wv, wn, ws, we, 0.0, 0.0, 0.0, True, posed[0], posed[1], posed[2], posed[3],
                 True, seps)
    nearest, face = -math.inf, -1
    for k in range(we - ws + e - s):  # (the wall piece's faces first)
        if seps[k] > nearest:
            nearest, face = seps[k], k
    n = we - ws
    return face < n and internal[ws + face] and hidden[ws + face] != REFLEX and hidden[ws + (face + 1) % n] != REFLEX


@leaf_kernel
def _level_beside(lv: np.ndarray, ln: np.ndarray, first: np.ndarray, body_first: np.ndarray, q: int, pose: np.ndarray,
                  wv: np.ndarray, wn: np.ndarray, wfirst: np.ndarray, internal: np.ndarray, found: np.ndarray,
                  count: int, w: int, work: tuple) -> float:
    """How near body q (shape q, at `pose`) lies to a surface that wall piece w carries on across a
    seam: the least separation of any of its pieces from a piece of `found[:count]` with a face on
    the line of one of w's, facing the same way, joined to it (`geometry.span_on_line`: meeting or
    overlapping it, or a face that does, and so on: a row of narrow flush boxes is one floor, QA: a
    star sliding sunk on two tips at 23.7 m/s passed a 6 cm box in a substep at fast and was put
    back at the next one's seam, 0.34 m behind), where that face is the nearest of the piece's
    (within seams.PROBE: a ball in a box's corner lies by its inner faces, not by the outer faces it
    shares with the floor); inf if none. A face another piece covers (`internal`, physics.seams) is
    no surface, so neither nearest nor an axis: a star's tip sunk 2.3 mm in one box, 2.1 mm short of
    its seam, lay nearer that covered side face (and the star's own cut between two of its pieces,
    parallel to it) than the top, so was not seen lying on the floor, and the next seam put the
    star back 72 mm (QA, fast)."""
    posed, seps = work[0], work[1]
    s, e = wfirst[w], wfirst[w + 1]
    level = math.inf
    for r in range(s, e):
        nx, ny, offset, own_lo, own_hi = face_line(wv, wn, s, e, r)
        grew = True
        while grew:  # the stretch of the line the faces joined to w's cover
            grew = False
            for m in range(count):
                h = found[m]
                face, lo, hi = span_on_line(wv, wn, wfirst[h], wfirst[h + 1], nx, ny, offset, -ny, nx)
                if h != w and face >= 0 and lo <= own_hi + PROBE and own_lo <= hi + PROBE and \
                        (lo < own_lo or hi > own_hi):
                    own_lo, own_hi, grew = min(own_lo, lo), max(own_hi, hi), True
        for m in range(count):
            h = found[m]
            if h == w:
                continue
            hs, he = wfirst[h], wfirst[h + 1]
            face, lo, hi = span_on_line(wv, wn, hs, he, nx, ny, offset, -ny, nx)
            if face < 0 or lo > own_hi + PROBE or own_lo > hi + PROBE:
                continue
            for i in range(body_first[q], body_first[q + 1]):
                _separations(lv, ln, first[i], first[i + 1], pose[0], pose[1], pose[2], wv, wn, hs, he, 0.0, 0.0, 0.0,
                             True, posed[0], posed[1], posed[2], posed[3], True, seps)
                nearest = separation = -math.inf  # (h's faces first, then the body piece's)
                for k in range(he - hs + first[i + 1] - first[i]):
                    if k < he - hs and internal[hs + k]:
                        continue
                    separation = max(separation, seps[k])
                    if k < he - hs:
                        nearest = max(nearest, seps[k])
                if seps[face - hs] >= nearest - PROBE:
                    level = min(level, separation)
    return level


@leaf_kernel
def first_pair_hit(lva: np.ndarray, lna: np.ndarray, fa: np.ndarray, ra: np.ndarray, start_a: np.ndarray,
                   end_a: np.ndarray, lvb: np.ndarray, lnb: np.ndarray, fb: np.ndarray, rb: np.ndarray,
                   start_b: np.ndarray, end_b: np.ndarray, target: float, tolerance: float, allowance: float,
                   work: tuple) -> float:
    """The earliest impact of any piece of body A with any piece of body B, both moving (1.0 if
    none)."""
    best = 1.0
    for i in range(len(fa) - 1):
        for j in range(len(fb) - 1):
            t = pair_time_of_impact(lva, lna, fa[i], fa[i + 1], ra[i], start_a, end_a, lvb, lnb, fb[j], fb[j + 1],
                                    rb[j], start_b, end_b, target, tolerance, allowance, work[3], False, work)
            if t < best:
                best = t
    return best


@kernel
def body_pair_hits(lv: np.ndarray, ln: np.ndarray, first: np.ndarray, reach: np.ndarray, body_first: np.ndarray,
                   pairs: np.ndarray, state: np.ndarray, rows: np.ndarray, radius: np.ndarray, thickness: np.ndarray,
                   meet: bool, sweep_all: bool, slop: float, target: float, tolerance: float, allowance: float,
                   hits: np.ndarray, arm_hits: np.ndarray) -> int:
    """Continuous collision between bodies: for each pair (shapes of a `ShapeTable`, rows `rows[q]`
    of a `body.BodyStore` state, swept from the substep's start to now) of which one is moving (awake
    and dynamic, or kinematic and turning), a dynamic one (with `meet`, or only against a kinematic
    one), and whose relative step could matter (any beyond `slop` against a kinematic body, or with
    `sweep_all`; else, between two dynamic ones, half the thinner's width), the earliest impact; it
    goes into `hits[q]` of each awake dynamic body of the pair and, for a pair with a kinematic body,
    into `arm_hits[g]` (else 1.0) for the caller to judge the arm. Returns how many pairs hit."""
    return _pair_hits(lv, ln, first, reach, body_first, pairs, state, rows, radius, thickness, meet, sweep_all, slop,
                      target, tolerance, allowance, hits, arm_hits, toi_work(widest(first)))


@leaf_kernel
def _pair_hits(lv: np.ndarray, ln: np.ndarray, first: np.ndarray, reach: np.ndarray, body_first: np.ndarray,
               pairs: np.ndarray, state: np.ndarray, rows: np.ndarray, radius: np.ndarray, thickness: np.ndarray,
               meet: bool, sweep_all: bool, slop: float, target: float, tolerance: float, allowance: float,
               hits: np.ndarray, arm_hits: np.ndarray, work: tuple) -> int:
    """`body_pair_hits`' work, `work` its scratch (`toi_work`). (A leaf: the views it takes of each
    pair's pieces cost nothing; in a kernel, each one is two atomic reference counts.)"""
    count = 0
    start_a, end_a, start_b, end_b = work[4][0], work[4][1], work[4][2], work[4][3]
    for g in range(len(pairs)):
        arm_hits[g] = 1.0
        a, b = pairs[g, 0], pairs[g, 1]
        ka, kb = rows[a], rows[b]
        dyn_a, dyn_b = state[ka, INV_MASS] != 0.0, state[kb, INV_MASS] != 0.0
        if not (dyn_a or dyn_b) or (dyn_a and dyn_b and not meet):
            continue
        moving_a = (state[ka, ASLEEP] == 0.0 and state[ka, INV_MASS] > 0.0) or (
            not dyn_a and state[ka, SPIN] != 0.0)
        moving_b = (state[kb, ASLEEP] == 0.0 and state[kb, INV_MASS] > 0.0) or (
            not dyn_b and state[kb, SPIN] != 0.0)
        if not (moving_a or moving_b):
            continue  # a resting ball is swept only against a turning windmill (which it may stall)
        kinematic_pair = not (dyn_a and dyn_b)
        limit = slop if kinematic_pair or sweep_all else 0.5 * min(thickness[a], thickness[b])
        travel = length_near(state[ka, X] - state[ka, X0] - state[kb, X] + state[kb, X0],
                             state[ka, Y] - state[ka, Y0] - state[kb, Y] + state[kb, Y0],
                             abs(state[ka, ANGLE] - state[ka, ANGLE0]) * radius[a],
                             abs(state[kb, ANGLE] - state[kb, ANGLE0]) * radius[b], limit, limit)
        if travel < limit:
            continue
        pa0, pa1, pb0, pb1 = body_first[a], body_first[a + 1], body_first[b], body_first[b + 1]
        start_a[0], start_a[1], start_a[2] = state[ka, X0], state[ka, Y0], state[ka, ANGLE0]
        end_a[0], end_a[1], end_a[2] = state[ka, X], state[ka, Y], state[ka, ANGLE]
        start_b[0], start_b[1], start_b[2] = state[kb, X0], state[kb, Y0], state[kb, ANGLE0]
        end_b[0], end_b[1], end_b[2] = state[kb, X], state[kb, Y], state[kb, ANGLE]
        hit = first_pair_hit(lv, ln, first[pa0:pa1 + 1], reach[pa0:pa1], start_a, end_a,
                             lv, ln, first[pb0:pb1 + 1], reach[pb0:pb1], start_b, end_b, target, tolerance, allowance,
                             work)
        if hit < 1.0:
            count += 1
            if dyn_a and state[ka, ASLEEP] == 0.0 and hit < hits[a]:
                hits[a] = hit
            if dyn_b and state[kb, ASLEEP] == 0.0 and hit < hits[b]:
                hits[b] = hit
            if kinematic_pair:
                arm_hits[g] = hit
    return count


@leaf_kernel
def reaches_wall(lv: np.ndarray, ln: np.ndarray, first: np.ndarray, reach: np.ndarray, x: float, y: float,
                 angle: float, vx: float, vy: float, spin: float, dt: float, wv: np.ndarray, wn: np.ndarray, ws: int,
                 we: int, work: tuple) -> bool:
    """Whether the body, moving on with its velocity for dt, would press into the wall piece (by
    more than GAP_TOLERANCE: a face that only grazes a corner, level with it, is not a hit).
    `work`: scratch (`toi_work`)."""
    pose, end = work[4][0], work[4][1]
    pose[0], pose[1], pose[2] = x, y, angle
    end[0], end[1], end[2] = x + vx * dt, y + vy * dt, angle + spin * dt
    for i in range(len(first) - 1):
        if time_of_impact(lv, ln, first[i], first[i + 1], reach[i], pose, end, wv, wn, ws, we, -GAP_TOLERANCE,
                          GAP_TOLERANCE / 2, 0.0, work) < 1.0:
            return True
    return False


@leaf_kernel
def _closes(move_a: np.ndarray, move_b: np.ndarray, pose_a: np.ndarray, pose_b: np.ndarray, speed: float,
            allowed: bool, dt: float, gap: float) -> bool:
    """Whether `pair_reaches` tries the motion to (move_a, move_b): allowed, fast enough to close the
    gap within dt (`speed`: the most it closes it by, per second), and a motion at all."""
    still = True
    for k in range(3):
        if move_a[k] != pose_a[k] or move_b[k] != pose_b[k]:
            still = False
    return allowed and speed * dt >= gap + GAP_TOLERANCE and not still


@leaf_kernel
def pair_reaches(lva: np.ndarray, lna: np.ndarray, fa: np.ndarray, ra: np.ndarray, radius_a: float,
                 pose_a: np.ndarray, vel_a: np.ndarray, lvb: np.ndarray, lnb: np.ndarray, fb: np.ndarray,
                 rb: np.ndarray, radius_b: float, pose_b: np.ndarray, vel_b: np.ndarray, dt: float, gap: float,
                 may_halt_a: bool, may_halt_b: bool, work: tuple) -> bool:
    """The same for two bodies: whether they would press into each other (by more than
    GAP_TOLERANCE) within dt, moving on as they are, or with either one halted (if `may_halt_` it:
    it has something else to meet). The solve that follows may stop a body against something else (a
    light ball the heavy block drives into a wall); a kept gap between bodies that then part costs
    nothing, as the solver only stops approach. `gap` (their separation now) rules out at once
    bodies too slow to close it. `work`: scratch (`toi_work`); its motions must not hold the poses
    and velocities."""
    turn_a, turn_b = abs(vel_a[2]) * radius_a, abs(vel_b[2]) * radius_b
    end_a, end_b = work[4][2], work[4][3]
    for k in range(3):
        end_a[k] = pose_a[k] + vel_a[k] * dt
        end_b[k] = pose_b[k] + vel_b[k] * dt
    # Each motion (A's end, B's end), with the most it can close the gap by (no point moves
    # farther); too little, or no motion at all: skip it.
    moves_a = (end_a, pose_a, end_a)
    moves_b = (end_b, end_b, pose_b)
    least = (gap + GAP_TOLERANCE) / dt if dt > 0.0 else math.inf  # the speed `_closes` compares with
    speeds = (length_near(vel_a[0] - vel_b[0], vel_a[1] - vel_b[1], turn_a, turn_b, least, least),
              length_near(vel_b[0], vel_b[1], turn_b, 0.0, least, least),
              length_near(vel_a[0], vel_a[1], turn_a, 0.0, least, least))
    use = (_closes(end_a, end_b, pose_a, pose_b, speeds[0], True, dt, gap),
           _closes(pose_a, end_b, pose_a, pose_b, speeds[1], may_halt_a, dt, gap),
           _closes(end_a, pose_b, pose_a, pose_b, speeds[2], may_halt_b, dt, gap))
    if not (use[0] or use[1] or use[2]):
        return False
    for i in range(len(fa) - 1):
        for j in range(len(fb) - 1):
            posed, at_start = work[0], work[3]
            _separations(lva, lna, fa[i], fa[i + 1], pose_a[0], pose_a[1], pose_a[2], lvb, lnb, fb[j], fb[j + 1],
                         pose_b[0], pose_b[1], pose_b[2], False, posed[0], posed[1], posed[2], posed[3], False,
                         at_start)
            fresh = True  # the scratch holds both pieces as posed at the start, until an advancement moves them
            for m in range(3):
                if not use[m]:
                    continue
                if pair_time_of_impact(lva, lna, fa[i], fa[i + 1], ra[i], pose_a, moves_a[m], lvb, lnb, fb[j],
                                       fb[j + 1], rb[j], pose_b, moves_b[m], -GAP_TOLERANCE, GAP_TOLERANCE / 2, 0.0,
                                       at_start, True, work, fresh) < 1.0:
                    return True
                fresh = False
    return False


@inlined_kernel
def pairs_apart(lv: np.ndarray, ln: np.ndarray, first: np.ndarray, reach: np.ndarray, body_first: np.ndarray,
                pairs: np.ndarray, gaps: np.ndarray, state: np.ndarray, rows: np.ndarray, radius: np.ndarray,
                near_walls: np.ndarray, dt: float, apart: np.ndarray, pressed: np.ndarray) -> None:
    """The gap test for touching body pairs (shapes of a `ShapeTable` at rows `rows[q]` of a
    `body.BodyStore` state; gaps[g] the pair's smallest separation): `apart[g]` when the gap is
    wider than GAP_TOLERANCE and `pair_reaches` says the two would not close it this substep (a body
    may be halted if it has something else near: another pair, or a wall: q in `near_walls`), unless a push
    can reach it through a chain of pairs that do touch. `pressed[q]`: the body is in a pair that
    touches (or is pushed through such a chain).

    A kinematic body (a windmill's arm) is never halted by what it meets and passes no push on: each
    ball that meets it is judged as if alone with it (in a fan of shots, the other balls that met
    the arm changed a shot's contacts, and it ended elsewhere than played alone)."""
    busy = np.zeros(len(rows), dtype=np.int64)
    for g in range(len(pairs)):
        busy[pairs[g, 0]] += 1
        busy[pairs[g, 1]] += 1
    if len(pairs):
        for q in near_walls:
            busy[q] += 1
    _apart(lv, ln, first, reach, body_first, pairs, gaps, state, rows, radius, dt, apart, busy, np.empty((4, 3)),
           toi_work(widest(first)))
    pressed[:] = False
    _push_through(state, rows, pairs, apart, pressed)


@leaf_kernel
def _apart(lv: np.ndarray, ln: np.ndarray, first: np.ndarray, reach: np.ndarray, body_first: np.ndarray,
           pairs: np.ndarray, gaps: np.ndarray, state: np.ndarray, rows: np.ndarray, radius: np.ndarray, dt: float,
           apart: np.ndarray, busy: np.ndarray, poses: np.ndarray, work: tuple) -> None:
    """`pairs_apart`'s gap test pair by pair (`busy[q]`: how many pairs and walls body q has; `poses`
    and `work`, scratch). (A leaf: the views it takes of each pair's pieces cost nothing; in a kernel,
    each one is two atomic reference counts.)"""
    pose_a, vel_a, pose_b, vel_b = poses[0], poses[1], poses[2], poses[3]
    for g in range(len(pairs)):
        apart[g] = False
        if not gaps[g] > GAP_TOLERANCE:
            continue
        a, b = pairs[g, 0], pairs[g, 1]
        ka, kb = rows[a], rows[b]
        pa0, pa1, pb0, pb1 = body_first[a], body_first[a + 1], body_first[b], body_first[b + 1]
        pose_a[0], pose_a[1], pose_a[2] = state[ka, X], state[ka, Y], state[ka, ANGLE]
        vel_a[0], vel_a[1], vel_a[2] = state[ka, VX], state[ka, VY], state[ka, SPIN]
        pose_b[0], pose_b[1], pose_b[2] = state[kb, X], state[kb, Y], state[kb, ANGLE]
        vel_b[0], vel_b[1], vel_b[2] = state[kb, VX], state[kb, VY], state[kb, SPIN]
        apart[g] = not pair_reaches(
            lv, ln, first[pa0:pa1 + 1], reach[pa0:pa1], radius[a], pose_a, vel_a,
            lv, ln, first[pb0:pb1 + 1], reach[pb0:pb1], radius[b], pose_b, vel_b,
            dt, gaps[g], busy[a] > 1 and state[ka, INV_MASS] > 0.0, busy[b] > 1 and state[kb, INV_MASS] > 0.0, work)


@leaf_kernel
def _push_through(state: np.ndarray, rows: np.ndarray, pairs: np.ndarray, apart: np.ndarray,
                  pressed: np.ndarray) -> None:
    """`pairs_apart`'s chains: which bodies are pressed, and the pairs a push reaches through."""
    grew = False
    for g in range(len(pairs)):
        if not apart[g]:
            grew |= _press(state, rows, pressed, pairs[g, 0]) | _press(state, rows, pressed, pairs[g, 1])
    while grew:  # through a chain of gaps, a push can reach: keep those contacts too
        grew = False
        for g in range(len(pairs)):
            if apart[g] and (pressed[pairs[g, 0]] or pressed[pairs[g, 1]]):
                apart[g], grew = False, True
                _press(state, rows, pressed, pairs[g, 0])
                _press(state, rows, pressed, pairs[g, 1])


@inlined_leaf
def _press(state: np.ndarray, rows: np.ndarray, pressed: np.ndarray, q: int) -> bool:
    """Mark body q pressed, if it is dynamic (a push goes through it); returns whether it was marked."""
    if state[rows[q], INV_MASS] == 0.0:
        return False
    pressed[q] = True
    return True


@warm_up("continuous collision")
def _warm() -> None:
    square = ConvexSet.of([((0.5, -0.5), (0.5, 0.5), (-0.5, 0.5), (-0.5, -0.5))],
                          [((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))])
    wall = ConvexSet.of([((2.0, -1.0), (3.0, -1.0), (3.0, 1.0), (2.0, 1.0))],
                        [((0.0, -1.0), (1.0, 0.0), (0.0, 1.0), (-1.0, 0.0))])
    start, end, still = np.array([0.0, 0.0, 0.0]), np.array([2.0, 0.0, 0.5]), np.array([3.0, 3.0, 0.0])
    args = (square.verts, square.normals, square.first, square.reach)
    table = ShapeTable.of([square, square])
    grid = BoxGrid(np.array([[2.0, -1.0, 3.0, 1.0]]), 1.0)
    state = np.zeros((2, len(COLUMNS)))
    state[:, INV_MASS] = 1.0
    state[1, X], state[1, ANGLE] = 2.0, 0.5
    first_wall_hits(table.pieces.verts, table.pieces.normals, table.pieces.first, table.pieces.reach,
                    table.body_first, state, np.array([0, 1], dtype=np.int64), np.full(2, 0.71), 0.005, grid.arrays,
                    FatBoxes().of(state, 1), np.zeros(1, dtype=np.bool_), np.empty(1, dtype=np.int64), wall.verts,
                    wall.normals, wall.first, np.zeros(4, dtype=np.bool_), np.zeros(4, dtype=np.int8), 0.005, 0.001,
                    0.005, 0.0025, np.empty(2),
                    toi_work(4), np.empty((2, 4)))
    first_pair_hit(*args, start, end, *args, still, still, 0.005, 0.001, 0.005, toi_work(4))
    body_pair_hits(table.pieces.verts, table.pieces.normals, table.pieces.first, table.pieces.reach,
                   table.body_first, np.array([[0, 1]], dtype=np.int64), state, np.array([0, 1], dtype=np.int64),
                   np.full(2, 0.71), np.full(2, 1.0), True, False, 0.005, 0.005, 0.001, 0.005, np.ones(2), np.ones(1))
    pairs_apart(table.pieces.verts, table.pieces.normals, table.pieces.first, table.pieces.reach, table.body_first,
                np.array([[0, 1]], dtype=np.int64), np.array([0.01]), state, np.array([0, 1], dtype=np.int64),
                np.full(2, 0.71), np.zeros(1, dtype=np.int64), 1.0 / 240.0, np.zeros(1, dtype=np.bool_),
                np.zeros(2, dtype=np.bool_))
    reaches_wall(*args, 0.0, 0.0, 0.0, 2.0, 0.0, 0.5, 1.0 / 240.0, wall.verts, wall.normals, 0, 4, toi_work(4))
    pair_reaches(*args, 0.7, start, end, *args, 0.7, still, end, 1.0 / 240.0, 0.01, True, True, toi_work(4))
