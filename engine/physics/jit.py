"""The engine's compiled kernels: numba's `njit` with one set of settings, and the list of kernels a
first launch compiles.

A kernel is written once, in the subset of Python numba compiles (numbers, numpy arrays, loops), and
runs compiled when numba is present. With `NUMBA_DISABLE_JIT=1`, or where numba is missing, the very
same function runs interpreted, which is how a test reaches a kernel line by line.

Settings: `cache=True` keeps the machine code on disk (next to the module, or numba's user cache
when that is read-only), so only the first launch compiles; no `fastmath`, so every operation is the
IEEE one the interpreted code would do and runs stay bit-for-bit repeatable.

Each kernel module registers a *warm-up*: a call with small, typical arguments that makes numba
compile (or load from the cache) every kernel it defines with the argument types the engine uses.
`compile_kernels` runs them all, reporting progress, before a window or a long command starts.
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable
from typing import TypeVar

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

WARM_UPS: list[tuple[str, Callable[[], None]]] = []


def kernel(fn: F) -> F:
    """Compile `fn` with the engine's settings (or leave it as it is without numba)."""
    if numba is None:
        return fn
    return numba.njit(cache=True, nogil=True)(fn)


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
    if progress is not None:
        progress(len(steps), len(steps), "ready")
    return time.perf_counter() - start
