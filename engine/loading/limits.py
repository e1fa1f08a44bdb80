"""Limits on what content may say, checked before any work is done. Every number is finite; each
has a documented range (the README's table is made from `LIMITS`). They keep every check cheap —
at 64 vertices an outline is checked in 4 ms and cut into convex pieces in 16 ms, and a file holds at
most MAX_TOTAL_VERTICES of them (a few seconds at worst) — and every world finite."""

from __future__ import annotations

import re
import unicodedata
from typing import Annotated

import numpy as np
from pydantic import AfterValidator, Field, Strict, StringConstraints

from polygolf.engine.physics.polygon import MAX_SIDES, MIN_SIDES

MAX_FILE_BYTES = 1 << 20  # 1 MiB a content file
MAX_DEPTH = 32  # YAML nesting
MAX_NODES = 50_000  # YAML values, aliases expanded
MAX_COORDINATE = 100_000.0  # m, any position or vertex
MAX_RADIUS = 50.0  # m, a body's size
MIN_RADIUS = 0.01
MAX_HALF = 1_000.0  # m, half a wall box
MAX_WALL_VERTICES = 64
MAX_TOTAL_VERTICES = 10_000  # all the outlines of one file together
MAX_STAR_POINTS = 64
MAX_SPEED = 1_000.0  # m/s, a velocity component
MAX_SPIN = 1_000.0  # rad/s
MAX_ANGLE = 3_600.0  # degrees
MIN_DENSITY, MAX_DENSITY = 1e-3, 1e6  # kg/m²
MAX_FRICTION = 10.0
MAX_DRAG = 1_000.0  # 1/s or m/s²
MAX_GRAVITY = 1_000.0  # m/s² a component
MAX_BODIES, MAX_WALLS = 2_000, 5_000
MAX_START_PAIRS = 8  # pairs of bodies a body, at most, that start within reach (bounding circles overlapping)
MAX_NAME = 100  # characters
MIN_TILE, MAX_TILE = 1.0, 100.0  # m
MAX_TILE_INDEX = 100  # |column|, |row|
MAX_TILES = 400  # a hole
MAX_ITEMS = 100  # things in one pattern
MAX_ENTRIES = 500  # border sets, patterns, courses, holes in a course
MAX_KICK = 50.0  # m/s
MAX_PUSH = 100.0  # m/s²
MAX_WINDMILL = 20.0  # rad/s
MAX_CUP_SPEED = 100.0  # m/s
MAX_LAUNCH_EVERY = 3_600.0  # s
MAX_SECONDS = 3_600.0  # `simulate --seconds`

LIMITS: list[tuple[str, str]] = [
    ("content file size", f"≤ {MAX_FILE_BYTES // 1024} KiB"),
    ("YAML nesting depth", f"≤ {MAX_DEPTH}"),
    ("YAML values (anchors, aliases and `<<` merge keys expanded)", f"≤ {MAX_NODES:,}"),
    ("every number", "finite (no .inf, .nan); at most 4,300 characters (YAML 1.1's base-60 `1:30` included)"),
    ("coordinates: positions, vertices, box centres", f"|x|, |y| ≤ {MAX_COORDINATE:,.0f} m"),
    ("shape radius (regular, star, random)", f"{MIN_RADIUS} – {MAX_RADIUS:g} m"),
    ("a `vertices` shape's reach from its centroid", f"≤ {MAX_RADIUS:g} m"),
    ("wall box half-extents", f"0 < half ≤ {MAX_HALF:,.0f} m"),
    ("vertices: regular and random shapes, `vertices` bodies", f"{MIN_SIDES} – {MAX_SIDES}"),
    ("vertices: wall and pattern polygons", f"3 – {MAX_WALL_VERTICES}"),
    ("vertices of all the outlines in one file", f"≤ {MAX_TOTAL_VERTICES:,}"),
    ("star points {p/q}", f"5 ≤ p ≤ {MAX_STAR_POINTS}, 2 ≤ q < p/2"),
    ("velocity components", f"|v| ≤ {MAX_SPEED:,.0f} m/s"),
    ("spin", f"|ω| ≤ {MAX_SPIN:,.0f} rad/s"),
    ("angles", f"|a| ≤ {MAX_ANGLE:,.0f}°"),
    ("density", f"{MIN_DENSITY:g} – {MAX_DENSITY:g} kg/m²"),
    ("restitution", "0 – 1"),
    ("friction", f"0 – {MAX_FRICTION:g}"),
    ("drag rates (linear, angular, rolling)", f"0 – {MAX_DRAG:,.0f}"),
    ("gravity components", f"|g| ≤ {MAX_GRAVITY:,.0f} m/s²"),
    ("bodies, walls in a scene", f"1 – {MAX_BODIES:,}, ≤ {MAX_WALLS:,}"),
    ("bodies starting within reach of each other", f"≤ {MAX_START_PAIRS} pairs a body (bounding circles "
                                                   "overlapping: a pile touches, a heap in one spot is refused)"),
    ("names", f"1 – {MAX_NAME} characters, no control characters or direction overrides, no spaces or invisible "
              "(zero-width) characters before or after, no zero-width space, word joiner or soft hyphen in it (the "
              "joiners of Persian or an emoji family are text), something that shows (one line on the HUD, the "
              "scorecard and in messages)"),
    ("tile size", f"{MIN_TILE:g} – {MAX_TILE:g} m; wall thickness, ball and cup radius ≤ a quarter of it"),
    ("tile positions `at`", f"|column|, |row| ≤ {MAX_TILE_INDEX}; ≤ {MAX_TILES} tiles a hole"),
    ("pattern items; border sets, patterns, courses, holes a course", f"≤ {MAX_ITEMS}; ≤ {MAX_ENTRIES}"),
    ("bumper kick", f"0 < kick ≤ {MAX_KICK:g} m/s"),
    ("slope push", f"|a| ≤ {MAX_PUSH:g} m/s² a component"),
    ("windmill speed", f"|ω| ≤ {MAX_WINDMILL:g} rad/s"),
    ("cup max_speed", f"0 < v ≤ {MAX_CUP_SPEED:g} m/s"),
    ("par; max_strokes", "1 – 20; 1 – 99"),
    ("launcher: every", f"0.1 – {MAX_LAUNCH_EVERY:,.0f} s"),
    ("`simulate --seconds`", f"1/120 ≤ s ≤ {MAX_SECONDS:,.0f} (at least one frame)"),
]


def finite(lo: float | None = None, hi: float | None = None, *, gt: float | None = None):
    """A strict float (ints accepted, strings and booleans not) that is finite and in range."""
    return Annotated[float, Strict(), Field(allow_inf_nan=False, ge=lo, le=hi, gt=gt)]


def count(lo: int, hi: int):
    return Annotated[int, Strict(), Field(ge=lo, le=hi)]


Coordinate = finite(-MAX_COORDINATE, MAX_COORDINATE)
Point = tuple[Coordinate, Coordinate]
Angle = finite(-MAX_ANGLE, MAX_ANGLE)
Radius = finite(MIN_RADIUS, MAX_RADIUS)
Half = finite(hi=MAX_HALF, gt=0.0)
Speed = finite(-MAX_SPEED, MAX_SPEED)
Spin = finite(-MAX_SPIN, MAX_SPIN)
Density = finite(MIN_DENSITY, MAX_DENSITY)
Restitution = finite(0.0, 1.0)
Friction = finite(0.0, MAX_FRICTION)
Rate = finite(0.0, MAX_DRAG)
Acceleration = finite(-MAX_GRAVITY, MAX_GRAVITY)


_INVISIBLE = {0x200B, 0x2060, 0xFEFF, 0x00AD}  # zero-width space, word joiner, zero-width no-break space, soft hyphen
_BIDI = {*range(0x202A, 0x202F), *range(0x2066, 0x206A), 0x200E, 0x200F, 0x061C}  # direction overrides, marks


# Letters and signs that show nothing: the Hangul fillers and the blank Braille pattern (QA8: a player
# named U+3164 was taken, and the bests named a blank).
BLANK = frozenset({0x115F, 0x1160, 0x3164, 0xFFA0, 0x2800})


def shows(name: str) -> bool:
    """Whether `name` has a character that shows: a letter, digit, punctuation or symbol that is not
    one of the BLANK ones. Format characters (zero-width ones, Cf), spaces of every kind and marks
    alone show nothing; inside a name that shows they are kept (a joiner in Persian, an emoji family)."""
    return any(unicodedata.category(c)[0] in "LNPS" and ord(c) not in BLANK for c in name)


def breaks_a_line(c: str) -> bool:
    """A character no name may hold: a control character or line break, a direction override or mark
    (it reorders what follows), half a surrogate pair (bytes that were not UTF-8). Joiners (U+200C,
    U+200D: Persian, Devanagari, emoji families) and other format characters are text."""
    return unicodedata.category(c) in ("Cc", "Zl", "Zp", "Cs") or ord(c) in _BIDI


def _one_line(name: str) -> str:
    """A name is shown on one line (HUD, scorecard, console, error messages) and found by what it
    shows: a control character would break the line, a direction override reorder what follows it,
    spaces about it or nothing visible in it make a name that looks like another or like none."""
    bad = next((c for c in name if breaks_a_line(c)), None)
    if bad is not None:
        raise ValueError(f"a name may not hold control characters, got U+{ord(bad):04X}")
    if name != name.strip():
        raise ValueError(f"a name may not start or end with spaces, got {name!r}")
    if not shows(name):
        raise ValueError("a name needs a letter, digit or sign that shows")
    # (A zero-width space or joiner at an end shows nothing: `Meadow` and `Meadow` + U+200B were two
    # courses that looked alike, with different ids; a zero-width space, word joiner or soft hyphen
    # anywhere joins nothing either: 'An' U+200B 'n' looked like 'Ann'.)
    end = next((c for c in (name[0], name[-1]) if unicodedata.category(c) == "Cf"), None)
    if end is not None:
        raise ValueError(f"a name may not start or end with an invisible character, got U+{ord(end):04X}")
    hidden = next((c for c in name if ord(c) in _INVISIBLE), None)
    if hidden is not None:
        raise ValueError(f"a name may not hold an invisible space or hyphen, got U+{ord(hidden):04X}")
    return name


Name = Annotated[str, StringConstraints(min_length=1, max_length=MAX_NAME), AfterValidator(_one_line)]
Seed = count(0, 2**63 - 1)


def _matching(pattern: str, what: str):
    compiled = re.compile(pattern)

    def check(value: str) -> str:
        if not compiled.fullmatch(value):
            raise ValueError(f"{what}, got {value[:40]!r}")
        return value

    return AfterValidator(check)


Key = Annotated[str, Strict(), _matching(r"[A-Za-z0-9][A-Za-z0-9_.-]{0,99}",
                                         "a name is letters, digits, '-', '_' and '.' (at most 100)")]
FileName = Annotated[str, Strict(), _matching(r"[A-Za-z0-9][A-Za-z0-9_-]{0,99}",
                                              "a hole is named by its file in this folder, without '.yaml' "
                                              "(letters, digits, '-', '_')")]
Colour = Annotated[str, Strict(), _matching(r"#([0-9a-fA-F]{6}|[0-9a-fA-F]{8})",
                                            'a colour is "#RRGGBB" or "#RRGGBBAA"')]


def check_start_pairs(positions: np.ndarray, radii: np.ndarray) -> None:
    """Raise if more pairs of bodies start within reach of each other than MAX_START_PAIRS a body:
    a heap of bodies in one spot makes every pair a contact (2 000 in one spot took minutes and
    gigabytes a frame), where a pile of bodies that touch makes a few a body."""
    limit, pairs = MAX_START_PAIRS * len(radii), 0
    for start in range(0, len(radii), 256):  # (rows of the distance matrix a block at a time)
        gap = np.hypot(*(positions[start:start + 256, None, :] - positions[None, :, :]).transpose(2, 0, 1))
        reach = radii[start:start + 256, None] + radii[None, :]
        pairs += int(np.triu(gap < reach, k=start + 1).sum())
    if pairs > limit:
        raise ValueError(f"{pairs:,} pairs of bodies start within reach of each other (their bounding circles "
                         f"overlap): at most {MAX_START_PAIRS} a body ({limit:,} here); spread them out")


def check_vertex_budget(outlines: int) -> None:
    """Raise if one file's outlines hold too many vertices together."""
    if outlines > MAX_TOTAL_VERTICES:
        raise ValueError(f"{outlines:,} vertices in all: at most {MAX_TOTAL_VERTICES:,} in one file")
