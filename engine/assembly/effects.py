"""Which effects a world needs, and why: the answer decides which stages its world holds.

Derived once, from the world spec, for scenes and holes alike. The content may list its effects
itself (`WorldSpec.listed`); the game's rules (`WorldSpec.rules`) are always there.
"""

from __future__ import annotations

from polygolf.engine.assembly.spec import WorldSpec
from polygolf.engine.physics.settings import FRAME_DT, LINEAR_SLOP


def derive_effects(spec: WorldSpec, substeps: int) -> dict[str, str]:
    """Effect -> the reason the content needs it."""
    reasons: dict[str, str] = {}
    bodies = spec.bodies
    dragged = [b for b in bodies if b.drag is not None]
    if dragged:
        b, d = dragged[0], dragged[0].drag
        reasons["drag"] = f"{b.name} has drag (linear {d.linear:g}/s, angular {d.angular:g}/s, " \
                          f"rolling {d.rolling:g} m/s²)"

    if spec.gravity != (0.0, 0.0):
        reasons["gravity"] = f"the scene pushes every body at ({spec.gravity[0]:g}, {spec.gravity[1]:g}) m/s²"

    spinning = [b for b in bodies if b.spin]
    if spinning:
        reasons["spin"] = f"{spinning[0].name} starts spinning at {spinning[0].spin:g} rad/s"
    elif spec.touchable:
        reasons["spin"] = "a contact off the centre of mass turns a polygon"

    if spec.touchable:
        for key in ("restitution", "friction"):
            best = _best_product(spec, key)
            if best is not None:
                reasons[key] = best

    if spec.touchable and bodies:
        fastest = max(bodies, key=lambda b: b.fastest)
        reach = fastest.fastest * FRAME_DT / substeps
        what = "walls" if spec.walls else "bodies"
        if reach > LINEAR_SLOP:
            reasons["ccd"] = f"{fastest.name} moves up to {reach:.3g} m a substep: {what} must not be skipped"
        elif spec.gravity != (0.0, 0.0):
            reasons["ccd"] = f"gravity speeds bodies up: {what} must not be skipped"
    reasons.update(spec.content_effects)
    return reasons


def _best_product(spec: WorldSpec, key: str) -> str | None:
    """The largest body x wall (or body x body, where bodies meet) coefficient, described, or None if
    every one is zero: the first such pair, taking each body in turn against the walls, the kinematic
    bodies, then the other bodies. (Coefficients are not negative, so a body's best partner is the
    largest other value: found in one pass, not a pass a body, which took a thousand-body scene 0.18 s.)"""
    others = [(getattr(w.material, key), "wall") for w in spec.walls]
    others += [(getattr(k.material, key), k.name) for k in spec.kinematic]
    own = [getattr(b.material, key) for b in spec.bodies]
    top_other = max((value for value, _ in others), default=0.0)
    first = second = -1  # the bodies of the largest and second largest own values
    for k, value in enumerate(own):
        if first < 0 or value > own[first]:
            first, second = k, first
        elif second < 0 or value > own[second]:
            second = k

    def best_partner(k: int) -> float:
        """The largest value body k meets."""
        partner = top_other
        if spec.collide_bodies:
            other = second if k == first else first
            if other >= 0:
                partner = max(partner, own[other])
        return partner

    best = max((own[k] * best_partner(k) for k in range(len(own))), default=0.0)
    if not best > 0.0:
        return None
    for k, body in enumerate(spec.bodies):
        if own[k] * best_partner(k) != best:
            continue
        bodies = [(own[j], o.name) for j, o in enumerate(spec.bodies) if j != k] if spec.collide_bodies else []
        for value, name in others + bodies:
            if own[k] * value == best:
                return f"{body.name} {key} {own[k]:g} x {name} {value:g}"
    return None  # not reached: the best product is some pair's


def effects_for(spec: WorldSpec, substeps: int) -> dict[str, str]:
    """The effects the world will simulate, each with its reason: the rules, then the content's own
    list if it has one, else what its content needs."""
    derived = derive_effects(spec, substeps)
    if spec.listed is not None:
        chosen = {e: f"listed in {spec.listed_by}" + (f" ({derived[e]})" if e in derived else "")
                  for e in spec.listed}
    else:
        chosen = derived
    return {**spec.rules, **chosen}
