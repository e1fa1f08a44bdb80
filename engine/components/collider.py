import math
from dataclasses import dataclass, field

from polygolf.engine.physics.body import Material
from polygolf.engine.physics.polygon import Outline, Vec

__all__ = ["Collider", "Material"]


@dataclass(slots=True)
class Collider:
    """A body's shape in its own frame (centroid at the origin), split into convex pieces.

    World-space vertices are cached per pose, so a body that has not moved is not transformed again.
    """

    outline: Outline
    pieces: tuple[Outline, ...]
    normals: tuple[tuple[Vec, ...], ...]
    radius: float  # bounding radius about the centroid
    material: Material
    piece_reach: tuple[float, ...] = ()  # per piece, farthest vertex from the centroid
    thickness: float = 0.0  # the thinnest width of any piece: a smaller relative step cannot pass through it
    _pose: tuple[float, float, float] = (math.nan, math.nan, math.nan)
    _world_pieces: list[list[Vec]] = field(default_factory=list)
    _world_normals: list[list[Vec]] = field(default_factory=list)

    def world(self, x: float, y: float, angle: float) -> tuple[list[list[Vec]], list[list[Vec]]]:
        """Vertices and normals of every piece at the given pose."""
        if self._pose != (x, y, angle):
            c, s = math.cos(angle), math.sin(angle)
            self._world_pieces = [[(x + c * px - s * py, y + s * px + c * py) for px, py in piece]
                                  for piece in self.pieces]
            self._world_normals = [[(c * nx - s * ny, s * nx + c * ny) for nx, ny in normals]
                                   for normals in self.normals]
            self._pose = (x, y, angle)
        return self._world_pieces, self._world_normals
