"""`polygolf explain`: the pipeline of a scene or a hole, and the reason each system is in it."""

from __future__ import annotations

from pathlib import Path

from engine.course import HOLES_DIR, find_course, load_courses, load_hole, load_library
from engine.pipeline import build_scene
from engine.scene import EFFECTS, ShapeSpec, load_scene
from engine.simulation import Simulation
from engine.yamlsource import ContentError, load_yaml

_WHY = {
    "integrate": "always: moves bodies and puts stopped ones to rest",
    "broadphase": "walls or other bodies can be touched: grid of bounding boxes",
    "narrowphase": "separating axes and clipping on the broadphase's candidates",
    "resolve": "sequential impulses on contacts",
}


def _describe(title: str, sim: Simulation) -> str:
    knobs = sim.ctx.knobs
    lines = [f"{title} at {sim.preset_name}: {knobs.substeps} substeps, {knobs.iterations} iterations, "
             f"{knobs.position_correction} position correction"]
    for name in sim.system_names:
        why = sim.reasons.get(name, _WHY.get(name, ""))
        if name == "resolve":
            friction = sim.reasons.get("friction")
            why += f"; friction {'on: ' + friction if friction else 'off: no contact has friction'}"
        lines.append(f"  {name:<12} {why}")
    for effect in EFFECTS:
        if effect not in sim.system_names and effect != "friction":
            lines.append(f"  (no {effect})")
    return "\n".join(lines)


def explain(target: str, preset: str | None = None) -> str:
    """`target`: a scene file, a hole file, or COURSE:HOLE (hole number or id)."""
    from engine.hole import HoleWorld

    path = Path(target)
    if path.suffix in (".yaml", ".yml") and path.exists():
        data, _ = load_yaml(path)
        if isinstance(data, dict) and "tiles" in data:
            hole = load_hole(path, load_library(path.parent / "tiles.yaml"))
        else:
            scene = load_scene(path)
            with build_scene(scene, preset) as sim:
                return _describe(scene.name, sim)
    elif ":" in target:
        course_name, which = target.split(":", 1)
        course = find_course(load_courses(), course_name)
        holes = course.holes
        entry = holes[int(which) - 1] if which.isdigit() and 1 <= int(which) <= len(holes) else next(
            (h for h in holes if getattr(h, "id", None) == which), None)
        if entry is None:
            raise KeyError(f"{course.name} has no hole {which!r}")
        if isinstance(entry, ContentError):
            raise entry
        hole = entry
    else:
        hole = load_hole(HOLES_DIR / f"{target}.yaml", load_library())
    world = HoleWorld(hole, ShapeSpec(regular=5, radius=1.0), preset or "balanced")
    try:
        return _describe(f"{hole.spec.name} ({hole.id})", world.sim)
    finally:
        world.close()
