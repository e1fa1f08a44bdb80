"""`polygolf explain`: the pipeline of a scene and the reason for each system in it."""

from __future__ import annotations

from engine.pipeline import build_scene
from engine.scene import EFFECTS, load_scene

_WHY = {
    "integrate": "always: moves bodies and puts stopped ones to rest",
    "broadphase": "walls or other bodies can be touched: grid of bounding boxes",
    "narrowphase": "separating axes and clipping on the broadphase's candidates",
    "resolve": "sequential impulses on contacts",
}


def explain(path: str, preset: str | None = None) -> str:
    scene = load_scene(path)
    with build_scene(scene, preset) as sim:
        lines = [f"{scene.name} at {sim.preset_name}: {sim.ctx.knobs.substeps} substeps, "
                 f"{sim.ctx.knobs.iterations} iterations, {sim.ctx.knobs.position_correction} position correction"]
        for name in sim.system_names:
            why = sim.reasons.get(name, _WHY.get(name, ""))
            if name == "resolve":
                friction = sim.reasons.get("friction")
                why += f"; friction {'on: ' + friction if friction else 'off: no contact has friction'}"
            lines.append(f"  {name:<12} {why}")
        missing = [e for e in EFFECTS if e not in sim.system_names and e != "friction"]
        for effect in missing:
            lines.append(f"  (no {effect})")
    return "\n".join(lines)
