"""A running simulation: one named esper world, its processors, and the measurements taken on it."""

from __future__ import annotations

import math
import time
from collections.abc import Sequence
from dataclasses import dataclass, field

import esper
import numpy as np

from polygolf.engine.components import Body
from polygolf.engine.components.resources import Resources
from polygolf.engine.physics.motion import kinetic_energy
from polygolf.engine.physics.presets import Knobs
from polygolf.engine.systems.run import StageRun, measure_substep, schedule


@dataclass(slots=True)
class Metrics:
    initial_energy: float = 0.0
    max_energy: float = 0.0
    final_energy: float = 0.0
    max_energy_rise: float = 0.0  # largest increase of kinetic energy over one substep, J
    max_penetration: float = 0.0
    nan: bool = False
    frames: int = 0
    wall_seconds: float = 0.0
    system_seconds: dict[str, float] = field(default_factory=dict)

    def packed(self) -> np.ndarray:
        """What `run.measure_substep` keeps up to date."""
        return np.array([self.final_energy, self.max_energy, self.max_energy_rise, float(self.nan),
                         self.max_penetration])

    def unpack(self, values: np.ndarray) -> None:
        self.final_energy, self.max_energy, self.max_energy_rise, nan, self.max_penetration = values.tolist()
        self.nan = nan != 0.0

    def energy_ratio(self, energy: float) -> float | None:
        if self.initial_energy > 0.0:
            return energy / self.initial_energy
        return 1.0 if energy == 0.0 else None


class Simulation:
    """Steps whole 1/60 s frames; each frame runs every processor once per substep. Consecutive
    compiled stages run as one (`systems.run`); a world that is all compiled stages runs each
    frame in one kernel call, measuring included, and so does a hole whose golf rules around that
    run are quiet (no shot asked for, no event to count): then the rules are called once a frame,
    or again after a substep in which a ball dropped.

    esper keeps its worlds in module state, so every call switches to this simulation's own world;
    `close()` deletes it.
    """

    def __init__(self, world: str, res: Resources, processors: Sequence[esper.Processor],
                 names: dict[int, str], preset_name: str = "custom", reasons: dict[str, str] | None = None,
                 scene_name: str = "") -> None:
        self.world = world
        self.res = res
        self.processors = list(processors)
        self.names = names
        self.preset_name = preset_name
        self.reasons = reasons or {}
        self.scene_name = scene_name
        self.metrics = Metrics()
        esper.switch_world(world)
        scheduled = schedule(res, self.processors)
        for priority, proc in enumerate(reversed(scheduled)):
            esper.add_processor(proc, priority=priority)
        self._parts = _frame_parts(scheduled)
        self._rules = [*self._parts[0], *self._parts[2]] if self._parts is not None else []
        energy = self.kinetic_energy()
        self.metrics.initial_energy = self.metrics.max_energy = self.metrics.final_energy = energy

    # -- stepping ---------------------------------------------------------------------------------

    @property
    def system_names(self) -> list[str]:
        return [p.name for p in self.processors]

    def step(self, frames: int = 1, measure: bool = True, profile: bool = False) -> None:
        """Advance `frames` frames. `measure` tracks energy, penetration and NaN after every substep;
        `profile` times each processor, each calling its own kernels (slower: it bypasses esper.process
        and the runs of compiled stages, and counts each stage's own call)."""
        esper.switch_world(self.world)
        metrics = self.metrics
        substeps = self.res.config.knobs.substeps
        start = time.perf_counter()
        times = metrics.system_seconds
        for _ in range(frames):
            if self._parts is not None and not profile:
                values = metrics.packed() if measure else None
                self._step_frame(substeps, values)
                if values is not None:
                    metrics.unpack(values)
                metrics.frames += 1
                continue
            for _ in range(substeps):
                if profile:
                    for proc in self.processors:
                        t0 = time.perf_counter()
                        proc.process()
                        times[proc.name] = times.get(proc.name, 0.0) + time.perf_counter() - t0
                else:
                    esper.process()
                if measure:
                    self._measure()
            metrics.frames += 1
        metrics.wall_seconds += time.perf_counter() - start

    def _step_frame(self, substeps: int, metrics: np.ndarray | None) -> None:
        """One frame of a world whose compiled stages are one run, between golf rules that can say
        when they are quiet (`quiet()`: their next calls would do nothing until a stage tells them
        something): the run takes every substep it can at once, the rules being called where they
        could act, so the frame is the same as a substep at a time."""
        before, run, after = self._parts
        left = substeps
        while left:
            for proc in before:
                proc.process()
            quiet = not self._rules or all(proc.quiet() for proc in self._rules)
            left -= run.process(left if quiet else 1, metrics)
            for proc in after:
                proc.process()

    def run(self, seconds: float, measure: bool = True) -> None:
        self.step(round(seconds * 60.0), measure=measure)

    def _measure(self) -> None:
        values = self.metrics.packed()
        measure_substep(self.res.bodies.gather(esper.get_component(Body)), self.res.stats.values, values)
        self.metrics.unpack(values)

    @property
    def knobs(self) -> Knobs:
        return self.res.config.knobs

    def set_knobs(self, knobs: Knobs, preset_name: str) -> None:
        """Switch the accuracy knobs live; the stages stay (every preset keeps continuous collision)."""
        self.res.config.knobs = knobs
        self.preset_name = preset_name

    # -- reading ----------------------------------------------------------------------------------

    def kinetic_energy(self) -> float:
        esper.switch_world(self.world)
        return kinetic_energy(self.res.bodies.gather(esper.get_component(Body)))[0]

    def body(self, name: str) -> Body:
        esper.switch_world(self.world)
        for ent, label in self.names.items():
            if label == name:
                return esper.component_for_entity(ent, Body)
        raise KeyError(name)

    def bodies(self) -> list[tuple[str, Body]]:
        esper.switch_world(self.world)
        return [(label, esper.component_for_entity(ent, Body)) for ent, label in self.names.items()]

    def report(self) -> dict:
        """The JSON object of `polygolf simulate` (design notes' contract)."""
        m = self.metrics
        return {
            "scene": self.scene_name,
            "preset": self.preset_name,
            "knobs": {"substeps": self.knobs.substeps, "iterations": self.knobs.iterations},
            "steps": m.frames,
            "systems": self.system_names,
            "bodies": [
                {"name": name, "position": [b.x, b.y], "angle": math.degrees(b.angle),
                 "velocity": [b.vx, b.vy], "spin": b.spin, "at_rest": b.asleep}
                for name, b in self.bodies()
            ],
            "metrics": {
                "max_penetration": m.max_penetration,
                "max_energy_ratio": m.energy_ratio(m.max_energy),
                "final_energy_ratio": m.energy_ratio(m.final_energy),
                "nan": m.nan,
                "wall_ms": m.wall_seconds * 1000.0,
            },
        }

    def close(self) -> None:
        """Delete this simulation's world (switching away from it first)."""
        if self.world in esper.list_worlds():
            if esper.current_world == self.world:
                esper.switch_world("default")
            esper.delete_world(self.world)
        self.res.contacts.let_go()

    def __enter__(self) -> Simulation:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def _frame_parts(scheduled: Sequence[esper.Processor]) -> tuple[list, StageRun, list] | None:
    """The scheduled processors as (before, run, after) if there is one run of compiled stages and
    every other processor can say when it is quiet; else None (a substep at a time)."""
    runs = [k for k, proc in enumerate(scheduled) if isinstance(proc, StageRun)]
    if len(runs) != 1 or not all(hasattr(proc, "quiet") for proc in scheduled if not isinstance(proc, StageRun)):
        return None
    return list(scheduled[:runs[0]]), scheduled[runs[0]], list(scheduled[runs[0] + 1:])
