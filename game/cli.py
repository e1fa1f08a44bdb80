"""The `polygolf` command.

Window commands import arcade only when they run, so `simulate`, `validate` and `explain` work on a
machine with no display at all.

A command that steps physics headless readies the compiled kernels first (`startup.prepare_physics`:
one stderr line while a first launch compiles them), after its arguments and content are checked, so
a mistake is reported at once and the compile is never timed as stepping. Window commands do it on
their loading screen; `schema`, `explain`, `scores` and `validate` without `--prove` never do it.
"""

from __future__ import annotations

import argparse
import importlib.util
import itertools
import json
import math
import os
import re
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import NoReturn

from polygolf import __version__
from polygolf.engine.golf.search import EFFORTS
from polygolf.engine.loading.limits import MAX_FILE_BYTES, MAX_SECONDS
from polygolf.engine.loading.paths import CONTENT_DIR, content_names, content_roots, misplaced_folders, named_file
from polygolf.engine.loading.yamlsource import ContentError, key_text, read_at_most
from polygolf.engine.physics.presets import PRESETS
from polygolf.game import startup

EXIT_CONTENT = 2
PROGRESS_AFTER = 2.0  # s of wall time before `simulate` shows its progress on a terminal


class Parser(argparse.ArgumentParser):
    """argparse that refuses a bad argument in one line (no usage block), exit status 2."""

    def error(self, message: str) -> NoReturn:
        """`polygolf: --option: why`, as the README writes it (argparse says `argument --option: why`)."""
        argument = re.fullmatch(r"argument ([^:]+): (.*)", message, re.DOTALL)
        self.exit(EXIT_CONTENT, f"polygolf: {argument[1].split('/')[-1]}: {argument[2]}\n" if argument else
                  f"{self.prog}: {message}\n")


def seconds_arg(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
    if not (math.isfinite(value) and 0.0 < value <= MAX_SECONDS):
        raise argparse.ArgumentTypeError(f"{text} is not in 0 < seconds <= {MAX_SECONDS:g}")
    if round(value * 60) < 1:  # (simulate steps whole frames: this would be none at all)
        raise argparse.ArgumentTypeError(f"{text} is less than a frame (1/60 s)")
    return value


def shape_arg(text: str) -> tuple[str, object]:
    from polygolf.game.shapes import parse_shape

    try:
        return parse_shape(text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def _whole(text: str) -> int | None:
    """A whole number written in ASCII digits (not `١٢` nor `²`, which `str.isdigit` takes), of at most
    20 of them (more is out of every option's range, and Python refuses to read 5,000); else None."""
    digits = text.strip()
    return int(digits) if re.fullmatch(r"[0-9]{1,20}", digits) else None


def _quoted(text: str) -> str:
    """An argument as an error quotes it, cut short (a 5,000-digit seed is not echoed whole)."""
    return repr(text) if len(text) <= 40 else repr(text[:40]) + "..."


def jobs_arg(text: str) -> int:
    if (value := _whole(text)) is None or not 1 <= value <= 64:
        raise argparse.ArgumentTypeError(f"{_quoted(text)} is not a number of processes from 1 to 64")
    return value


def players_arg(text: str) -> int:
    from polygolf.game.session import MAX_PLAYERS

    if (value := _whole(text)) is None or not 1 <= value <= MAX_PLAYERS:
        raise argparse.ArgumentTypeError(f"{_quoted(text)} is not a number of players from 1 to {MAX_PLAYERS}")
    return value


def names_arg(text: str) -> list[str]:
    """The players' names, each held to the rules the names screen holds them to (`session.player_name`:
    those of a course's name, and Unicode's composed form, so 'Ánn' typed either way is one name)."""
    from polygolf.game.session import MAX_NAME, MAX_PLAYERS, player_name

    names = [name.strip() for name in text.split(",")]
    if not 1 <= len(names) <= MAX_PLAYERS or not all(names):
        raise argparse.ArgumentTypeError(f"{text!r}: give 1 to {MAX_PLAYERS} names of 1 to {MAX_NAME} characters, "
                                         "separated by commas")
    taken = []
    for name in names:
        try:
            taken.append(player_name(name))
        except ValueError as exc:
            raise argparse.ArgumentTypeError(f"{name!r}: {exc}") from None
    if len(set(taken)) != len(taken):
        raise argparse.ArgumentTypeError(f"{text!r}: every player needs a different name")
    return taken


def player_names(players: int | None, names: list[str] | None) -> list[str] | None:
    """The names for `--players N [--names A,B]`; None: neither given (the saved choice)."""
    from polygolf.game.session import default_names

    if names is not None and players is not None and len(names) != players:
        raise ValueError(f"--names gives {len(names)} name{'s' if len(names) != 1 else ''} for --players {players}")
    if names is not None:
        return names
    return default_names(players) if players is not None else None


MAX_SEED = 2**63 - 1


def seed_arg(text: str) -> int:
    if (value := _whole(text)) is None or value > MAX_SEED:
        raise argparse.ArgumentTypeError(f"{_quoted(text)} is not a seed: a whole number from 0 to {MAX_SEED}")
    return value


def hole_number_arg(text: str) -> int:
    if (value := _whole(text)) is None or not 1 <= value <= 99:
        raise argparse.ArgumentTypeError(f"{_quoted(text)} is not a hole number from 1 to 99")
    return value


def yaml_arg(text: str) -> Path:
    if not text.lower().endswith((".yaml", ".yml")):
        raise argparse.ArgumentTypeError(f"{text!r} is not a .yaml file")
    return Path(text)


def skill_arg(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
    if not (math.isfinite(value) and 0.0 <= value <= 1.0):
        raise argparse.ArgumentTypeError(f"{text} is not a skill from 0 to 1")
    return value


def png_arg(text: str) -> Path:
    if not text.lower().endswith(".png"):
        raise argparse.ArgumentTypeError(f"{text!r} is not a .png file")
    return Path(text)


def finite_json(value):
    """The report with every non-finite number as null: `--json` is always strict JSON."""
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {k: finite_json(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [finite_json(v) for v in value]
    return value


def _simulate(args: argparse.Namespace) -> int:
    from polygolf.engine.golf.scenes import build_scene_file

    frames = round(args.seconds * 60)
    path = named_file(args.scene, "scenes")
    if not path.exists() and len(path.parts) == 1 and not path.suffix:  # (a bare name that named no scene)
        raise KeyError(f"no scene {args.scene!r}: give a scene file, or one of {', '.join(content_names('scenes'))}")
    with build_scene_file(path, args.preset) as sim:
        startup.prepare_physics()
        started = time.perf_counter()
        shown = False
        for done in range(0, frames, 60):
            sim.step(min(60, frames - done))
            if sys.stderr.isatty() and time.perf_counter() - started > PROGRESS_AFTER:
                print(f"\rsimulate: {(done + 60) / 60:.0f} of {args.seconds:g} s", end="", file=sys.stderr)
                shown = True
        if shown:
            print(file=sys.stderr)
        report = finite_json(sim.report())
    if args.json:
        print(json.dumps(report, allow_nan=False))
        return 0
    m = report["metrics"]
    print(f"{report['scene']}: {report['steps']} frames at {report['preset']} ({', '.join(report['systems'])})")
    for b in report["bodies"]:
        state = "at rest" if b["at_rest"] else f"v=({b['velocity'][0]:.4g}, {b['velocity'][1]:.4g}) m/s"
        print(f"  {b['name']}: at ({b['position'][0]:.4g}, {b['position'][1]:.4g}) m, "
              f"{b['angle']:.4g} deg, spin {b['spin']:.4g} rad/s, {state}")
    ratios = [f"{ratio:.4g}" if ratio is not None else "n/a (started at rest)"
              for ratio in (m["max_energy_ratio"], m["final_energy_ratio"])]
    print(f"  max penetration {m['max_penetration']:.3g} m, max energy ratio {ratios[0]}, final {ratios[1]}, "
          f"{m['wall_ms']:.1f} ms")
    return 0


def _count(n: int, word: str) -> str:
    return f"{n} {word}{'' if n == 1 else 's'}"


def _validate(args: argparse.Namespace) -> int:
    from polygolf.game.tools.validate import validate_paths

    count, problems = validate_paths(args.paths or content_roots())
    if args.paths and not count:  # (a folder with no content in it: the wrong folder, not a clean one)
        print(f"polygolf: validate: no content files (*.yaml) in {', '.join(args.paths)}", file=sys.stderr)
        return EXIT_CONTENT
    if not args.paths:  # (the player's folders that are files: nothing in them was checked)
        problems = misplaced_folders("", "holes", "themes", "scenes") + problems
    for problem in problems:
        print(problem, file=sys.stderr)
    warnings = _prove_warnings(args.paths or content_roots(), {p.file for p in problems}) if args.prove else []
    for warning in warnings:
        print(warning, file=sys.stderr)
    extra = f", {_count(len(warnings), 'warning')}" if args.prove else ""
    print(f"{_count(count, 'file')} checked, {_count(len(problems), 'problem')}{extra}")
    return 1 if problems else 0


def _prove_warnings(paths, broken: set[str]) -> list[str]:
    """`validate --prove`: each valid hole file proven by the search golfer; its doubts as warnings."""
    from polygolf.engine.golf.holes import load_hole_file
    from polygolf.engine.loading.yamlsource import line_of, load_yaml
    from polygolf.game.tools.par import launches, prove_all, warnings_for
    from polygolf.game.tools.validate import _kind, content_files

    files = [f for f in content_files(paths) if _kind(f) == "hole" and str(f) not in broken]
    holes = {}
    for f in files:
        try:
            holes[f] = load_hole_file(f)
        except ContentError:
            continue  # (its library is broken: validate reports that file)
    files = [f for f in holes if not launches(holes[f])]  # (nobody plays a collision test: no par to prove)
    if files:
        startup.prepare_physics()
    proofs = prove_all([holes[f] for f in files])
    out = []
    for path, proof in zip(files, proofs):
        line = line_of(("par",), load_yaml(path)[1])
        out += [f"{path}:{line}: par: warning: {text}" for text in warnings_for(proof)]
    return out


def _par(args: argparse.Namespace) -> int:
    """The search golfer proves each hole and estimates its par; exit 1 if any hole is in doubt."""
    from polygolf.game.tools.par import holes_named, prove_all, table, warnings_for

    holes, broken, passed_over = holes_named(args.target)
    for problem in [*broken, *passed_over]:
        print(f"polygolf: skipped: {problem}", file=sys.stderr)
    tty = sys.stderr.isatty() and not args.json
    if holes:
        startup.prepare_physics()

    def done(proof) -> None:
        if tty:
            print(f"proved {proof.hole} in {proof.seconds:.1f} s", file=sys.stderr)

    proofs = prove_all(holes, args.effort, args.preset, args.jobs, done)
    if args.json:
        print(json.dumps([p.row() | {"strokes": p.strokes, "seconds": round(p.seconds, 3), "shots": p.shots}
                          for p in proofs]))
    else:
        print(table(proofs) if proofs else "nothing to prove")
    doubts = [f"{p.hole}: {text}" for p in proofs for text in warnings_for(p)]
    for doubt in doubts:
        print(f"polygolf: {doubt}", file=sys.stderr)
    return 1 if doubts or broken else 0


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
    from polygolf.engine.golf.nine import NINE
    from polygolf.game.app import run_hole_file, run_play

    if args.file is not None:
        course_options = [f"--{name}" for name in ("course", "hole", "players", "names", "seed")
                          if getattr(args, name) is not None]
        if course_options:
            print(f"polygolf: {', '.join(course_options)}: a hole file is played alone, by one player (they are for "
                  "a course)", file=sys.stderr)
            return EXIT_CONTENT
        return _window(run_hole_file, args.file, args.theme, args.shape, args.preset, args.watch)
    args.course, args.hole = args.course or "meadow", 1 if args.hole is None else args.hole
    if args.watch:
        print("polygolf: --watch needs a hole file: polygolf play FILE.yaml --watch", file=sys.stderr)
        return EXIT_CONTENT
    if args.seed is not None and args.course != "random-nine":
        print("polygolf: --seed is for --course random-nine", file=sys.stderr)
        return EXIT_CONTENT
    if args.course == "random-nine" and args.hole is not None and args.hole > NINE:  # before minutes of building
        print(f"polygolf: random-nine has holes 1 to {NINE}", file=sys.stderr)
        return EXIT_CONTENT
    return _window(run_play, args.course, args.hole, args.theme, args.shape, args.preset,
                   player_names(args.players, args.names), args.seed)


def _keep_aside(path: Path, text: str) -> Path | None:
    """An author's file about to be written over with other text is renamed to FILE.bak first (or
    FILE.bak2, FILE.bak3...: a backup already there is kept too); returns that name, or None when
    nothing would be lost."""
    try:
        if read_at_most(path, MAX_FILE_BYTES).decode("utf-8", errors="replace") == text:
            return None
    except FileNotFoundError:
        return None
    for n in itertools.count(1):
        kept = path.with_name(f"{path.name}.bak{n if n > 1 else ''}")
        try:
            os.link(path, kept)  # (a name taken, even by another process meanwhile, is never written over)
        except FileExistsError:
            continue
        except OSError:  # no hard links here (FAT, say): a rename, to a name free a moment ago
            if kept.exists():
                continue
            path.rename(kept)
            return kept
        path.unlink()
        return kept
    raise AssertionError("unreachable")


def _generate(args: argparse.Namespace) -> int:
    """One procedural hole: drawn, loaded, proven by the search golfer (draws it cannot sink are
    refused), written with the golfer's par, and checked again as `validate` checks it."""
    from polygolf.engine.golf.generate import GenerateError, generate, golfer_proof, schema_ref
    from polygolf.engine.golf.holes import library_beside
    from polygolf.game.tools.validate import check_file

    started = time.perf_counter()
    out: Path = args.out
    try:
        out.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        print(f"polygolf: --out: cannot make the folder {out.parent}: {exc.strerror}", file=sys.stderr)
        return EXIT_CONTENT
    # Said now, not after the proof's minutes: a folder, a pipe or a device there (a FIFO would wait for a
    # reader for ever, /dev/zero never ends), or a read-only folder.
    if out.is_dir() or (out.exists() and not out.is_file()) or not os.access(out.parent, os.W_OK):
        why = "a folder" if out.is_dir() else "not a regular file" if out.exists() else "its folder is read-only"
        print(f"polygolf: --out: cannot write {out}: {why}", file=sys.stderr)
        return EXIT_CONTENT
    library = library_beside(out)  # the library `validate` and `play` will read it with
    startup.prepare_physics()
    print(f"polygolf: generating hole {args.hole} of seed {args.seed}, proving it at {args.preset}...",
          file=sys.stderr)
    try:
        made = generate(args.seed, library, number=args.hole, prove=golfer_proof(args.preset),
                        schema=schema_ref(out.parent),
                        progress=lambda line: print(f"polygolf: {line}", file=sys.stderr))
    except GenerateError as exc:
        print(f"polygolf: {exc}", file=sys.stderr)
        return 1
    try:
        kept = _keep_aside(out, made.text)
        out.write_text(made.text, encoding="utf-8")
    except OSError as exc:
        print(f"polygolf: --out: cannot write {out}: {exc.strerror or exc}", file=sys.stderr)
        return EXIT_CONTENT
    if kept is not None:
        print(f"polygolf: {out} held other text: it is kept as {kept}", file=sys.stderr)
    problems = check_file(out)
    for problem in problems:
        print(problem, file=sys.stderr)
    if problems:
        return 1
    proof = made.proof
    print(f"{out}: {made.plan.name}, {len(made.plan.tiles)} tiles, estimated par {proof.estimated_par} "
          f"(golfer's best {proof.best_strokes}), draw {made.plan.draw}, {time.perf_counter() - started:.1f} s")
    return 0


def _autoplay(args: argparse.Namespace) -> int:
    """The search golfer plays a whole round headless (every shot searched with the round's own physics,
    at `--skill`); saved and recorded like any round."""
    import random

    from polygolf.engine.golf.holes import Hole, find_course
    from polygolf.game.app import build_nine_here
    from polygolf.game.golfer_process import answer, origin_of, question_for
    from polygolf.game.session import RANDOM_NINE, Game, par_text, strokes_text, unplayable
    from polygolf.game.tools.par import LAUNCHES, launches

    game = Game.load()
    if args.seed is not None and args.course != RANDOM_NINE:
        raise ValueError("--seed is for --course random-nine")
    if args.course == RANDOM_NINE:
        game.choose_random_nine(args.seed)
        course = game.random_nine or build_nine_here(game.random_seed)
    elif not game.courses:
        raise ValueError(game.problems[0] if game.problems else "no course could be read")
    else:
        course = find_course(game.courses, args.course, game.course_problems)
    problem = unplayable(course)
    if problem is not None:  # (no round to play, save or record: said before anything is done)
        raise ValueError(problem)
    launched = [k for k, hole in enumerate(course.holes, 1) if isinstance(hole, Hole) and launches(hole)]
    if launched:
        raise ValueError(f"{course.name}: hole {launched[0]} {LAUNCHES}")
    for problem in course.holes:  # (the round plays on without them, as in the game: said here as `par` says it)
        if isinstance(problem, ContentError):
            print(f"polygolf: skipped: {problem}", file=sys.stderr)
    game.courses, game.course_index = [course], 0  # this round's course, not saved as the menu's choice
    game.players = player_names(args.players, args.names) or ["Golfer"]
    if args.shape is not None:
        game.shape_label, game.shape = args.shape
    game.preset = args.preset
    startup.prepare_physics()
    game.start_round()
    session = game.session
    rng = random.Random(0)  # the same round every time for the same arguments

    def plan(hole):
        shot = answer(question_for(hole, game.shape, args.skill, rng.randrange(2 ** 31), args.preset))
        return origin_of(shot), shot.arrow

    session.play_out(plan)
    replay = game.save_round(session)
    round_ = session.round
    for seat, name in enumerate(round_.players):
        total, par = round_.total_strokes(seat), round_.total_par(seat)
        cards = " ".join(str(r.strokes) if r.strokes is not None else "-" for r in round_.cards[seat])
        print(f"{name}: {strokes_text(total)} ({par_text(total - par)}) on {course.name}: {cards}")
    if replay is not None:
        print(f"replay: {replay}")
    return 0


def _scores(args: argparse.Namespace) -> int:
    from polygolf.game.session import escaped, strokes_text
    from polygolf.game.store import Store

    store = Store()
    # A course's id is its name in lower case, spaces as dashes: `--course "Meadow"` means meadow, and
    # "Random nine · seed 777" (as the scorecard names it) random-nine-777.
    wanted = args.course
    if wanted is not None:
        nine = re.fullmatch(r"random[ -]nine[ ·-]+(?:seed[ -]*)?(\d+)", wanted.strip(), re.IGNORECASE)
        wanted = f"random-nine-{nine.group(1)}" if nine else wanted.lower().replace(" ", "-")
    bests = store.bests(wanted)
    if not bests and wanted is not None and not re.fullmatch(r"random-nine-\d+", wanted):
        from polygolf.engine.golf.holes import find_course, load_all_courses

        courses, unread = load_all_courses()
        find_course(courses, wanted, unread)  # (a course nobody knows is a mistyped name, not one without rounds)
    if not store.done:  # (the database could not be read: its warning on stderr says why)
        if not args.json:  # (with --json nothing on stdout: an empty list would say there are no rounds)
            print("no rounds could be read" + (f" on {escaped(args.course)}" if args.course else ""))
        return 1
    if args.json:  # (JSON escapes every control character itself)
        print(json.dumps([{"course": b.course, "hole": b.hole, "number": None if b.position is None else b.position + 1,
                           "name": b.name, "shape": b.shape, "strokes": b.strokes, "par": b.par, "player": b.player,
                           "when": b.when} for b in bests]))
        return 0
    if not bests:
        print("no rounds saved yet" + (f" on {escaped(args.course)}" if args.course else ""))
        return 0
    for b in sorted(bests, key=lambda b: (b.course, b.shape, b.position is None, b.position or 0)):
        # Text read back from the database, which a hand may have edited: escaped, never raw to the terminal.
        which = f"hole {b.position + 1}" if b.hole is not None else "course"
        where = f"{escaped(b.course)} {which} ({escaped(b.name)})"
        print(f"{where:<44} {escaped(b.shape):<14} {strokes_text(b.strokes):>11}, par {b.par:<3} {escaped(b.player)}, "
              f"{escaped(b.when[:10])}")
    return 0


def _replay(args: argparse.Namespace) -> int:
    from polygolf.game.record import ReplayError, engine
    from polygolf.game.replay import load_for_replay, verify

    try:
        record, course = load_for_replay(args.file)
    except ReplayError as exc:
        print(f"polygolf: {exc}", file=sys.stderr)
        return EXIT_CONTENT
    if not args.verify:
        from polygolf.game.app import run_replay

        return _window(run_replay, args.file)
    startup.prepare_physics()
    lines = []
    for line, same in verify(record, course):
        print(line, flush=True)  # as each hole is played: a long round says how it goes
        lines.append((line, same))
    ok = bool(lines) and all(same for _, same in lines) and len(lines) == len(record.holes)
    print(f"{args.file}: {'verified' if ok else 'does NOT match'}: {len(lines)} of {len(record.holes)} holes "
          "simulated again")
    if not ok and record.engine != engine():
        print(f"polygolf: {args.file} was recorded by another physics engine "
              f"({record.engine or 'from before replays kept it'}; this one {engine()}): it need not replay bit "
              "for bit", file=sys.stderr)
    return 0 if ok else 1


def _hole_number(course: str, hole: str) -> int:
    """`render`'s HOLE: a number as it is (the course says whether it has that hole), else a hole's name
    looked up as `par` and `explain` look up COURSE:HOLE (`scenes.find_hole`: an unknown one lists the
    course's holes, a broken one is its error); its number is where it first comes in its course."""
    from polygolf.engine.golf.holes import Hole, find_course, load_all_courses
    from polygolf.engine.golf.nine import COURSE_ID as RANDOM_NINE
    from polygolf.engine.golf.nine import NINE
    from polygolf.engine.golf.scenes import find_hole

    if re.fullmatch(r"\s*[0-9]{1,4}\s*", hole):
        return int(hole)
    if course == RANDOM_NINE:  # (built from a seed, not content: its holes go by number)
        raise ValueError(f"random-nine has holes 1 to {NINE}: give a number, not {hole!r}")
    found = find_hole(f"{course}:{hole}", Path.cwd())
    courses, unread = load_all_courses()
    return next(k for k, h in enumerate(find_course(courses, course, unread).holes, 1)
                if isinstance(h, Hole) and h.id == found.id)


def _render(args: argparse.Namespace) -> int:
    from polygolf.engine.golf.nine import NINE
    from polygolf.game.app import WINDOW_SIZE, render_hole

    try:
        args.out.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        print(f"polygolf: --out: cannot make the folder {args.out.parent}: {exc.strerror}", file=sys.stderr)
        return EXIT_CONTENT
    try:
        if args.seed is not None and args.course != "random-nine":
            raise ValueError("--seed is for random-nine")
        number = _hole_number(args.course, args.hole)
        if args.course == "random-nine" and not 1 <= number <= NINE:  # said before minutes of building
            raise ValueError(f"random-nine has holes 1 to {NINE}")
        out = _window(render_hole, args.course, number, args.theme, args.shape, args.out, WINDOW_SIZE, args.seed,
                      player_names(args.players, None))
    except OSError as exc:
        print(f"polygolf: --out: cannot write {args.out}: {exc.strerror or exc}", file=sys.stderr)
        return EXIT_CONTENT
    if out == 0:
        print(args.out)
    return out


def _bench_accuracy(args: argparse.Namespace) -> int:
    from pathlib import Path

    from polygolf.game.tools import accuracy

    missing = [name for name in ("matplotlib", *(() if args.no_progress else ("tqdm",)))
               if importlib.util.find_spec(name) is None]
    if missing:  # (said before minutes of sweeping, not after)
        print(f"polygolf: bench accuracy needs {' and '.join(missing)}: pip install 'polygolf[bench]'", file=sys.stderr)
        return EXIT_CONTENT
    cases = accuracy.all_cases(args.quick)
    startup.prepare_physics()
    if args.quick:
        settings = accuracy.sweep_settings(substeps=(1, 4, 16), iterations=(1, 8, 20))
    else:
        settings = accuracy.sweep_settings()
    workers = args.workers or os.cpu_count() or 1
    started = time.perf_counter()
    rows, effects = accuracy.sweep(settings, repeats=args.repeats, workers=workers, quick=args.quick,
                                   progress=not args.no_progress)
    minutes, seconds = divmod(round(time.perf_counter() - started), 60)
    command = "polygolf bench accuracy" + (" --quick" if args.quick else "") + f" --repeats {args.repeats}"
    took = (f"{minutes} min " if minutes else "") + f"{seconds} s with {workers} process{'es' if workers > 1 else ''}"
    paths = accuracy.write_report(rows, cases, Path(args.out), effects, command, took)
    for row in sorted((r for r in rows if r.preset), key=lambda r: r.cost_us):
        print(f"{row.preset:<9} {row.label:<18} error {row.error:.4f}  {row.cost_us / 1000:7.1f} ms per simulated s"
              f"  {'on' if row.on_front else 'OFF'} the front")
    print(f"{sum(r.on_front for r in rows)} of {len(rows)} settings on the Pareto front; wrote "
          + ", ".join(str(p) for p in paths.values()))
    return 0


def _schema(args: argparse.Namespace) -> int:
    from polygolf.game.tools.schema import schemas, write_schemas

    if args.out is None:
        print(json.dumps(schemas(), indent=2, sort_keys=True))
        return 0
    try:
        for path in write_schemas(Path(args.out)):
            print(path)
    except OSError as exc:
        print(f"polygolf: --out: cannot write {args.out}: {exc.strerror or exc}", file=sys.stderr)
        return EXIT_CONTENT
    return 0


def _explain(args: argparse.Namespace) -> int:
    from polygolf.game.tools.explain import explain

    print(explain(args.path, args.preset))
    return 0


def build_parser() -> argparse.ArgumentParser:
    parser = Parser(prog="polygolf", description="Mini golf with a polygon for a ball.")
    parser.add_argument("--version", action="version", version=f"polygolf {__version__}")
    sub = parser.add_subparsers(dest="command", description="with no command, the game opens at its menu")

    sim = sub.add_parser("simulate", help="run a physics scene headless and report the result")
    sim.add_argument("scene", help="scene YAML file, or a scene's name (pile)")
    sim.add_argument("--seconds", type=seconds_arg, default=2.0,
                     help=f"simulated time, 0 < s <= {MAX_SECONDS:g} (default 2)")
    sim.add_argument("--preset", choices=list(PRESETS), default=None,
                     help="accuracy preset (default: the scene's, else balanced)")
    sim.add_argument("--json", action="store_true", help="print one JSON object")
    sim.set_defaults(run=_simulate)

    play = sub.add_parser("play", help="play a hole of a course, or a hole file, straight away")
    play.add_argument("file", nargs="?", type=Path, default=None, help="a hole file to play on its own")
    play.add_argument("--watch", action="store_true", help="with a hole file: build it again each time it is saved")
    play.add_argument("--course", default=None, help="course name (default meadow)")
    play.add_argument("--hole", type=int, default=None, help="hole number (default 1)")
    play.add_argument("--theme", default=None, help="grass, sand, night ...")
    play.add_argument("--shape", type=shape_arg, default=None, help="pentagon, star-5-2, 7 (sides), random-SEED ...")
    play.add_argument("--preset", choices=list(PRESETS), default="balanced")
    play.add_argument("--players", type=players_arg, default=None, help="1 to 4 players taking turns (default: as "
                                                                          "chosen last in the menu)")
    play.add_argument("--names", type=names_arg, default=None, help="the players' names: Ann,Bob")
    play.add_argument("--seed", type=seed_arg, default=None, help="with --course random-nine: the course's seed "
                                                                  "(default: the one chosen last)")
    play.set_defaults(run=_play)

    gen = sub.add_parser("generate", help="a procedural hole: valid, proven sinkable by the golfer, par estimated")
    gen.add_argument("--seed", type=seed_arg, required=True, help="the same seed gives the same hole")
    gen.add_argument("--out", type=yaml_arg, required=True, help="hole file to write (folders are made)")
    gen.add_argument("--hole", type=hole_number_arg, default=1,
                     help="which hole of the seed (default 1; Random nine's hole k is --hole k)")
    gen.add_argument("--preset", choices=list(PRESETS), default="fast",
                     help="the preset the golfer proves it at (default fast, as Random nine)")
    gen.set_defaults(run=_generate)

    auto = sub.add_parser("autoplay", help="the search golfer plays a round headless; saved and recorded")
    auto.add_argument("--course", default="meadow", help="course name (default meadow)")
    auto.add_argument("--players", type=players_arg, default=None, help="1 to 4 golfers taking turns (default 1)")
    auto.add_argument("--names", type=names_arg, default=None, help="their names: Ann,Bob")
    auto.add_argument("--preset", choices=list(PRESETS), default="balanced")
    auto.add_argument("--shape", type=shape_arg, default=None, help="pentagon, star-5-2, random-SEED ...")
    auto.add_argument("--seed", type=seed_arg, default=None, help="with --course random-nine: the course's seed")
    auto.add_argument("--skill", type=skill_arg, default=1.0,
                      help="how well it aims, 0 (about 7 degrees and 20%% of power astray) to 1 (exact, the default)")
    auto.set_defaults(run=_autoplay)

    scores = sub.add_parser("scores", help="the bests kept: per hole and per course, for each ball shape")
    scores.add_argument("--course", default=None, help="only this course (its id: meadow, hazards ...)")
    scores.add_argument("--json", action="store_true", help="one JSON list")
    scores.set_defaults(run=_scores)

    rep = sub.add_parser("replay", help="show a recorded round; --verify simulates it again headless")
    rep.add_argument("file", type=Path, help="a replay file (replays/*.json in the data folder)")
    rep.add_argument("--verify", action="store_true", help="exit 0 only if every hole ends bit for bit as recorded")
    rep.set_defaults(run=_replay)

    render = sub.add_parser("render", help="draw a hole to a PNG without a window")
    render.add_argument("course")
    render.add_argument("hole", help="its number, or its name (its file's, as `par COURSE:HOLE` takes it: castle)")
    render.add_argument("--theme", default=None)
    render.add_argument("--shape", type=shape_arg, default=None)
    render.add_argument("--out", type=png_arg, required=True, help="PNG file to write (folders are made)")
    render.add_argument("--seed", type=seed_arg, default=None, help="with random-nine: the course's seed")
    render.add_argument("--players", type=players_arg, default=None,
                        help="1 to 4 balls across the tee (default: as chosen last in the menu)")
    render.set_defaults(run=_render)

    val = sub.add_parser("validate", help="check content files (default: the shipped and your own content)")
    val.add_argument("paths", nargs="*", help="files or folders")
    val.add_argument("--prove", action="store_true",
                     help="also let the search golfer play each valid hole; warn if it cannot sink it or its par "
                          "is off by more than one (some seconds for all the shipped holes)")
    val.set_defaults(run=_validate)

    par = sub.add_parser("par", help="the search golfer proves each hole can be sunk and estimates its par")
    par.add_argument("target", help="a course (meadow), COURSE:N (meadow:9) or a hole file")
    par.add_argument("--json", action="store_true", help="one JSON list: a row per hole")
    par.add_argument("--effort", choices=list(EFFORTS), default="quick", help="how hard it searches (default quick)")
    par.add_argument("--preset", choices=list(PRESETS), default="fast", help="physics preset (default fast)")
    par.add_argument("--jobs", type=jobs_arg, default=None, help="processes (default: one a core)")
    par.set_defaults(run=_par)

    bench = sub.add_parser("bench", help="measure what accuracy costs")
    bench_sub = bench.add_subparsers(dest="bench_command", required=True)
    acc = bench_sub.add_parser("accuracy", help="sweep the solver's knobs over hard cases and real shots; "
                                                "write a Markdown and CSV table and a plot")
    acc.add_argument("--out", default="docs", help="folder for accuracy.md, .csv and .png (default docs)")
    acc.add_argument("--repeats", type=int, default=3, help="timed runs per setting (median; default 3)")
    acc.add_argument("--quick", action="store_true", help="a coarse grid and five cases (about a minute)")
    acc.add_argument("--workers", type=jobs_arg, default=None, help="processes (default: one a core)")
    acc.add_argument("--no-progress", action="store_true", help="no progress bar")
    acc.set_defaults(run=_bench_accuracy)

    sch = sub.add_parser("schema", help="JSON Schema for every kind of content file (for editors)")
    sch.add_argument("--out", default=None, help="folder for hole/tiles/courses/theme/scene.schema.json "
                                                 "(default: one JSON object on standard output)")
    sch.set_defaults(run=_schema)

    exp = sub.add_parser("explain", help="list a scene's or hole's pipeline and why each system is in it")
    exp.add_argument("path", help="scene or hole YAML file or name (pile, straight), or COURSE:HOLE (meadow:3)")
    exp.add_argument("--preset", choices=list(PRESETS), default=None)
    exp.set_defaults(run=_explain)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    run = getattr(args, "run", _menu)
    if os.environ.get("POLYGOLF_CONTENT") and not (CONTENT_DIR / "holes").is_dir():
        print(f"polygolf: POLYGOLF_CONTENT: {CONTENT_DIR} is not a content folder (no holes/ in it)", file=sys.stderr)
        return EXIT_CONTENT
    try:
        return run(args)
    except ContentError as exc:
        print(f"polygolf: {exc}", file=sys.stderr)
        return EXIT_CONTENT
    except UnicodeError as exc:  # (a ValueError whose first word is only the codec's name)
        print(f"polygolf: {exc.reason}: {exc.object[exc.start:exc.end]!r} is not text ({exc.encoding})"
              if isinstance(exc, (UnicodeEncodeError, UnicodeDecodeError)) else f"polygolf: {exc}", file=sys.stderr)
        return EXIT_CONTENT
    except (KeyError, ValueError) as exc:  # unknown course, theme, shape, hole number
        print(f"polygolf: {exc.args[0] if exc.args else exc}", file=sys.stderr)
        return EXIT_CONTENT
    except KeyboardInterrupt:  # Ctrl-C: what was finished is kept (a Random nine's holes built so far)
        print("polygolf: stopped", file=sys.stderr)
        return 130
    except BrokenPipeError:
        # The reader went away (`polygolf simulate ... | head`): stop quietly, as command-line tools do.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except OSError as exc:  # a path the system refuses to look at (a name longer than it allows)
        name = key_text(exc.filename) if exc.filename is not None else ""
        print(f"polygolf: {name + ': ' if name else ''}{exc.strerror or exc}", file=sys.stderr)
        return EXIT_CONTENT


if __name__ == "__main__":
    sys.exit(main())
