"""Convex polygon against convex polygon: separating axes, then reference-face clipping.

This is the manifold of box2d-lite / Box2D v2 (`b2CollidePolygons`): find the axis of least
penetration on either polygon, take that edge as the reference face, pick the most anti-parallel edge
of the other polygon as the incident edge, clip it to the reference face's side planes and keep the
clipped points that lie within `margin` of the face. A flat face-to-face touch therefore gives two
points that are solved together, never two unrelated contacts.

The kernels read pieces as row ranges of (n, 2) vertex and normal arrays (`geometry.ConvexSet`), in
world coordinates. A wall's pieces carry seam masks, row for row (physics.seams): `internal` edges
are never a reference face, `hidden` vertices never a contact point.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from polygolf.engine.physics.geometry import ConvexSet, ShapeTable, face_line, pose_piece, span_on_line
from polygolf.engine.physics.jit import inlined_kernel, inlined_leaf, leaf_kernel, warm_up
from polygolf.engine.physics.polygon import Vec
from polygolf.engine.physics.seams import HIDDEN, PROBE, REFLEX
from polygolf.engine.physics.settings import CONTACT_MARGIN, LINEAR_SLOP
from polygolf.engine.physics.toi import (
    reaches_wall,
    separations_in_body_frame,
    toi_work,
    wall_beyond_body_faces,
    widest,
)

# Prefer polygon A's face unless B's is clearly better: stops the reference face flickering between
# the two polygons when they are nearly parallel, which would spoil warm starting.
_REFERENCE_TOLERANCE = 5e-4
# At a seam, the wall's face replaces A's as the reference only if it is about as near (m), or A lies
# no deeper behind the wall's face line than the contact margin (where a resting or pressed body sinks to).
_SEAM_SWITCH = 0.005
# m: rounding room for `_circle_beyond` (a vertex posed in floating point may stand a hair outside
# its body's bounding circle).
_CIRCLE_SLACK = 1e-9

# Columns of a contact row written by `collide_convex` / `collide_sets` (BODY: by `bodies_wall_contacts`).
X, Y, SEP, FEATURE, REF_IS_A, CLIP_X, CLIP_Y, FACE_X, FACE_Y, NX, NY, PIECE_A, PIECE_B, BODY = range(14)
ROW = 14
# The feature of a point clipped at the reference face's side plane by its first vertex, or by its second.
CLIPPED_LOW, CLIPPED_HIGH = 100.0, 101.0
NO_SEAMS = np.zeros(0, dtype=np.bool_)
NO_HIDDEN = np.zeros(0, dtype=np.int8)  # (`hidden` for a body, which has no seams)


@inlined_leaf
def max_separation(v1: np.ndarray, n1: np.ndarray, s1: int, e1: int, v2: np.ndarray, s2: int, e2: int,
                   skip: np.ndarray, skip_start: int, limit: float) -> tuple[float, int]:
    """Largest separation of polygon 2 (rows s2..e2) from the faces of polygon 1 (rows s1..e1), but
    the faces marked in `skip` (from row `skip_start`; -1: none), and that face's index in 1; or,
    as soon as some face separates them by more than `limit`, that face's (a caller that only asks
    whether they are more than `limit` apart needs no more; `math.inf`: the largest, always).

    A face stops being scanned at the first vertex no farther out than the best face so far: it
    can no longer be the largest (the first of equals is kept), so the answer is the same."""
    best, best_edge = -1e300, 0
    for i in range(e1 - s1):
        if skip_start >= 0 and skip[skip_start + i]:
            continue
        nx, ny = n1[s1 + i, 0], n1[s1 + i, 1]
        vx, vy = v1[s1 + i, 0], v1[s1 + i, 1]
        lowest = 1e300
        for j in range(s2, e2):
            d = (v2[j, 0] - vx) * nx + (v2[j, 1] - vy) * ny
            if d < lowest:
                lowest = d
                if d <= best:
                    break
        if lowest > best:
            best, best_edge = lowest, i
            if best > limit:
                break
    return best, best_edge


@inlined_leaf
def _incident_edge(normals: np.ndarray, s: int, e: int, nx: float, ny: float, skip: np.ndarray,
                   skip_start: int) -> int:
    """The face most opposed to the reference normal (a wall's internal edges face nothing)."""
    best, lowest = 0, 1e300
    for i in range(e - s):
        d = normals[s + i, 0] * nx + normals[s + i, 1] * ny
        if d < lowest and not (skip_start >= 0 and skip[skip_start + i]):
            lowest, best = d, i
    return best


@inlined_leaf
def _meets_free_corner(va: np.ndarray, na: np.ndarray, sa: int, ea: int, edge: int, vb: np.ndarray, sb: int,
                       hidden: np.ndarray, i1: int, i2: int, margin: float) -> bool:
    """Whether a vertex of B's incident edge (i1, i2) that no other piece covers lies where A's
    reference face makes a contact of it: within `margin` of the face and between its side planes.
    That is a true corner of the wall, struck by A's face, whatever covers the edge's other end (a
    gate wall whose far end lies in a border wall struck a ball at its free corner with the wall's
    face, as the hidden corner 2.35 m off asked: QA)."""
    nx, ny = na[sa + edge, 0], na[sa + edge, 1]
    r1x, r1y = va[sa + edge, 0], va[sa + edge, 1]
    r2 = sa + (edge + 1) % (ea - sa)
    tx, ty = va[r2, 0] - r1x, va[r2, 1] - r1y
    reach = PROBE * math.sqrt(tx * tx + ty * ty)
    meets = False
    for k in (i1, i2):
        px, py = vb[sb + k, 0] - r1x, vb[sb + k, 1] - r1y
        along = tx * px + ty * py
        meets |= hidden[sb + k] == 0 and nx * px + ny * py <= margin and -reach <= along <= tx * tx + ty * ty + reach
    return meets


@inlined_leaf
def _clip(points: np.ndarray, count: int, nx: float, ny: float, offset: float, plane_id: float) -> int:
    """Keep the part of a segment (rows 0, 1 of x, y, feature) where n·p <= offset
    (Sutherland-Hodgman on one plane); returns how many points are left."""
    if count < 2:
        return count
    x0, y0, f0 = points[0, 0], points[0, 1], points[0, 2]
    x1, y1, f1 = points[1, 0], points[1, 1], points[1, 2]
    d0 = nx * x0 + ny * y0 - offset
    d1 = nx * x1 + ny * y1 - offset
    out = 0
    if d0 <= 0.0:
        points[out, 0], points[out, 1], points[out, 2] = x0, y0, f0
        out += 1
    if d1 <= 0.0:
        points[out, 0], points[out, 1], points[out, 2] = x1, y1, f1
        out += 1
    if d0 * d1 < 0.0:
        t = d0 / (d0 - d1)
        points[out, 0], points[out, 1], points[out, 2] = x0 + t * (x1 - x0), y0 + t * (y1 - y0), plane_id
        out += 1
    return out


@leaf_kernel
def collide_convex(va: np.ndarray, na: np.ndarray, sa: int, ea: int, vb: np.ndarray, nb: np.ndarray, sb: int,
                   eb: int, internal: np.ndarray, hidden: np.ndarray, seams: bool, margin: float,
                   out: np.ndarray, row: int, clip: np.ndarray) -> int:
    """Contact manifold of two convex CCW pieces, or nothing if they are more than `margin` apart.

    Writes up to two contact rows from `row` on (columns X..NY; the normal points from A to B) and
    returns how many. With `seams`, `internal` and `hidden` mark B's edges and vertices row for row
    with `vb` (B is a wall piece: `hidden` holds seams.HIDDEN or seams.REFLEX, else 0). `clip`: (3, 3)
    scratch for the clipped points.

    The manifold is the reference face's, its incident edge clipped to the face's side planes
    (`_face_manifold`); with seams, room left goes to A's vertices beyond the end of one of B's faces
    at an inside corner of the walls (`_inside_corner_rows`)."""
    made = _face_manifold(va, na, sa, ea, vb, nb, sb, eb, internal, hidden, seams, margin, out, row, clip)
    if seams and made < 2:
        made += _inside_corner_rows(va, sa, ea, vb, nb, sb, eb, internal, hidden, margin, out, row + made, 2 - made)
    return made


@inlined_leaf
def _inside_corner_rows(va: np.ndarray, sa: int, ea: int, vb: np.ndarray, nb: np.ndarray, sb: int, eb: int,
                        internal: np.ndarray, hidden: np.ndarray, margin: float, out: np.ndarray, row: int,
                        room: int) -> int:
    """At a reflex corner R of the walls (the inside of a V, a step's foot: seams.REFLEX), the free
    space is a wedge, bounded by each face's line beyond the face's end too: a vertex of A past R's
    side plane of a face of B that ends at R (at most CONTACT_MARGIN past, no deeper than
    LINEAR_SLOP behind the line), within `margin` of the line, is a contact of that face, as if the
    face went on. The clipping drops it, and the neighbour whose face goes on from R answers only
    along its own normal: a needle sliding down one leg of a V, its tip in the corner, sunk in that
    leg and so just beyond the other's covered edge, went through the other leg at 20 m/s (QA; a
    5 cm wall, fast and balanced). Up to `room` rows from `row`; returns how many."""
    made = 0
    count_b = eb - sb
    for r in range(count_b):
        if hidden[sb + r] != REFLEX:
            continue
        rx, ry = vb[sb + r, 0], vb[sb + r, 1]
        for face in (r, (r - 1) % count_b):  # the face that leaves R, the face that comes to it
            if internal[sb + face]:
                continue
            other = (r + 1) % count_b if face == r else face  # its other end
            tx, ty = vb[sb + other, 0] - rx, vb[sb + other, 1] - ry
            length = math.sqrt(tx * tx + ty * ty)
            if length == 0.0:
                continue
            tx, ty = tx / length, ty / length
            nx, ny = nb[sb + face, 0], nb[sb + face, 1]
            for k in range(ea - sa):
                px, py = va[sa + k, 0], va[sa + k, 1]
                sep = nx * (px - rx) + ny * (py - ry)
                past = -(tx * (px - rx) + ty * (py - ry))
                if not (0.0 < past <= CONTACT_MARGIN and -LINEAR_SLOP <= sep <= margin):
                    continue
                if made == room:
                    return made
                o = out[row + made]
                o[X], o[Y], o[SEP] = px - 0.5 * sep * nx, py - 0.5 * sep * ny, sep
                o[FEATURE], o[REF_IS_A] = ((face * 128 + k) * 2 + 1) * 256 + k, 0.0
                o[CLIP_X], o[CLIP_Y], o[FACE_X], o[FACE_Y] = px, py, vb[sb + face, 0], vb[sb + face, 1]
                o[NX], o[NY] = -nx, -ny
                made += 1
    return made


@inlined_leaf
def _face_manifold(va: np.ndarray, na: np.ndarray, sa: int, ea: int, vb: np.ndarray, nb: np.ndarray, sb: int,
                   eb: int, internal: np.ndarray, hidden: np.ndarray, seams: bool, margin: float,
                   out: np.ndarray, row: int, clip: np.ndarray) -> int:
    """`collide_convex`'s manifold of the reference face (box2d-lite's), without the inside corners."""
    no_skip = NO_SEAMS
    sep_a, edge_a = max_separation(va, na, sa, ea, vb, sb, eb, no_skip, -1, margin)
    if sep_a > margin:
        return 0
    sep_b, edge_b = max_separation(vb, nb, sb, eb, va, sa, ea, no_skip, -1, margin)
    if sep_b > margin:
        return 0
    seam_start = sb if seams else -1
    if seams:
        covered = 0
        for k in range(sb, eb):
            if internal[k]:
                covered += 1
        if covered > 0:
            if covered == eb - sb:
                return 0  # a piece covered all round: the pieces around it answer for it
            if internal[sb + edge_b]:
                apart = sep_b > 0.0
                sep_b, edge_b = max_separation(vb, nb, sb, eb, va, sa, ea, internal, sb, math.inf)
                if apart and sep_a < 0.0 and sep_b < 0.0:
                    # A lies beyond a face another piece covers, clear of this one: that piece answers
                    # for what lies there. The other faces alone would make an overlap of pieces that
                    # do not touch (QA: a star passing the tip of a wall of two triangles, 1 mm off,
                    # was struck by one across the edge they share).
                    return 0

    ref_is_a = not (sep_b > sep_a + _REFERENCE_TOLERANCE)
    if ref_is_a:
        edge = edge_a
        inc_edge = _incident_edge(nb, sb, eb, na[sa + edge, 0], na[sa + edge, 1], internal, seam_start)
        count_inc = eb - sb
    else:
        edge = edge_b
        inc_edge = _incident_edge(na, sa, ea, nb[sb + edge, 0], nb[sb + edge, 1], no_skip, -1)
        count_inc = ea - sa
    i1, i2 = inc_edge, (inc_edge + 1) % count_inc
    if ref_is_a and seams and (hidden[sb + i1] != 0 or hidden[sb + i2] != 0) and \
            (sep_b >= sep_a - _SEAM_SWITCH or sep_b >= -CONTACT_MARGIN) and \
            not _meets_free_corner(va, na, sa, ea, edge, vb, sb, hidden, i1, i2, margin):
        # A's face would meet a wall corner that lies on a flat stretch of wall: the wall's own face
        # there, as near as A's or with A outside it (but for a resting or pressed body's sinking, up
        # to the contact margin), is the true surface, so it is the reference (a slanted face of A
        # would make a ghost hit: QA, a random ball sliding on two feet over a seam, its face 7.7 mm
        # above the corner, was kicked up at 1.9 m/s; a spinning square striking by a seam bounced
        # twice as high; a pentagon pressed 5.2 mm into a floor, its face slanting up over a seam,
        # lost the far end of its face's contact and was tipped at 0.09 rad/s, where the slop was
        # the bound). Otherwise the hidden corner is just left out below.
        ref_is_a = False
        edge = edge_b
        inc_edge = _incident_edge(na, sa, ea, nb[sb + edge, 0], nb[sb + edge, 1], no_skip, -1)
        count_inc = ea - sa
        i1, i2 = inc_edge, (inc_edge + 1) % count_inc

    if ref_is_a:
        ref_v, ref_n, rs, re, inc_v, is_ = va, na, sa, ea, vb, sb
    else:
        ref_v, ref_n, rs, re, inc_v, is_ = vb, nb, sb, eb, va, sa
    nx, ny = ref_n[rs + edge, 0], ref_n[rs + edge, 1]
    r1x, r1y = ref_v[rs + edge, 0], ref_v[rs + edge, 1]
    r2 = rs + (edge + 1) % (re - rs)
    r2x, r2y = ref_v[r2, 0], ref_v[r2, 1]
    tx, ty = r2x - r1x, r2y - r1y
    tlen = (tx * tx + ty * ty) ** 0.5
    tx, ty = tx / tlen, ty / tlen

    # Clip the incident segment to the slab between the reference face's two side planes.
    # Feature ids: an unclipped point keeps its incident vertex; a clipped one takes the side plane.
    points = clip
    points[0, 0], points[0, 1], points[0, 2] = inc_v[is_ + i1, 0], inc_v[is_ + i1, 1], i1
    points[1, 0], points[1, 1], points[1, 2] = inc_v[is_ + i2, 0], inc_v[is_ + i2, 1], i2
    lo = tx * r1x + ty * r1y
    hi = tx * r2x + ty * r2y
    count = _clip(points, 2, -tx, -ty, -lo, CLIPPED_LOW)
    if count < 2:
        return 0
    count = _clip(points, count, tx, ty, hi, CLIPPED_HIGH)
    if count < 2:
        return 0

    face_offset = nx * r1x + ny * r1y
    base_id = (edge * 128 + inc_edge) * 2 + (0 if ref_is_a else 1)
    made = 0
    for k in range(2):
        px, py, feature = points[k, 0], points[k, 1], int(points[k, 2])
        sep = nx * px + ny * py - face_offset
        if ref_is_a and seams and feature < eb - sb and hidden[sb + feature] != 0:
            continue  # a wall's corner on a flat stretch of wall: the faces around it answer for it
        if sep <= margin:
            o = out[row + made]
            o[X], o[Y], o[SEP] = px - 0.5 * sep * nx, py - 0.5 * sep * ny, sep
            o[FEATURE], o[REF_IS_A] = base_id * 256 + feature, 1.0 if ref_is_a else 0.0
            o[CLIP_X], o[CLIP_Y], o[FACE_X], o[FACE_Y] = px, py, r1x, r1y
            o[NX], o[NY] = (nx, ny) if ref_is_a else (-nx, -ny)
            made += 1
    return made


@inlined_leaf
def collide_sets(va: np.ndarray, na: np.ndarray, fa: np.ndarray, vb: np.ndarray, nb: np.ndarray, fb: np.ndarray,
                 pieces_b: np.ndarray, internal: np.ndarray, hidden: np.ndarray, seams: bool, margin: float,
                 b_outer: bool, out: np.ndarray, clip: np.ndarray) -> int:
    """Every contact between the pieces of A (`fa` ranges of va/na, world coordinates) and the
    pieces of B listed in `pieces_b`: A's pieces in the outer loop, or B's if `b_outer` (a body
    against wall pieces, judged piece by piece). Rows carry the two piece indices; `out` needs
    2·(A's pieces)·len(pieces_b) rows. Returns the rows written. `clip`: `collide_convex`'s scratch."""
    rows = 0
    count_a, count_b = len(fa) - 1, len(pieces_b)
    for outer in range(count_b if b_outer else count_a):
        for inner in range(count_a if b_outer else count_b):
            i, jj = (inner, outer) if b_outer else (outer, inner)
            j = pieces_b[jj]
            made = collide_convex(va, na, fa[i], fa[i + 1], vb, nb, fb[j], fb[j + 1], internal, hidden, seams,
                                  margin, out, rows, clip)
            for k in range(rows, rows + made):
                out[k, PIECE_A], out[k, PIECE_B] = i, j
            rows += made
    return rows


@leaf_kernel
def wall_contacts(va: np.ndarray, na: np.ndarray, shape_verts: np.ndarray, shape_normals: np.ndarray,
                  fa: np.ndarray, reach: np.ndarray, x: float, y: float, angle: float, vx: float, vy: float,
                  spin: float, dt: float, pressed: bool, walls: tuple, pieces: np.ndarray, near: np.ndarray,
                  margin: float, out: np.ndarray, clip: np.ndarray, work: tuple) -> int:
    """A body's contacts with the wall pieces listed (`collide_sets`, wall piece by wall piece),
    keeping those of a piece only if the body is in it, or is `pressed` by another body, or would
    press into it moving on as it is for dt (`toi.reaches_wall`): a ball passing a corner it never
    touches is never hit, however near it passes (a contact within GAP_TOLERANCE of a corner, kept
    unasked, took the body's next face for its normal and struck a dodecagon level with a box's top).
    `va`, `na`: the body's pieces posed at (x, y, angle); `shape_*`: the same in its own frame.
    Returns the rows kept, at the top of `out`. `clip`, `work`: scratch for `collide_convex` and the
    time of impact (`toi.toi_work`).

    A piece's face goes on across a seam in a flush neighbour (`near`: every piece near the body):
    its contact is kept too if the body would press into a neighbour that carries that face on
    (`_presses_on_across_seam`). A tip landing fast beside a seam would pass the first box's end
    before it sank, while the next box was still beyond the margin: neither contact acted, and
    continuous collision stopped the ball at the next box's hidden corner instead (a hexagon at 21
    m/s landing 25 mm behind the same landing on one floor, its bounce and spin lost). And a point
    the clipping made where such a face meets its neighbour is left out (`_clipped_at_seam`)."""
    wv, wn, wf, internal, hidden = walls
    rows = collide_sets(va, na, fa, wv, wn, wf, pieces, internal, hidden, True, margin, True, out, clip)
    kept = 0
    k = 0
    while k < rows:
        piece = out[k, PIECE_B]
        lowest = out[k, SEP]
        end = k + 1
        while end < rows and out[end, PIECE_B] == piece:
            lowest = min(lowest, out[end, SEP])
            end += 1
        g = int(piece)
        if pressed or lowest <= 0.0 or reaches_wall(shape_verts, shape_normals, fa, reach, x, y, angle,
                                                    vx, vy, spin, dt, wv, wn, wf[g], wf[g + 1], work) \
                or _presses_on_across_seam(shape_verts, shape_normals, fa, reach, x, y, angle, vx, vy, spin, dt, wv,
                                           wn, wf, g, near, out, k, end, work):
            for r in range(k, end):
                if _clipped_at_seam(wv, wn, wf, g, near, out, r):
                    continue
                for c in range(ROW):  # (row by row: a leaf copies no array)
                    out[kept, c] = out[r, c]
                kept += 1
        k = end
    return kept


@leaf_kernel
def _presses_on_across_seam(lv: np.ndarray, ln: np.ndarray, fa: np.ndarray, reach: np.ndarray, x: float, y: float,
                            angle: float, vx: float, vy: float, spin: float, dt: float, wv: np.ndarray,
                            wn: np.ndarray, wf: np.ndarray, g: int, near: np.ndarray, rows: np.ndarray, k: int,
                            end: int, work: tuple) -> bool:
    """Whether piece g's contact rows k..end of `rows` (each on the same face of g: the reference)
    meet a surface that goes on across a seam into which the body would press, moving on as it is
    for dt (`toi.reaches_wall`): another piece of `near` with a face on the same line, facing the
    same way, meeting or overlapping g's (`geometry.span_on_line`). Then the rows are the contact
    the one flat surface would give."""
    for r in range(k, end):
        if rows[r, REF_IS_A] != 0.0 or rows[r, FACE_X] != rows[k, FACE_X] or rows[r, FACE_Y] != rows[k, FACE_Y]:
            return False
    face, nx, ny, offset, lo, hi = _reference_line(wv, wn, wf, g, rows, k)
    for m in range(len(near) if face >= 0 else 0):
        a, b = _carried_on(wv, wn, wf, near[m], g, nx, ny, offset)
        if a <= hi + PROBE and lo <= b + PROBE and reaches_wall(lv, ln, fa, reach, x, y, angle, vx, vy, spin, dt, wv,
                                                               wn, wf[near[m]], wf[near[m] + 1], work):
            return True
    return False


@inlined_leaf
def _clipped_at_seam(wv: np.ndarray, wn: np.ndarray, wf: np.ndarray, g: int, near: np.ndarray, rows: np.ndarray,
                     r: int) -> bool:
    """Whether row r (of wall piece g) is a point the clipping made at an end of g's face, where a
    piece of `near` carries that face on: a point inside one of the body's edges, which the one flat
    surface would not have (the neighbour makes the edge's own points beyond; kept, it shared a
    landing tip's impulse and the bounce differed from one off a whole floor, accurate)."""
    side = int(rows[r, FEATURE]) % 256
    if rows[r, REF_IS_A] != 0.0 or not (side == CLIPPED_LOW or side == CLIPPED_HIGH):
        return False
    face, nx, ny, offset, lo, hi = _reference_line(wv, wn, wf, g, rows, r)
    for m in range(len(near) if face >= 0 else 0):
        a, b = _carried_on(wv, wn, wf, near[m], g, nx, ny, offset)
        if (a < lo - PROBE <= b) if side == CLIPPED_LOW else (a <= hi + PROBE < b):
            return True
    return False


@inlined_leaf
def _reference_line(wv: np.ndarray, wn: np.ndarray, wf: np.ndarray, g: int, rows: np.ndarray, k: int
                    ) -> tuple[int, float, float, float, float, float]:
    """Row k's reference face on wall piece g (the face that starts at FACE_X, FACE_Y; -1 if none):
    its row, normal, its line's offset (n·p) and its stretch along (-ny, nx)."""
    for r in range(wf[g], wf[g + 1]):
        if wv[r, 0] == rows[k, FACE_X] and wv[r, 1] == rows[k, FACE_Y]:
            nx, ny, offset, lo, hi = face_line(wv, wn, wf[g], wf[g + 1], r)
            return r, nx, ny, offset, lo, hi
    return -1, 0.0, 0.0, 0.0, 0.0, 0.0


@inlined_leaf
def _carried_on(wv: np.ndarray, wn: np.ndarray, wf: np.ndarray, h: int, g: int, nx: float, ny: float,
                offset: float) -> tuple[float, float]:
    """The stretch along (-ny, nx) of wall piece h's face on g's line n·p = offset, facing n (inf,
    -inf if it has none, or h is g itself)."""
    if h == g:
        return math.inf, -math.inf
    _, a, b = span_on_line(wv, wn, wf[h], wf[h + 1], nx, ny, offset, -ny, nx)
    return a, b


@leaf_kernel
def _circle_beyond(wv: np.ndarray, wn: np.ndarray, s: int, e: int, x: float, y: float, reach: float) -> bool:
    """Whether the point (x, y) lies more than `reach` beyond some face of the wall piece of rows
    s..e: every point of a body about it of bounding radius r then lies more than `reach` - r
    beyond that face. (No early return: the loop is the whole call, so numba takes no reference
    counts on the arrays per call; see `jit`.)"""
    farthest = -math.inf
    for k in range(s, e):
        d = (x - wv[k, 0]) * wn[k, 0] + (y - wv[k, 1]) * wn[k, 1]
        if d > farthest:
            farthest = d
    return farthest > reach


@leaf_kernel
def _clear_of(verts: np.ndarray, normals: np.ndarray, first: np.ndarray, p0: int, p1: int, x: float, y: float,
              reach: float) -> bool:
    """Whether the point (x, y) lies more than `reach` beyond some face of each of the posed pieces
    p0..p1 (rows `first`): a body about it of bounding radius r is then more than `reach` - r clear
    of every one of them, and `collide_convex` would find that face a separating axis for each piece
    of it (no row at all)."""
    clear = True
    for p in range(p0, p1):
        clear &= _circle_beyond(verts, normals, first[p], first[p + 1], x, y, reach)
    return clear


@leaf_kernel
def close_to_walls(wv: np.ndarray, wn: np.ndarray, wall_first: np.ndarray, near: np.ndarray, n0: int, n1: int,
                   x: float, y: float, radius: float, margin: float) -> bool:
    """Whether a body about (x, y) of bounding radius `radius` has a wall piece among near[n0:n1]
    that its bounding circle does not stay more than `margin` clear of (then `collide_convex` may
    make a row; else none)."""
    beyond = radius + margin + _CIRCLE_SLACK
    for n in range(n0, n1):
        g = near[n]
        if not _circle_beyond(wv, wn, wall_first[g], wall_first[g + 1], x, y, beyond):
            return True
    return False


@leaf_kernel
def _any_close(wv: np.ndarray, wn: np.ndarray, wall_first: np.ndarray, which: np.ndarray, radius: np.ndarray,
               states: np.ndarray, near_first: np.ndarray, near: np.ndarray, margin: float) -> bool:
    """Whether any body of `bodies_wall_contacts` is `close_to_walls`."""
    for q in range(len(which)):
        if close_to_walls(wv, wn, wall_first, near, near_first[q], near_first[q + 1], states[q, 0], states[q, 1],
                          radius[which[q]], margin):
            return True
    return False


@inlined_kernel
def bodies_wall_contacts(lv: np.ndarray, ln: np.ndarray, first: np.ndarray, reach: np.ndarray,
                         body_first: np.ndarray, which: np.ndarray, radius: np.ndarray, states: np.ndarray,
                         pressed: np.ndarray, near_first: np.ndarray, near: np.ndarray, walls: tuple, dt: float,
                         margin: float) -> np.ndarray:
    """`wall_contacts` for many bodies in one call: body q is shape `which[q]` of a
    `geometry.ShapeTable` (lv, ln, first, reach, body_first; bounding radius `radius[which[q]]`)
    in state states[q] = (x, y, angle, vx, vy, spin), `pressed[q]`, near the wall pieces
    near[near_first[q]:near_first[q + 1]]. Returns the rows kept, body by body, each with its q in
    column BODY.

    A wall piece its bounding circle stays more than `margin` clear of is passed over without
    posing the body (`collide_convex` would find a separating axis and make no row, so the rows are
    the same), and nothing is made while no body comes that close: a ball near a wall but clear of
    it is most of its substeps there."""
    if not _any_close(walls[0], walls[1], walls[2], which, radius, states, near_first, near, margin):
        return np.empty((0, ROW))
    rows = 0
    for q in range(len(which)):
        pieces = body_first[which[q] + 1] - body_first[which[q]]
        rows += 2 * pieces * (near_first[q + 1] - near_first[q])
    out = np.empty((rows, ROW))
    # Each body is posed into its own rows of one table-sized array: nothing is allocated a body.
    verts, normals = np.empty((len(lv), 2)), np.empty((len(lv), 2))
    work, clip = toi_work(max(widest(first), widest(walls[2]))), np.empty((3, 3))
    close = np.empty(len(near), dtype=np.int64)
    kept = _wall_rows(lv, ln, first, reach, body_first, which, radius, states, pressed, near_first, near, walls, dt,
                      margin, out, verts, normals, work, clip, close)
    return out[:kept]


@leaf_kernel
def _wall_rows(lv: np.ndarray, ln: np.ndarray, first: np.ndarray, reach: np.ndarray, body_first: np.ndarray,
               which: np.ndarray, radius: np.ndarray, states: np.ndarray, pressed: np.ndarray, near_first: np.ndarray,
               near: np.ndarray, walls: tuple, dt: float, margin: float, out: np.ndarray, verts: np.ndarray,
               normals: np.ndarray, work: tuple, clip: np.ndarray, close: np.ndarray) -> int:
    """`bodies_wall_contacts`' work, into `out`; how many rows. (A leaf: the views it takes of a
    body's rows cost nothing, so each close wall piece goes to `wall_contacts` as it is, whose
    separating axes answer first for a piece the body is clear of.) A piece the body's bounding
    circle stays clear of, or separated from the body by a face of either more than the margin (asked
    in the body's frame, `toi.separations_in_body_frame`, `toi.wall_beyond_body_faces`), is passed
    over first, and a body with no other piece close is not posed at all."""
    kept = 0
    wv, wn, wf = walls[0], walls[1], walls[2]
    for q in range(len(which)):
        x, y, angle = states[q, 0], states[q, 1], states[q, 2]
        beyond = radius[which[q]] + margin + _CIRCLE_SLACK
        count = 0
        for n in range(near_first[q], near_first[q + 1]):
            g = near[n]
            if not _circle_beyond(wv, wn, wf[g], wf[g + 1], x, y, beyond):
                close[count] = g
                count += 1
        if count == 0:
            continue
        p0, p1 = body_first[which[q]], body_first[which[q] + 1]
        # Of those, the pieces some face of which every piece of the body lies beyond, or that lie
        # beyond a face of every piece of the body (the separating axes, asked without posing the
        # body), make no row either.
        c, sn = math.cos(angle), math.sin(angle)
        left = 0
        seps = work[1]
        for m in range(count):
            g = close[m]
            clear = True
            for i in range(p0, p1):
                separations_in_body_frame(lv, first[i], first[i + 1], x, y, c, sn, wv, wn, wf[g], wf[g + 1], seps)
                past = False
                for k in range(wf[g + 1] - wf[g]):
                    past |= seps[k] > margin + _CIRCLE_SLACK
                if not past:  # or beyond a face of the body's piece
                    past = wall_beyond_body_faces(lv, ln, first[i], first[i + 1], x, y, c, sn, wv, wf[g], wf[g + 1],
                                                  work[0][0]) > margin + _CIRCLE_SLACK
                clear &= past
            if not clear:
                close[left] = g
                left += 1
        count = left
        if count == 0:
            continue
        v0, v1 = first[p0], first[p1]
        pose_piece(lv, ln, v0, v1, x, y, angle, verts[v0:v1], normals[v0:v1])
        made = wall_contacts(verts, normals, lv, ln, first[p0:p1 + 1], reach[p0:p1], x, y, angle, states[q, 3],
                             states[q, 4], states[q, 5], dt, pressed[q], walls, close[:count],
                             near[near_first[q]:near_first[q + 1]], margin, out[kept:], clip, work)
        for k in range(kept, kept + made):
            out[k, BODY] = q
        kept += made
    return kept


@inlined_kernel
def bodies_pair_contacts(lv: np.ndarray, ln: np.ndarray, first: np.ndarray, body_first: np.ndarray,
                         pairs: np.ndarray, poses: np.ndarray, radius: np.ndarray, margin: float
                         ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Contact rows between the bodies of each pair (shapes pairs[g] of a `geometry.ShapeTable`, at
    poses[q] = x, y, angle, bounding radii radius[q]), A's pieces in the outer loop (`collide_sets`);
    pairs farther apart than their radii and the margin are not looked at. Returns, for the pairs
    that have rows, in order: the rows (the t-th such pair's are rows[pair_first[t]:pair_first[t +
    1]], each with t in column BODY), pair_first, the pairs, and each one's smallest separation."""
    total = 0
    for g in range(len(pairs)):
        a, b = pairs[g, 0], pairs[g, 1]
        total += 2 * (body_first[a + 1] - body_first[a]) * (body_first[b + 1] - body_first[b])
    out = np.empty((total, ROW))
    pair_first = np.zeros(len(pairs) + 1, dtype=np.int64)
    touching = np.empty((len(pairs), 2), dtype=np.int64)
    gaps = np.empty(len(pairs))
    # Every body is posed once, into its own rows of one table-sized array, however many pairs it is in.
    posed_v, posed_n = np.empty((len(lv), 2)), np.empty((len(lv), 2))
    posed = np.zeros(len(body_first) - 1, dtype=np.bool_)
    every = np.arange(len(first))  # B's pieces, all of them: every[:count]
    clip = np.empty((3, 3))
    rows, t = _pair_rows(first, body_first, pairs, poses, radius, margin, lv, ln, out, pair_first, touching, gaps,
                         posed_v, posed_n, posed, every, clip)
    return out[:rows], pair_first[:t + 1].copy(), touching[:t].copy(), gaps[:t].copy()


@leaf_kernel
def _pair_rows(first: np.ndarray, body_first: np.ndarray, pairs: np.ndarray, poses: np.ndarray, radius: np.ndarray,
               margin: float, lv: np.ndarray, ln: np.ndarray, out: np.ndarray, pair_first: np.ndarray,
               touching: np.ndarray, gaps: np.ndarray, posed_v: np.ndarray, posed_n: np.ndarray, posed: np.ndarray,
               every: np.ndarray, clip: np.ndarray) -> tuple[int, int]:
    """`bodies_pair_contacts`' work into its arrays; how many rows and how many pairs have some. (A
    leaf: the views it takes cost nothing, so each pair within reach goes to `collide_sets`, whose
    separating axes answer first for pieces that are apart.) A pair one of whose bodies' bounding
    circles stays more than the margin clear of every piece of the other is passed over before its
    separating axes (`_clear_of`: the face it stays beyond is one of them, so no row would come)."""
    rows = t = 0
    for g in range(len(pairs)):
        a, b = pairs[g, 0], pairs[g, 1]
        reach = radius[a] + radius[b] + margin
        dx, dy = poses[a, 0] - poses[b, 0], poses[a, 1] - poses[b, 1]
        if dx ** 2 + dy ** 2 > reach * reach:
            continue
        for q in (a, b):
            if not posed[q]:
                v0, v1 = first[body_first[q]], first[body_first[q + 1]]
                pose_piece(lv, ln, v0, v1, poses[q, 0], poses[q, 1], poses[q, 2], posed_v[v0:v1], posed_n[v0:v1])
                posed[q] = True
        a0, a1, b0, b1 = body_first[a], body_first[a + 1], body_first[b], body_first[b + 1]
        if _clear_of(posed_v, posed_n, first, a0, a1, poses[b, 0], poses[b, 1], radius[b] + margin + _CIRCLE_SLACK) \
                or _clear_of(posed_v, posed_n, first, b0, b1, poses[a, 0], poses[a, 1],
                             radius[a] + margin + _CIRCLE_SLACK):
            continue
        made = collide_sets(posed_v, posed_n, first[a0:a1 + 1], posed_v, posed_n, first[b0:b1 + 1], every[:b1 - b0],
                            NO_SEAMS, NO_HIDDEN, False, margin, False, out[rows:], clip)
        if made == 0:
            continue
        lowest = out[rows, SEP]
        for k in range(rows, rows + made):
            out[k, BODY] = t
            if out[k, SEP] < lowest:
                lowest = out[k, SEP]
        touching[t, 0], touching[t, 1], gaps[t] = a, b, lowest
        rows += made
        t += 1
        pair_first[t] = rows
    return rows, t


@inlined_kernel
def kept_pairs(rows: np.ndarray, pair_first: np.ndarray, pairs: np.ndarray, apart: np.ndarray, ents: np.ndarray,
               store_rows: np.ndarray, materials: np.ndarray
               ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The pairs not `apart`, as the contact table takes them: their rows (column BODY renumbered),
    pair_first, entities, store rows and materials (A's restitution and friction, then B's)."""
    keep = 0
    total = 0
    for g in range(len(pairs)):
        if not apart[g]:
            keep += 1
            total += pair_first[g + 1] - pair_first[g]
    out = np.empty((total, rows.shape[1]))
    first = np.zeros(keep + 1, dtype=np.int64)
    pair_ents = np.empty((keep, 2), dtype=np.int64)
    body_rows = np.empty((keep, 2), dtype=np.int64)
    pair_materials = np.empty((keep, 4))
    t = r = 0
    for g in range(len(pairs)):
        if apart[g]:
            continue
        a, b = pairs[g, 0], pairs[g, 1]
        for k in range(pair_first[g], pair_first[g + 1]):
            out[r] = rows[k]
            out[r, BODY] = t
            r += 1
        pair_ents[t, 0], pair_ents[t, 1] = ents[a], ents[b]
        body_rows[t, 0], body_rows[t, 1] = store_rows[a], store_rows[b]
        pair_materials[t, 0], pair_materials[t, 1] = materials[a, 0], materials[a, 1]
        pair_materials[t, 2], pair_materials[t, 3] = materials[b, 0], materials[b, 1]
        t += 1
        first[t] = r
    return out, first, pair_ents, body_rows, pair_materials


# --- the same for callers holding vertex lists (tests, tools) ---------------------------------------

@dataclass(slots=True)
class RawContact:
    """One clipped point: where it is, how deep, which features made it, and the geometry NGS needs."""

    x: float  # midway between the incident point and the reference face
    y: float
    separation: float  # negative when overlapping
    feature: int  # stable id of the (reference edge, incident feature) pair, for warm starting
    ref_is_a: bool  # True when the reference face belongs to polygon A
    clip_x: float  # the point on the incident polygon
    clip_y: float
    face_x: float  # a point on the reference face
    face_y: float


def _rows(points: Sequence[Vec]) -> np.ndarray:
    return np.asarray(points, dtype=np.float64).reshape(-1, 2)


def separation(verts_a: Sequence[Vec], normals_a: Sequence[Vec], verts_b: Sequence[Vec],
               normals_b: Sequence[Vec]) -> float:
    """Separating-axis distance: a lower bound on the true distance, exact when it is negative."""
    va, na, vb, nb = _rows(verts_a), _rows(normals_a), _rows(verts_b), _rows(normals_b)
    sa, _ = max_separation(va, na, 0, len(va), vb, 0, len(vb), NO_SEAMS, -1, math.inf)
    sb, _ = max_separation(vb, nb, 0, len(vb), va, 0, len(va), NO_SEAMS, -1, math.inf)
    return sa if sa > sb else sb


def collide_polygons(
    verts_a: Sequence[Vec], normals_a: Sequence[Vec], verts_b: Sequence[Vec], normals_b: Sequence[Vec],
    margin: float, internal_b: frozenset[int] = frozenset(), hidden_b: frozenset[int] = frozenset(),
    reflex_b: frozenset[int] = frozenset(),
) -> tuple[Vec, list[RawContact]] | None:
    """Contact manifold of two convex CCW polygons, or None if they are more than `margin` apart:
    the unit normal from A to B (the first point's) and up to two points. `internal_b`, `hidden_b`,
    `reflex_b`: B's covered edges and vertices, and those at inside corners (B a wall piece;
    physics.seams)."""
    va, na, vb, nb = _rows(verts_a), _rows(normals_a), _rows(verts_b), _rows(normals_b)
    seams = bool(internal_b or hidden_b or reflex_b)
    internal = np.array([k in internal_b for k in range(len(vb))], dtype=np.bool_)
    hidden = np.array([REFLEX if k in reflex_b else HIDDEN if k in hidden_b else 0 for k in range(len(vb))],
                      dtype=np.int8)
    out = np.empty((2, ROW))
    made = collide_convex(va, na, 0, len(va), vb, nb, 0, len(vb), internal, hidden, seams, float(margin), out, 0,
                          np.empty((3, 3)))
    if not made:
        return None
    contacts = [RawContact(x=o[X], y=o[Y], separation=o[SEP], feature=int(o[FEATURE]), ref_is_a=bool(o[REF_IS_A]),
                           clip_x=o[CLIP_X], clip_y=o[CLIP_Y], face_x=o[FACE_X], face_y=o[FACE_Y])
                for o in out[:made].tolist()]
    return (float(out[0, NX]), float(out[0, NY])), contacts


@warm_up("contacts")
def _warm() -> None:
    square = [(0.5, -0.5), (0.5, 0.5), (-0.5, 0.5), (-0.5, -0.5)]
    normals = [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)]
    lifted = [(x, y + 0.995) for x, y in square]
    collide_polygons(square, normals, lifted, normals, 0.01, frozenset({3}), frozenset({0}))
    separation(square, normals, lifted, normals)
    va, na = _rows(square), _rows(normals)
    first = np.array([0, 4], dtype=np.int64)
    walls = (_rows(lifted), na, first, np.zeros(4, dtype=np.bool_), np.zeros(4, dtype=np.int8))
    for pressed in (False, True):
        wall_contacts(va, na, va, na, first, np.array([0.71]), 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0 / 240.0, pressed,
                      walls, np.zeros(1, dtype=np.int64), np.zeros(1, dtype=np.int64), 0.01, np.empty((2, ROW)),
                      np.empty((3, 3)), toi_work(4))
    collide_sets(va, na, first, _rows(lifted), na, first, np.zeros(1, dtype=np.int64), NO_SEAMS, NO_HIDDEN, False,
                 0.01, False, np.empty((2, ROW)), np.empty((3, 3)))
    table = ShapeTable.of([ConvexSet.of([square], [normals])])
    bodies_wall_contacts(table.pieces.verts, table.pieces.normals, table.pieces.first, table.pieces.reach,
                         table.body_first, np.zeros(1, dtype=np.int64), np.full(1, 0.71),
                         np.array([[0.0, 0.0, 0.0, 0.0, 1.0, 0.0]]),
                         np.zeros(1, dtype=np.bool_), np.array([0, 1], dtype=np.int64), np.zeros(1, dtype=np.int64),
                         walls, 1.0 / 240.0, 0.01)
    two = ShapeTable.of([ConvexSet.of([square], [normals])] * 2)
    rows, pair_first, pairs, _ = bodies_pair_contacts(
        two.pieces.verts, two.pieces.normals, two.pieces.first, two.body_first, np.array([[0, 1]], dtype=np.int64),
        np.array([[0.0, 0.0, 0.0], [0.0, 0.99, 0.0]]), np.full(2, 0.71), 0.01)
    kept_pairs(rows, pair_first, pairs, np.zeros(len(pairs), dtype=np.bool_), np.arange(2, dtype=np.int64),
               np.arange(2, dtype=np.int64), np.ones((2, 2)))
