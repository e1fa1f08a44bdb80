"""Runs of compiled stages (`systems.run`): a world steps through one kernel call a run, and that must
be exactly what its processors do one by one, each with its own `process` (as a profile does)."""

from __future__ import annotations

import math

import esper
import numpy as np
import pytest

from polygolf.engine.assembly.simulation import Simulation
from polygolf.engine.components import Collider
from polygolf.engine.golf.play import HolePlay
from polygolf.engine.golf.scenes import find_hole
from polygolf.engine.loading.scene import Scene, ShapeSpec, build_scene
from polygolf.engine.physics.contact import ContactTable
from polygolf.engine.physics.jit import COMPILED, compiled_entry
from polygolf.engine.physics.motion import kinetic_energy
from polygolf.engine.systems.run import BROADPHASE, StageRun, run_stages, schedule

from .conftest import ROOT
from .helpers import scene_sim

# Bodies against walls and each other, resting piles, spin, friction, NGS and no warm start.
SCENES = [("pile", "balanced"), ("corner", "accurate"), ("body-tunnel", "fast"), ("stack-drop", "balanced"),
          ("seam-slide", "fast"), ("heavy-crush", "balanced")]


def step_alone(sim: Simulation, frames: int) -> None:
    """Each processor's own `process`, in the table's order, substep by substep (and measuring)."""
    esper.switch_world(sim.world)
    for _ in range(frames * sim.knobs.substeps):
        for proc in sim.processors:
            proc.process()
        sim._measure()
    sim.metrics.frames += frames


def _same_tables(a: ContactTable, b: ContactTable) -> None:
    for x, y in zip(a.arrays, b.arrays, strict=True):
        assert np.array_equal(x, y)


@pytest.mark.parametrize(("scene", "preset"), SCENES)
def test_a_run_is_its_processors_one_by_one(scene, preset):
    with scene_sim(scene, preset) as whole, scene_sim(scene, preset) as alone, scene_sim(scene, preset) as timed:
        before, _, after = whole._parts  # a scene's stages are all compiled: one call a frame
        assert before == after == []
        touched = False  # (whether a frame ended with contacts to compare: a slide, a resting stack)
        for _ in range(40):
            whole.step(3)
            step_alone(alone, 3)
            timed.step(3, profile=True)
            touched |= len(whole.res.contacts.table) > 0
            for other in (alone, timed):
                assert np.array_equal(whole.res.bodies.state, other.res.bodies.state)
                _same_tables(whole.res.contacts.table, other.res.contacts.table)
                assert np.array_equal(whole.res.stats.values, other.res.stats.values)
                assert whole.metrics.max_energy_rise == other.metrics.max_energy_rise
                assert whole.metrics.max_penetration == other.metrics.max_penetration
        assert set(timed.metrics.system_seconds) == set(timed.system_names)
        assert touched or whole.res.stats.bounces > 0 or whole.res.stats.toi_hits > 0


def test_a_crowd_whose_kept_pairs_outgrow_their_room_is_held_again():
    """150 small balls packed close under gravity (some 15 fat-box pairs a ball, more than the
    broadphase first makes room for): the run notices, holds its inputs again with room enough, and
    steps exactly as the processors one by one."""
    balls = [{"name": f"b{k}", "shape": {"regular": 7, "radius": 0.03},
              "position": [0.1 + 0.065 * (k % 15), 0.1 + 0.065 * (k // 15)], "velocity": [0.2 * (k % 3 - 1), 0.0],
              "restitution": 0.2, "friction": 0.4} for k in range(150)]
    walls = [{"box": {"center": [0.5, -0.05], "half": [1.0, 0.05]}},
             {"box": {"center": [-0.05, 0.5], "half": [0.05, 1.0]}},
             {"box": {"center": [1.05, 0.5], "half": [0.05, 1.0]}}]
    scene = Scene.model_validate({"name": "packed", "bodies": balls, "walls": walls, "gravity": [0.0, -9.81]})
    with build_scene(scene, "balanced") as whole, build_scene(scene, "balanced") as alone:
        fat_pairs = whole._parts[1]._by_code[BROADPHASE].fat_pairs
        whole.step(1)
        step_alone(alone, 1)
        room = len(fat_pairs.pairs)
        assert fat_pairs.outgrown()  # (the pairs were searched for every substep)
        for _ in range(30):
            whole.step(1)
            step_alone(alone, 1)
            assert np.array_equal(whole.res.bodies.state, alone.res.bodies.state)
        assert len(fat_pairs.pairs) > room and fat_pairs.count[0] > room // 2  # more room, and pairs kept in it
        assert not fat_pairs.outgrown()


@pytest.mark.parametrize("name", ["hazards:6", "hazards:2", "meadow:8", "hazards:9"])  # a windmill; water;
# walls only; a windmill, bumpers, water, sand and a slope
def test_a_hole_played_through_runs_is_played_alone_the_same(name):
    """A hole's world has golf stages between its runs; a windmill's pinch test runs in the kernel."""
    hole = find_hole(name, ROOT)
    shape = ShapeSpec(star=(5, 2), radius=1.0)
    whole, alone = HolePlay(hole, shape, "balanced"), HolePlay(hole, shape, "balanced")
    try:
        tee = whole.ball.x, whole.ball.y
        for world in (whole, alone):
            assert world.shoot(tee, (6.0, 2.5))
        struck = 0
        for _ in range(240):
            whole.step(1)
            step_alone(alone.sim, 1)
            assert np.array_equal(whole.sim.res.bodies.state, alone.sim.res.bodies.state)
            heard, heard_alone = whole.drain_events(), alone.drain_events()
            assert heard == heard_alone  # golf events and impacts, in the same order
            struck += len(heard[1])
        assert whole.state.strokes == alone.state.strokes == 1
        assert struck > 1  # the club, and at least a wall
    finally:
        whole.close()
        alone.close()


def test_schedule_joins_each_stretch_of_compiled_stages():
    hole = find_hole("hazards:6", ROOT)
    world = HolePlay(hole, ShapeSpec(regular=5, radius=1.0))
    try:
        scheduled = schedule(world.sim.res, world.sim.processors)
        names = [p.name for p in scheduled]
        runs = [p for p in scheduled if isinstance(p, StageRun)]
        assert names[0] == "shot" and names[-1] == "scoring"
        assert len(runs) == 1 and [m.name for m in runs[0].members][:3] == ["windmill", "integrate", "spin"]
        assert runs[0].name.endswith("+resolve+impacts+restitution+cup")  # the cup is a kernel too
        assert names[names.index(runs[0].name) + 1:] == ["scoring"]  # the other golf rules need Python
        assert sum(len(p.members) if isinstance(p, StageRun) else 1 for p in scheduled) == len(world.sim.processors)
        before, run, after = world.sim._parts  # a frame in one call while the shot and scoring stages are
        assert ([p.name for p in before], run.name, [p.name for p in after]) == (["shot"], runs[0].name, ["scoring"])
        # quiet (the windmill's drive is a kernel)
    finally:
        world.close()


def test_a_lone_stage_between_python_stages_is_its_own_processor():
    """Water Carry: the cup comes after water, alone; it stays a processor (its own kernel call),
    and the hole goes a substep at a time (water is Python and cannot say it is quiet)."""
    hole = find_hole("hazards:2", ROOT)
    world = HolePlay(hole, ShapeSpec(regular=5, radius=1.0))
    try:
        scheduled = schedule(world.sim.res, world.sim.processors)
        assert [p.name for p in scheduled][-3:] == ["water", "cup", "scoring"]
        assert not isinstance(scheduled[-2], StageRun) and world.sim._parts is None
        assert sum(isinstance(p, StageRun) for p in scheduled) == 1
    finally:
        world.close()


def test_a_frame_that_drops_the_ball_into_the_cup_is_the_substeps_one_by_one():
    """Straight: a putt into the cup. The golf rules are quiet between the shot and the drop, so
    frames go through in one kernel call; the run stops after the substep the ball drops in, so the
    scoring stage hears of it before the next, as it does a substep at a time."""
    hole = find_hole("meadow:1", ROOT)
    shape = ShapeSpec(regular=6, radius=1.0)
    whole, alone = HolePlay(hole, shape, "fast"), HolePlay(hole, shape, "fast")
    try:
        assert whole.sim._parts is not None
        tee = whole.ball.x, whole.ball.y
        for world in (whole, alone):
            assert world.shoot(tee, (2.0, 0.0))
        frames = 0
        while not whole.state.holed and frames < 600:
            whole.step(1)
            step_alone(alone.sim, 1)
            frames += 1
            assert np.array_equal(whole.sim.res.bodies.state, alone.sim.res.bodies.state)
            assert whole.drain_events() == alone.drain_events()
            assert (whole.state.holed, whole.state.strokes) == (alone.state.holed, alone.state.strokes)
        assert whole.state.holed and whole.state.strokes == 1 and 30 < frames < 600
        esper.switch_world(whole.sim.world)
        assert not esper.has_component(whole.ball_entity, Collider)  # scoring took the ball off the green
    finally:
        whole.close()
        alone.close()


@pytest.mark.parametrize("preset", ["fast", "balanced"])
def test_two_balls_that_drop_one_after_the_other_are_the_substeps_one_by_one(preset):
    """Two players putt at once on Straight: the second ball drops while the first still rolls, and
    the first rolls over the cup after it (its collider gone) and drops too. Frames in one kernel
    call, stopped at each drop, against the processors a substep at a time."""
    hole = find_hole("meadow:1", ROOT)
    shape = ShapeSpec(regular=6, radius=1.0)
    cup = hole.layout.cup
    whole, alone = HolePlay(hole, shape, preset, players=2), HolePlay(hole, shape, preset, players=2)
    try:
        for world in (whole, alone):
            for seat, power in ((0, 1.9), (1, 2.8)):
                world.turn = seat
                x, y = world.ball.x, world.ball.y
                d = math.dist((x, y), cup)
                assert world.shoot((x, y), (power * (cup[0] - x) / d, power * (cup[1] - y) / d))
        holed_while_the_other_rolled = False
        for _ in range(600):
            whole.step(1)
            step_alone(alone.sim, 1)
            assert np.array_equal(whole.sim.res.bodies.state, alone.sim.res.bodies.state)
            assert whole.drain_events() == alone.drain_events()
            states = [(p.state.holed, p.state.strokes) for p in whole.players]
            assert states == [(p.state.holed, p.state.strokes) for p in alone.players]
            holed_while_the_other_rolled |= any(p.state.holed for p in whole.players) and not whole.all_at_rest
            if whole.finished:
                break
        assert whole.finished and holed_while_the_other_rolled
    finally:
        whole.close()
        alone.close()


def test_bumpers_kick_in_a_frame_run_as_a_substep_at_a_time():
    """Pinball Wizard: its bumpers kick in the run's kernel, frames in one call, and the lights (kept
    in the kernel's array, handed to the components when a run ends) are those of the processors
    one by one."""
    hole = find_hole("hazards:5", ROOT)
    shape = ShapeSpec(star=(5, 2), radius=1.0)
    whole, alone = HolePlay(hole, shape, "balanced"), HolePlay(hole, shape, "balanced")
    try:
        assert whole.sim._parts is not None and "bumper" in whole.sim._parts[1].name
        angle = 2 * math.pi * 4 / 12
        for world in (whole, alone):
            assert world.shoot((world.ball.x, world.ball.y), (5.0 * math.cos(angle), 5.0 * math.sin(angle)))
        kicks, lit_seen = 0, False
        for _ in range(240):
            whole.step(1)
            step_alone(alone.sim, 1)
            assert np.array_equal(whole.sim.res.bodies.state, alone.sim.res.bodies.state)
            heard = whole.drain_events()
            assert heard == alone.drain_events()
            kicks += sum(impact.kind == "bumper" for impact in heard[1])
            assert [b.lit for b in whole.bumpers] == [b.lit for b in alone.bumpers]
            lit_seen |= any(b.lit > 0.0 for b in whole.bumpers)
        assert kicks >= 3 and lit_seen
    finally:
        whole.close()
        alone.close()


def test_a_table_put_from_outside_is_what_the_run_goes_on_from():
    """`Contacts.table` fetches the run's table when asked; one set from outside is handed back in."""
    with scene_sim("pile", "balanced") as sim, scene_sim("pile", "balanced") as alone:
        sim.step(40)
        alone.step(40, profile=True)
        table = sim.res.contacts.table
        assert len(table) > 0
        _same_tables(table, alone.res.contacts.table)
        # Both forget their warm start: the run must start cold as the processors do.
        sim.res.contacts.table = ContactTable.empty()
        alone.res.contacts.table = ContactTable.empty()
        sim.step(1)
        alone.step(1, profile=True)
        assert np.array_equal(sim.res.bodies.state, alone.res.bodies.state)
        _same_tables(sim.res.contacts.table, alone.res.contacts.table)


def test_candidates_go_between_runs_as_between_processors():
    """A run that finds candidates but leaves them to another hands them on, as processors do."""
    with scene_sim("pile") as sim:
        sim.step(40)
        broadphase = next(p for p in sim.processors if p.name == "broadphase")
        finder = StageRun(sim.res, [broadphase])
        finder.process()
        found = sim.res.candidates.arrays
        broadphase.process()
        assert all(np.array_equal(a, b) for a, b in zip(found, sim.res.candidates.arrays, strict=True))
        assert len(sim.res.candidates.pair_ents) > 0


def test_a_run_calls_its_kernel_without_dispatch_and_answers_the_same():
    """`jit.compiled_entry`: the run's machine code called directly (where numba compiles) gives
    what numba's dispatch of the same call gives, and a kernel's entry answers as the kernel."""
    with scene_sim("pile", "balanced") as sim:
        sim.step(2)
        run = sim._parts[1]
        assert (run._run is not run_stages) == COMPILED
        state = sim.res.bodies.state.copy()
        assert compiled_entry(kinetic_energy, state)(state) == kinetic_energy(state)
        assert kinetic_energy(state)[0] > 0.0
