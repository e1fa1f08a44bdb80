"""The `polygolf` command.

Window commands import arcade only when they run, so `simulate`, `validate` and `explain` work on a
machine with no display at all.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Sequence

from polygolf import __version__
from polygolf.engine.loading.paths import CONTENT_DIR
from polygolf.engine.loading.yamlsource import ContentError
from polygolf.engine.physics.presets import PRESETS

EXIT_CONTENT = 2


def _simulate(args: argparse.Namespace) -> int:
    from polygolf.engine.loading.scene import build_scene, load_scene

    scene = load_scene(args.scene)
    with build_scene(scene, args.preset) as sim:
        sim.run(args.seconds)
        report = sim.report()
    if args.json:
        print(json.dumps(report))
        return 0
    m = report["metrics"]
    print(f"{report['scene']}: {report['steps']} frames at {report['preset']} ({', '.join(report['systems'])})")
    for b in report["bodies"]:
        state = "at rest" if b["at_rest"] else f"v=({b['velocity'][0]:.4g}, {b['velocity'][1]:.4g}) m/s"
        print(f"  {b['name']}: at ({b['position'][0]:.4g}, {b['position'][1]:.4g}) m, "
              f"{b['angle']:.4g} deg, spin {b['spin']:.4g} rad/s, {state}")
    print(f"  max penetration {m['max_penetration']:.3g} m, max energy ratio {m['max_energy_ratio']}, "
          f"final {m['final_energy_ratio']}, {m['wall_ms']:.1f} ms")
    return 0


def _validate(args: argparse.Namespace) -> int:
    from polygolf.game.tools.validate import validate_paths

    count, problems = validate_paths(args.paths or [CONTENT_DIR])
    for problem in problems:
        print(problem, file=sys.stderr)
    print(f"{count} files checked, {len(problems)} problem{'s' if len(problems) != 1 else ''}")
    return 1 if problems else 0


def _window(run, *args) -> int:
    from polygolf.game.app import NoDisplay

    try:
        run(*args)
    except NoDisplay as exc:
        print(f"polygolf: {exc}", file=sys.stderr)
        return 1
    return 0


def _menu(args: argparse.Namespace) -> int:
    from polygolf.game.app import run_menu

    return _window(run_menu)


def _play(args: argparse.Namespace) -> int:
    from polygolf.game.app import run_play

    return _window(run_play, args.course, args.hole, args.theme, args.shape, args.preset)


def _render(args: argparse.Namespace) -> int:
    from pathlib import Path

    from polygolf.game.app import render_hole

    out = _window(render_hole, args.course, args.hole, args.theme, args.shape, Path(args.out))
    if out == 0:
        print(args.out)
    return out


def _bench_accuracy(args: argparse.Namespace) -> int:
    from pathlib import Path

    from polygolf.game.tools import accuracy

    cases = accuracy.all_cases(args.quick)
    if args.quick:
        settings = accuracy.sweep_settings(substeps=(1, 4, 16), iterations=(1, 8, 20))
    else:
        settings = accuracy.sweep_settings()
    rows = accuracy.measure(settings, repeats=args.repeats, workers=args.workers, quick=args.quick,
                            progress=not args.no_progress)
    effects = accuracy.effect_costs()
    command = "polygolf bench accuracy" + (" --quick" if args.quick else "") + f" --repeats {args.repeats}"
    paths = accuracy.write_report(rows, cases, Path(args.out), effects, command)
    for row in sorted((r for r in rows if r.preset), key=lambda r: r.cost_us):
        print(f"{row.preset:<9} {row.label:<18} error {row.error:.4f}  {row.cost_us / 1000:7.1f} ms per simulated s"
              f"  {'on' if row.on_front else 'OFF'} the front")
    print(f"{sum(r.on_front for r in rows)} of {len(rows)} settings on the Pareto front; wrote "
          + ", ".join(str(p) for p in paths.values()))
    return 0


def _explain(args: argparse.Namespace) -> int:
    from polygolf.game.tools.explain import explain

    print(explain(args.path, args.preset))
    return 0


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="polygolf", description="Mini golf with a polygon for a ball.")
    parser.add_argument("--version", action="version", version=f"polygolf {__version__}")
    sub = parser.add_subparsers(dest="command", description="with no command, the game opens at its menu")

    sim = sub.add_parser("simulate", help="run a physics scene headless and report the result")
    sim.add_argument("scene", help="scene YAML file")
    sim.add_argument("--seconds", type=float, default=2.0, help="simulated time (default 2)")
    sim.add_argument("--preset", choices=list(PRESETS), default=None,
                     help="accuracy preset (default: the scene's, else balanced)")
    sim.add_argument("--json", action="store_true", help="print one JSON object")
    sim.set_defaults(run=_simulate)

    play = sub.add_parser("play", help="play a hole of a course straight away")
    play.add_argument("--course", default="meadow", help="course name (default meadow)")
    play.add_argument("--hole", type=int, default=1, help="hole number (default 1)")
    play.add_argument("--theme", default=None, help="grass, sand, night ...")
    play.add_argument("--shape", default=None, help="pentagon, star-5-2, 7 (sides), random-SEED ...")
    play.add_argument("--preset", choices=list(PRESETS), default="balanced")
    play.set_defaults(run=_play)

    render = sub.add_parser("render", help="draw a hole to a PNG without a window")
    render.add_argument("course")
    render.add_argument("hole", type=int)
    render.add_argument("--theme", default=None)
    render.add_argument("--shape", default=None)
    render.add_argument("--out", required=True, help="PNG file to write")
    render.set_defaults(run=_render)

    val = sub.add_parser("validate", help="check content files (default: all of content/)")
    val.add_argument("paths", nargs="*", help="files or folders")
    val.set_defaults(run=_validate)

    bench = sub.add_parser("bench", help="measure what accuracy costs")
    bench_sub = bench.add_subparsers(dest="bench_command", required=True)
    acc = bench_sub.add_parser("accuracy", help="sweep the solver's knobs over hard cases and real shots; "
                                                "write a Markdown and CSV table and a plot")
    acc.add_argument("--out", default="docs", help="folder for accuracy.md, .csv and .png (default docs)")
    acc.add_argument("--repeats", type=int, default=3, help="timed runs per setting (median; default 3)")
    acc.add_argument("--quick", action="store_true", help="a coarse grid and five cases (about a minute)")
    acc.add_argument("--workers", type=int, default=2, help="processes, one a core (default 2)")
    acc.add_argument("--no-progress", action="store_true", help="no progress bar")
    acc.set_defaults(run=_bench_accuracy)

    exp = sub.add_parser("explain", help="list a scene's or hole's pipeline and why each system is in it")
    exp.add_argument("path", help="scene or hole YAML file, or COURSE:HOLE (meadow:3)")
    exp.add_argument("--preset", choices=list(PRESETS), default=None)
    exp.set_defaults(run=_explain)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    run = getattr(args, "run", _menu)
    try:
        return run(args)
    except ContentError as exc:
        print(f"polygolf: {exc}", file=sys.stderr)
        return EXIT_CONTENT
    except (KeyError, ValueError) as exc:  # unknown course, theme, shape, hole number
        print(f"polygolf: {exc.args[0] if exc.args else exc}", file=sys.stderr)
        return EXIT_CONTENT


if __name__ == "__main__":
    sys.exit(main())
