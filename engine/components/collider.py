from dataclasses import dataclass

from polygolf.engine.physics.body import Material
from polygolf.engine.physics.geometry import ConvexSet
from polygolf.engine.physics.polygon import Outline

__all__ = ["Collider", "Material"]


@dataclass(slots=True, frozen=True)
class Collider:
    """A body's shape in its own frame (centroid at the origin), split into convex pieces. Never
    changed once made, so bodies of one shape and material may share one."""

    outline: Outline
    shape: ConvexSet  # the convex pieces, in the body's frame
    radius: float  # bounding radius about the centroid
    material: Material
    thickness: float = 0.0  # the thinnest width of any piece: a smaller relative step cannot pass through it
