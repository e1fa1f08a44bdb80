"""Exact mass properties of a simple polygon, convex or not.

The outline is a fan of signed triangles from the origin; summing their exact area, first and second
moments gives the polygon's, whatever its convexity (Eberly, "Polygonal and polyhedral mass
properties"). The inertia is then moved to the centroid with the parallel-axis theorem.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from polygolf.engine.physics.polygon import PolygonError, Vec


@dataclass(frozen=True, slots=True)
class MassProperties:
    area: float
    mass: float
    centroid: Vec
    inertia: float  # about the centroid, kg·m²


def mass_properties(vertices: Sequence[Vec], density: float = 1.0) -> MassProperties:
    n = len(vertices)
    if n < 3:
        raise PolygonError(f"a polygon needs at least 3 vertices, got {n}")
    ox, oy = vertices[0]  # work relative to a vertex: keeps precision far from the origin
    area2 = sx = sy = second = 0.0
    for i in range(n):
        x0, y0 = vertices[i][0] - ox, vertices[i][1] - oy
        x1, y1 = vertices[(i + 1) % n][0] - ox, vertices[(i + 1) % n][1] - oy
        c = x0 * y1 - x1 * y0
        area2 += c
        sx += (x0 + x1) * c
        sy += (y0 + y1) * c
        second += c * (x0 * x0 + x0 * x1 + x1 * x1 + y0 * y0 + y0 * y1 + y1 * y1)
    area = 0.5 * area2
    if area <= 0.0:
        raise PolygonError("mass properties need a counter-clockwise outline with positive area")
    cx, cy = sx / (3.0 * area2), sy / (3.0 * area2)
    mass = density * area
    inertia_about_origin = density * second / 12.0
    inertia = inertia_about_origin - mass * (cx * cx + cy * cy)
    return MassProperties(area=area, mass=mass, centroid=(ox + cx, oy + cy), inertia=inertia)
