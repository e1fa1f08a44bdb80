"""A substep's contacts as one table of arrays: manifolds between two bodies, merged across convex pieces.

A non-convex body touches a wall through several convex pieces. Solving each piece's contact on its
own is the original PolyGolf fault (a star landing flat on two tips got two full impulses). Here every
point between the same two bodies that shares a normal goes into one manifold, reduced to the two
points that span the contact, and the solver treats those two points as one block.

`build_contacts` makes the table from the narrowphase's contact rows (`collide.ROW` columns) in one
compiled call, `carry_impulses` warm-starts it from the last substep's table (`find_contacts`, the
narrowphase's whole substep, puts it into a `TableSlot`); the solver, the restitution phase, the
bumper and the impacts stage read and write the same arrays. `ContactTable.manifolds` shows a table
as `Manifold` objects (for tests and tools; the step never builds one), `table_of`
makes a table of hand-made ones.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

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
    bodies_pair_contacts,
    bodies_wall_contacts,
    close_to_walls,
    kept_pairs,
)
from polygolf.engine.physics.geometry import ConvexSet, ShapeTable
from polygolf.engine.physics.jit import counted_kernel, inlined_kernel, kernel, leaf_kernel, structure, warm_up
from polygolf.engine.physics.motion import wake_pairs
from polygolf.engine.physics.settings import RESTITUTION_THRESHOLD
from polygolf.engine.physics.toi import pairs_apart

# Normals closer than this (cosine) are the same contact plane.
SAME_NORMAL_COS = math.cos(math.radians(2.0))

# Columns of a manifold row (`ContactTable.normals`): its normal (from A to B) and its block matrix
# (the solver fills it for two-point manifolds).
M_NX, M_NY, M_K11, M_K12, M_K22 = range(5)
MANIFOLD_COLUMNS = 5
# Columns of a point row (`ContactTable.points`): what the narrowphase made (P_X..P_FRICTION), the
# solver's state (P_NORMAL_IMPULSE..P_APPROACH), the local geometry NGS reads (P_REF_IS_A..P_LQY: the
# reference face's normal and a point on it in the reference body's frame, the incident point in
# its body's frame) and the restitution.
P_X, P_Y, P_SEP, P_FRICTION, P_NORMAL_IMPULSE, P_TANGENT_IMPULSE, P_PUSH_IMPULSE, P_RA_X, P_RA_Y, P_RB_X, P_RB_Y, \
    P_NORMAL_MASS, P_TANGENT_MASS, P_APPROACH, P_REF_IS_A, P_LNX, P_LNY, P_LFX, P_LFY, P_LQX, P_LQY, \
    P_RESTITUTION = range(22)
POINT_COLUMNS = 22
# Columns of a point's key (`ContactTable.keys`), which matches it across substeps together with
# its manifold's entity A: the other entity (a wall contact: the wall's entity; else body B's),
# the other side's piece (a wall's: its index among that wall's pieces), A's piece, the feature.
K_OTHER, K_PIECE, K_OWN, K_FEATURE = range(4)
KEY_COLUMNS = 4


@dataclass(slots=True)
class ContactPoint:
    x: float
    y: float
    separation: float
    key: tuple  # (other piece, own piece, feature), a wall's (wall entity, its piece, own piece, feature)
    restitution: float
    friction: float
    # Local geometry for non-linear position correction: the reference face in its body's frame and
    # the incident point in its body's frame.
    ref_is_a: bool = True
    local_normal: tuple[float, float] = (0.0, 0.0)
    local_face: tuple[float, float] = (0.0, 0.0)
    local_clip: tuple[float, float] = (0.0, 0.0)
    # Solver state.
    ra_x: float = 0.0
    ra_y: float = 0.0
    rb_x: float = 0.0
    rb_y: float = 0.0
    normal_mass: float = 0.0
    tangent_mass: float = 0.0
    normal_impulse: float = 0.0
    tangent_impulse: float = 0.0
    push_impulse: float = 0.0
    approach_speed: float = 0.0  # relative normal velocity before solving; negative when closing


@dataclass(slots=True)
class Manifold:
    """Up to two points between body A and body B sharing one normal (from A to B): a row of a
    `ContactTable` as an object, or a hand-made one for `table_of`."""

    entity_a: int
    entity_b: int  # -1 for the static world
    body_a: Body
    body_b: Body
    nx: float
    ny: float
    points: list[ContactPoint] = field(default_factory=list)
    # Block solver data for two-point manifolds (filled by the solver).
    k11: float = 0.0
    k12: float = 0.0
    k22: float = 0.0
    block: bool = False


def _point_row(p: ContactPoint) -> tuple[float, ...]:
    """A point's row, P_ columns in order."""
    return (p.x, p.y, p.separation, p.friction, p.normal_impulse, p.tangent_impulse, p.push_impulse, p.ra_x, p.ra_y,
            p.rb_x, p.rb_y, p.normal_mass, p.tangent_mass, p.approach_speed, float(p.ref_is_a), *p.local_normal,
            *p.local_face, *p.local_clip, p.restitution)


def _point_of(row: list[float], key: tuple) -> ContactPoint:
    """`_point_row` the other way."""
    (x, y, sep, friction, normal, tangent, push, rax, ray, rbx, rby, normal_mass, tangent_mass, approach, ref_is_a,
     lnx, lny, lfx, lfy, lqx, lqy, restitution) = row
    return ContactPoint(x=x, y=y, separation=sep, key=key, restitution=restitution, friction=friction,
                        ref_is_a=ref_is_a != 0.0, local_normal=(lnx, lny), local_face=(lfx, lfy),
                        local_clip=(lqx, lqy), ra_x=rax, ra_y=ray, rb_x=rbx, rb_y=rby, normal_mass=normal_mass,
                        tangent_mass=tangent_mass, normal_impulse=normal, tangent_impulse=tangent, push_impulse=push,
                        approach_speed=approach)


@dataclass(slots=True)
class ContactTable:
    """One substep's manifolds and their points. Manifold k: entities `ents[k]` (A, B; B = -1 for
    the static world), body rows `pair[k]` (rows of `store.state`; the static world is the row after
    the store's, `len(store.state)`), `normals[k]` (M_ columns), `block[k]`
    (solved as a block: written by the solver), its points rows first[k]:first[k + 1] of `points`
    (P_ columns) and `keys` (K_ columns)."""

    ents: np.ndarray  # (m, 2) int64
    pair: np.ndarray  # (m, 2) int64
    normals: np.ndarray  # (m, MANIFOLD_COLUMNS) float64
    block: np.ndarray  # (m,) bool
    first: np.ndarray  # (m + 1,) int64
    points: np.ndarray  # (points, POINT_COLUMNS) float64
    keys: np.ndarray  # (points, KEY_COLUMNS) int64
    store: BodyStore | None = None  # whose rows `pair` names
    static: Body | None = None  # the static world's stand-in body

    @classmethod
    def empty(cls) -> ContactTable:
        return cls(np.zeros((0, 2), dtype=np.int64), np.zeros((0, 2), dtype=np.int64), np.zeros((0, MANIFOLD_COLUMNS)),
                   np.zeros(0, dtype=np.bool_), np.zeros(1, dtype=np.int64), np.zeros((0, POINT_COLUMNS)),
                   np.zeros((0, KEY_COLUMNS), dtype=np.int64))

    def __len__(self) -> int:
        return len(self.pair)

    @property
    def arrays(self) -> tuple[np.ndarray, ...]:
        """The columns as a kernel takes them: ents, pair, normals, block, first, points, keys."""
        return self.ents, self.pair, self.normals, self.block, self.first, self.points, self.keys

    def body(self, row: int) -> Body:
        return self.static if row == len(self.store.state) else self.store.handle(row)

    def manifolds(self) -> list[Manifold]:
        """The table as objects, a snapshot (tests and tools read it; the step never does)."""
        points, keys, first = self.points.tolist(), self.keys.tolist(), self.first.tolist()
        out = []
        for k, ((ea, eb), (ra, rb), (nx, ny, k11, k12, k22), block) in enumerate(
                zip(self.ents.tolist(), self.pair.tolist(), self.normals.tolist(), self.block.tolist())):
            own = [_point_of(points[p], tuple(keys[p]) if eb == -1 else tuple(keys[p][K_PIECE:]))
                   for p in range(first[k], first[k + 1])]
            out.append(Manifold(ea, eb, self.body(ra), self.body(rb), nx, ny, own, k11, k12, k22, block))
        return out


def table_of(manifolds: Sequence[Manifold], store: BodyStore, static: Body) -> ContactTable:
    """A table of hand-made manifolds (tests, the warm-up): every body is `static` or one of
    `store`'s (by identity). A key is padded with zeros to its columns (a body pair's after entity B)."""
    row_of = {id(body): k for k, body in enumerate(store.bodies)}
    row_of[id(static)] = len(store.state)
    count = len(manifolds)
    ents = np.array([(m.entity_a, m.entity_b) for m in manifolds], dtype=np.int64).reshape(count, 2)
    pair = np.array([(row_of[id(m.body_a)], row_of[id(m.body_b)]) for m in manifolds], dtype=np.int64)
    normals = np.zeros((count, MANIFOLD_COLUMNS))
    normals[:, M_NX:M_NY + 1] = np.array([(m.nx, m.ny) for m in manifolds]).reshape(count, 2)
    first = np.zeros(count + 1, dtype=np.int64)
    first[1:] = np.cumsum([len(m.points) for m in manifolds])
    points = np.array([_point_row(p) for m in manifolds for p in m.points], dtype=np.float64)
    keys = np.array([((*p.key, 0, 0, 0, 0) if m.entity_b == -1 else (m.entity_b, *p.key, 0, 0, 0))[:KEY_COLUMNS]
                     for m in manifolds for p in m.points], dtype=np.int64)
    return ContactTable(ents, pair.reshape(count, 2), normals, np.zeros(count, dtype=np.bool_), first,
                        points.reshape(-1, POINT_COLUMNS), keys.reshape(-1, KEY_COLUMNS), store, static)


# Where `find_contacts` puts the table it makes (`TableSlot.table`, `ContactTable.arrays`): a kernel a
# leaf may call returns no array, and the narrowphase's stage is a leaf (`systems.narrowphase.touch`),
# which takes its tuples apart without counting a reference to each array in them.
TableSlot = structure(__name__, "TableSlot", ["table"],
                      "A contact table's columns (`table`), as a kernel puts them there.")


@kernel
def table_slot(table: tuple) -> TableSlot:
    """A slot holding `table` (`ContactTable.arrays`), for `find_contacts` to put the next one in."""
    return TableSlot(table)


@kernel
def slot_table(slot: TableSlot) -> tuple:
    """The table a slot holds."""
    return slot.table


# --- the kernels ------------------------------------------------------------------------------------

@leaf_kernel
def _reduce(rows: np.ndarray, member: np.ndarray, count: int, nx: float, ny: float, chosen: np.ndarray) -> int:
    """Keep the two points (rows `member[:count]`) that span the contact along the tangent, into
    `chosen`; returns how many. The least (tangent position, separation) and the greatest (tangent
    position, -separation), the first of equals, as Python's min and max on those tuples; if that is
    one point, the deepest alone. Two or fewer are kept as they are."""
    if count <= 2:
        for c in range(count):
            chosen[c] = member[c]
        return count
    tx, ty = ny, -nx
    lo = hi = member[0]
    lo_t = hi_t = rows[lo, X] * tx + rows[lo, Y] * ty
    lo_s = rows[lo, SEP]
    hi_s = -rows[lo, SEP]
    for c in range(1, count):
        r = member[c]
        t = rows[r, X] * tx + rows[r, Y] * ty
        s = rows[r, SEP]
        if (t < lo_t) if t != lo_t else (s < lo_s):  # a tuple's <: the first element that differs decides
            lo, lo_t, lo_s = r, t, s
        if (t > hi_t) if t != hi_t else (-s > hi_s):
            hi, hi_t, hi_s = r, t, -s
    if lo == hi:
        deepest = member[0]
        for c in range(1, count):
            if rows[member[c], SEP] < rows[deepest, SEP]:
                deepest = member[c]
        chosen[0] = deepest
        return 1
    chosen[0], chosen[1] = lo, hi
    return 2


@leaf_kernel
def _pose(state: np.ndarray, static: np.ndarray, row: int) -> tuple[float, float, float]:
    if row == state.shape[0]:
        return static[B_X], static[B_Y], static[B_ANGLE]
    return state[row, B_X], state[row, B_Y], state[row, B_ANGLE]


@leaf_kernel
def _to_local(x: float, y: float, angle: float, px: float, py: float) -> tuple[float, float]:
    """World point (px, py) in the frame of a body at (x, y, angle)."""
    c, s = math.cos(angle), math.sin(angle)
    dx, dy = px - x, py - y
    return c * dx + s * dy, -s * dx + c * dy


@leaf_kernel
def _local_geometry(rows: np.ndarray, r: int, state: np.ndarray, static: np.ndarray, row_a: int, row_b: int,
                    points: np.ndarray, p: int) -> None:
    """What NGS re-measures a point by: the reference face (normal, a point on it) in its body's
    frame, the incident point in its body's frame."""
    ref_is_a = rows[r, REF_IS_A] != 0.0
    ref, inc = (row_a, row_b) if ref_is_a else (row_b, row_a)
    fnx, fny = (rows[r, NX], rows[r, NY]) if ref_is_a else (-rows[r, NX], -rows[r, NY])
    x, y, angle = _pose(state, static, ref)
    c, s = math.cos(angle), math.sin(angle)
    points[p, P_LNX], points[p, P_LNY] = c * fnx + s * fny, -s * fnx + c * fny
    points[p, P_LFX], points[p, P_LFY] = _to_local(x, y, angle, rows[r, FACE_X], rows[r, FACE_Y])
    x, y, angle = _pose(state, static, inc)
    points[p, P_LQX], points[p, P_LQY] = _to_local(x, y, angle, rows[r, CLIP_X], rows[r, CLIP_Y])


@leaf_kernel
def _add_group(rows: np.ndarray, s: int, e: int, ea: int, eb: int, row_a: int, row_b: int, restitution: float,
               friction: float, other: np.ndarray, wall_materials: np.ndarray, wall_owner: np.ndarray,
               wall_index: np.ndarray, state: np.ndarray, static: np.ndarray, ngs: bool, ents: np.ndarray,
               pair: np.ndarray, normals: np.ndarray, first: np.ndarray, points: np.ndarray, keys: np.ndarray,
               scratch: np.ndarray, m: int, p: int) -> tuple[int, int, float]:
    """The manifolds of rows s:e, every contact between two bodies (entities ea, eb; eb = -1: the
    static world, each row's PIECE_B a wall piece), appended to the table's arrays at manifold m and
    point p: planes of (nearly) equal normal, in the order each plane first comes and with its first
    row's normal, each one manifold of at most two points (`_reduce`). A's restitution and friction
    multiply B's (`other`, or a wall piece's `wall_materials`); with `ngs`, each point gets its local
    geometry. Returns the next m and p, and the deepest overlap of the points kept (at least 0)."""
    plane, plane_row, member, chosen = scratch[0], scratch[1], scratch[2], scratch[3]
    planes = 0
    for r in range(s, e):
        nx, ny = rows[r, NX], rows[r, NY]
        plane[r - s] = -1
        for j in range(planes):
            q = plane_row[j]
            if rows[q, NX] * nx + rows[q, NY] * ny >= SAME_NORMAL_COS:
                plane[r - s] = j
                break
        if plane[r - s] < 0:
            plane_row[planes] = r
            plane[r - s] = planes
            planes += 1
    wall = eb == -1
    overlap = 0.0
    for j in range(planes):
        count = 0
        for r in range(s, e):
            if plane[r - s] == j:
                member[count] = r
                count += 1
        nx, ny = rows[plane_row[j], NX], rows[plane_row[j], NY]
        for c in range(_reduce(rows, member, count, nx, ny, chosen)):
            r = chosen[c]
            points[p, P_X], points[p, P_Y], points[p, P_SEP] = rows[r, X], rows[r, Y], rows[r, SEP]
            if wall:
                piece = int(rows[r, PIECE_B])
                rb, fb = wall_materials[piece, 0], wall_materials[piece, 1]
                keys[p, K_OTHER], keys[p, K_PIECE] = wall_owner[piece], wall_index[piece]
            else:
                rb, fb = other[0], other[1]
                keys[p, K_OTHER], keys[p, K_PIECE] = eb, int(rows[r, PIECE_B])
            keys[p, K_OWN], keys[p, K_FEATURE] = int(rows[r, PIECE_A]), int(rows[r, FEATURE])
            points[p, P_RESTITUTION] = restitution * rb
            points[p, P_FRICTION] = friction * fb
            points[p, P_REF_IS_A] = 1.0 if rows[r, REF_IS_A] != 0.0 else 0.0
            if ngs:
                _local_geometry(rows, r, state, static, row_a, row_b, points, p)
            if -rows[r, SEP] > overlap:
                overlap = -rows[r, SEP]
            p += 1
        ents[m, 0], ents[m, 1] = ea, eb
        pair[m, 0], pair[m, 1] = row_a, row_b
        normals[m, M_NX], normals[m, M_NY] = nx, ny
        m += 1
        first[m] = p
    return m, p, overlap


@inlined_kernel
def build_contacts(wall_rows: np.ndarray, near_ents: np.ndarray, near_rows: np.ndarray, near_materials: np.ndarray,
                   wall_materials: np.ndarray, wall_owner: np.ndarray, wall_index: np.ndarray,
                   pair_rows: np.ndarray, pair_first: np.ndarray, pair_ents: np.ndarray, pair_body_rows: np.ndarray,
                   pair_materials: np.ndarray, state: np.ndarray, static: np.ndarray, ngs: bool, deepest: float
                   ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, float]:
    """The table of one substep's contact rows (`_add_group` for each two bodies that touch), walls
    first. `wall_rows`: bodies' rows against wall pieces, body by body (body q = column BODY is
    entity `near_ents[q]`, row `near_rows[q]` of `state`, of restitution and friction
    `near_materials[q]`; a wall piece's material, entity and index there come from `wall_materials`,
    `wall_owner`, `wall_index`). Then body pairs: pair g is `pair_rows[pair_first[g]:pair_first[g +
    1]]` between entities `pair_ents[g]`, rows `pair_body_rows[g]`, materials `pair_materials[g]`
    (A's restitution and friction, then B's). The static world is the row after `state`'s, its pose
    `static`. Impulses start at zero (`carry_impulses` warm-starts them).

    Returns ents, pair, normals, first, points, keys (without `block`) and the deepest overlap of any
    point kept, or `deepest` if that is deeper."""
    n = wall_rows.shape[0] + pair_rows.shape[0]
    ents = np.empty((n, 2), dtype=np.int64)
    pair = np.empty((n, 2), dtype=np.int64)
    normals = np.zeros((n, MANIFOLD_COLUMNS))
    first = np.zeros(n + 1, dtype=np.int64)
    points = np.zeros((n, POINT_COLUMNS))
    keys = np.empty((n, KEY_COLUMNS), dtype=np.int64)
    scratch = np.empty((4, max(n, 2)), dtype=np.int64)
    m, p, deepest = _fill_table(wall_rows, near_ents, near_rows, near_materials, wall_materials, wall_owner, wall_index,
                                pair_rows, pair_first, pair_ents, pair_body_rows, pair_materials, state, static, ngs,
                                deepest, ents, pair, normals, first, points, keys, scratch)
    return ents[:m], pair[:m], normals[:m], first[:m + 1], points[:p], keys[:p], deepest


@leaf_kernel
def _fill_table(wall_rows: np.ndarray, near_ents: np.ndarray, near_rows: np.ndarray, near_materials: np.ndarray,
                wall_materials: np.ndarray, wall_owner: np.ndarray, wall_index: np.ndarray, pair_rows: np.ndarray,
                pair_first: np.ndarray, pair_ents: np.ndarray, pair_body_rows: np.ndarray, pair_materials: np.ndarray,
                state: np.ndarray, static: np.ndarray, ngs: bool, deepest: float, ents: np.ndarray, pair: np.ndarray,
                normals: np.ndarray, first: np.ndarray, points: np.ndarray, keys: np.ndarray, scratch: np.ndarray
                ) -> tuple[int, int, float]:
    """`build_contacts`' work into its arrays: how many manifolds and points, and the deepest
    overlap. (A leaf: in a kernel, each group's call and the views it takes counted references.)"""
    static_row = state.shape[0]
    m = p = 0
    s = 0
    while s < wall_rows.shape[0]:
        q = int(wall_rows[s, BODY])
        e = s + 1
        while e < wall_rows.shape[0] and wall_rows[e, BODY] == wall_rows[s, BODY]:
            e += 1
        m, p, overlap = _add_group(wall_rows, s, e, near_ents[q], -1, near_rows[q], static_row, near_materials[q, 0],
                                   near_materials[q, 1], near_materials[q], wall_materials, wall_owner, wall_index,
                                   state, static, ngs, ents, pair, normals, first, points, keys, scratch, m, p)
        if overlap > deepest:
            deepest = overlap
        s = e
    for g in range(pair_ents.shape[0]):
        m, p, overlap = _add_group(pair_rows, pair_first[g], pair_first[g + 1], pair_ents[g, 0], pair_ents[g, 1],
                                   pair_body_rows[g, 0], pair_body_rows[g, 1], pair_materials[g, 0],
                                   pair_materials[g, 1], pair_materials[g, 2:], wall_materials, wall_owner,
                                   wall_index, state, static, ngs, ents, pair, normals, first, points, keys, scratch,
                                   m, p)
        if overlap > deepest:
            deepest = overlap
    return m, p, deepest


@leaf_kernel
def _compare(ids: np.ndarray, i: int, ent: int, keys: np.ndarray, p: int) -> int:
    """-1, 0 or 1 as carried id i is before, equal to or after (ent, keys[p]), in lexicographic order."""
    if ids[i, 0] != ent:
        return -1 if ids[i, 0] < ent else 1
    for c in range(KEY_COLUMNS):
        if ids[i, c + 1] != keys[p, c]:
            return -1 if ids[i, c + 1] < keys[p, c] else 1
    return 0


@leaf_kernel
def _id_order(ids: np.ndarray, i: int, j: int) -> int:
    """-1, 0 or 1 as carried id i is before, equal to or after carried id j, in lexicographic order."""
    for c in range(KEY_COLUMNS + 1):
        if ids[i, c] != ids[j, c]:
            return -1 if ids[i, c] < ids[j, c] else 1
    return 0


@leaf_kernel
def _sort_ids(ids: np.ndarray, order: np.ndarray, spare: np.ndarray) -> None:
    """`order` (rows of `ids`) sorted by those rows in lexicographic order, equal ones kept in their
    order: a bottom-up merge sort through `spare` (as long), allocating nothing (numpy's argsort,
    once a column, made three arrays each time)."""
    c = len(order)
    source, target = order, spare
    width, in_spare = 1, False
    while width < c:
        for lo in range(0, c, 2 * width):
            mid, hi = min(lo + width, c), min(lo + 2 * width, c)
            i, j = lo, mid
            for k in range(lo, hi):
                if j < hi and (i >= mid or _id_order(ids, source[j], source[i]) < 0):
                    target[k] = source[j]
                    j += 1
                else:
                    target[k] = source[i]
                    i += 1
        source, target = target, source
        width, in_spare = 2 * width, not in_spare
    if in_spare:  # (an odd number of passes)
        for k in range(c):
            order[k] = spare[k]


@inlined_kernel
def carry_impulses(old_ents: np.ndarray, old_first: np.ndarray, old_keys: np.ndarray, old_points: np.ndarray,
                   ents: np.ndarray, first: np.ndarray, keys: np.ndarray, points: np.ndarray,
                   threshold: float) -> int:
    """Warm starting: each point of the new table whose (entity A, key) was a point of the old one
    that was pushing (a normal or tangent impulse) and resting (approach speed >= -threshold) starts
    with that point's impulses; of equal old ones, the last. Only persistent contacts are
    warm-started: an impact's impulse belongs to that impact, and re-applying it to a contact that
    is now opening would add energy. Returns how many points were carried."""
    ids = np.empty((old_keys.shape[0], KEY_COLUMNS + 1), dtype=np.int64)
    source = np.empty(old_keys.shape[0], dtype=np.int64)
    c = 0
    for k in range(old_ents.shape[0]):
        for p in range(old_first[k], old_first[k + 1]):
            if ((old_points[p, P_NORMAL_IMPULSE] != 0.0 or old_points[p, P_TANGENT_IMPULSE] != 0.0)
                    and old_points[p, P_APPROACH] >= -threshold):
                ids[c, 0] = old_ents[k, 0]
                for col in range(KEY_COLUMNS):
                    ids[c, col + 1] = old_keys[p, col]
                source[c] = p
                c += 1
    if c == 0:
        return 0
    order = np.arange(c)
    _sort_ids(ids, order, np.empty(c, dtype=np.int64))
    carried = 0
    for k in range(ents.shape[0]):
        for p in range(first[k], first[k + 1]):
            lo, hi = 0, c  # the first carried id after the point's
            while lo < hi:
                mid = (lo + hi) // 2
                if _compare(ids, order[mid], ents[k, 0], keys, p) <= 0:
                    lo = mid + 1
                else:
                    hi = mid
            if lo > 0 and _compare(ids, order[lo - 1], ents[k, 0], keys, p) == 0:
                q = source[order[lo - 1]]
                points[p, P_NORMAL_IMPULSE] = old_points[q, P_NORMAL_IMPULSE]
                points[p, P_TANGENT_IMPULSE] = old_points[q, P_TANGENT_IMPULSE]
                carried += 1
    return carried


@leaf_kernel
def nothing_to_touch(state: np.ndarray, shapes: tuple, walls: tuple, candidates: tuple, margin: float) -> bool:
    """Whether `find_contacts` would find no contact at all for these candidates: no body pair, and
    no body within `margin` of a wall piece near it (`collide.close_to_walls`). Asked first, for
    nothing (a leaf), where a lone ball near a wall but clear of it spends most substeps."""
    near_ents, near_first, near_found, pair_ents = candidates
    rows, radius, lookup = shapes[5], shapes[6], shapes[10]
    wv, wn, wall_first = walls[0][0], walls[0][1], walls[0][2]
    if len(pair_ents):
        return False
    for q in range(len(near_ents)):
        shape = lookup[near_ents[q]]
        k = rows[shape]
        if close_to_walls(wv, wn, wall_first, near_found, near_first[q], near_first[q + 1], state[k, B_X],
                          state[k, B_Y], radius[shape], margin):
            return False
    return True


@counted_kernel
def find_contacts(slot: TableSlot, lv: np.ndarray, ln: np.ndarray, first: np.ndarray, reach: np.ndarray,
                  body_first: np.ndarray, state: np.ndarray, store_rows: np.ndarray, radius: np.ndarray,
                  materials: np.ndarray, ents: np.ndarray, lookup: np.ndarray, pair_ents: np.ndarray,
                  near_ents: np.ndarray, near_first: np.ndarray, near_found: np.ndarray, walls: tuple,
                  wall_materials: np.ndarray, wall_owner: np.ndarray, wall_index: np.ndarray, static: np.ndarray,
                  dt: float, margin: float, ngs: bool, deepest: float, old_ents: np.ndarray, old_first: np.ndarray,
                  old_keys: np.ndarray, old_points: np.ndarray, warm: bool, threshold: float) -> float:
    """The narrowphase in one call: this substep's contact table (`build_contacts`' columns and a
    `block` of False, as `ContactTable.arrays`) put into `slot.table`, for the broadphase's
    candidates, warm-started from the last one's (`carry_impulses`, with `warm`); returns the
    deepest overlap of any point kept, or `deepest` if that is deeper. (A kernel a leaf may call,
    `counted_kernel`: the table goes into the slot, not back.) Bodies are shapes of a
    `geometry.ShapeTable` (lv .. body_first) at rows `store_rows` of a `body.BodyStore` state, with
    bounding radii, materials and entities; `lookup[entity]` is its shape. Candidates: body pairs
    (entities), and the bodies with wall pieces near (entities, their pieces in compressed rows).
    `walls` is the static world's `arrays`, `static` its stand-in body's row.

    Pairs first (their rows go after the walls', as always): a body another one presses on this
    substep can be pushed into a wall it is not moving towards yet, so its wall gaps must stay
    contacts. A contact with a gap acts only if the bodies, moving on as they are, would close it
    within the substep (`collide.wall_contacts`, `toi.pairs_apart`)."""
    # Empty arrays are made once and shared where nothing is to be made (numba counts each one it
    # makes, however small): without pairs, the candidates' own empty pairs stand for them.
    n = len(store_rows)
    pressed = np.zeros(n, dtype=np.bool_)
    no_rows, zero_first = np.empty((0, ROW)), np.zeros(1, dtype=np.int64)
    pairs, pair_rows, pair_first, gaps = pair_ents, no_rows, zero_first, np.empty(0)
    if len(pair_ents):
        shapes = np.empty((len(pair_ents), 2), dtype=np.int64)
        for g in range(len(pair_ents)):
            shapes[g, 0], shapes[g, 1] = lookup[pair_ents[g, 0]], lookup[pair_ents[g, 1]]
        poses = np.empty((n, 3))
        for q in range(n):
            poses[q, 0], poses[q, 1], poses[q, 2] = state[store_rows[q], B_X], state[store_rows[q], B_Y], \
                state[store_rows[q], B_ANGLE]
        pair_rows, pair_first, pairs, gaps = bodies_pair_contacts(lv, ln, first, body_first, shapes, poses, radius,
                                                                  margin)
    apart = np.zeros(len(pairs), dtype=np.bool_)
    if len(pairs):
        pairs_apart(lv, ln, first, reach, body_first, pairs, gaps, state, store_rows, radius, lookup[near_ents], dt,
                    apart, pressed)

    # The contact rows against walls (body by body), then between bodies (pair by pair).
    wall_rows, near = no_rows, near_found[:0]
    if len(near_ents):
        near = lookup[near_ents]
        held = pressed[near]
        moving = np.empty((len(near), 6))
        for q in range(len(near)):
            for c in range(6):
                moving[q, c] = state[store_rows[near[q]], B_X + c]
        wall_rows = bodies_wall_contacts(lv, ln, first, reach, body_first, near, radius, moving, held, near_first,
                                         near_found, walls, dt, margin)
    kept_rows, kept_first, kept_ents, kept_bodies, kept_materials = no_rows, zero_first, pairs, pairs, \
        np.empty((0, 4))
    if len(pairs):  # as for walls: bodies that will not meet do not touch
        kept_rows, kept_first, kept_ents, kept_bodies, kept_materials = kept_pairs(
            pair_rows, pair_first, pairs, apart, ents, store_rows, materials)
        if len(kept_ents):
            wake_pairs(state, kept_bodies)
    if not len(wall_rows) and not len(kept_ents):
        slot.table = (kept_ents, kept_ents, np.zeros((0, MANIFOLD_COLUMNS)), np.zeros(0, dtype=np.bool_), zero_first,
                      np.zeros((0, POINT_COLUMNS)), np.zeros((0, KEY_COLUMNS), dtype=np.int64))
        return deepest
    near_rows, near_materials = store_rows[near], materials[near]
    new_ents, pair, normals, new_first, points, keys, deepest = build_contacts(
        wall_rows, near_ents, near_rows, near_materials, wall_materials, wall_owner, wall_index, kept_rows, kept_first,
        kept_ents, kept_bodies, kept_materials, state, static, ngs, deepest)
    if warm and len(old_ents):
        carry_impulses(old_ents, old_first, old_keys, old_points, new_ents, new_first, keys, points, threshold)
    slot.table = (new_ents, pair, normals, np.zeros(len(pair), dtype=np.bool_), new_first, points, keys)
    return deepest


@warm_up("contact table")
def _warm() -> None:
    state = np.zeros((2, len(COLUMNS)))
    state[:, B_Y] = 0.5, 1.5
    rows = np.zeros((4, ROW))
    rows[:, X] = -0.5, 0.5, 0.0, 0.2
    rows[:, NY] = -1.0, -1.0, -1.0, 1.0
    rows[:, SEP] = -0.01
    rows[:, FEATURE] = 1.0, 2.0, 3.0, 4.0
    rows[3, REF_IS_A] = 1.0
    one = np.zeros(1, dtype=np.int64)
    for ngs in (False, True):
        ents, pair, normals, first, points, keys, _ = build_contacts(
            rows[:3], one, one, np.full((1, 2), 0.5), np.ones((1, 2)), one, one, rows[3:],
            np.array([0, 1], dtype=np.int64), np.array([[1, 2]], dtype=np.int64), np.array([[0, 1]], dtype=np.int64),
            np.full((1, 4), 0.5), state, np.zeros(len(COLUMNS)), ngs, 0.0)
        points[:, P_NORMAL_IMPULSE] = 1.0
        carry_impulses(ents, first, keys, points, ents, first, keys, points.copy(), RESTITUTION_THRESHOLD)
    # Two squares, one on the other, the lower one on a floor: pairs, walls and a warm start.
    square = ((0.5, -0.5), (0.5, 0.5), (-0.5, 0.5), (-0.5, -0.5))
    normals = ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))
    table = ShapeTable.of([ConvexSet.of([square], [normals])] * 2)
    floor = ConvexSet.of([((-5.0, -1.0), (5.0, -1.0), (5.0, 0.0), (-5.0, 0.0))], [normals[3:] + normals[:3]])
    walls = (floor.verts, floor.normals, floor.first, np.zeros(4, dtype=np.bool_), np.zeros(4, dtype=np.int8))
    state[:, B_Y] = 0.499, 1.498
    state[:, COLUMNS.index("inv_mass")] = state[:, COLUMNS.index("mass")] = 1.0
    ents = np.array([3, 4], dtype=np.int64)
    lookup = np.array([-1, -1, -1, 0, 1], dtype=np.int64)
    slot = table_slot(ContactTable.empty().arrays)
    for _ in range(2):
        last = slot_table(slot)
        find_contacts(
            slot, table.pieces.verts, table.pieces.normals, table.pieces.first, table.pieces.reach, table.body_first,
            state, np.arange(2, dtype=np.int64), np.full(2, 0.71), np.ones((2, 2)), ents, lookup,
            np.array([[3, 4]], dtype=np.int64), ents[:1], np.array([0, 1], dtype=np.int64), np.zeros(1, dtype=np.int64),
            walls, np.ones((1, 2)), np.zeros(1, dtype=np.int64), np.zeros(1, dtype=np.int64), np.zeros(len(COLUMNS)),
            1.0 / 240.0, 0.01, False, 0.0, last[0], last[4], last[6], last[5], True, RESTITUTION_THRESHOLD)
