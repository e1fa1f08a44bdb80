"""`polygolf bench accuracy`: what accuracy costs in time.

Every combination of the solver's knobs (substeps, velocity iterations, continuous collision,
position correction) runs the same cases:

- hard-case scenes with a closed form: the error is the relative error against it (rebound speed,
  spin, impulse, drag decay, momentum);
- hard-case scenes without one, and real shots on real holes: the error is against a converged
  reference run at a finer setting than any in the sweep (final position and angle), together with
  the deepest overlap, any rise of kinetic energy, and escaping through a wall.

Each case's error is a number in [0, 1] (see `case_error`); a setting's error is their mean. Its
cost is the median wall time per simulated second, over repeated runs. The report is a Markdown
table, a CSV and a plot of error against cost with the Pareto front and the presets marked.
"""

from __future__ import annotations

import csv
import math
import os
import statistics
from collections.abc import Callable, Iterable
from concurrent.futures import ProcessPoolExecutor, as_completed
from dataclasses import dataclass, field
from pathlib import Path

from polygolf.engine.assembly.stages import STAGES
from polygolf.engine.golf.golfer import golfer_for
from polygolf.engine.golf.holes import find_course, load_courses
from polygolf.engine.golf.play import HolePlay
from polygolf.engine.golf.world import DEFAULT_BALL
from polygolf.engine.loading.paths import SCENES_DIR
from polygolf.engine.loading.scene import build_scene, load_scene
from polygolf.engine.physics import polygon
from polygolf.engine.physics.presets import PRESETS, Knobs
from polygolf.engine.physics.settings import LINEAR_SLOP

REFERENCE = Knobs(substeps=32, iterations=30, position_iterations=6, ccd=True, position_correction="ngs")
SUBSTEPS = (1, 2, 3, 4, 6, 8, 12, 16)
ITERATIONS = (1, 2, 4, 8, 12, 20)
CORRECTIONS = ("split", "ngs", "none")


@dataclass
class Outcome:
    """What one run of a case left behind, for scoring."""

    x: float
    y: float
    angle: float
    vx: float
    vy: float
    spin: float
    radius: float
    max_penetration: float
    energy_gain: float  # largest kinetic energy seen over the initial, minus 1 (0 if it never rose)
    escaped: bool
    seconds: float = 0.0  # wall time spent stepping (building the world is not counted)
    extra: dict = field(default_factory=dict)


@dataclass
class Case:
    name: str
    kind: str  # "closed form", "reference", "shot" or "invariant"
    seconds: float
    run: Callable[[Knobs, bool], Outcome]  # (knobs, measure) -> outcome
    exact: Callable[[Outcome], float] | None = None  # closed-form relative error, if there is one


def _scene_case(name: str, seconds: float, exact=None, escaped=None) -> Case:

    scene = load_scene(SCENES_DIR / f"{name}.yaml")

    def run(knobs: Knobs, measure: bool) -> Outcome:
        with build_scene(scene, knobs) as sim:
            sim.run(seconds, measure=measure)
            _, body = sim.bodies()[0]
            radius = polygon.bounding_radius(scene.bodies[0].shape.outline())
            m = sim.metrics
            # Energy may only rise where something does work on the body (gravity here).
            scored = m.initial_energy > 0 and scene.gravity == (0.0, 0.0)
            gain = max(0.0, m.max_energy / m.initial_energy - 1.0) if scored else 0.0
            out = Outcome(body.x, body.y, body.angle, body.vx, body.vy, body.spin, radius, m.max_penetration,
                          gain, escaped(body) if escaped else False, m.wall_seconds)
            out.extra["bodies"] = {n: (b.vx, b.vy, b.mass) for n, b in sim.bodies()}
            return out

    return Case(name, "closed form" if exact else "reference", seconds, run, exact)


def pile_case(settle: float = 2.0, watch: float = 0.5) -> Case:
    """Twelve pentagons settling into a pile under gravity. No closed form and no single answer (a
    pile may settle many ways), so it is scored on what a settled pile must do: its overlaps stay
    near the linear slop (position correction) and it keeps still (solver convergence)."""

    scene = load_scene(SCENES_DIR / "pile.yaml")

    def run(knobs: Knobs, measure: bool) -> Outcome:
        with build_scene(scene, knobs) as sim:
            sim.run(settle, measure=measure)
            sim.metrics.max_penetration = 0.0
            fastest = 0.0
            for _ in range(round(watch * 60)):
                sim.step(1, measure=measure)
                fastest = max(fastest, max(math.hypot(b.vx, b.vy) for _, b in sim.bodies()))
            escaped = any(not (0.0 < b.x < 2.7 and b.y > 0.0) for _, b in sim.bodies())
            out = Outcome(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.2, 0.0, 0.0, escaped, sim.metrics.wall_seconds)
            out.extra["overlap"] = max(0.0, sim.metrics.max_penetration - LINEAR_SLOP)
            out.extra["fastest"] = fastest
            return out

    def settled(o: Outcome) -> float:
        return max(o.extra["overlap"] / (0.1 * o.radius), o.extra["fastest"] / 0.1)

    return Case("pile", "invariant", settle + watch, run, settled)


def overlap_case(seconds: float = 0.5) -> Case:
    """A body starting 5 cm inside a wall: position correction must push it out, without speed."""

    scene = load_scene(SCENES_DIR / "deep-overlap.yaml")

    def run(knobs: Knobs, measure: bool) -> Outcome:
        with build_scene(scene, knobs) as sim:
            sim.run(seconds, measure=measure)
            body = sim.body("ball")
            half = 0.5 / math.sqrt(2.0)
            out = Outcome(body.x, body.y, body.angle, body.vx, body.vy, body.spin, 0.5, 0.0, 0.0, False,
                          sim.metrics.wall_seconds)
            out.extra["overlap"] = max(0.0, half - body.x - LINEAR_SLOP)  # the wall's face is x = 0
            return out

    def pushed_out(o: Outcome) -> float:
        return max(o.extra["overlap"] / 0.01, math.hypot(o.vx, o.vy) / 0.1)

    return Case("deep-overlap", "invariant", seconds, run, pushed_out)


def _rel(value: float, expected: float) -> float:
    return abs(value - expected) / abs(expected)


def scene_cases() -> list[Case]:
    """The hard cases, scored against physics where physics gives the answer."""
    side, e = 0.5 * math.sqrt(2.0), 0.5
    mass, inertia = side * side, side**4 / 6.0

    def flat(o: Outcome) -> float:
        return max(_rel(o.vx, 5.0), abs(o.spin) * o.radius / 5.0)

    def vertex(o: Outcome) -> float:
        c, s = math.cos(math.radians(20)), math.sin(math.radians(20))
        corners = [(0.5 * math.cos(a) * c - 0.5 * math.sin(a) * s, 0.5 * math.cos(a) * s + 0.5 * math.sin(a) * c)
                   for a in (0, math.pi / 2, math.pi, 1.5 * math.pi)]
        rx, ry = min(corners)
        rn = -ry
        j = (1 + e) * 10.0 / (1 / mass + rn * rn / inertia)
        return max(_rel(o.vx, -10.0 + j / mass), _rel(o.spin, rn * j / inertia))

    def roll(o: Outcome) -> float:
        return _rel(math.hypot(o.vx, o.vy), 13.0 * math.exp(-0.7))

    def star(o: Outcome) -> float:
        return max(_rel(o.vx, 6.4), abs(o.spin) * o.radius / 6.4)

    def ratio(o: Outcome) -> float:
        bodies = o.extra["bodies"]
        (v1, _, m1), (v2, _, m2) = bodies["ball"], bodies["block"]
        return max(_rel(v1, (m1 - 0.5 * m2) / (m1 + m2) * 10.0), _rel(v2, 1.5 * m1 / (m1 + m2) * 10.0))

    return [
        _scene_case("flat-wall", 1.0, flat),
        _scene_case("vertex-hit", 0.5, vertex),
        _scene_case("long-roll", 1.0, roll),
        _scene_case("star-landing", 1.0, star),
        _scene_case("mass-ratio", 1.0, ratio),
        _scene_case("far-from-origin", 1.0, flat),
        _scene_case("corner", 3.0),
        _scene_case("fast-spin", 1.5),
        _scene_case("resting-contact", 3.0),
        _scene_case("thin-wall", 0.5, escaped=lambda b: b.x < 0.0),
        pile_case(),
        overlap_case(),
    ]


# (course, hole number, shot: None = the scripted golfer's first shot, else (grab offset, arrow))
SHOTS = [
    ("meadow", 1, ((0.0, 0.2), (2.6, 1.4))),  # a bank off the side wall, with spin
    ("meadow", 2, None),
    ("meadow", 3, None),
    ("meadow", 8, None),
    ("hazards", 1, None),  # through a bunker
    ("hazards", 3, None),  # onto ice
    ("hazards", 4, None),  # up a slope
    ("hazards", 6, None),  # past a windmill
]


def shot_cases(seconds: float = 4.0) -> list[Case]:
    """Real shots on real holes, followed until the ball rests (or `seconds` pass)."""

    courses = load_courses()
    shape = DEFAULT_BALL
    cases = []
    for course_name, number, shot in SHOTS:
        hole = find_course(courses, course_name).holes[number - 1]
        if shot is None:  # the scripted golfer's first shot, planned once
            tee = hole.layout.tee
            origin, arrow = golfer_for(hole).plan(tee)
            shot = ((origin[0] - tee[0], origin[1] - tee[1]), arrow)

        def run(knobs: Knobs, measure: bool, hole=hole, shot=shot) -> Outcome:
            world = HolePlay(hole, shape, knobs)
            try:
                tee = world.layout.tee
                (ox, oy), arrow = shot
                world.shoot((tee[0] + ox, tee[1] + oy), arrow)
                frames = 0
                while frames < seconds * 60 and not (frames > 0 and (world.ball_at_rest or world.state.finished)):
                    world.sim.step(1, measure=measure)
                    frames += 1
                b, m = world.ball, world.sim.metrics
                x0, y0, x1, y1 = world.layout.bounds
                # Energy is not scored on holes: bumpers and slopes add it by design.
                out = Outcome(b.x, b.y, b.angle, b.vx, b.vy, b.spin, world.collider.radius, m.max_penetration,
                              0.0, not (x0 <= b.x <= x1 and y0 <= b.y <= y1), m.wall_seconds)
                out.extra["holed"] = world.state.holed
                return out
            finally:
                world.close()

        cases.append(Case(f"{course_name}:{number}", "shot", seconds, run))
    return cases


def _angle_gap(a: float, b: float) -> float:
    d = (a - b) % (2 * math.pi)
    return min(d, 2 * math.pi - d)


def case_error(case: Case, outcome: Outcome, reference: Outcome | None) -> float:
    """A case's error in [0, 1]: the worst of its parts, each scaled so 1 means 'plainly wrong'.

    closed form: the relative error; reference: position off by 5 radii, angle off by pi, an overlap
    of a quarter radius, or 1 % more kinetic energy than at the start each count 1; escaping is 1.
    The pile (invariant): a resting overlap 10 % of a radius beyond the slop, or any body still moving
    at 0.1 m/s, counts 1. The deep overlap (invariant): still 1 cm deeper than the slop after half a
    second, or moving at 0.1 m/s, counts 1."""
    if outcome.escaped or not all(math.isfinite(v) for v in (outcome.x, outcome.y, outcome.vx, outcome.vy)):
        return 1.0
    if case.kind == "invariant":
        return min(1.0, case.exact(outcome))
    parts = [outcome.max_penetration / (0.25 * outcome.radius), outcome.energy_gain / 0.01]
    if case.exact is not None:
        parts.append(case.exact(outcome))
    elif reference is not None:
        parts.append(math.hypot(outcome.x - reference.x, outcome.y - reference.y) / (5 * outcome.radius))
        if case.kind != "shot":
            parts.append(_angle_gap(outcome.angle, reference.angle) / math.pi)
    return min(1.0, max(parts))


@dataclass
class Row:
    knobs: Knobs
    error: float
    cost_us: float  # median wall time per simulated second, µs
    errors: dict[str, float]
    on_front: bool = False
    preset: str = ""

    @property
    def label(self) -> str:
        k = self.knobs
        return f"{k.substeps}x{k.iterations} {k.position_correction}{'' if k.ccd else ' no-ccd'}"


def sweep_settings(substeps: Iterable[int] = SUBSTEPS, iterations: Iterable[int] = ITERATIONS,
                   corrections: Iterable[str] = CORRECTIONS) -> list[Knobs]:
    """The grid: every substep count x velocity iteration count x ccd on/off x position correction.
    Position iterations follow the velocity iterations (i // 2 + 1, at most 4) rather than being a
    fifth axis; the presets are points of this grid."""
    settings = [Knobs(substeps=s, iterations=i, position_iterations=max(1, min(4, i // 2 + 1)), ccd=ccd,
                      position_correction=c)
                for s in substeps for i in iterations for ccd in (True, False) for c in corrections]
    for knobs in PRESETS.values():  # the presets are always measured, whatever the grid
        if knobs not in settings:
            settings.append(knobs)
    return settings


_CASES: list[Case] = []
_REFERENCES: dict[str, Outcome] = {}


def _prepare(quick: bool) -> None:
    """Build the cases and their reference runs once in each worker process."""
    global _CASES, _REFERENCES
    _CASES = all_cases(quick)
    _REFERENCES = {c.name: c.run(REFERENCE, True) for c in _CASES if c.exact is None}


def _measure_one(knobs: Knobs, repeats: int) -> tuple[Knobs, dict[str, float], float]:
    errors = {case.name: case_error(case, case.run(knobs, True), _REFERENCES.get(case.name)) for case in _CASES}
    timings = [sum(case.run(knobs, False).seconds for case in _CASES) for _ in range(repeats)]
    cost = statistics.median(timings) / sum(c.seconds for c in _CASES) * 1e6
    return knobs, errors, cost


def all_cases(quick: bool = False) -> list[Case]:
    cases = scene_cases() + shot_cases()
    if quick:
        keep = {"flat-wall", "vertex-hit", "corner", "thin-wall", "pile", "deep-overlap", "meadow:2"}
        cases = [c for c in cases if c.name in keep]
    return cases


def measure(settings: list[Knobs], repeats: int = 3, workers: int | None = None, quick: bool = False,
            progress: bool = True) -> list[Row]:
    """Error and cost of every setting (`sweep` without the systems' costs)."""
    return sweep(settings, repeats, workers, quick, progress, effects=False)[0]


def sweep(settings: list[Knobs], repeats: int = 3, workers: int | None = None, quick: bool = False,
          progress: bool = True, effects: bool = True) -> tuple[list[Row], dict[str, float]]:
    """Error and cost of every setting, and with `effects` each system's cost (`effect_costs`).
    Settings are spread over `workers` processes (one a core), the costliest first so that no
    process is left with a long one at the end; each setting's runs, timed ones included, stay in
    one process. The systems' costs are measured in the pool too, alongside the settings."""
    rows = []
    workers = max(1, min(workers or os.cpu_count() or 1, len(settings)))
    with ProcessPoolExecutor(max_workers=workers, initializer=_prepare, initargs=(quick,)) as pool:
        systems = pool.submit(effect_costs) if effects else None
        costliest_first = sorted(settings, key=lambda k: -k.substeps * (k.iterations + k.position_iterations + 4))
        futures = [pool.submit(_measure_one, knobs, repeats) for knobs in costliest_first]
        done = as_completed(futures)
        if progress:
            from tqdm import tqdm

            done = tqdm(done, total=len(futures), desc="accuracy sweep", unit="setting")
        for future in done:
            knobs, errors, cost = future.result()
            rows.append(Row(knobs, statistics.fmean(errors.values()), cost, errors))
        costs = systems.result() if systems is not None else {}
    mark_front(rows)
    for name, knobs in PRESETS.items():
        for row in rows:
            if row.knobs == knobs:
                row.preset = name
    return rows, costs


def mark_front(rows: list[Row]) -> None:
    """Pareto front: no other setting is both cheaper and more accurate."""
    best = math.inf
    for row in sorted(rows, key=lambda r: (r.cost_us, r.error)):
        row.on_front = row.error < best
        best = min(best, row.error)


def effect_costs(frames: int = 600) -> dict[str, float]:
    """µs per 60 Hz frame each system costs while the scripted golfer plays every hole of the real
    courses (profiled: each processor timed on its own)."""

    totals: dict[str, float] = {}
    counted: dict[str, int] = {}
    for course in load_courses():
        if course.name not in ("Meadow", "Hazards"):
            continue
        for hole in course.playable:
            world = HolePlay(hole, DEFAULT_BALL)
            try:
                golfer = golfer_for(hole)
                for _ in range(frames):
                    if world.state.finished:
                        break
                    if world.ball_at_rest:
                        world.shoot(*golfer.plan((world.ball.x, world.ball.y)))
                    world.step(profile=True)
                for name, seconds in world.sim.metrics.system_seconds.items():
                    totals[name] = totals.get(name, 0.0) + seconds
                    counted[name] = counted.get(name, 0) + world.sim.metrics.frames
            finally:
                world.close()
    return {name: totals[name] / counted[name] * 1e6 for name in totals}


# --- the report -----------------------------------------------------------------------------------

def write_report(rows: list[Row], cases: list[Case], out: Path, effects: dict[str, float] | None = None,
                 command: str = "polygolf bench accuracy", took: str = "") -> dict[str, Path]:
    out.mkdir(parents=True, exist_ok=True)
    paths = {"csv": out / "accuracy.csv", "md": out / "accuracy.md", "png": out / "accuracy.png"}
    names = [c.name for c in cases]
    with paths["csv"].open("w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["substeps", "iterations", "position_iterations", "ccd", "position_correction", "error",
                         "cost_us_per_sim_second", "pareto", "preset", *names])
        for r in sorted(rows, key=lambda r: r.cost_us):
            k = r.knobs
            writer.writerow([k.substeps, k.iterations, k.position_iterations, int(k.ccd), k.position_correction,
                             f"{r.error:.6f}", f"{r.cost_us:.0f}", int(r.on_front), r.preset,
                             *(f"{r.errors[n]:.6f}" for n in names)])
    _plot(rows, paths["png"])
    paths["md"].write_text(_markdown(rows, cases, effects, command, took))
    return paths


def _plot(rows: list[Row], path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(10, 6.5), dpi=110)
    styles = {"split": ("o", "tab:blue"), "ngs": ("s", "tab:green"), "none": ("^", "tab:red")}
    for correction, (marker, colour) in styles.items():
        for ccd in (True, False):
            pts = [r for r in rows if r.knobs.position_correction == correction and r.knobs.ccd == ccd]
            if pts:
                ax.scatter([r.cost_us / 1000 for r in pts], [max(r.error, 1e-6) for r in pts], marker=marker,
                           facecolors=colour if ccd else "none", edgecolors=colour, alpha=0.55, s=26,
                           label=f"{correction}, ccd {'on' if ccd else 'off'}")
    front = sorted((r for r in rows if r.on_front), key=lambda r: r.cost_us)
    ax.plot([r.cost_us / 1000 for r in front], [max(r.error, 1e-6) for r in front], "k-", lw=1.5,
            label="Pareto front")
    for r in rows:
        if r.preset:
            ax.scatter([r.cost_us / 1000], [max(r.error, 1e-6)], marker="*", s=320, c="gold", edgecolors="black",
                       zorder=5)
            ax.annotate(f"{r.preset}\n{r.label}", (r.cost_us / 1000, max(r.error, 1e-6)), textcoords="offset points",
                        xytext=(10, 8), fontsize=9, weight="bold")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("cost: ms of computation per simulated second (median)")
    ax.set_ylabel("error: mean over cases (0 = exact, 1 = plainly wrong)")
    ax.set_title("PolyGolf solver settings: accuracy against time")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def _markdown(rows: list[Row], cases: list[Case], effects: dict[str, float] | None, command: str,
              took: str = "") -> str:
    names = [c.name for c in cases]
    front = sorted((r for r in rows if r.on_front), key=lambda r: r.cost_us)
    presets = sorted((r for r in rows if r.preset), key=lambda r: r.cost_us)
    lines = [
        "# Accuracy against time",
        "",
        f"Made by `{command}` ({len(rows)} settings, {len(cases)} cases{', ' + took if took else ''}). Cost is "
        "the median wall time per",
        "simulated second of all cases together; error is the mean of the cases' errors, each in [0, 1]",
        "(relative error against a closed form; otherwise against a reference run at "
        f"{REFERENCE.substeps} substeps x {REFERENCE.iterations} iterations with NGS:",
        "5 radii off in position, or pi in angle, a quarter-radius overlap, 1 % energy gained, or escaping",
        "through a wall count as 1).",
        "",
        "![error against cost](accuracy.png)",
        "",
        "## Presets",
        "",
        "| preset | setting | on the front | error | cost (ms per simulated s) |",
        "|---|---|---|---|---|",
    ]
    for r in presets:
        lines.append(f"| {r.preset} | {r.label} | {'yes' if r.on_front else 'no'} | {r.error:.4f} | "
                     f"{r.cost_us / 1000:.1f} |")
    lines += ["", "## Pareto front", "",
              "| setting | error | cost (ms per simulated s) | worst case |", "|---|---|---|---|"]
    for r in front:
        worst = max(r.errors, key=r.errors.get)
        lines.append(f"| {r.label} | {r.error:.4f} | {r.cost_us / 1000:.1f} | {worst} ({r.errors[worst]:.3f}) |")
    lines += ["", "## Error by case at the presets", "",
              "| case | kind | " + " | ".join(r.preset for r in presets) + " |",
              "|---|---|" + "---|" * len(presets)]
    for case in cases:
        lines.append(f"| {case.name} | {case.kind} | " + " | ".join(f"{r.errors[case.name]:.4f}" for r in presets)
                     + " |")
    lines += ["", "## What each knob buys", ""]
    lines += _knob_summary(rows)
    if effects:
        lines += ["", "## Cost of each system", "",
                  "µs per 60 Hz frame at `balanced`, each processor timed on its own while the scripted golfer",
                  "plays every hole of Meadow and Hazards (a system is only counted on holes that have it).", "",
                  "| system (in the stage table's order) | µs per frame |", "|---|---|"]
        for stage in STAGES:
            if stage.name in effects:
                lines.append(f"| {stage.name} | {effects[stage.name]:.1f} |")
    lines += ["", f"All {len(rows)} settings are in `accuracy.csv` (with every case's error: "
              + ", ".join(names) + ")."]
    return "\n".join(lines) + "\n"


def _knob_summary(rows: list[Row]) -> list[str]:
    def best(pred) -> Row | None:
        chosen = [r for r in rows if pred(r)]
        return min(chosen, key=lambda r: r.error) if chosen else None

    out = []
    for ccd in (True, False):
        r = best(lambda r, ccd=ccd: r.knobs.ccd == ccd)
        if r:
            out.append(f"- best with ccd {'on' if ccd else 'off'}: {r.label}, error {r.error:.4f} "
                       f"(thin wall {r.errors.get('thin-wall', float('nan')):.2f})")
    for correction in CORRECTIONS:
        r = best(lambda r, c=correction: r.knobs.position_correction == c)
        if r:
            out.append(f"- best with {correction} position correction: {r.label}, error {r.error:.4f}")
    return out
