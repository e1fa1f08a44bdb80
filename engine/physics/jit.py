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
per piece and per point. numba refuses to compile a leaf that makes an array.

Each kernel module registers a *warm-up*: a call with small, typical arguments that makes numba
compile (or load from the cache) every kernel it defines with the argument types the engine uses.
`compile_kernels` runs them all, reporting progress, before a window or a long command starts.
"""

from __future__ import annotations

import gc
import hashlib
import os
import shutil
import time
from collections.abc import Callable
from pathlib import Path
from typing import TypeVar

from platformdirs import user_cache_path

F = TypeVar("F", bound=Callable)

try:
    import numba
    import numba.typed
except ImportError:  # the same code, interpreted
    numba = None

# A list a kernel makes and keeps between calls: passing it costs one argument however much it holds
# (numba's typed list; a plain list where the code runs interpreted).
HeldList = numba.typed.List if numba is not None else list

COMPILED = numba is not None and os.environ.get("NUMBA_DISABLE_JIT", "0") in ("", "0")
ENGINE_DIR = Path(__file__).resolve().parents[1]
KEEP_CACHES = 3  # cache folders of different sources kept side by side (the current one among them)


# The engine's folders kernels and the constants they hold come from (the golf rules, assembly and
# loading have none, and no kernel imports from them: editing those compiles nothing).
KERNEL_SOURCES = ("physics", "systems", "components")


def engine_fingerprint(root: Path = ENGINE_DIR) -> str:
    """A digest of every source file of the engine's KERNEL_SOURCES folders under `root`, names
    and contents."""
    digest = hashlib.sha256()
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


if COMPILED:
    _base = os.environ.get("NUMBA_CACHE_DIR") or user_cache_path("polygolf", appauthor=False) / "kernels"
    try:
        numba.config.CACHE_DIR = str(cache_folder(Path(_base), engine_fingerprint()))
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


def inlined_kernel(fn: F) -> F:
    """A kernel numba inlines where another kernel calls it (a stage's kernel inside a run of
    stages): compiled once as part of its caller rather than once more on its own."""
    if numba is None:
        return fn
    return numba.njit(cache=True, nogil=True, inline="always")(fn)


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
    steps = kernel_steps()
    start = time.perf_counter()
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
