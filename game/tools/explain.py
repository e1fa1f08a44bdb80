"""`polygolf explain`: the pipeline of a scene or a hole, and the reason each stage is in it.

Reads the one stage table (`engine.assembly.stages`): every stage the world holds with why, and every
stage an effect could bring that this world leaves out.
"""

from __future__ import annotations

from pathlib import Path

from polygolf.engine.assembly.simulation import Simulation
from polygolf.engine.assembly.stages import STAGES
from polygolf.engine.golf.holes import Hole, find_course, load_all_courses, load_hole_file
from polygolf.engine.golf.play import HolePlay
from polygolf.engine.golf.scenes import build_scene_file
from polygolf.engine.golf.world import DEFAULT_BALL
from polygolf.engine.loading.paths import named_file
from polygolf.engine.loading.yamlsource import ContentError, load_yaml


def _describe(title: str, sim: Simulation) -> str:
    knobs = sim.knobs
    lines = [f"{title} at {sim.preset_name}: {knobs.substeps} substeps, {knobs.iterations} iterations, "
             f"{knobs.position_correction} position correction"]
    present = set(sim.system_names)
    for stage in STAGES:
        if stage.name not in present:
            continue
        why = sim.reasons.get(stage.effect or "", stage.why)
        if stage.name == "resolve":
            friction = sim.reasons.get("friction")
            why += f"; friction {'on: ' + friction if friction else 'off: no contact has friction'}"
        lines.append(f"  {stage.name:<12} {why}")
    absent = [stage.name for stage in STAGES if stage.effect is not None and stage.name not in present]
    if absent:
        lines.append(f"  (no {', no '.join(absent)})")
    return "\n".join(lines)


def _file(target: str) -> Path | None:
    """The scene or hole file `target` names (`paths.named_file`: a path, or a name in the content
    folders' scenes/ or holes/); None for COURSE:HOLE."""
    for folder in ("scenes", "holes"):
        path = named_file(target, folder)
        if path.is_file():
            return path
    return None if ":" in target or Path(target).suffix not in (".yaml", ".yml") else Path(target)


def _course_hole(target: str) -> Hole:
    """COURSE:HOLE (number or id), of any content folder's courses."""
    if ":" not in target:
        raise KeyError(f"no scene or hole {target!r}: give a file, a scene or hole name, or COURSE:HOLE")
    course_name, which = target.split(":", 1)
    holes = find_course(load_all_courses()[0], course_name).holes
    entry = holes[int(which) - 1] if which.isdigit() and len(which) < 5 and 1 <= int(which) <= len(holes) else next(
        (h for h in holes if getattr(h, "id", None) == which), None)
    if entry is None:
        raise KeyError(f"{course_name} has no hole {which[:24]!r}{'…' if len(which) > 24 else ''}")
    if isinstance(entry, ContentError):
        raise entry
    return entry


def explain(target: str, preset: str | None = None) -> str:
    """`target`: a scene or hole file or name, or COURSE:HOLE (hole number or id)."""
    path = _file(target)
    if path is not None and path.exists():
        data, _ = load_yaml(path)
        if not (isinstance(data, dict) and "tiles" in data):
            with build_scene_file(path, preset) as sim:
                return _describe(sim.scene_name, sim)
    hole = load_hole_file(path) if path is not None else _course_hole(target)
    play = HolePlay(hole, DEFAULT_BALL, preset or "balanced")
    try:
        return _describe(f"{hole.spec.name} ({hole.id})", play.sim)
    finally:
        play.close()
