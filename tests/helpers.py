"""Small helpers shared by the physics tests."""

from __future__ import annotations

from types import SimpleNamespace

import esper

from polygolf.engine.assembly.assemble import make_wall
from polygolf.engine.assembly.simulation import Simulation
from polygolf.engine.assembly.stages import stages_for
from polygolf.engine.components import Material
from polygolf.engine.components.resources import Resources, StaticWorld, StepConfig
from polygolf.engine.golf.scenes import build_scene_file
from polygolf.engine.physics.presets import preset

from .conftest import SCENES


def scene_sim(name: str, preset: str = "balanced") -> Simulation:
    return build_scene_file(SCENES / f"{name}.yaml", preset)


def step_until(sim: Simulation, condition, max_frames: int = 600) -> int:
    """Step frame by frame until `condition()` holds; returns the frames taken."""
    for frame in range(1, max_frames + 1):
        sim.step()
        if condition():
            return frame
    raise AssertionError(f"condition not reached in {max_frames} frames")


def resources(knobs: str = "balanced", walls=(), cell: float = 2.0, effects=()) -> Resources:
    """Resources for processors assembled by hand in the current world; `walls` are (outline,
    material, extra components) or bare outlines, created as entities and filed in the grid."""
    made = []
    for wall_spec in walls:
        outline, material, extra = wall_spec if len(wall_spec) == 3 and isinstance(wall_spec[1], Material) \
            else (wall_spec, Material(), ())
        wall = make_wall(outline, material)
        made.append((esper.create_entity(wall, *extra), wall))
    return Resources(config=StepConfig(knobs=preset(knobs), effects=frozenset(effects)),
                     statics=StaticWorld.of(made, cell))


def pipeline(res: Resources, effects, walls: bool) -> list[esper.Processor]:
    """The stage table's processors for `effects` in a world where things can touch, added to the
    current world in order."""
    shape = SimpleNamespace(touchable=True, walls=[object()] if walls else [])
    procs = [stage.processor(res) for stage in stages_for(frozenset(effects), shape, res.config.knobs)]
    for proc in procs:
        esper.add_processor(proc, priority=-len(esper._processors))
    return procs
