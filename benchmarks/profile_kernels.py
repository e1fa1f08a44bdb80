"""Where a scenario's time goes, kernel by kernel: Linux `perf` samples the steady state of a run, and
the compiled kernels get their names (a profiling aid, not a test).

    python benchmarks/profile_kernels.py {100,1000,ball,fan} [--seconds 4] [--top 40] [--out perf.data]
    python benchmarks/profile_kernels.py {100,1000,ball,fan} --increfs 3000

numba's machine code has no symbols `perf` can see: a sample in it shows as a bare address. This
script writes `/tmp/perf-PID.map` (perf's map of JIT code) from the object code numba loads for each
kernel (from its cache or just compiled): every function in it, the kernels a kernel inlined
excepted, at the address it was loaded to; and numba's reference counting (`NRT_incref`,
`NRT_decref`: atomic operations, often a tenth of a frame). It records only after the warm-up
(`perf record -p` on this process while it steps), so loading and compiling are not in the profile.
Needs `perf` (Debian's linux-perf) and perf_event_paranoid <= 2. No call graph: numba's code keeps
no frame pointers, so the flat profile (`--no-children`) is what to read.

Who takes those references, then: `--increfs N` attaches gdb to the stepping process, stops at each of
the next N calls of numba's `NRT_incref` just long enough to read its return address, and counts them
by the kernel that called (a kernel that inlined a stage or a helper counts its references too).
Needs gdb and ptrace (root, or ptrace_scope 0).
"""

from __future__ import annotations

import argparse
import bisect
import math
import os
import re
import subprocess
import sys
import tempfile
import threading
from pathlib import Path

import numba.core.codegen as codegen

# Keep each library's object code as numba loads it (it drops it once loaded): the map is read from it.
_set_compiled_object = codegen.CPUCodeLibrary._set_compiled_object


def _keep_object(self: codegen.CPUCodeLibrary, value: bytes) -> None:
    self._profiled_object = value
    _set_compiled_object(self, value)


codegen.CPUCodeLibrary._set_compiled_object = _keep_object

sys.path.insert(0, str(Path(__file__).parent))
from bench_physics import pentagons_in_a_box  # noqa: E402
from bench_pymunk import HOLE, ball_on_hole  # noqa: E402

from polygolf.engine.golf.scenes import find_hole  # noqa: E402
from polygolf.engine.golf.shots import Shot, simulate_shots  # noqa: E402
from polygolf.engine.loading.scene import ShapeSpec, build_scene  # noqa: E402
from polygolf.engine.physics.jit import compile_kernels  # noqa: E402


def kernel_symbols() -> dict[int, tuple[int, str]]:
    """{address: (size, name)} of every function in the object code of every kernel loaded so far."""
    from numba.core.registry import CPUDispatcher
    from numba.core.runtime import nrt

    dispatchers = {id(v): v for m in list(sys.modules.values()) if getattr(m, "__name__", "").startswith("polygolf")
                   for v in vars(m).values() if isinstance(v, CPUDispatcher)}
    symbols: dict[int, tuple[int, str]] = {}
    for dispatcher in dispatchers.values():
        for compiled in dispatcher.overloads.values():
            library, entry = compiled.library, compiled.fndesc.llvm_func_name
            blob = getattr(library, "_profiled_object", None) or getattr(library, "_compiled_object", None)
            if not blob:
                continue
            with tempfile.NamedTemporaryFile(suffix=".o") as obj:
                obj.write(blob)
                obj.flush()
                listing = subprocess.run(["nm", "-S", "--defined-only", obj.name], capture_output=True,
                                         text=True).stdout
            functions = [(int(v, 16), int(s, 16), n) for v, s, t, n in
                         (line.split() for line in listing.splitlines() if len(line.split()) == 4) if t in "tTWw"]
            # One text section an object: its functions lie where the entry point lies, at their offsets.
            base = next((library.get_pointer_to_function(entry) - v for v, _, n in functions if n == entry), None)
            if base is not None:
                symbols.update({base + v: (s, n) for v, s, n in functions})
    runtime = nrt.rtsys._library
    found = sorted((runtime.get_pointer_to_function(fn.name), fn.name) for fn in runtime._final_module.functions
                   if not fn.is_declaration)
    found = [(address, name) for address, name in found if address]
    for (address, name), (following, _) in zip(found, [*found[1:], (found[-1][0] + 256, "")]):
        symbols.setdefault(address, (min(following - address, 256), f"numba-runtime:{name}"))
    return symbols


GDB_COUNTER = """
import bisect, collections, gdb
counts = collections.Counter()
class Caller(gdb.Breakpoint):
    def stop(self):
        counts[int(gdb.parse_and_eval("*(unsigned long*)$rsp"))] += 1
        return sum(counts.values()) >= LIMIT
Caller("*" + str(INCREF))
gdb.execute("continue", to_string=True)
with open(OUT, "w") as out:
    for address, count in counts.items():
        out.write(f"{address} {count}\\n")
"""


def readable(text: str) -> str:
    """numba's mangled kernel names in `text` as dotted names (`polygolf.engine.physics.toi._apart`)."""
    def dotted(match: re.Match) -> str:
        body, parts = match.group(1), []
        while body and body[0].isdigit():
            digits = re.match(r"\d+", body).group(0)
            size = int(digits)
            parts.append(body[len(digits):len(digits) + size])
            body = body[len(digits) + size:]
        return ".".join(parts)
    return re.sub(r"_ZN(?:7cpython)?((?:\d+\w+?)+)B\d+v\d+\S*", dotted, text)


def count_increfs(symbols: dict[int, tuple[int, str]], limit: int, top: int, step) -> None:
    """Attach gdb, count the callers of the next `limit` increfs (while this process steps), print them."""
    incref = next(address for address, (_, name) in symbols.items() if name == "numba-runtime:NRT_incref")
    with tempfile.TemporaryDirectory() as folder:
        script, out = Path(folder) / "count.py", Path(folder) / "counts.txt"
        script.write_text(f"LIMIT, INCREF, OUT = {limit}, {incref}, {str(out)!r}\n" + GDB_COUNTER)
        done = threading.Event()
        gdb = threading.Thread(target=lambda: (subprocess.run(
            ["gdb", "-q", "-batch", "-iex", "set auto-load safe-path /nonexistent", "-p", str(os.getpid()),
             "-x", str(script)], capture_output=True), done.set()))
        gdb.start()
        while not done.is_set():
            step()
        gdb.join()
        counts = [tuple(map(int, line.split())) for line in out.read_text().splitlines()] if out.exists() else []
    starts = sorted(symbols)
    callers: dict[str, int] = {}
    for address, count in counts:
        start = starts[max(bisect.bisect_right(starts, address) - 1, 0)]
        size, name = symbols[start]
        name = name if start <= address < start + size else "(outside the kernels)"
        callers[name] = callers.get(name, 0) + count
    total = sum(callers.values()) or 1
    print(f"{sum(c for _, c in counts)} increfs, by the kernel that called:")
    for name, count in sorted(callers.items(), key=lambda item: -item[1])[:top]:
        print(f"{100 * count / total:6.1f}%  {readable(name)[:120]}")


def scenario(name: str):
    """A function that steps the scenario a while, each call."""
    if name == "fan":
        hole = find_hole(HOLE, Path.cwd())
        shots = [Shot(hole.layout.tee, (2.4 * math.cos(2 * math.pi * k / 1000), 2.4 * math.sin(2 * math.pi * k / 1000)))
                 for k in range(1000)]
        return lambda: simulate_shots(hole, shots, "balanced", shape=ShapeSpec(regular=6, radius=1.0), max_seconds=3.0)
    scene = ball_on_hole() if name == "ball" else pentagons_in_a_box(int(name))
    sim = build_scene(scene, "balanced")
    sim.step(30, measure=False)
    return lambda: sim.step(10, measure=False)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scenario", choices=["100", "1000", "ball", "fan"])
    parser.add_argument("--seconds", type=float, default=4.0, help="how long perf records")
    parser.add_argument("--top", type=int, default=40, help="how many symbols to show")
    parser.add_argument("--out", default="perf.data", help="perf's data file")
    parser.add_argument("--increfs", type=int, default=0, help="count the callers of this many increfs (gdb)")
    args = parser.parse_args()
    compile_kernels()
    step = scenario(args.scenario)
    step()  # warm: first calls, first allocations
    symbols = kernel_symbols()
    Path(f"/tmp/perf-{os.getpid()}.map").write_text("".join(
        f"{address:x} {size:x} {name}\n" for address, (size, name) in sorted(symbols.items())))
    if args.increfs:
        count_increfs(symbols, args.increfs, args.top, step)
        return
    done = threading.Event()
    recorder = threading.Thread(target=lambda: (subprocess.run(
        ["perf", "record", "-q", "-p", str(os.getpid()), "-o", args.out, "--", "sleep", str(args.seconds)]),
        done.set()))
    recorder.start()
    while not done.is_set():
        step()
    recorder.join()
    report = subprocess.run(["perf", "report", "-i", args.out, "--no-children", "--sort", "sym", "-g", "none"],
                            capture_output=True, text=True).stdout
    rows = [line for line in report.splitlines() if line.strip() and not line.startswith("#")]
    for line in rows[:args.top]:
        print(readable(line)[:140])


if __name__ == "__main__":
    main()
