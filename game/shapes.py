"""The balls a player can choose: regular polygons, stars and seeded random shapes."""

from __future__ import annotations

import random
import re

from pydantic import ValidationError

from polygolf.engine.golf.world import DEFAULT_BALL
from polygolf.engine.loading.scene import ShapeSpec
from polygolf.engine.physics.polygon import MAX_SIDES, MIN_SIDES

CATALOGUE: list[tuple[str, ShapeSpec]] = [
    ("Triangle", ShapeSpec(regular=3, radius=1.0)),
    ("Square", ShapeSpec(regular=4, radius=1.0)),
    ("Pentagon", DEFAULT_BALL),
    ("Hexagon", ShapeSpec(regular=6, radius=1.0)),
    ("Heptagon", ShapeSpec(regular=7, radius=1.0)),
    ("Octagon", ShapeSpec(regular=8, radius=1.0)),
    ("Nonagon", ShapeSpec(regular=9, radius=1.0)),
    ("Decagon", ShapeSpec(regular=10, radius=1.0)),
    ("Hendecagon", ShapeSpec(regular=11, radius=1.0)),
    ("Dodecagon", ShapeSpec(regular=12, radius=1.0)),
    ("Star {5/2}", ShapeSpec(star=(5, 2), radius=1.0)),
    ("Star {7/2}", ShapeSpec(star=(7, 2), radius=1.0)),
    ("Star {7/3}", ShapeSpec(star=(7, 3), radius=1.0)),
    ("Star {8/3}", ShapeSpec(star=(8, 3), radius=1.0)),
]


def random_shape(rng: random.Random | None = None) -> tuple[str, ShapeSpec]:
    rng = rng or random.Random()
    seed = rng.randrange(1_000_000)
    vertices = rng.randint(4, 9)
    return f"Random #{seed}", ShapeSpec(random={"seed": seed, "vertices": vertices}, radius=1.0)


def labels_shape(label: str, spec: ShapeSpec) -> bool:
    """Whether `label` is what the game calls the ball `spec` (a catalogue name, "N-gon", "Star
    {p/q}", "Random #SEED", each of radius 1): a saved setting whose label names another shape, or
    none, is no setting the game made (QA: "Triangle" over a star {8/3} was shown, and kept its
    rounds as the Triangle's bests)."""
    if spec.radius != 1.0:
        return False
    if (label, spec) in CATALOGUE:
        return True
    if spec.regular is not None:
        return label == f"{spec.regular}-gon"
    if spec.star is not None:
        return label == f"Star {{{spec.star[0]}/{spec.star[1]}}}"
    return spec.random is not None and label == f"Random #{spec.random.seed}"


def parse_shape(text: str) -> tuple[str, ShapeSpec]:
    """A shape from the command line: a catalogue name ('pentagon', 'star-5-2'), a side count
    ('6'), or 'random-SEED'."""
    key = text.strip().lower()
    for label, spec in CATALOGUE:
        slug = re.sub(r"[^a-z0-9]+", "-", label.lower()).strip("-")
        if key in (label.lower(), slug):
            return label, spec
    try:
        if key.isdigit() and len(key) < 4:
            sides = int(key)
            return f"{sides}-gon", ShapeSpec(regular=sides, radius=1.0)
        match = re.fullmatch(r"random-(\d{1,18})", key)
        if match:
            seed = int(match.group(1))
            return f"Random #{seed}", ShapeSpec(random={"seed": seed, "vertices": 4 + seed % 6}, radius=1.0)
        match = re.fullmatch(r"star-(\d{1,2})-(\d{1,2})", key)
        if match:
            p, q = int(match.group(1)), int(match.group(2))
            return f"Star {{{p}/{q}}}", ShapeSpec(star=(p, q), radius=1.0)
    except ValidationError as exc:
        reason = exc.errors(include_url=False)[0]["msg"].removeprefix("Value error, ")
        raise ValueError(f"shape {text!r}: {reason}") from None
    if key.isdigit():
        raise ValueError(f"shape {text!r}: a polygon has {MIN_SIDES} to {MAX_SIDES} sides")
    names = ", ".join(re.sub(r"[^a-z0-9]+", "-", label.lower()).strip("-") for label, _ in CATALOGUE)
    raise ValueError(f"unknown shape {text!r}; try one of: {names}, a side count, or random-SEED")
