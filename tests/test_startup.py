"""Startup: the console line while a first launch compiles the physics kernels (and none when they load
from the cache), the window's loading screen, and the kernels run interpreted (NUMBA_DISABLE_JIT=1)
over a chosen part of the physics tests, so both paths stay covered."""

from __future__ import annotations

import inspect
import io
import json
import os
import re
import subprocess
import sys
import time
from pathlib import Path

import arcade
import pytest

from polygolf.engine.loading.paths import SCENES_DIR
from polygolf.engine.physics import jit
from polygolf.game import startup
from polygolf.game.cli import main
from polygolf.game.flow import ScreenFlow
from polygolf.game.session import Game
from polygolf.game.startup import LEAD, ConsoleProgress
from polygolf.game.views.loading import LoadingView
from polygolf.game.views.menu import MenuView

from .test_screens import window  # noqa: F401  (the one test window)

ROOT = Path(__file__).resolve().parent.parent
SCENE = SCENES_DIR / "flat-wall.yaml"
# The physics tests run again interpreted: the kernels of collide.py, contact.py, toi.py, geometry.py,
# grid.py, motion.py and solver.py line by line, directly (test_collide, test_contact, test_grid,
# test_bodies, test_solver) and through the pipeline (hard cases, systems, random shapes in a box,
# parallel shots on holes).
INTERPRETED = ["tests/test_collide.py", "tests/test_contact.py", "tests/test_hard_cases.py", "tests/test_systems.py",
               "tests/test_grid.py", "tests/test_property.py", "tests/test_shots.py", "tests/test_solver.py",
               "tests/test_bodies.py",
               # the seam rules (stop 30), each way through them: continuous collision, the gap test, the clip
               "tests/test_physics_golf.py::test_a_landing_beside_a_seam_is_a_landing_on_one_floor",
               "tests/test_physics_golf.py::test_a_pentagon_pressed_into_a_floor_with_a_seam_under_its_face_is_not_tipped"]


class Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def wait_for(condition, seconds: float = 5.0) -> None:
    end = time.monotonic() + seconds
    while not condition() and time.monotonic() < end:
        time.sleep(0.01)


# --- the console line ------------------------------------------------------------------------------

def test_a_quick_start_writes_nothing():
    out = Terminal()
    progress = ConsoleProgress(out, quiet_for=5.0)
    progress.compiling = True
    for done, label in enumerate(["shapes", "contacts", "continuous collision"]):
        progress(done, 3, label)
    progress(3, 3, "ready")
    progress.close()
    time.sleep(0.05)
    assert out.getvalue() == ""


def test_a_slow_load_from_the_cache_writes_nothing():
    """Not compiling: however long the load takes (a busy machine), the line would be untrue."""
    out = Terminal()
    progress = ConsoleProgress(out, quiet_for=0.02)
    progress(0, 2, "shapes")
    time.sleep(0.2)  # the timer has looked more than once
    progress(1, 2, "contacts")
    progress(2, 2, "ready")
    progress.close()
    assert out.getvalue() == ""


def test_a_slow_first_step_shows_the_line_while_it_runs_then_updates_it_in_place():
    out = Terminal()
    progress = ConsoleProgress(out, quiet_for=0.05)
    progress(0, 3, "shapes")
    progress.compiling = True  # as numba's compile event does, inside the step
    wait_for(lambda: progress.shown)  # the timer writes it while "shapes" is still compiling
    assert out.getvalue() == f"\r{LEAD}: 1/3 shapes..."
    progress(1, 3, "contacts")
    progress(2, 3, "grid")  # shorter than the line before: blanked to its end
    progress(3, 3, "ready")
    progress.close()
    text = out.getvalue()
    assert text.count("\n") == 1 and text.endswith("\n")
    frames = text.split("\r")[1:]
    longest = len(f"{LEAD}: 2/3 contacts...")
    assert frames[:3] == [f"{LEAD}: 1/3 shapes...", f"{LEAD}: 2/3 contacts...", f"{LEAD}: 3/3 grid...".ljust(longest)]
    assert frames[3].startswith(f"{LEAD}: done in ") and frames[3].rstrip().endswith(" s")


def test_off_a_terminal_each_step_is_a_plain_line():
    now = [0.0]
    out = io.StringIO()
    progress = ConsoleProgress(out, quiet_for=0.5, clock=lambda: now[0])
    progress.compiling = True
    progress(0, 2, "shapes")  # at once: nothing yet
    now[0] = 1.0
    progress(1, 2, "contacts")
    now[0] = 3.0
    progress(2, 2, "ready")
    progress.close()
    assert out.getvalue() == f"{LEAD}: 2/2 contacts...\n{LEAD}: done in 3.0 s\n"


def test_a_step_that_fails_leaves_no_line_open():
    out = Terminal()
    progress = ConsoleProgress(out, quiet_for=-1.0)
    progress.compiling = True
    progress(0, 2, "shapes")
    progress.close()  # as prepare_physics does when a warm-up raises
    assert out.getvalue() == f"\r{LEAD}: 1/2 shapes...\n"


def test_numba_compiling_is_noticed_and_a_compiled_call_is_not():
    numba = pytest.importorskip("numba")
    if not jit.COMPILED:
        pytest.skip("numba is disabled: nothing compiles")
    add = numba.njit(lambda x: x + 1)  # not cached: compiled here
    progress = ConsoleProgress(io.StringIO())
    with startup.watching_compiles(progress):
        add(1)
    assert progress.compiling
    progress = ConsoleProgress(io.StringIO())
    with startup.watching_compiles(progress):
        add(2)  # the same types: already compiled
    assert not progress.compiling


def test_commands_compile_only_when_they_step_physics(monkeypatch, capsys, tmp_path):
    calls = []

    def compile_kernels(progress=None) -> float:
        calls.append(progress)
        return 0.0

    monkeypatch.setattr(jit, "compile_kernels", compile_kernels)
    for argv in (["schema"], ["validate", str(SCENE)], ["explain", str(SCENE)], ["scores"],
                 ["schema", "--out", str(tmp_path)]):
        assert main(argv) == 0, argv
    assert calls == []
    capsys.readouterr()
    assert main(["simulate", str(SCENE), "--seconds", "0.1", "--json"]) == 0
    assert len(calls) == 1 and isinstance(calls[0], ConsoleProgress)
    json.loads(capsys.readouterr().out)  # stdout is the report alone


def test_first_launch_compiles_with_one_line_on_stderr_and_the_next_loads_silently(tmp_path):
    """A cold numba cache (its own folder) in a new process: stderr says what is compiling and how
    long it took, stdout gets nothing; the second launch loads the cache without a word. Only the
    first two warm-up groups, to keep the test short (all of them take 10-20 s cold: see
    benchmarks/bench_start.py)."""
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "numba"))
    env.pop("NUMBA_DISABLE_JIT", None)
    code = ("from polygolf.engine.physics import jit\n"
            "from polygolf.game.startup import prepare_physics\n"
            "steps = jit.kernel_steps()[:2]\n"
            "jit.kernel_steps = lambda: steps\n"
            "prepare_physics()\n")
    first = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=180)
    assert first.returncode == 0 and first.stdout == "", first.stderr
    lines = first.stderr.splitlines()
    assert lines and all(line.startswith(LEAD + ": ") for line in lines), first.stderr
    assert lines[-1].startswith(f"{LEAD}: done in ") and lines[-1].endswith(" s")
    assert any(line.endswith("...") and "/2 " in line for line in lines[:-1])  # a "k/2 label..." step
    again = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=120)
    assert again.returncode == 0 and again.stdout == "" and again.stderr == "", again.stderr


# A child process that runs two warm-ups (and a made-up one) through `jit.helped` with a helper for
# the second, and prints, step by step, how many kernels numba compiled (not loaded) in it.
HELPED_CHILD = """
import json, sys
from numba.core import event
from polygolf.engine.physics import jit
compiles = []
class Count(event.Listener):
    def on_start(self, _event): compiles[-1] += 1
    def on_end(self, _event): pass
named = dict(jit.kernel_steps())
steps = [("shapes", named["shapes"]), ("motion", named["motion"]), ("made up", lambda: None)]
with event.install_listener("numba:compile", Count()), jit.helped(steps, json.loads(sys.argv[1])) as helped:
    for label, fn in helped:
        compiles.append(0)
        fn()
print(json.dumps(compiles))
"""


def _helped_child(tmp_path: Path, helpers: list) -> tuple[list[int], list[Path]]:
    """Run HELPED_CHILD with a cold cache: compiles per step, and what it left in its temporary folder.
    It runs in a folder holding another `polygolf` (one that fails on import), as from another copy
    of the game: its helper must still compile this one."""
    temp, decoy, script = tmp_path / "temp", tmp_path / "elsewhere" / "polygolf", tmp_path / "child" / "helped.py"
    for folder in (temp, decoy, script.parent):
        folder.mkdir(parents=True, exist_ok=True)
    (decoy / "__init__.py").write_text("raise ImportError('another copy of the game')\n")
    script.write_text(HELPED_CHILD)
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "numba"), TMPDIR=str(temp))
    env.pop("NUMBA_DISABLE_JIT", None)
    out = subprocess.run([sys.executable, str(script), json.dumps(helpers)], capture_output=True, text=True,
                         env=env, cwd=decoy.parent, timeout=120)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout), list(temp.iterdir())


@pytest.mark.skipif(not jit.COMPILED, reason="nothing compiles without numba")
def test_a_first_launch_shares_the_compile_with_a_helper_and_loads_what_it_made(tmp_path):
    """A cold cache on a machine with two cores: the helper compiles the second group while this
    process compiles the first; this process then loads it (no compile of its own), and the next
    launch compiles nothing. A group the helper does not know (it fails) is run here as if there
    were no helper. The helpers' folders are gone afterwards."""
    if len(os.sched_getaffinity(0)) < 2:
        pytest.skip("one core: no helper")
    compiles, left = _helped_child(tmp_path, [["shapes", ["motion", "made up"]]])
    assert compiles[0] > 0 and compiles[1] == 0 and compiles[2] == 0, compiles
    assert left == []
    again, _ = _helped_child(tmp_path, [["shapes", ["motion"]]])
    assert again == [0, 0, 0]


def test_a_helper_starts_only_on_a_first_launch_and_the_steps_keep_their_order(tmp_path, monkeypatch):
    """A cache marked complete, one core, or no group to give away (none of the steps, or one before
    the step the helper would start with): the steps run as they are, no process started. Else the
    helper starts with its step, and its group's step waits for it first; the cache is marked
    complete once every warm-up has run without an error."""
    ran, made, waited, closed = [], [], [], []

    class Helper:
        def __init__(self, labels: list[str], cache: Path) -> None:
            made.append(labels)
            self.labels = labels

        def wait_for(self, label: str) -> None:
            waited.append((label, ran[:]))

        def close(self) -> None:
            closed.append(True)

    steps = [(label, lambda label=label: ran.append(label)) for label in ("a", "b", "c")]
    monkeypatch.setattr(jit, "_Helper", Helper)
    monkeypatch.setattr(jit, "CACHE", tmp_path)
    monkeypatch.setattr(jit, "_spare_cores", lambda: True)
    (tmp_path / jit.COMPLETE).touch()
    with jit.helped(steps, [("a", ["b"])]) as helped:
        assert helped == steps  # not a first launch
    (tmp_path / jit.COMPLETE).unlink()
    for helpers in ([("b", ["a"])], [("a", ["x"])], [("x", ["b"])]):
        with jit.helped(steps, helpers) as helped:
            assert helped == steps, helpers
    monkeypatch.setattr(jit, "_spare_cores", lambda: False)
    with jit.helped(steps, [("a", ["b"])]) as helped:
        assert helped == steps
    assert made == []
    monkeypatch.setattr(jit, "_spare_cores", lambda: True)
    with jit.helped(steps, [("a", ["b", "x"])]) as helped:
        assert [label for label, _ in helped] == ["a", "b", "c"]
        for _, fn in helped:
            fn()
    assert ran == ["a", "b", "c"] and made == [["b"]] and waited == [("b", ["a"])] and closed == [True]
    assert not (tmp_path / jit.COMPLETE).exists()  # "a", "b" and "c" are not every warm-up
    monkeypatch.setattr(jit, "WARM_UPS", steps[:2])
    with pytest.raises(RuntimeError), jit.helped(steps, [("a", ["b"])]) as helped:
        helped[0][1]()  # the helper starts
        raise RuntimeError("a step failed")
    assert not (tmp_path / jit.COMPLETE).exists() and closed == [True, True]
    with jit.helped(steps, [("a", ["b"])]) as helped:
        for _, fn in helped:
            fn()
    assert (tmp_path / jit.COMPLETE).exists()  # every warm-up ran: the next launch needs no helper


def test_compiled_kernels_are_kept_per_version_of_the_engine_sources(tmp_path):
    """A kernel holds the code of the kernels it calls, from other files too, which numba's own
    check (each kernel against its own file) misses: the cache folder is named by a digest of every
    engine source, so an edit anywhere compiles afresh, and a few older folders are kept."""
    engine = tmp_path / "engine"
    for folder in ("physics", "systems", "golf"):
        (engine / folder).mkdir(parents=True)
    (engine / "physics" / "grid.py").write_text("SIDE = 1\n")
    (engine / "systems" / "run.py").write_text("STAGES = 2\n")
    (engine / "golf" / "rules.py").write_text("PAR = 3\n")
    first = jit.engine_fingerprint(engine)
    assert jit.engine_fingerprint(engine) == first
    (engine / "golf" / "rules.py").write_text("PAR = 4\n")  # no kernel comes from the golf rules
    assert jit.engine_fingerprint(engine) == first
    (engine / "physics" / "grid.py").write_text("SIDE = 2\n")  # a callee, not the run's own file
    assert jit.engine_fingerprint(engine) != first
    # ... which holds while every kernel module is in those folders and imports from no other.
    assert all(name.split(".")[2] in jit.KERNEL_SOURCES for name in jit.KERNEL_MODULES)
    for folder in jit.KERNEL_SOURCES:
        for source in (jit.ENGINE_DIR / folder).rglob("*.py"):
            used = set(re.findall(r"polygolf\.engine\.(\w+)", source.read_text()))
            assert used <= set(jit.KERNEL_SOURCES), (source, used)
    base = tmp_path / "kernels"
    for age, name in enumerate(["a", "b", "c", "d"]):
        folder = jit.cache_folder(base, name)
        os.utime(folder, (1000.0 + age, 1000.0 + age))
    assert sorted(p.name for p in base.iterdir()) == ["b", "c", "d"]  # "a", used longest ago, went
    jit.cache_folder(base, "b")  # in use again: kept
    jit.cache_folder(base, "e")
    assert sorted(p.name for p in base.iterdir()) == ["b", "d", "e"]
    if jit.COMPILED:
        import numba

        assert Path(numba.config.CACHE_DIR).name == jit.engine_fingerprint()
    # No folder can be made there: the engine still imports (numba then caches where it can).
    blocked = tmp_path / "file"
    blocked.write_text("not a folder")
    env = dict(os.environ, NUMBA_CACHE_DIR=str(blocked / "kernels"))
    result = subprocess.run([sys.executable, "-c", "import polygolf.engine.physics.jit"], capture_output=True,
                            text=True, env=env, timeout=60)
    assert result.returncode == 0, result.stderr


def test_once_ready_the_collector_has_the_compiled_engine_out_of_sight():
    """`settle` (the end of `compile_kernels` and of the loading screen) freezes what the process
    holds, so a full pass of the cyclic collector no longer walks numba's objects."""
    import gc

    jit.compile_kernels()
    frozen = gc.get_freeze_count()
    assert frozen > 50_000  # numba's compiler and caches, at least
    assert len(gc.get_objects()) < frozen / 10


def test_leaf_kernels_hand_back_only_numbers():
    """A leaf runs without numba's reference counts (`jit.leaf_kernel`): an array it handed back
    would be released once too often by its caller. numba refuses a leaf that makes an array, not
    one that returns an array it was given; each leaf's annotation says what it returns."""
    jit._load_kernel_modules()
    if not jit.COMPILED:
        pytest.skip("numba is disabled: no leaf is compiled")
    assert len(jit.LEAVES) > 50
    for leaf in jit.LEAVES:
        returns = inspect.signature(leaf.py_func).return_annotation
        assert returns is not inspect.Signature.empty, leaf.py_func.__name__
        text = returns.__name__ if isinstance(returns, type) else str(returns)  # a class, or a string / alias
        words = set(re.findall(r"[A-Za-z_.]+", text)) - {"tuple"}
        assert words <= {"None", "bool", "float", "int"}, (leaf.py_func.__name__, returns)


def test_prepare_physics_runs_every_warm_up(monkeypatch):
    ran = []
    steps = [(label, lambda label=label: ran.append(label)) for label in ("a", "b")]
    monkeypatch.setattr(jit, "kernel_steps", lambda: steps)
    assert startup.prepare_physics(io.StringIO()) >= 0.0
    assert ran == ["a", "b"]


# --- the loading screen ----------------------------------------------------------------------------

def test_loading_screen_keeps_drawing_while_slow_steps_run_then_moves_on(window, tmp_path):  # noqa: F811
    events: list[str] = []
    console = ConsoleProgress(Terminal(), quiet_for=0.0)
    step_seconds = 0.25

    drawn = [0]  # frames drawn so far
    during: list[int] = []  # frames drawn while each step ran

    def compile_step(label: str) -> None:
        console.compiling = True  # as numba's compile event does
        before = drawn[0]
        time.sleep(step_seconds)
        during.append(drawn[0] - before)
        events.append(label)

    slow = [(label, lambda label=label: compile_step(label)) for label in "abc"]
    view = LoadingView(Game.load(), then=lambda: events.append("then"), steps=slow, console=console)
    window.show_view(view)
    view.on_update(1 / 60)
    time.sleep(0.05)
    assert events == [] and view.done == 0  # nothing runs before the screen has been drawn once
    pictures: dict[float, object] = {}
    frames, began = 0, time.perf_counter()
    while not view.finished and time.perf_counter() - began < 10.0:
        fraction = view.fraction
        view.on_draw()
        # (A step ends on its own thread: a frame is this fraction's only if it did not move meanwhile.)
        if view.fraction == fraction and fraction not in pictures:
            pictures[fraction] = arcade.get_image(0, 0, *window.get_framebuffer_size()).convert("RGB")
        frames += 1
        drawn[0] = frames
        view.on_update(1 / 60)
        time.sleep(1 / 60)
    assert events == ["a", "b", "c", "then"]  # every step once, in order, then the next screen once
    # The window went on drawing while the steps ran: frames during every step, not one a step (how
    # many a second is the renderer's and the machine's business, not this test's).
    assert len(during) == len(slow) and min(during) >= 2 and frames > 3 * len(slow)
    assert {0.0, 1 / 3, 2 / 3} <= set(pictures)
    # From a terminal the same compile is the command line's line too, ended when the screen moves on.
    assert console.stream.getvalue().endswith(" s\n") and f"{LEAD}: 3/3 c..." in console.stream.getvalue()
    shots = Path(os.environ.get("POLYGOLF_SCREENSHOTS", tmp_path))
    shots.mkdir(parents=True, exist_ok=True)
    third = pictures[1 / 3]
    third.save(shots / "loading.png")
    # The bar runs from x = 360 to 920 (560 px, centred); its middle row is 62 - 11 px below the
    # window's middle. A third done: the button colour from its left edge to a third of the way.
    button = view.game.theme.rgba("button")[:3]
    row = third.crop((0, 360 + 51, 1280, 360 + 52)).getdata()
    filled = [x for x, pixel in enumerate(row) if pixel == button]
    assert filled and abs(min(filled) - 360) <= 3 and abs(max(filled) - (360 + 560 / 3)) <= 3


def test_a_failing_step_is_raised_on_the_window_s_thread(window):  # noqa: F811
    def broken() -> None:
        raise RuntimeError("no compiler")

    view = LoadingView(Game.load(), then=lambda: pytest.fail("moved on"), steps=[("broken", broken)],
                       console=ConsoleProgress(Terminal()))
    window.show_view(view)
    view.on_draw()
    with pytest.raises(RuntimeError, match="no compiler"):  # on the first update after the thread stops
        for _ in range(500):
            view.on_update(1 / 60)
            time.sleep(0.01)


def test_a_cached_start_passes_through_to_the_menu(window):  # noqa: F811
    jit.compile_kernels()  # loaded (or compiled, on a machine's first run) before the screen opens
    game = Game.load()
    flow = ScreenFlow(window, game)
    flow.loading(then=flow.menu)
    assert isinstance(window.current_view, LoadingView)
    window.current_view.console.stream = console = Terminal()  # nothing compiles: not a word on stderr
    began = time.perf_counter()
    while isinstance(window.current_view, LoadingView) and time.perf_counter() - began < 5.0:
        window.current_view.on_draw()
        window.current_view.on_update(1 / 60)
        time.sleep(1 / 60)
    assert isinstance(window.current_view, MenuView)
    assert time.perf_counter() - began < 2.0  # every step is already loaded: a moment
    assert console.getvalue() == ""


# --- the kernels interpreted -----------------------------------------------------------------------

def test_physics_tests_pass_with_the_kernels_interpreted():
    """NUMBA_DISABLE_JIT=1 runs every kernel as plain Python: the same code must give the same
    results (a kernel that only works compiled, or only interpreted, fails here or in the suite)."""
    env = dict(os.environ, NUMBA_DISABLE_JIT="1")
    code = ("import sys, pytest\n"
            "from polygolf.engine.physics import jit\n"
            "assert not jit.COMPILED, 'NUMBA_DISABLE_JIT=1 should leave the kernels interpreted'\n"
            f"sys.exit(pytest.main(['-p', 'no:cacheprovider', '--no-xvfb', '-n', '0', *{INTERPRETED!r}]))\n")
    started = time.perf_counter()
    result = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, env=env,
                            timeout=300)
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-2000:]
    assert " passed" in result.stdout and "skipped" not in result.stdout
    assert time.perf_counter() - started < 120, "the interpreted subset should stay well under a minute"


# --- the warm-ups cover the engine -------------------------------------------------------------------

def _signatures() -> dict[str, list]:
    import importlib

    from numba.core.registry import CPUDispatcher

    found = {}
    for name in jit.KERNEL_MODULES:
        for attr, value in vars(importlib.import_module(name)).items():
            if isinstance(value, CPUDispatcher):
                found[f"{name}.{attr}"] = list(value.signatures)
    return found


@pytest.mark.skipif(not jit.COMPILED, reason="nothing is compiled with the kernels interpreted")
def test_stepping_compiles_nothing_the_warm_ups_did_not():
    """Every argument type the engine passes a kernel was compiled (or loaded) by the warm-ups: a
    first launch compiles everything behind the loading screen, never in the middle of a shot."""
    from polygolf.engine.golf.scenes import build_scene_file, find_hole
    from polygolf.engine.golf.shots import fan, simulate_shots
    from polygolf.engine.loading.scene import ShapeSpec
    from polygolf.engine.physics.presets import Knobs

    jit.compile_kernels()
    before = _signatures()
    for scene in sorted(SCENES_DIR.glob("*.yaml")):
        for knobs in ("balanced", Knobs(substeps=2, iterations=4, position_correction="ngs", warm_start=False)):
            with build_scene_file(scene, knobs) as sim:
                sim.run(1.0)
    for name in ("hazards:6", "meadow:8", "hazards:2"):  # a windmill, bumpers, water
        hole = find_hole(name, ROOT)
        simulate_shots(hole, fan(hole.layout.tee, 6, [1.0, 3.0]), "fast", shape=ShapeSpec(star=(5, 2), radius=1.0),
                       max_seconds=4.0, path=True)
    added = {name: [s for s in sigs if s not in before.get(name, [])] for name, sigs in _signatures().items()}
    assert not {name: new for name, new in added.items() if new}


@pytest.mark.skipif(not jit.COMPILED, reason="nothing is compiled with the kernels interpreted")
def test_one_compiled_run_serves_every_world():
    """Every stage a world does not run gets inputs of the same types as its own (`run.IDLE`), so a
    run of compiled stages is compiled once, whatever stages the world has."""
    from polygolf.engine.golf.play import HolePlay
    from polygolf.engine.golf.scenes import build_scene_file, find_hole
    from polygolf.engine.loading.scene import ShapeSpec
    from polygolf.engine.systems import run

    for scene, preset in (("pile", "balanced"), ("corner", "accurate"), ("body-tunnel", "fast")):
        with build_scene_file(SCENES_DIR / f"{scene}.yaml", preset) as sim:
            sim.step(2)
    for name in ("hazards:6", "hazards:4", "meadow:8"):
        world = HolePlay(find_hole(name, ROOT), ShapeSpec(regular=5, radius=1.0))
        try:
            world.step(2)
        finally:
            world.close()
    assert len(run.run_stages.signatures) == 1
    assert len(run.hold.signatures) == 1
