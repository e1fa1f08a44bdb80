"""`polygolf par`: the search golfer proves holes (each can be sunk) and estimates their par, one
process per core; `polygolf validate --prove` turns the same proofs into warnings."""

from __future__ import annotations

import os
from collections.abc import Callable, Iterator
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

from polygolf.engine.golf.holes import Hole, find_course, load_all_courses, load_hole_file
from polygolf.engine.golf.scenes import find_hole
from polygolf.engine.golf.search import HoleProof, prove_hole
from polygolf.engine.loading.yamlsource import ContentError

PAR_SLACK = 1  # strokes the declared par may differ from the estimate before a warning


def holes_named(target: str) -> tuple[list[Hole], list[ContentError], list[str]]:
    """A course (its id or name), COURSE:N, or a hole file: the holes to prove, the broken ones, and
    why the others are passed over (a collision test launches its ball itself: nobody plays it)."""
    if target.endswith((".yaml", ".yml")) or os.sep in target or ":" in target:
        holes, broken = [load_hole_file(target) if Path(target).exists() else find_hole(target, Path.cwd())], []
    else:
        courses, unread = load_all_courses()
        course = find_course(courses, target, unread)
        holes, broken = course.playable, [h for h in course.holes if isinstance(h, ContentError)]
    return [h for h in holes if not launches(h)], broken, [f"{h.id}: {LAUNCHES}" for h in holes if launches(h)]


LAUNCHES = "launches the ball itself (a collision test): the golfer cannot play it"


def launches(hole: Hole) -> bool:
    """Whether the hole launches its ball again and again (it never rests for a stroke)."""
    return hole.spec.launch is not None


def _prove(job: tuple[Hole, str, str]) -> HoleProof:
    hole, effort, knobs = job
    return prove_hole(hole, effort=effort, knobs=knobs)


def prove_all(holes: list[Hole], effort: str = "quick", knobs: str = "fast", jobs: int | None = None,
              done: Callable[[HoleProof], None] | None = None) -> list[HoleProof]:
    """Proofs in the holes' order, `jobs` holes at a time (default: a process per core)."""
    jobs = max(1, min(jobs or os.cpu_count() or 1, len(holes)))
    work = [(hole, effort, knobs) for hole in holes]
    if jobs == 1:
        proofs: Iterator[HoleProof] = map(_prove, work)
        return [_tell(p, done) for p in proofs]
    with ProcessPoolExecutor(max_workers=jobs) as pool:
        return [_tell(p, done) for p in pool.map(_prove, work)]


def _tell(proof: HoleProof, done: Callable[[HoleProof], None] | None) -> HoleProof:
    if done is not None:
        done(proof)
    return proof


def warnings_for(proof: HoleProof) -> list[str]:
    """What an author should hear about a proof: a hole nobody sinks, a par out of line."""
    out = []
    if not proof.sunk:
        out.append(f"the search golfer could not sink it with every shape it tried (strokes: "
                   f"{', '.join('-' if s is None else str(s) for s in proof.strokes)})")
    if abs(proof.estimated_par - proof.par) > PAR_SLACK:
        out.append(f"par {proof.par} is more than {PAR_SLACK} from the estimated par {proof.estimated_par}")
    return out


def table(proofs: list[HoleProof]) -> str:
    """The human-readable table: a row per hole and a total."""
    width = max([18, *(len(p.hole) + 2 for p in proofs)])  # (a long hole id ran into the name)
    lines = [f"{'hole':<{width}}{'name':<22}{'par':>4}{'estimate':>10}{'best':>6}{'sunk':>6}{'seconds':>9}"
             f"{'shots/s':>9}"]
    for p in proofs:
        best = "-" if p.best_strokes is None else str(p.best_strokes)
        rate = p.shots / p.seconds if p.seconds > 0 else 0.0
        lines.append(f"{p.hole:<{width}}{p.name[:21]:<22}{p.par:>4}{p.estimated_par:>10}{best:>6}"
                     f"{'yes' if p.sunk else 'NO':>6}{p.seconds:>9.1f}{rate:>9.0f}")
    lines.append(f"{'total':<{width + 22}}{sum(p.par for p in proofs):>4}{sum(p.estimated_par for p in proofs):>10}")
    return "\n".join(lines)
