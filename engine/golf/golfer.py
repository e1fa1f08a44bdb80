"""A scripted golfer: plans shots from the hole's geometry alone. Used by the tests (a whole round
played by real shots), the benchmarks (a ball that keeps moving) and the play view's hint.

It never reads the physics' future: it aims at the farthest point of the shortest clear path that it
can see (never a point on a slope, where nothing rests), and picks the arrow length whose roll stops
there (or just past the cup, so the ball crosses it slowly). The roll is worked out along the line
with the green's drag law and the surfaces it crosses (sand, ice, slopes); walls it leaves out.
"""

from __future__ import annotations

import heapq
import math

import numpy as np

from polygolf.engine.components.hazards import Ice, Region, Sand
from polygolf.engine.golf.holes import Hole
from polygolf.engine.golf.layout import HoleLayout, point_clearance
from polygolf.engine.golf.play import HolePlay
from polygolf.engine.loading.scene import DragSpec
from polygolf.engine.physics.polygon import Vec
from polygolf.engine.physics.settings import MAX_SHOT_SPEED, SHOT_POWER

CUP_OVERSHOOT = 0.3  # m past the cup's centre: the ball is slow there, so it drops


def roll_distance(speed: float, drag: DragSpec) -> float:
    """How far a ball sent at `speed` rolls under dv/dt = -k·v - c before it stops."""
    k, c = drag.linear, drag.rolling
    if c <= 0.0:
        return math.inf if k <= 0.0 else speed / k
    if k <= 0.0:
        return speed * speed / (2.0 * c)
    stop = math.log1p(k * speed / c) / k
    return (speed - c * stop) / k


def speed_for(distance: float, drag: DragSpec) -> float:
    """The launch speed that rolls `distance` (capped at the fastest shot), by bisection."""
    lo, hi = 0.0, MAX_SHOT_SPEED
    if roll_distance(hi, drag) <= distance:
        return hi
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if roll_distance(mid, drag) < distance:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def _segment_distance(p: Vec, q: Vec, a: Vec, b: Vec) -> float:
    """Shortest distance between segments pq and ab."""

    def point_seg(x: Vec, u: Vec, v: Vec) -> float:
        ex, ey = v[0] - u[0], v[1] - u[1]
        length2 = ex * ex + ey * ey
        t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((x[0] - u[0]) * ex + (x[1] - u[1]) * ey) / length2))
        return math.hypot(x[0] - u[0] - t * ex, x[1] - u[1] - t * ey)

    def orient(u: Vec, v: Vec, w: Vec) -> float:
        return (v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0])

    if (orient(p, q, a) > 0) != (orient(p, q, b) > 0) and (orient(a, b, p) > 0) != (orient(a, b, q) > 0):
        return 0.0
    return min(point_seg(p, a, b), point_seg(q, a, b), point_seg(a, p, q), point_seg(b, p, q))


class AutoGolfer:
    def __init__(self, layout: HoleLayout, ball_radius: float, drag: DragSpec) -> None:
        self.layout = layout
        self.drag = drag
        self.clearance = 0.9 * ball_radius
        self.avoid = layout.wall_outlines() + layout.zone_outlines("water")  # walls, and water it will not cross
        self.edges = [(o[i], o[(i + 1) % len(o)]) for o in self.avoid for i in range(len(o))]
        # Each edge's box, so `clear` measures only the edges whose boxes come within the clearance of
        # the segment's: the others are farther than that (with room for rounding), so the answer is
        # the same, at a fraction of the cost (a hole's sample graph asks some 6 000 times).
        self._edge_boxes = np.array([(min(u[0], v[0]), min(u[1], v[1]), max(u[0], v[0]), max(u[1], v[1]))
                                     for u, v in self.edges], dtype=np.float64).reshape(-1, 4)
        self._reach = self.clearance * (1.0 + 1e-9) + 1e-9
        size = layout.tile_size
        nodes: list[Vec] = list(layout.route)
        for x0, y0, _, _ in layout.floor:
            for i in range(1, 5):
                for j in range(1, 5):
                    nodes.append((x0 + size * i / 5, y0 + size * j / 5))
        self.nodes = [n for n in nodes if self._free(n)] + [layout.cup]
        self.cup = len(self.nodes) - 1
        self.surfaces = []
        for kind, outline, push in layout.zones:
            if kind in ("sand", "ice", "slope"):
                xs, ys = zip(*outline)
                self.surfaces.append((Region(tuple(outline), (min(xs), min(ys), max(xs), max(ys))), kind, push))
        self.links: list[list[tuple[int, float]]] = [[] for _ in self.nodes]
        for i, a in enumerate(self.nodes):
            for j in range(i + 1, len(self.nodes)):
                b = self.nodes[j]
                d = math.dist(a, b)
                if d < 1.6 * size and self.clear(a, b):
                    self.links[i].append((j, d))
                    self.links[j].append((i, d))

    def _free(self, p: Vec) -> bool:
        return point_clearance(self.layout, *p, self.avoid) >= self.clearance * 1.3

    def clear(self, a: Vec, b: Vec) -> bool:
        """Whether segment ab keeps the clearance from every wall and water edge."""
        boxes, reach, edges = self._edge_boxes, self._reach, self.edges
        near = np.flatnonzero((boxes[:, 0] <= max(a[0], b[0]) + reach) & (boxes[:, 2] >= min(a[0], b[0]) - reach)
                              & (boxes[:, 1] <= max(a[1], b[1]) + reach) & (boxes[:, 3] >= min(a[1], b[1]) - reach))
        return all(_segment_distance(a, b, *edges[k]) >= self.clearance for k in near.tolist())

    def path(self, start: Vec) -> list[Vec]:
        """Shortest clear path from `start` to the cup through the sample points."""
        dist = {-1: 0.0}
        prev: dict[int, int] = {}
        heap = [(0.0, -1)]
        while heap:
            d, i = heapq.heappop(heap)
            if d > dist.get(i, math.inf):
                continue
            if i == self.cup:
                break
            neighbours = ([(j, math.dist(start, n)) for j, n in enumerate(self.nodes) if self.clear(start, n)]
                          if i == -1 else self.links[i])
            for j, w in neighbours:
                if d + w < dist.get(j, math.inf):
                    dist[j] = d + w
                    prev[j] = i
                    heapq.heappush(heap, (d + w, j))
        if self.cup not in prev:
            return [self.layout.cup]
        out, i = [], self.cup
        while i != -1:
            out.append(self.nodes[i])
            i = prev[i]
        return out[::-1]

    def on_slope(self, p: Vec) -> bool:
        return any(kind == "slope" and region.contains(*p) for region, kind, _ in self.surfaces)

    def roll(self, start: Vec, direction: Vec, speed: float, dt: float = 1 / 120) -> float:
        """How far a ball sent from `start` along `direction` rolls before it stops (or turns back)."""
        if not self.surfaces:
            return roll_distance(speed, self.drag)
        ux, uy = direction
        k, c = self.drag.linear, self.drag.rolling
        x, y = start
        travelled, v = 0.0, speed
        while v > 0.0 and travelled < 300.0:
            scale, along = 1.0, 0.0
            for region, kind, push in self.surfaces:
                if region.contains(x, y):
                    if kind == "slope":
                        along += push[0] * ux + push[1] * uy
                    else:
                        scale = Sand().drag_scale if kind == "sand" else Ice().drag_scale
            v = v * math.exp(-k * scale * dt) - c * scale * dt + along * dt
            step = max(v, 0.0) * dt
            x, y, travelled = x + ux * step, y + uy * step, travelled + step
        return travelled

    def plan(self, position: Vec) -> tuple[Vec, Vec]:
        """(grab point, arrow) for a shot from `position`: grabbed at the centroid, so no spin."""
        route = self.path(position)
        target = next((p for p in reversed(route) if self.clear(position, p) and not self.on_slope(p)), route[0])
        distance = math.dist(position, target)
        if distance < 1e-6:
            return position, (0.0, 0.0)
        ux, uy = (target[0] - position[0]) / distance, (target[1] - position[1]) / distance
        if target == self.layout.cup:
            distance += CUP_OVERSHOOT
        lo, hi = 0.0, MAX_SHOT_SPEED
        if self.roll(position, (ux, uy), hi) <= distance:
            speed = hi
        else:
            for _ in range(40):
                mid = 0.5 * (lo + hi)
                lo, hi = (mid, hi) if self.roll(position, (ux, uy), mid) < distance else (lo, mid)
            speed = 0.5 * (lo + hi)
        return position, (ux * speed / SHOT_POWER, uy * speed / SHOT_POWER)


_PLANNERS: dict[int, tuple[Hole, AutoGolfer]] = {}  # the last holes' planners, by the hole object
_PLANNERS_KEPT = 8


def golfer_for(hole: Hole) -> AutoGolfer:
    """The hole's planner, built once for each of the last few holes asked about: building one
    samples the hole and links the samples (tens of ms), and the search golfer asks again for every
    ball shape and every hint. A planner never changes once built, nor does a loaded hole."""
    kept = _PLANNERS.get(id(hole))
    if kept is not None and kept[0] is hole:
        return kept[1]
    spec, lib = hole.spec, hole.library
    golfer = AutoGolfer(hole.layout, lib.ball.radius, spec.green or lib.green)
    _PLANNERS[id(hole)] = (hole, golfer)  # (the hole held, so its id names no other hole meanwhile)
    while len(_PLANNERS) > _PLANNERS_KEPT:
        del _PLANNERS[next(iter(_PLANNERS))]
    return golfer


def play_hole(world: HolePlay, max_frames: int = 60 * 120) -> int:
    """Play a hole to the end with planned shots; returns the frames it took."""
    golfer = golfer_for(world.hole)
    frames = 0
    while not world.state.finished and frames < max_frames:
        if world.ball_at_rest:
            origin, arrow = golfer.plan((world.ball.x, world.ball.y))
            world.shoot(origin, arrow)
        world.step()
        frames += 1
    return frames
