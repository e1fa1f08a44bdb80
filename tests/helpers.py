"""Small helpers shared by the physics tests."""

from __future__ import annotations

from polygolf.engine.assembly.simulation import Simulation
from polygolf.engine.loading.scene import build_scene, load_scene

from .conftest import SCENES


def scene_sim(name: str, preset: str = "balanced") -> Simulation:
    return build_scene(load_scene(SCENES / f"{name}.yaml"), preset)


def step_until(sim: Simulation, condition, max_frames: int = 600) -> int:
    """Step frame by frame until `condition()` holds; returns the frames taken."""
    for frame in range(1, max_frames + 1):
        sim.step()
        if condition():
            return frame
    raise AssertionError(f"condition not reached in {max_frames} frames")
