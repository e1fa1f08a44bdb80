"""The search golfer: it plays real shots with the game's own physics instead of guessing.

From where the ball lies it simulates a fan of candidate shots (direction × power) to rest in one
world (`simulate_shots`), scores where each ended by the strokes it cost and the distance left *along
the hole's route* (a walking distance round walls and water, not as the crow flies), then refines
around the best few (a shrinking cross-entropy search that also tries grab points, i.e. spin). So it
banks off a wall when that is shorter, and it never trusts a line it has not simulated.

It plays stroke by stroke (no look-ahead beyond the distance left). `skill` < 1 adds aiming noise to
the chosen shot, which makes it a fair opponent. `prove_hole` plays a hole with several shapes: the
proof that it can be sunk, and an estimate of its par.
"""

from __future__ import annotations

import heapq
import math
import random
import statistics
import time
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from polygolf.engine.golf.golfer import golfer_for, speed_for
from polygolf.engine.golf.holes import Hole
from polygolf.engine.golf.layout import HoleLayout
from polygolf.engine.golf.shots import Shot, ShotResult, simulate_shots
from polygolf.engine.loading.scene import ShapeSpec
from polygolf.engine.physics.polygon import Outline
from polygolf.engine.physics.presets import Knobs
from polygolf.engine.physics.settings import MAX_SHOT_SPEED, SHOT_POWER

ROUTE_STEP = 0.25  # m between the route map's nodes
MAX_ROUTE_NODES = 250_000  # a larger hole's route map is coarser (its search, Python's, some seconds)
STROKE = 4.0  # m of route: what one more stroke weighs when two shots are compared
SHOT_SECONDS = 12.0  # a shot still rolling after this long (stuck on a windmill, say) counts as a bad one
PROOF_SHAPES = (ShapeSpec(regular=6, radius=1.0), ShapeSpec(regular=3, radius=1.0), ShapeSpec(star=(5, 2), radius=1.0))


@dataclass(frozen=True)
class Effort:
    """How hard the golfer looks: a coarse fan, then refinement rounds around the best shots."""

    directions: int  # evenly spread directions in the fan
    reaches: tuple[float, ...]  # roll lengths of the fan, as multiples of the distance left along the route
    rounds: int  # refinement rounds after the fan
    per_round: int  # shots tried in each round
    keep: int  # best shots sampled around in a round

    @property
    def most_shots(self) -> int:
        """Shots simulated per stroke at most (the planned shot, the fan and every round)."""
        return 1 + self.directions * len(self.reaches) + self.rounds * self.per_round


EFFORTS = {
    "quick": Effort(directions=32, reaches=(0.5, 1.0, 1.5), rounds=2, per_round=24, keep=4),
    "normal": Effort(directions=36, reaches=(0.45, 0.8, 1.1, 1.7), rounds=2, per_round=32, keep=5),
    "thorough": Effort(directions=60, reaches=(0.35, 0.6, 0.85, 1.1, 1.5, 2.3), rounds=3, per_round=48, keep=6),
}


class RouteMap:
    """Distance to the cup along the green for any point: Dijkstra over a grid of nodes where the ball
    fits (clear of walls by most of its radius, out of water), eight neighbours each."""

    def __init__(self, layout: HoleLayout, ball_radius: float, step: float = ROUTE_STEP) -> None:
        x0, y0, x1, y1 = layout.bounds
        # A hole too large for a grid of this step gets a coarser one (tiles far apart, or huge ones).
        step = max(step, math.sqrt((x1 - x0) * (y1 - y0) / MAX_ROUTE_NODES))
        self.origin, self.step = (x0, y0), step
        self.nx, self.ny = int(math.ceil((x1 - x0) / step)), int(math.ceil((y1 - y0) / step))
        xs = x0 + (np.arange(self.nx) + 0.5) * step
        ys = y0 + (np.arange(self.ny) + 0.5) * step
        px, py = (a.ravel() for a in np.meshgrid(xs, ys, indexing="xy"))  # node k = j * nx + i
        free = np.zeros(px.shape, dtype=bool)
        for fx0, fy0, fx1, fy1 in layout.floor:
            free |= (px >= fx0) & (px <= fx1) & (py >= fy0) & (py <= fy1)
        free &= self._clear_of(xs, ys, layout.wall_outlines(), 0.6 * ball_radius)
        free &= self._clear_of(xs, ys, layout.zone_outlines("water"), 0.3 * ball_radius)
        self.free = free
        self.points = np.stack([px, py], axis=1)
        self.distance = self._dijkstra(layout.cup)

    def _clear_of(self, xs: np.ndarray, ys: np.ndarray, outlines: list, distance: float) -> np.ndarray:
        """Which nodes lie `distance` or more from every outline (and outside it): each outline asked
        only about the nodes of its box grown by `distance` (the rest are farther), not every node."""
        clear = np.ones((self.ny, self.nx), dtype=bool)
        (x0, y0), step = self.origin, self.step
        for outline in outlines:
            ox, oy = [x for x, _ in outline], [y for _, y in outline]
            i0, i1 = (max(0, math.floor((min(ox) - distance - x0) / step - 1.0)),
                      min(self.nx, math.ceil((max(ox) + distance - x0) / step + 1.0)))
            j0, j1 = (max(0, math.floor((min(oy) - distance - y0) / step - 1.0)),
                      min(self.ny, math.ceil((max(oy) + distance - y0) / step + 1.0)))
            if i0 < i1 and j0 < j1:
                bx, by = np.meshgrid(xs[i0:i1], ys[j0:j1], indexing="xy")
                clear[j0:j1, i0:i1] &= _clearance(bx, by, [outline]) >= distance
        return clear.ravel()

    def _node(self, x: float, y: float) -> tuple[int, int]:
        return int((x - self.origin[0]) / self.step), int((y - self.origin[1]) / self.step)

    def _dijkstra(self, cup: tuple[float, float]) -> np.ndarray:
        dist = np.full(self.free.shape, np.inf)
        free = self.free.tolist()
        best = dist.tolist()
        heap: list[tuple[float, int]] = []
        ci, cj = self._node(*cup)
        for j in range(cj - 2, cj + 3):
            for i in range(ci - 2, ci + 3):
                if 0 <= i < self.nx and 0 <= j < self.ny and free[j * self.nx + i]:
                    k = j * self.nx + i
                    best[k] = math.dist(cup, self.points[k])
                    heapq.heappush(heap, (best[k], k))
        moves = [(di, dj, self.step * math.hypot(di, dj)) for di in (-1, 0, 1) for dj in (-1, 0, 1) if di or dj]
        while heap:
            d, k = heapq.heappop(heap)
            if d > best[k]:
                continue
            j, i = divmod(k, self.nx)
            for di, dj, w in moves:
                ii, jj = i + di, j + dj
                if 0 <= ii < self.nx and 0 <= jj < self.ny:
                    n = jj * self.nx + ii
                    # a diagonal step only between two free sides, so it never cuts a wall's corner
                    if free[n] and d + w < best[n] and (not (di and dj) or (free[j * self.nx + ii]
                                                                             and free[jj * self.nx + i])):
                        best[n] = d + w
                        heapq.heappush(heap, (d + w, n))
        dist[:] = best
        return dist

    def __call__(self, x: float, y: float) -> float:
        """Distance left from (x, y): through the nearest reachable nodes, else infinity."""
        ci, cj = self._node(x, y)
        for reach in (2, 5):
            best = math.inf
            for j in range(max(cj - reach, 0), min(cj + reach + 1, self.ny)):
                for i in range(max(ci - reach, 0), min(ci + reach + 1, self.nx)):
                    k = j * self.nx + i
                    d = self.distance[k]
                    if d < math.inf:
                        best = min(best, d + math.hypot(x - self.points[k, 0], y - self.points[k, 1]))
            if best < math.inf:
                return best
        return math.inf


def _clearance(px: np.ndarray, py: np.ndarray, outlines: list) -> np.ndarray:
    """Each point's distance to the nearest outline (0 inside one)."""
    best = np.full(px.shape, np.inf)
    for outline in outlines:
        inside = np.zeros(px.shape, dtype=bool)
        n = len(outline)
        for a in range(n):
            (ax, ay), (bx, by) = outline[a], outline[(a + 1) % n]
            ex, ey = bx - ax, by - ay
            t = np.clip(((px - ax) * ex + (py - ay) * ey) / (ex * ex + ey * ey), 0.0, 1.0)
            best = np.minimum(best, np.hypot(px - ax - t * ex, py - ay - t * ey))
            crosses = (ay > py) != (by > py)
            with np.errstate(divide="ignore", invalid="ignore"):
                inside ^= crosses & (px < ax + (py - ay) * ex / np.where(ey == 0.0, 1.0, ey))
        best[inside] = 0.0
    return best


@dataclass(frozen=True)
class Choice:
    """A shot the golfer simulated, where it went, and what that cost (m of route; lower is better)."""

    shot: Shot
    result: ShotResult
    cost: float


@dataclass
class SearchStats:
    shots: int = 0  # shots simulated
    seconds: float = 0.0  # wall time spent simulating them
    ball_seconds: float = 0.0  # game time they covered, summed over the shots


class SearchGolfer:
    """Chooses shots on one hole for one ball shape by simulating candidates with the game's physics."""

    def __init__(self, hole: Hole, shape: ShapeSpec, knobs: Knobs | str = "balanced",
                 effort: Effort | str = "normal", seed: int = 0) -> None:
        self.hole, self.shape, self.knobs = hole, shape, knobs
        self.effort = EFFORTS[effort] if isinstance(effort, str) else effort
        self.radius = hole.library.ball.radius
        self.drag = hole.spec.green or hole.library.green
        self.route = RouteMap(hole.layout, self.radius)
        self.planner = golfer_for(hole)
        self.rng = random.Random(seed)
        self.stats = SearchStats()

    def cost(self, result: ShotResult) -> float:
        """Strokes (each worth STROKE m) plus the route distance left; nothing left once holed."""
        if result.holed:
            return STROKE * result.penalties
        left = self.route(*result.rest)
        if left == math.inf:  # somewhere the ball cannot be played from along the green
            left = 3 * STROKE + math.dist(result.rest, self.hole.layout.cup)
        stuck = STROKE if result.seconds >= SHOT_SECONDS else 0.0
        return STROKE * (1 + result.penalties) + left + stuck

    def simulate(self, shots: list[Shot], windmills: Sequence[float] = (), path: bool = False,
                 obstacles: Sequence[Outline] = ()) -> list[ShotResult]:
        """`simulate_shots` on this golfer's hole; `obstacles`: the other players' balls where they
        rest, as walls (the shot should not count on passing through them)."""
        start = time.perf_counter()
        results = simulate_shots(self.hole, shots, self.knobs, shape=self.shape, max_seconds=SHOT_SECONDS, path=path,
                                 windmills=windmills, obstacles=obstacles)
        self.stats.shots += len(shots)
        self.stats.seconds += time.perf_counter() - start
        self.stats.ball_seconds += sum(r.seconds for r in results)
        return results

    def _arrow(self, heading: float, roll: float) -> tuple[float, float]:
        """The arrow that sends the ball along `heading` to roll `roll` m on the open green."""
        speed = min(speed_for(max(roll, 0.05), self.drag), MAX_SHOT_SPEED)
        length = speed / SHOT_POWER
        return length * math.cos(heading), length * math.sin(heading)

    def fan(self, start: tuple[float, float], angle: float = 0.0) -> list[Shot]:
        """The planned line of the scripted golfer, then every direction at every reach."""
        left = self.route(*start)
        left = math.dist(start, self.hole.layout.cup) if left == math.inf else left
        origin, arrow = self.planner.plan(start)
        shots = [Shot(start, arrow, angle=angle)] if math.hypot(*arrow) > 0.0 else []
        effort = self.effort
        for reach in effort.reaches:
            for k in range(effort.directions):
                heading = 2 * math.pi * (k + 0.5 * (reach > 1.0)) / effort.directions
                shots.append(Shot(start, self._arrow(heading, reach * left), angle=angle))
        return shots

    def search(self, start: tuple[float, float], angle: float = 0.0, windmills: Sequence[float] = (),
               obstacles: Sequence[Outline] = ()) -> Choice:
        """The best shot found from `start` (the ball turned `angle`)."""
        return self._tried(start, angle, windmills, obstacles)[0]

    def _tried(self, start: tuple[float, float], angle: float, windmills: Sequence[float],
               obstacles: Sequence[Outline] = ()) -> list[Choice]:
        """Every shot the search simulated from `start`, best first."""
        effort = self.effort
        shots = self.fan(start, angle)
        results = self.simulate(shots, windmills, obstacles=obstacles)
        tried = [Choice(s, r, self.cost(r)) for s, r in zip(shots, results)]
        tried.sort(key=lambda c: c.cost)
        spread_heading, spread_power, spread_grab = 2 * math.pi / effort.directions, 0.25, 0.5 * self.radius
        for _ in range(effort.rounds):
            if tried[0].result.holed and tried[0].result.penalties == 0:
                break
            elites = tried[:effort.keep]
            shots = []
            for n in range(effort.per_round):
                around = elites[n % len(elites)].shot
                heading = math.atan2(around.arrow[1], around.arrow[0]) + self.rng.gauss(0.0, spread_heading)
                length = math.hypot(*around.arrow) * math.exp(self.rng.gauss(0.0, spread_power))
                length = min(length, MAX_SHOT_SPEED / SHOT_POWER)
                side = self.rng.gauss(0.0, spread_grab)
                side = max(-0.8 * self.radius, min(0.8 * self.radius, side))
                grab = (-math.sin(heading) * side, math.cos(heading) * side)  # off the line: spin
                shots.append(Shot(start, (length * math.cos(heading), length * math.sin(heading)), grab, angle))
            tried += [Choice(s, r, self.cost(r)) for s, r in zip(shots, self.simulate(shots, windmills,
                                                                                  obstacles=obstacles))]
            tried.sort(key=lambda c: c.cost)
            spread_heading, spread_power, spread_grab = 0.5 * spread_heading, 0.6 * spread_power, 0.6 * spread_grab
        return tried

    def aim(self, start: tuple[float, float], angle: float = 0.0, windmills: Sequence[float] = (),
            skill: float = 1.0, rng: random.Random | None = None, obstacles: Sequence[Outline] = ()) -> Shot:
        """The shot a golfer of `skill` (1 = exact, 0 = wild) plays from `start`, its direction and
        length spoiled by noise that grows as skill falls. Below skill 1 it is the shot, of the best
        few found, that fares best on average when played that loosely (each tried astray by one
        spread of the noise either way in aim and power): a shot that skirts water is a poor bet
        for a golfer whose aim wanders, who would otherwise play it into the water again and again.
        `obstacles`: the other players' balls (outlines where they rest), met as walls."""
        miss = _miss(skill)
        tried = self._tried(start, angle, windmills, obstacles)
        shot = tried[0].shot
        if miss > 0.0 and len(tried) > 1:
            finalists = [c.shot for c in tried[:FINALISTS]]
            loose = [_astray(s, heading * AIM_SPREAD * miss, POWER_SPREAD * miss * power)
                     for s in finalists for heading, power in LOOSE_PLAYS]
            costs = [self.cost(r) for r in self.simulate(loose, windmills, obstacles=obstacles)]
            totals = [sum(costs[k * len(LOOSE_PLAYS):(k + 1) * len(LOOSE_PLAYS)]) for k in range(len(finalists))]
            shot = finalists[totals.index(min(totals))]
        return spoil(shot, skill, rng or self.rng)


AIM_SPREAD, POWER_SPREAD = 0.12, 0.2  # rad, and log of the power, astray (one spread) at skill 0
FINALISTS = 6  # the best shots a loose golfer weighs
LOOSE_PLAYS = ((0, 0), (1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, -1), (1, -1), (-1, 1))  # in spreads


def _miss(skill: float) -> float:
    return max(0.0, min(1.0, 1.0 - skill))


def _astray(shot: Shot, heading: float, power: float) -> Shot:
    """`shot` turned by `heading` (rad) and its arrow's length times e^`power` (at most the fastest
    shot's)."""
    direction = math.atan2(shot.arrow[1], shot.arrow[0]) + heading
    length = min(math.hypot(*shot.arrow) * math.exp(power), MAX_SHOT_SPEED / SHOT_POWER)
    return Shot(shot.start, (length * math.cos(direction), length * math.sin(direction)), shot.grab, shot.angle)


def spoil(shot: Shot, skill: float, rng: random.Random) -> Shot:
    """`shot` as a golfer of `skill` plays it: about 7° of aim and 20 % of power astray at skill 0."""
    miss = _miss(skill)
    if miss == 0.0:
        return shot
    return _astray(shot, rng.gauss(0.0, AIM_SPREAD * miss), rng.gauss(0.0, POWER_SPREAD * miss))


@dataclass
class HoleRun:
    """One ball played through a hole by the search golfer."""

    strokes: int  # shots plus penalty strokes
    sunk: bool
    shots: list[Shot] = field(default_factory=list)
    results: list[ShotResult] = field(default_factory=list)


def play_out(golfer: SearchGolfer, skill: float = 1.0, rng: random.Random | None = None) -> HoleRun:
    """Play the hole from the tee until the ball drops or is picked up. Each stroke's outcome is the
    simulated result of the shot actually chosen (the same physics as playing it); windmills keep
    turning between strokes as the ball's travel takes time."""
    hole = golfer.hole
    limit = hole.spec.max_strokes or hole.library.max_strokes
    speeds = [speed for _, _, speed in hole.layout.windmills]
    start, angle, clock = hole.layout.tee, 0.0, 0.0
    run = HoleRun(strokes=0, sunk=False)
    while run.strokes < limit:
        windmills = [speed * clock for speed in speeds]
        choice = golfer.search(start, angle, windmills)
        shot, result = choice.shot, choice.result
        if skill < 1.0:
            shot = spoil(shot, skill, rng or golfer.rng)
            result = golfer.simulate([shot], windmills)[0]
        run.shots.append(shot)
        run.results.append(result)
        run.strokes += 1 + result.penalties
        clock += result.seconds
        if result.holed:
            run.sunk = True
            break
        start, angle = result.rest, result.angle
    return run


@dataclass
class HoleProof:
    """The golfer's proof of one hole (the `polygolf par` row; see the design notes)."""

    hole: str
    name: str
    par: int
    estimated_par: int
    best_strokes: int | None  # fewest strokes of any shape that sank it
    sunk: bool  # every shape tried sank it
    strokes: list[int | None]  # per shape tried, None where it was picked up
    seconds: float  # wall time of the proof
    shots: int  # shots simulated
    ball_seconds: float  # game time simulated, summed over those shots

    def row(self) -> dict[str, object]:
        return {"hole": self.hole, "name": self.name, "par": self.par, "estimated_par": self.estimated_par,
                "best_strokes": self.best_strokes, "sunk": self.sunk}


def estimate_par(strokes: list[int | None], limit: int) -> int:
    """Par from the golfer's strokes over several shapes: the median (a ball picked up counts as the
    limit), one more than a search golfer needs, as players are not exact; at least 2, since a par
    of 1 would make every hole in one merely par."""
    counted = [s if s is not None else limit for s in strokes]
    return max(2, math.ceil(statistics.median(counted)) + 1)


def prove_hole(hole: Hole, shapes: Sequence[ShapeSpec] | None = None, effort: Effort | str = "quick",
               knobs: Knobs | str = "fast", seed: int = 0) -> HoleProof:
    """Play `hole` with each shape (by default a hexagon, a triangle and a star {5/2})."""
    began = time.perf_counter()
    strokes: list[int | None] = []
    shots, ball_seconds = 0, 0.0
    for shape in shapes or PROOF_SHAPES:
        golfer = SearchGolfer(hole, shape, knobs, effort, seed)
        run = play_out(golfer)
        strokes.append(run.strokes if run.sunk else None)
        shots += golfer.stats.shots
        ball_seconds += golfer.stats.ball_seconds
    sunk_with = [s for s in strokes if s is not None]
    limit = hole.spec.max_strokes or hole.library.max_strokes
    return HoleProof(hole=hole.id, name=hole.spec.name, par=hole.spec.par, estimated_par=estimate_par(strokes, limit),
                     best_strokes=min(sunk_with) if sunk_with else None, sunk=len(sunk_with) == len(strokes),
                     strokes=strokes, seconds=time.perf_counter() - began, shots=shots, ball_seconds=ball_seconds)
