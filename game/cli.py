"""The `polygolf` command.

Window commands import arcade only when they run, so `simulate`, `validate` and `explain` work on a
machine with no display at all.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Sequence

from engine.presets import PRESETS

EXIT_CONTENT = 2


def _simulate(args: argparse.Namespace) -> int:
    from engine.pipeline import build_scene
    from engine.scene import load_scene

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


def _explain(args: argparse.Namespace) -> int:
    from engine.explain import explain

    print(explain(args.path, args.preset))
    return 0


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="polygolf", description="Mini golf with a polygon for a ball.")
    sub = parser.add_subparsers(dest="command")

    sim = sub.add_parser("simulate", help="run a physics scene headless and report the result")
    sim.add_argument("scene", help="scene YAML file")
    sim.add_argument("--seconds", type=float, default=2.0, help="simulated time (default 2)")
    sim.add_argument("--preset", choices=list(PRESETS), default=None,
                     help="accuracy preset (default: the scene's, else balanced)")
    sim.add_argument("--json", action="store_true", help="print one JSON object")
    sim.set_defaults(run=_simulate)

    exp = sub.add_parser("explain", help="list a scene's or hole's pipeline and why each system is in it")
    exp.add_argument("path", help="scene YAML file, or COURSE:HOLE")
    exp.add_argument("--preset", choices=list(PRESETS), default=None)
    exp.set_defaults(run=_explain)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    from engine.yamlsource import ContentError

    parser = build_parser()
    args = parser.parse_args(argv)
    if args.command is None:
        parser.print_help()
        return 0
    try:
        return args.run(args)
    except ContentError as exc:
        print(f"polygolf: {exc}", file=sys.stderr)
        return EXIT_CONTENT


if __name__ == "__main__":
    sys.exit(main())
