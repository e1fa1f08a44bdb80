"""The engine's compiled kernels: numba's `njit` with one set of settings, and the list of kernels a
first launch compiles.

A kernel is written once, in the subset of Python numba compiles (numbers, numpy arrays, loops), and
runs compiled when numba is present. With `NUMBA_DISABLE_JIT=1`, or where numba is missing, the very
same function runs interpreted, which is how a test reaches a kernel line by line.

Settings: `cache=True` keeps the machine code on disk, so only the first launch compiles; no
`fastmath`, so every operation is the IEEE one the interpreted code would do and runs stay bit-for-bit
repeatable.

Where: the platform's user cache folder (`NUMBA_CACHE_DIR` instead, if set), in a folder named by a
digest of the engine's sources (`engine_fingerprint`). numba checks a cached kernel against its own
file only, but a kernel holds the code of every kernel it calls, from other files too: after an edit,
a checkout or an upgrade it would load a kernel built from the old callees. A new digest compiles
afresh instead; the last few folders are kept, older ones removed.

numba counts references to every array a kernel is handed and cancels the counts it can prove
balanced; it cannot when the arrays die on different branches (an `and`/`or` chain or an early
return over them, a call that takes them on one branch only), and then every call costs two
atomic operations per array. A *leaf* (`leaf_kernel`: it makes no array, returns only numbers, and
calls only other leaves) is compiled without reference counting at all, so a call costs what its
arithmetic does: the narrowphase's, the time of impact's and the solver's inner functions, called
per piece and per point. numba refuses to compile a leaf that makes an array. A leaf may call a
*counted* kernel (`counted_kernel`: it makes arrays, but returns only numbers), which counts the
references it takes itself: a stage whose work is mostly a leaf's (the sweep, the solver) is then a
leaf too, and a run of stages hands it its tuples without counting a reference to each array in them.
A stage that makes arrays (the broadphase, the narrowphase) is a leaf as well: the counted kernel it
calls puts them into a numba structure handed in (a StructRef), where the run takes them from.

Each kernel module registers a *warm-up*: a call with small, typical arguments that makes numba
compile (or load from the cache) every kernel it defines with the argument types the engine uses.
`compile_kernels` runs them all, reporting progress, before a window or a long command starts. On a
first launch with a core to spare, a helper process compiles some of them meanwhile (`helped`).
"""

from __future__ import annotations

import gc
import glob
import hashlib
import os
import shutil
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager, suppress
from dataclasses import make_dataclass
from pathlib import Path
from typing import TypeVar

from platformdirs import user_cache_path

F = TypeVar("F", bound=Callable)

try:
    import numba
except ImportError:  # the same code, interpreted
    numba = None

COMPILED = numba is not None and os.environ.get("NUMBA_DISABLE_JIT", "0") in ("", "0")
ENGINE_DIR = Path(__file__).resolve().parents[1]
KEEP_CACHES = 3  # cache folders of different sources kept side by side (the current one among them)


# The engine's folders kernels and the constants they hold come from (the golf rules, assembly and
# loading have none, and no kernel imports from them: editing those compiles nothing).
KERNEL_SOURCES = ("physics", "systems", "components")


def engine_fingerprint(root: Path = ENGINE_DIR) -> str:
    """A digest of every source file of the engine's KERNEL_SOURCES folders under `root`, names
    and contents, and of numba's version (a new numba compiles afresh, into a folder of its own)."""
    digest = hashlib.sha256(numba.__version__.encode() if numba is not None else b"")
    for path in sorted(p for folder in KERNEL_SOURCES for p in (root / folder).rglob("*.py")):
        digest.update(path.relative_to(root).as_posix().encode() + b"\0" + path.read_bytes() + b"\0")
    return digest.hexdigest()[:16]


def cache_folder(base: Path, fingerprint: str) -> Path:
    """The folder compiled kernels of these sources go to under `base`, made if need be; of the
    others there, all but the most recently used KEEP_CACHES - 1 are removed."""
    folder = base / fingerprint
    if not folder.is_dir():
        others = sorted((p for p in base.glob("*") if p.is_dir()), key=lambda p: p.stat().st_mtime, reverse=True)
        for stale in others[KEEP_CACHES - 1:]:
            shutil.rmtree(stale, ignore_errors=True)
        folder.mkdir(parents=True, exist_ok=True)
    folder.touch()  # used now
    return folder


CACHE: Path | None = None  # the folder this process's kernels are cached in (None: numba's own places)
if COMPILED:
    _base = os.environ.get("NUMBA_CACHE_DIR") or user_cache_path("polygolf", appauthor=False) / "kernels"
    try:
        CACHE = cache_folder(Path(_base), engine_fingerprint())
        numba.config.CACHE_DIR = str(CACHE)
    except OSError:  # no writable cache folder: numba's own places (beside the code, or its user cache)
        pass

WARM_UPS: list[tuple[str, Callable[[], None]]] = []
LEAVES: list = []  # every `leaf_kernel` (a test checks what they return)


def kernel(fn: F) -> F:
    """Compile `fn` with the engine's settings (or leave it as it is without numba)."""
    if numba is None:
        return fn
    return numba.njit(cache=True, nogil=True)(fn)


def leaf_kernel(fn: F) -> F:
    """A kernel that makes no array, returns only numbers (never an array, not even one handed in)
    and calls only other leaves: compiled without numba's reference counting (see above)."""
    if numba is None:
        return fn
    compiled = numba.njit(cache=True, nogil=True, _nrt=False)(fn)
    LEAVES.append(compiled)
    return compiled


def counted_kernel(fn: F) -> F:
    """A kernel that may make arrays but returns only numbers (never an array), so a leaf may call it:
    compiled with reference counting whoever calls it (numba would compile it as its caller is)."""
    if numba is None:
        return fn
    return numba.njit(cache=True, nogil=True, _nrt=True)(fn)


def inlined_leaf(fn: F) -> F:
    """A leaf numba puts into each kernel that calls it rather than calling it: a small helper called
    once a body in a loop, where the call (every array passed is some ten machine words) would cost
    more than its work. Its code is then optimised again in every kernel that reaches it, so each
    one lengthens the first launch's compile: inline what a measurement says pays for that."""
    if numba is None:
        return fn
    compiled = numba.njit(cache=True, nogil=True, _nrt=False, inline="always")(fn)
    LEAVES.append(compiled)
    return compiled


def inlined_kernel(fn: F) -> F:
    """A kernel numba inlines where another kernel calls it: a step of the narrowphase inside
    `contact.find_contacts`, which then hands it its arrays without counting a reference to each
    (a kernel called counts one to each array it is handed, however it got them). Compiled on its
    own too, for callers outside (tests, warm-ups)."""
    if numba is None:
        return fn
    return numba.njit(cache=True, nogil=True, inline="always")(fn)


def structure(module: str, name: str, fields: Sequence[str], doc: str) -> type:
    """A class `name` whose objects hold `fields`, passed to a kernel as one numba structure (a
    StructRef: one argument however much it holds, its type read off the object by numba's
    dispatch); a slotted dataclass of the same fields where the kernels run interpreted. Its
    numba type class is put into `module` beside it, where the cache finds it again."""
    if not COMPILED:
        made = make_dataclass(name, list(fields), slots=True)
        made.__doc__ = doc
        return made
    from numba.experimental import structref

    def preprocess_fields(self, typed: tuple) -> tuple:
        return tuple((field, numba.types.unliteral(typ)) for field, typ in typed)

    kind_name = f"_{name}Type"
    kind = type(kind_name, (numba.types.StructRef,), {"preprocess_fields": preprocess_fields, "__module__": module,
                                                       "__qualname__": kind_name})
    setattr(sys.modules[module], kind_name, structref.register(kind))
    proxy = type(name, (structref.StructRefProxy,), {"__doc__": doc, "__module__": module, "__qualname__": name})
    structref.define_proxy(proxy, kind, list(fields))
    return proxy


def compiled_entry(fn: Callable, *args: object) -> Callable:
    """`fn`'s machine code for arguments of these types, called without numba's dispatch (which types
    every argument of every call, a structure's through Python: about a microsecond, a tenth of a
    lone ball's frame). For a caller that makes many calls whose arguments keep these types; it
    compiles (or loads) that code now if need be. Without numba, or if `fn` is not a kernel (a
    wrapper put in its place, as a profile does), `fn` itself."""
    if not COMPILED or not isinstance(fn, numba.core.registry.CPUDispatcher):
        return fn
    signature = tuple(numba.typeof(arg) for arg in args)
    if signature not in fn.overloads:
        fn.compile(signature)
    return fn.overloads[signature].entry_point


def warm_up(label: str) -> Callable[[Callable[[], None]], Callable[[], None]]:
    """Register a function that calls a module's kernels once with the types the engine uses."""
    def register(fn: Callable[[], None]) -> Callable[[], None]:
        WARM_UPS.append((label, fn))
        return fn
    return register


# Every module that defines kernels, in the order a first launch compiles them.
KERNEL_MODULES = (
    "polygolf.engine.physics.geometry",
    "polygolf.engine.physics.motion",
    "polygolf.engine.physics.collide",
    "polygolf.engine.physics.contact",
    "polygolf.engine.physics.toi",
    "polygolf.engine.physics.grid",
    "polygolf.engine.physics.solver",
    "polygolf.engine.systems.run",
)


def _load_kernel_modules() -> None:
    """Import every module that defines kernels, so their warm-ups are registered."""
    import importlib

    for name in KERNEL_MODULES:
        importlib.import_module(name)


def kernel_steps() -> list[tuple[str, Callable[[], None]]]:
    """The warm-ups one by one (a loading screen runs one a frame so it can draw between them)."""
    _load_kernel_modules()
    return list(WARM_UPS)


def compile_kernels(progress: Callable[[int, int, str], None] | None = None) -> float:
    """Compile (or load from the cache) every kernel; `progress(done, total, label)` is called before
    each group and once at the end. Returns the seconds it took."""
    start = time.perf_counter()
    with helped(kernel_steps()) as steps:
        for done, (label, fn) in enumerate(steps):
            if progress is not None:
                progress(done, len(steps), label)
            fn()
    settle()
    if progress is not None:
        progress(len(steps), len(steps), "ready")
    return time.perf_counter() - start


def settle() -> None:
    """Once the kernels are ready: what the process holds so far (numba's compiler and caches, a
    hundred thousand objects that live as long as the process) is moved out of sight of Python's
    cyclic collector (`gc.freeze`), whose full passes would walk it all, 45 ms each: a dropped frame
    in play, a third of a fan of shots' time."""
    gc.collect()
    gc.freeze()


# On a first launch, helper processes compile some warm-up groups while this process compiles the
# others: (the step of this process a helper starts with, the groups it compiles in order). The
# kernels call each other (the grid, time of impact, contacts, the contact table, the solver, in that
# order; every stage needs them all): the first helper takes the second half of that chain while
# this process compiles the first; the second compiles each stage alone while this process compiles
# the run of stages. About as much work on each side.
HELPERS: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("shapes", ("contacts", "contact table", "contact solver")),
    ("compiled stages", ("stages one by one",)),
)

# A file in the cache folder: every warm-up has run there from these sources (numba files a kernel
# under its source file's place, so another checkout of the same sources compiles afresh).
COMPLETE = f"complete-{hashlib.sha256(str(ENGINE_DIR).encode()).hexdigest()[:12]}"
HELPER_FOLDER = "polygolf-kernels-"  # how the temporary folder a helper compiles into is named
Step = tuple[str, Callable[[], None]]


@contextmanager
def helped(steps: Sequence[Step], helpers: Sequence[tuple[str, Sequence[str]]] = HELPERS) -> Iterator[list[Step]]:
    """The warm-up `steps`, to be run in order, sped up on a first launch (the cache folder is not
    marked COMPLETE) on a machine with a core to spare. As this process starts a helper's first
    step, the helper process starts on its groups, with a copy of the cache as it is then; such a
    group's step here first waits for the helper to finish it, takes its new kernels into the cache
    and so loads rather than compiles them. What a helper does not deliver (it failed, or was
    stopped), this process compiles as it would have anyway. Once every registered warm-up has run
    without an error, the cache is marked COMPLETE.

    A helper compiles into a folder of its own, and only kernels this process has no file for are
    taken: numba names a kernel's cached versions by how many it had, so two processes writing the
    same kernel at once could give one version's name to another's code."""
    labels = [label for label, _ in steps]
    plan = [(at, [label for label in groups if label in labels]) for at, groups in helpers if at in labels]
    plan = [(at, groups) for at, groups in plan if groups and labels.index(at) < labels.index(groups[0])]
    if CACHE is None or not plan or (CACHE / COMPLETE).exists() or not _spare_cores():
        yield list(steps)
    else:
        started: list[_Helper] = []
        try:
            yield [(label, _helped_step(label, fn, plan, started, CACHE)) for label, fn in steps]
        finally:
            for helper in started:
                helper.close()
    if CACHE is not None and {label for label, _ in WARM_UPS} <= set(labels):
        with suppress(OSError):  # unmarked, the next launch starts a helper that loads rather than compiles
            (CACHE / COMPLETE).touch()


def _helped_step(label: str, fn: Callable[[], None], plan: list[tuple[str, list[str]]], started: list[_Helper],
                 cache: Path) -> Callable[[], None]:
    """Step `label`: start the helpers that start with it, wait for the one compiling it, then run it."""
    def step() -> None:
        started.extend(_Helper(groups, cache) for at, groups in plan if at == label)
        for helper in started:
            if label in helper.labels:
                helper.wait_for(label)
        fn()
    return step


def _spare_cores() -> bool:
    cores = os.sched_getaffinity(0) if hasattr(os, "sched_getaffinity") else range(os.cpu_count() or 1)
    return len(cores) > 1


class _Helper:
    """A process compiling warm-up groups (`help_compile`) into a copy of the cache of its own, and
    the delivery of what it compiled into this process's cache."""

    def __init__(self, labels: Sequence[str], cache: Path) -> None:
        self.labels, self.cache = list(labels), cache
        self.folder: Path | None = None
        self.done: list[str] = []
        self.proc: subprocess.Popen | None = None
        code = "import sys; from polygolf.engine.physics.jit import help_compile; help_compile(sys.argv[1:])"
        try:
            self.folder = Path(tempfile.mkdtemp(prefix=HELPER_FOLDER))
            shutil.copytree(cache, self.folder / cache.name)
            # It must compile these very sources: it gets this process's import path, and works in its
            # own folder (a `-c` process looks first in the folder it starts in, which could hold
            # another copy of the game).
            path = os.pathsep.join(entry or os.getcwd() for entry in sys.path)
            self.proc = subprocess.Popen([sys.executable, "-c", code, *self.labels], stdin=subprocess.DEVNULL,
                                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
                                         cwd=self.folder,
                                         env=dict(os.environ, NUMBA_CACHE_DIR=str(self.folder), PYTHONPATH=path))
        except OSError:  # no helper: this process compiles its groups too
            self.proc = None

    def close(self) -> None:
        if self.proc is not None:
            self.proc.kill()  # done by now, unless a step of this process failed
            self.proc.wait()
            self.proc.stdout.close()
        if self.folder is not None:
            shutil.rmtree(self.folder, ignore_errors=True)

    def wait_for(self, label: str) -> None:
        """Read the helper's lines (a label each, as it finishes a group) up to `label` or its end,
        then deliver what it has compiled."""
        while self.proc is not None and label not in self.done:
            line = self.proc.stdout.readline()
            if not line:  # it ended, or failed
                break
            self.done.append(line.strip())
        self.deliver()

    def deliver(self) -> None:
        """Copy into the cache each kernel the helper has cached and this process has not: its
        versions first, its index (which names them) last, each written whole before it is named."""
        if self.proc is None or self.folder is None:
            return
        theirs = self.folder / self.cache.name  # (kernels of other sources would be in another folder)
        for index in theirs.glob("*/*.nbi"):
            mine = self.cache / index.relative_to(theirs)
            if mine.exists():
                continue
            try:
                mine.parent.mkdir(parents=True, exist_ok=True)
                for path in [*index.parent.glob(f"{glob.escape(index.stem)}.*.nbc"), index]:
                    part = mine.parent / f".{path.name}.part"
                    shutil.copyfile(path, part)
                    os.replace(part, mine.parent / path.name)
            except OSError:  # (a full disk, say) not delivered: this process compiles it
                continue


def help_compile(labels: Sequence[str]) -> None:
    """A helper process (`helped`): the warm-up groups `labels` in order, a line on stdout after each."""
    steps = dict(kernel_steps())
    try:
        for label in labels:
            steps[label]()
            print(label, flush=True)
    except BrokenPipeError:  # the process it helped is gone (a window closed mid-compile): nobody takes this
        folder = Path(os.environ.get("NUMBA_CACHE_DIR", ""))
        if folder.name.startswith(HELPER_FOLDER):
            shutil.rmtree(folder, ignore_errors=True)
