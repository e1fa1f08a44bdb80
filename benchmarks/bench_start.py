"""How long a launch waits for the physics engine's compiled kernels (a benchmark script, not a test;
no display needed):

- cold: a fresh numba cache folder (NUMBA_CACHE_DIR), so every kernel is compiled, as on a first launch;
- warm: the same folder again, so every kernel is loaded from the cache, as on every later launch;
- `polygolf simulate SCENE` of one frame, cold and warm: from starting the process to its first
  simulated frame (the process ends right after it).

Each is a new Python process (imports included), the median over --repeats. NUMBA_CACHE_DIR moves the
cache (`jit`: the user cache folder otherwise) to a temporary folder, so the cold runs are really cold
and the developer's cache is left alone.

    python benchmarks/bench_start.py [--repeats 3] [--scene content/scenes/flat-wall.yaml]
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
COMPILE = "from polygolf.engine.physics.jit import compile_kernels; print(compile_kernels())"


def run(args: list[str], cache: Path) -> tuple[float, str]:
    """Seconds from starting the process to its end, and its stdout (it must succeed)."""
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache))
    env.pop("NUMBA_DISABLE_JIT", None)
    started = time.perf_counter()
    result = subprocess.run([sys.executable, *args], capture_output=True, text=True, env=env, timeout=600)
    seconds = time.perf_counter() - started
    if result.returncode != 0:
        sys.exit(f"bench_start: {' '.join(args)} failed:\n{result.stderr}")
    return seconds, result.stdout


def measure(repeats: int, scene: Path) -> dict[str, list[tuple[float, float | None]]]:
    """Per row: (process seconds, seconds inside it) for each repeat, each with its own cache folder."""
    one_frame = ["-m", "polygolf", "simulate", str(scene), "--seconds", f"{1 / 60:.6f}", "--json"]
    rows: dict[str, list[tuple[float, float | None]]] = {
        "cold: compile every kernel": [], "warm: load them from the cache": [],
        f"simulate {scene.stem}, 1 frame, cold": [], f"simulate {scene.stem}, 1 frame, warm": []}
    names = list(rows)
    for k in range(repeats):
        with tempfile.TemporaryDirectory(prefix="numba-cold-") as folder:
            cache = Path(folder)
            for name in names[:2]:
                seconds, out = run(["-c", COMPILE], cache)
                rows[name].append((seconds, float(out.strip())))
        with tempfile.TemporaryDirectory(prefix="numba-cold-") as folder:
            cache = Path(folder)
            for name in names[2:]:
                seconds, out = run(one_frame, cache)
                rows[name].append((seconds, json.loads(out)["metrics"]["wall_ms"] / 1000))
        print(f"repeat {k + 1} of {repeats} done", file=sys.stderr)
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3, help="runs of each (median; default 3)")
    parser.add_argument("--scene", type=Path, default=ROOT / "content" / "scenes" / "flat-wall.yaml",
                        help="the scene `polygolf simulate` runs (default flat-wall)")
    args = parser.parse_args()
    rows = measure(max(1, args.repeats), args.scene)
    print(f"median of {args.repeats}, {os.cpu_count()} cores; process: from its start to its exit, imports included")
    print(f"{'':<40} {'process':>9}   inside")
    for name, runs in rows.items():
        process = statistics.median(r[0] for r in runs)
        inside = statistics.median(r[1] for r in runs if r[1] is not None)
        what = f"{inside:.3f} s compile_kernels" if "kernel" in name or "cache" in name else \
            f"{inside * 1000:.2f} ms stepping (wall_ms)"
        print(f"{name:<40} {process:>7.2f} s   {what}")

if __name__ == "__main__":
    main()
