from dataclasses import dataclass

from polygolf.engine.components.collider import Material
from polygolf.engine.physics.polygon import Outline, Vec


@dataclass(slots=True)
class Wall:
    """A static obstacle, stored in world coordinates as convex pieces with their outward normals."""

    outline: Outline
    pieces: tuple[Outline, ...]
    normals: tuple[tuple[Vec, ...], ...]
    material: Material
    piece_aabbs: tuple[tuple[float, float, float, float], ...]
    # Per piece, what other walls cover (see physics.seams): edges that may not be a contact's
    # reference face, vertices that may not be a contact point, and of those the reflex ones (inside
    # corners). Filled when the world is built.
    internal: tuple[frozenset[int], ...] = ()
    hidden: tuple[frozenset[int], ...] = ()
    reflex: tuple[frozenset[int], ...] = ()
