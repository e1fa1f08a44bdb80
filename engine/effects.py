"""Which effects a scene needs, and why: the answer decides which processors its world holds."""

from __future__ import annotations

import math

from engine.scene import EFFECTS, Scene
from engine.settings import FRAME_DT, LINEAR_SLOP


def derive_effects(scene: Scene, substeps: int = 4) -> dict[str, str]:
    """Effect -> the reason the scene's content needs it. Effects a scene lists explicitly are taken
    as given (see `effects_for`)."""
    reasons: dict[str, str] = {}
    walls, bodies = scene.walls, scene.bodies
    contacts = bool(walls) or len(bodies) > 1

    dragged = [b for b in bodies if b.drag.any]
    if dragged:
        b = dragged[0]
        reasons["drag"] = f"{b.name} has drag (linear {b.drag.linear:g}/s, angular {b.drag.angular:g}/s, " \
                          f"rolling {b.drag.rolling:g} m/s²)"

    if scene.gravity != (0.0, 0.0):
        reasons["gravity"] = f"the scene pushes every body at ({scene.gravity[0]:g}, {scene.gravity[1]:g}) m/s²"

    spinning = [b for b in bodies if b.spin]
    if spinning:
        reasons["spin"] = f"{spinning[0].name} starts spinning at {spinning[0].spin:g} rad/s"
    elif contacts:
        reasons["spin"] = "a contact off the centre of mass turns a polygon"

    if contacts:
        for key, label in (("restitution", "restitution"), ("friction", "friction")):
            best = _best_product(scene, key)
            if best is not None:
                reasons[label] = best

    if walls:
        fastest = max(bodies, key=lambda b: math.hypot(*b.velocity) + abs(b.spin) * _radius(b))
        reach = (math.hypot(*fastest.velocity) + abs(fastest.spin) * _radius(fastest)) * FRAME_DT / substeps
        if reach > LINEAR_SLOP:
            reasons["ccd"] = f"{fastest.name} moves up to {reach:.3g} m a substep: walls must not be skipped"
        elif scene.gravity != (0.0, 0.0):
            reasons["ccd"] = "gravity speeds bodies up: walls must not be skipped"
    return reasons


def _radius(body) -> float:
    from engine.polygon import bounding_radius

    return bounding_radius(body.shape.outline())


def _best_product(scene: Scene, key: str) -> str | None:
    """The largest ball x wall (or ball x ball) coefficient, described, or None if every one is zero."""
    best, text = 0.0, None
    for body in scene.bodies:
        own = getattr(body, key)
        others = [(getattr(w, key), "wall") for w in scene.walls]
        others += [(getattr(o, key), o.name) for o in scene.bodies if o is not body]
        for value, name in others:
            if own * value > best:
                best, text = own * value, f"{body.name} {key} {own:g} x {name} {value:g}"
    return text


def effects_for(scene: Scene, substeps: int = 4) -> dict[str, str]:
    """The effects the world will simulate: the scene's own list if it has one, else derived."""
    if scene.effects is not None:
        derived = derive_effects(scene, substeps)
        return {e: "listed in the scene" + (f" ({derived[e]})" if e in derived else "")
                for e in EFFECTS if e in scene.effects}
    return derive_effects(scene, substeps)
