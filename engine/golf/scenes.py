"""Scenes on real holes: a scene that names a hole (`hole: meadow:2`, or a hole file beside the
scene) gets the hole's walls, windmills, hazards, green and cup around its own bodies, so authors and
tests can fire exact shots on real holes. Scenes without a hole are built by `loading.scene`."""

from __future__ import annotations

import re
from dataclasses import replace
from pathlib import Path

from polygolf.engine.assembly.assemble import assemble
from polygolf.engine.assembly.simulation import Simulation
from polygolf.engine.assembly.spec import WorldSpec
from polygolf.engine.components import Ball, Cup, HoleState, Launcher
from polygolf.engine.golf.holes import Hole, find_course, load_all_courses, load_hole_file
from polygolf.engine.golf.world import DEFAULT_BALL, hole_spec
from polygolf.engine.loading.scene import Scene, load_scene, scene_spec
from polygolf.engine.loading.yamlsource import ContentError, line_of, load_yaml
from polygolf.engine.physics.presets import Knobs


def find_hole(name: str, beside: Path) -> Hole:
    """COURSE:N or COURSE:ID (a hole of any content folder's course, by its number or its file's
    name), or a hole file (relative to `beside`)."""
    if ":" in name:
        course_name, which = name.split(":", 1)
        courses, unread = load_all_courses()
        holes = find_course(courses, course_name, unread).holes
        if re.fullmatch(r"[0-9]{1,4}", which) and 1 <= int(which) <= len(holes):
            hole = holes[int(which) - 1]
        else:  # by its id: its file's name (a broken hole's too, to say what is wrong with it)
            hole = next((h for h in holes if (h.id if isinstance(h, Hole) else Path(h.file).stem) == which), None)
            if hole is None:
                raise KeyError(f"{course_name} has holes 1 to {len(holes)} (or give a hole's name: "
                               f"{', '.join(h.id for h in holes if isinstance(h, Hole))})")
        if isinstance(hole, ContentError):
            raise hole
        return hole
    if Path(name).name != name or name.startswith(".") or "\\" in name or not name.endswith((".yaml", ".yml")):
        raise KeyError(f"{name!r} is not a hole file beside the scene (its name, ending .yaml), nor COURSE:N")
    path = beside / name
    if not path.is_file():
        raise KeyError(f"no hole file {path}")
    return load_hole_file(path)


def scene_on_hole(scene: Scene, hole: Hole) -> WorldSpec:
    """The scene's bodies on the hole: its walls and windmills too, its hazards and cup, and the
    green's drag on every body that has none of its own."""
    own = scene_spec(scene)
    course = hole_spec(hole, DEFAULT_BALL)
    green = course.bodies[0].drag
    bodies = [replace(b, drag=b.drag or (replace(green) if green else None),  # each body its own copy
                      extras=(*b.extras, Ball(*b.position))) for b in own.bodies]
    entities = [e for e in course.entities if not isinstance(e[0], HoleState | Launcher)]
    cup = next(e[0] for e in entities if isinstance(e[0], Cup))
    return replace(own, bodies=bodies, walls=own.walls + course.walls, kinematic=course.kinematic, entities=entities,
                   rules={"cup": f"the hole's cup at ({cup.x:g}, {cup.y:g})"},
                   content_effects={k: v for k, v in course.content_effects.items() if k != "launch"},
                   cell_size=course.cell_size)


def build_scene_file(path: str | Path, knobs: Knobs | str | None = None) -> Simulation:
    """A scene file as a simulation, on its hole if it names one."""
    path = Path(path)
    scene = load_scene(path)
    hole = scene_hole(scene, path)
    return assemble(scene_spec(scene) if hole is None else scene_on_hole(scene, hole), knobs)


def scene_hole(scene: Scene, path: Path) -> Hole | None:
    """The hole the scene file at `path` names (None if it names none); a ContentError at its `hole`
    line if there is no such hole or the hole is broken (`validate` asks the same)."""
    if scene.hole is None:
        return None
    try:
        return find_hole(scene.hole, path.parent)
    except (KeyError, ContentError) as exc:
        _, lines = load_yaml(path)
        message = str(exc) if isinstance(exc, ContentError) else exc.args[0]
        raise ContentError(path, line_of(("hole",), lines), "hole", message) from None
