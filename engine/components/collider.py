import math
from dataclasses import dataclass, field

import numpy as np

from polygolf.engine.physics.body import Material
from polygolf.engine.physics.geometry import ConvexSet, pose_set
from polygolf.engine.physics.polygon import Outline

__all__ = ["Collider", "Material"]


@dataclass(slots=True)
class Collider:
    """A body's shape in its own frame (centroid at the origin), split into convex pieces.

    World-space vertices are kept for the last pose asked for, so a body that has not moved is not
    transformed again."""

    outline: Outline
    shape: ConvexSet  # the convex pieces, in the body's frame
    radius: float  # bounding radius about the centroid
    material: Material
    thickness: float = 0.0  # the thinnest width of any piece: a smaller relative step cannot pass through it
    _pose: tuple[float, float, float] = (math.nan, math.nan, math.nan)
    _verts: np.ndarray = field(default_factory=lambda: np.empty((0, 2)))
    _normals: np.ndarray = field(default_factory=lambda: np.empty((0, 2)))

    def posed(self, x: float, y: float, angle: float) -> tuple[np.ndarray, np.ndarray]:
        """Vertices and normals of every piece at the given pose (rows as in `shape`)."""
        if self._pose != (x, y, angle):
            if len(self._verts) != len(self.shape.verts):
                self._verts, self._normals = np.empty_like(self.shape.verts), np.empty_like(self.shape.normals)
            pose_set(self.shape.verts, self.shape.normals, x, y, angle, self._verts, self._normals)
            self._pose = (x, y, angle)
        return self._verts, self._normals
