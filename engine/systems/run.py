"""A run of compiled stages: consecutive stages of the stage table whose whole work is a kernel, run by
one kernel call (`run_stages`) instead of a Python call each. A world whose every stage is one runs a
whole frame, all its substeps, in one call.

Nothing here is a second engine: the run calls each stage's own kernel (the one its processor's
`process` calls) with the processor's own `inputs()`, in the stage table's order. Between stages
it hands on what they share as the resources do between processors: the candidates (broadphase to
narrowphase), the contact table (narrowphase to the solver, restitution and the next substep's
rest detection and warm start), the stats. The impacts a run hears are told to the listener when it
ends, in order, and the balls it drops into the cup are marked holed and said so then. A stage that
needs Python (the other golf rules, which change components) stays a processor of its own and ends a
run. The windmill's drive and the bumper's kick are kernels too (the bumpers' lights are handed to
their components when the run ends).

Every stage kind has a place in the inputs tuple; a stage the world does not run gets `IDLE` inputs
of the same types, so one compiled `run_stages` serves every world.
"""

from __future__ import annotations

import esper
import numpy as np

from polygolf.engine.components import Body, Collider
from polygolf.engine.components.resources import (
    BOUNCES,
    COLD_RESTARTS,
    PENETRATION,
    TOI_HITS,
    Resources,
    Shapes,
    StaticWorld,
)
from polygolf.engine.physics.body import COLUMNS, BodyStore
from polygolf.engine.physics.contact import ContactTable, TableSlot
from polygolf.engine.physics.geometry import Areas
from polygolf.engine.physics.grid import FatBoxes, no_fat_pairs
from polygolf.engine.physics.jit import compiled_entry, kernel, leaf_kernel, structure, warm_up
from polygolf.engine.physics.motion import accelerate, drag, kinetic_energy, turn
from polygolf.engine.physics.settings import RESTITUTION_THRESHOLD
from polygolf.engine.systems.broadphase import BroadphaseProcessor, Picked, pick, pick_into
from polygolf.engine.systems.bumper import BumperProcessor, kick
from polygolf.engine.systems.ccd import CCDProcessor, sweep
from polygolf.engine.systems.cup import CupProcessor, drop
from polygolf.engine.systems.drag import DragProcessor
from polygolf.engine.systems.gravity import GravityProcessor
from polygolf.engine.systems.ice import IceProcessor
from polygolf.engine.systems.impacts import HEARD_COLUMNS, ImpactsProcessor, hear
from polygolf.engine.systems.integrate import IntegrateProcessor, integrate
from polygolf.engine.systems.narrowphase import NarrowphaseProcessor, contact_table, touch, touch_into
from polygolf.engine.systems.resolve import ResolveProcessor, resolve
from polygolf.engine.systems.restitution import RestitutionProcessor, bounce
from polygolf.engine.systems.sand import SandProcessor
from polygolf.engine.systems.slope import SlopeProcessor, push_on_slopes
from polygolf.engine.systems.spin import SpinProcessor
from polygolf.engine.systems.surface import scale_on_surfaces
from polygolf.engine.systems.windmill import WindmillProcessor, drive

# Stage codes, and the place of each stage's inputs in the inputs tuple (the last one has none).
(INTEGRATE, GRAVITY, SLOPE, SAND, ICE, DRAG, CCD, BROADPHASE, NARROWPHASE, RESOLVE, IMPACTS, CUP, WINDMILL,
 BUMPER, RESTITUTION, SPIN) = range(16)
CODES: dict[type[esper.Processor], int] = {
    IntegrateProcessor: INTEGRATE, GravityProcessor: GRAVITY, SlopeProcessor: SLOPE, SandProcessor: SAND,
    IceProcessor: ICE, DragProcessor: DRAG, CCDProcessor: CCD, BroadphaseProcessor: BROADPHASE,
    NarrowphaseProcessor: NARROWPHASE, ResolveProcessor: RESOLVE, ImpactsProcessor: IMPACTS,
    RestitutionProcessor: RESTITUTION, SpinProcessor: SPIN, CupProcessor: CUP, WindmillProcessor: WINDMILL,
    BumperProcessor: BUMPER,
}

# The stages that read or make the contact table.
TABLE_STAGES = frozenset((INTEGRATE, NARROWPHASE, RESOLVE, IMPACTS, RESTITUTION, BUMPER))

# Columns of a run's metrics (`Simulation.Metrics`, as `measure_substep` keeps them).
FINAL_ENERGY, MAX_ENERGY, MAX_RISE, NAN, MAX_PENETRATION = range(5)


@leaf_kernel
def measure_substep(state: np.ndarray, stats: np.ndarray, metrics: np.ndarray) -> None:
    """After a substep: kinetic energy (last, largest, largest rise over one substep), whether
    anything is no longer finite, and the deepest overlap since the last look (read from `stats`,
    which it resets)."""
    energy, finite = kinetic_energy(state)
    if not finite:
        metrics[NAN] = 1.0
    if energy - metrics[FINAL_ENERGY] > metrics[MAX_RISE]:
        metrics[MAX_RISE] = energy - metrics[FINAL_ENERGY]
    metrics[FINAL_ENERGY] = energy
    if energy > metrics[MAX_ENERGY]:
        metrics[MAX_ENERGY] = energy
    if stats[PENETRATION] > metrics[MAX_PENETRATION]:
        metrics[MAX_PENETRATION] = stats[PENETRATION]
    stats[PENETRATION] = 0.0


# What a run keeps between calls (`hold`), as the fields of one numba structure (a StructRef): passing
# it costs one argument however much it holds, and numba's dispatch reads its type off the object. (It
# was a typed list: numba hashed the list's long type at every call.)
HELD_FIELDS = ("codes", "state", "shapes", "walls", "fat_boxes", "inputs", "candidates", "table", "found", "slot",
               "picked")

Held = structure(__name__, "Held", HELD_FIELDS, """A run's stage codes, a store's state; what the stages share, the
    shapes (`Shapes.packed`), the walls (`StaticWorld.packed`) and their fat boxes; each stage's inputs; and
    what changes from substep to substep: the candidates (`Candidates.arrays`), the contact table
    (`ContactTable.arrays`: the next run's warm start) and the broadphase's found-walls array (grown when it
    must be); and where the narrowphase and the broadphase, leaves, put what they make (`contact.TableSlot`,
    `broadphase.Picked`).""")


@kernel
def hold(codes: np.ndarray, state: np.ndarray, shapes: tuple, walls: tuple, fat_boxes: tuple, inputs: tuple,
         candidates: tuple, table: tuple, found: np.ndarray) -> Held:
    """What a run keeps between calls (`Held`)."""
    return Held(codes, state, shapes, walls, fat_boxes, inputs, candidates, table, found, TableSlot(table),
                Picked(candidates, found))


@kernel
def held_table(held: Held) -> tuple:
    """The contact table a run keeps (`ContactTable.arrays`)."""
    return held.table


@kernel
def put_table(held: Held, table: tuple) -> None:
    """Give a run the contact table to go on from."""
    held.table = table


@kernel
def held_candidates(held: Held) -> tuple:
    """The candidates a run keeps (`Candidates.arrays`)."""
    return held.candidates


@kernel
def put_candidates(held: Held, candidates: tuple) -> None:
    """Give a run the candidates to use."""
    held.candidates = candidates


@kernel
def run_stages(held: Held, substeps: int, dt: float, stats: np.ndarray, metrics: np.ndarray, measure: bool
               ) -> tuple[int, int]:
    """A run's stages (`hold`), in order, `substeps` times, each with its inputs, and
    `measure_substep` after each substep with `measure`; but it stops after a substep in which a
    ball dropped into the cup (the golf rules must hear of it before the next). Returns how many
    manifolds the contact table it holds now has, and how many substeps it ran.

    What it holds is taken out once, before the loops, each stage's inputs too: numba counts a
    reference to each array taken out of a structure or a tuple (here, not in a leaf) and lets it go
    after, and the calls in these loops keep it from cancelling the two (taken out in each stage's
    branch, the counts came to some 1 000 a frame of a lone ball, against about 180 a call taken out
    here). Every stage is a leaf, handed what was taken out as it is, for nothing; the broadphase and
    the narrowphase put the arrays they make where the run takes them from (`broadphase.Picked`,
    `contact.TableSlot`)."""
    codes, state, shapes, walls, fat_boxes = held.codes, held.state, held.shapes, held.walls, held.fat_boxes
    (integrating, pulling, sloping, sanding, icing, dragging, sweeping, picking, touching, solving, hearing, cups,
     mills, bumpers, threshold) = held.inputs
    rows, push, which = pulling
    dragged, rates = dragging
    static, dropped = walls[4], cups[4]
    candidates, table, found, slot, picked = held.candidates, held.table, held.found, held.slot, held.picked
    ran = 0
    while ran < substeps:
        for code in codes:
            if code == WINDMILL:
                drive(state, mills)
            elif code == INTEGRATE:
                integrate(state, table, integrating, dt)
            elif code == SPIN:
                turn(state, dt)
            elif code == GRAVITY:
                accelerate(state, rows, push, which, dt)
            elif code == SLOPE:
                push_on_slopes(state, sloping, dt)
            elif code == SAND:
                scale_on_surfaces(state, sanding)
            elif code == ICE:
                scale_on_surfaces(state, icing)
            elif code == DRAG:
                drag(state, dragged, rates, dt)
            elif code == CCD:
                stats[TOI_HITS] += sweep(state, shapes, walls, fat_boxes, sweeping)
            elif code == BROADPHASE:
                if pick_into(state, shapes, walls, fat_boxes, picking, found, picked):
                    found = picked.found  # (grown)
                candidates = picked.candidates
            elif code == NARROWPHASE:
                if len(candidates[0]) or len(candidates[3]) or len(table[1]):  # (else: nothing near, no table)
                    if touch_into(state, shapes, walls, touching, candidates, table, stats, dt, slot):
                        table = slot.table  # (else the table stands: empty, and nothing near enough to touch)
            elif code == RESOLVE:
                if len(table[1]):
                    stats[COLD_RESTARTS] += resolve(state, static, solving, table, dt)
            elif code == IMPACTS:
                hear(table, hearing)
            elif code == CUP:
                drop(state, cups)
            elif code == BUMPER:
                kick(state, table, bumpers, dt)
            elif code == RESTITUTION:
                if len(table[1]):
                    stats[BOUNCES] += bounce(state, static, table, threshold)
        if measure:
            measure_substep(state, stats, metrics)
        ran += 1
        if dropped[0] > 0:
            break  # a ball dropped
    held.candidates, held.table, held.found = candidates, table, found
    return len(table[1]), ran


def _no_work() -> tuple:
    """`toi.toi_work(0)`, made without calling a kernel (this runs at import)."""
    return np.empty((4, 0, 2)), np.empty(0), np.empty(0), np.empty(0), np.empty((5, 3))


def _idle_inputs() -> tuple:
    """Inputs of every stage for a world without it: empty, of the types the stage's own give."""
    ints, floats, flags = np.zeros(0, dtype=np.int64), np.zeros(0), np.zeros(0, dtype=np.bool_)
    areas = Areas.of([], [])
    return (
        (flags, flags.copy(), np.ones(1, dtype=np.bool_), ints, ints.copy(), flags.copy()),  # integrate
        (ints, np.zeros((1, 2)), ints),  # gravity
        (ints, areas.verts, areas.first, areas.boxes, np.zeros((0, 2)), ints.copy()),  # slope
        (ints, areas.verts, areas.first, areas.boxes, floats, ints.copy()),  # sand
        (ints, areas.verts, areas.first, areas.boxes, floats, ints.copy()),  # ice
        (ints, np.zeros((0, 4))),  # drag
        (flags, ints, floats, _no_work(), np.empty((2, 4)), False, True, no_fat_pairs(), False),  # ccd
        (flags, ints, ints, np.zeros(1, dtype=np.int64), np.zeros((0, 2), dtype=np.int64), False, True,
         no_fat_pairs(), np.empty((2, 4))),  # broadphase
        (False, True),  # narrowphase
        (True, 1, 1, 0, True),  # resolve
        (flags, np.zeros((1, HEARD_COLUMNS)), np.zeros(1, dtype=np.int64)),  # impacts
        (ints, np.zeros((0, 4)), flags, ints, np.zeros(1, dtype=np.int64)),  # cup
        (ints, floats),  # windmill
        (ints, floats, floats.copy()),  # bumper
        RESTITUTION_THRESHOLD,  # restitution
    )


IDLE = _idle_inputs()
_NO_METRICS = np.zeros(5)


class StageRun(esper.Processor):
    """Consecutive compiled stages as one processor: `process()` runs them for one substep, as
    esper does; `process(substeps, metrics)` runs several, up to a ball's drop into the cup (the
    golf rules that follow hear of it before the next substep; `Simulation.step`).
    `members` are the stages' processors (whose own `process` runs the same kernels, for a test of
    a processor alone).

    What the run reads is held in a kernel's list (`hold`), made again only when esper's lists
    change (any component added or taken away gives new lists) or the knobs do. The contact table
    stays in it from run to run; `Contacts.table` fetches it when a stage or a tool outside asks,
    and a table put there from outside is handed back in. The candidates live and die in a run that
    both finds and uses them, else they go through `Candidates` as between processors."""

    def __init__(self, res: Resources, members: list[esper.Processor]) -> None:
        codes = [CODES[type(member)] for member in members]
        self.res, self.members = res, members
        self.name = "+".join(member.name for member in members)
        self.codes = np.array(codes, dtype=np.int64)
        self._by_code = dict(zip(codes, members, strict=True))
        self._finds, self._uses = BROADPHASE in codes, NARROWPHASE in codes
        # Whether it reads or makes the contact table (a run of the cup alone, after water, does not: it
        # neither takes the table nor keeps it).
        self._contacts = bool(TABLE_STAGES.intersection(codes))
        self._impacts, self._cup, self._bumper = self._by_code.get(IMPACTS), self._by_code.get(CUP), \
            self._by_code.get(BUMPER)
        self._key: tuple = ()
        self._held: Held | None = None
        self._run = run_stages  # (`run_stages` for what it holds, without numba's dispatch: `_hold`)
        self._dt = 0.0
        self._fat_pairs = self._by_code[BROADPHASE].fat_pairs if self._finds else None
        self._holds = 0  # manifolds in the table it holds

    def _hold(self) -> None:
        """Make the held list again if esper's lists or the knobs changed."""
        res = self.res
        everyone, config = esper.get_component(Body), res.config
        key = self._key
        if key and everyone is key[0] and config.knobs is key[1] and config.gravity is key[2]:
            return
        key = (everyone, config.knobs, config.gravity)
        table = res.contacts.table  # (fetched from the list about to go, if it is this run's)
        res.shapes.current(res.bodies, everyone, esper.get_components(Body, Collider))
        inputs = tuple(self._by_code[code].inputs() if code in self._by_code else IDLE[code]
                       for code in range(len(IDLE)))
        state = res.bodies.state
        self._held = hold(self.codes, state, res.shapes.packed, res.statics.packed,
                          res.fat_boxes.of(state, len(res.statics.grid)), inputs,
                          res.candidates.arrays, table.arrays, np.zeros(16, dtype=np.int64))
        self._key = key
        self._dt = config.dt
        self._run = compiled_entry(run_stages, self._held, 1, self._dt, res.stats.values, _NO_METRICS, False)
        self._holds = len(table)
        if self._contacts:
            res.contacts.keep(self, self._holds)

    def table(self) -> ContactTable:
        """The contact table this run holds."""
        return contact_table(held_table(self._held), self.res.bodies, self.res.statics.body)

    def process(self, substeps: int = 1, metrics: np.ndarray | None = None) -> int:
        """Run `substeps` substeps, or fewer if a ball drops into the cup; returns how many ran."""
        res = self.res
        self._hold()
        contacts = res.contacts
        if self._contacts and contacts.keeper is not self and (contacts.size or self._holds):  # a table
            put_table(self._held, contacts.table.arrays)  # put there since
        if self._uses and not self._finds:
            put_candidates(self._held, res.candidates.arrays)
        self._holds, ran = self._run(self._held, substeps, self._dt, res.stats.values,
                                     _NO_METRICS if metrics is None else metrics, metrics is not None)
        if self._contacts:
            contacts.keep(self, self._holds, fresh=self._uses)
        if self._impacts is not None:
            self._impacts.tell()
        if self._cup is not None:
            self._cup.tell()
        if self._bumper is not None:
            self._bumper.tell()
        if self._finds and not self._uses:
            found = res.candidates
            found.near, found.near_first, found.near_found, found.pair_ents = held_candidates(self._held)
        if self._fat_pairs is not None and self._fat_pairs.outgrown():
            self._key = ()  # its kept pairs need more room: hold its inputs again (`FatPairs.of` gives it)
        return ran


def schedule(res: Resources, processors: list[esper.Processor]) -> list[esper.Processor]:
    """The processors as esper runs them: each stretch of compiled stages as one run; but a lone
    stage between Python ones (the cup after water) stays its own processor, whose `process` calls
    the same kernel for less than a run's call costs (a run takes out and puts back all it holds)."""
    out: list[esper.Processor] = []
    stretch: list[esper.Processor] = []
    for proc in [*processors, None]:
        if proc is not None and type(proc) in CODES:
            stretch.append(proc)
            continue
        if stretch:
            out.append(StageRun(res, stretch) if len(stretch) > 1 or len(processors) == 1 else stretch[0])
        stretch = []
        if proc is not None:
            out.append(proc)
    return out


def _empty_world() -> tuple:
    """A world of nothing, in the types the stages take (for the warm-ups)."""
    table = ContactTable.empty().arrays
    candidates = (np.zeros(0, dtype=np.int64), np.zeros(1, dtype=np.int64), np.zeros(0, dtype=np.int64),
                  np.zeros((0, 2), dtype=np.int64))
    shapes = Shapes()
    shapes.current(BodyStore(), [], [])
    walls = StaticWorld.of([], 1.0).packed
    state = np.zeros((0, len(COLUMNS)))
    return table, candidates, shapes.packed, walls, state, 1.0 / 240.0, np.zeros(4), FatBoxes().of(state, 0), \
        np.zeros(16, dtype=np.int64)


@warm_up("compiled stages")
def _warm() -> None:
    """A run of every stage, and what goes in and out of one."""
    table, candidates, shapes, walls, state, dt, stats, fat_boxes, found = _empty_world()
    held = hold(np.array(sorted(CODES.values()), dtype=np.int64), state, shapes, walls, fat_boxes,
                        IDLE, candidates, table, found)
    put_table(held, table)
    run_stages(held, 1, dt, stats, np.zeros(5), True)
    held_table(held)
    put_candidates(held, candidates)
    held_candidates(held)
    measure_substep(state, stats, np.zeros(5))


@warm_up("stages one by one")
def _warm_alone() -> None:
    """Each stage's kernel on its own, as its processor calls it (a profile, a processor alone)."""
    table, candidates, shapes, walls, state, dt, stats, fat_boxes, found = _empty_world()
    integrate(state, table, IDLE[INTEGRATE], dt)
    push_on_slopes(state, IDLE[SLOPE], dt)
    scale_on_surfaces(state, IDLE[SAND])
    sweep(state, shapes, walls, fat_boxes, IDLE[CCD])
    pick(state, shapes, walls, fat_boxes, IDLE[BROADPHASE], found)
    touch(state, shapes, walls, IDLE[NARROWPHASE], candidates, table, stats, dt)
    resolve(state, walls[4], IDLE[RESOLVE], table, dt)
    hear(table, IDLE[IMPACTS])
    drop(state, IDLE[CUP])
    drive(state, IDLE[WINDMILL])
    kick(state, table, IDLE[BUMPER], dt)
    bounce(state, walls[4], table, IDLE[RESTITUTION])
