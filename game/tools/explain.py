"""`polygolf explain`: the pipeline of a scene or a hole, and the reason each stage is in it.

Reads the one stage table (`engine.assembly.stages`): every stage the world holds with why, and every
stage an effect could bring that this world leaves out.
"""

from __future__ import annotations

from pathlib import Path

from polygolf.engine.assembly.simulation import Simulation
from polygolf.engine.assembly.stages import STAGES
from polygolf.engine.golf.holes import load_hole_file
from polygolf.engine.golf.play import HolePlay
from polygolf.engine.golf.scenes import build_scene_file, find_hole
from polygolf.engine.golf.world import DEFAULT_BALL
from polygolf.engine.loading.paths import named_file
from polygolf.engine.loading.yamlsource import load_yaml


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


KIND_WORDS = {"library": "tile library", "courses": "courses file", "theme": "theme"}


def explain(target: str, preset: str | None = None) -> str:
    """`target`: a scene or hole file or name, or COURSE:HOLE (hole number or id)."""
    path = _file(target)
    if path is not None and path.exists():
        from polygolf.game.tools.validate import _kind

        kind = _kind(path)
        if kind not in ("hole", "scene", "unknown"):  # (an unknown one is read as a scene: its errors say why)
            raise KeyError(f"{path} is a {KIND_WORDS.get(kind, kind)}: explain takes a hole or a scene (a file, a "
                           "name, or COURSE:HOLE)")
        data, _ = load_yaml(path)
        if not (isinstance(data, dict) and "tiles" in data):
            with build_scene_file(path, preset) as sim:
                return _describe(sim.scene_name, sim)
    if path is None and ":" not in target:
        raise KeyError(f"no scene or hole {target!r}: give a file, a scene or hole name, or COURSE:HOLE")
    hole = load_hole_file(path) if path is not None else find_hole(target, Path.cwd())
    play = HolePlay(hole, DEFAULT_BALL, preset or "balanced")
    try:
        return _describe(f"{hole.spec.name} ({hole.id})", play.sim)
    finally:
        play.close()
