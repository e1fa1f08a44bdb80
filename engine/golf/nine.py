"""Random nine: a course of nine generated holes drawn from one seed, kept in the data folder.

Proving nine holes takes a while (the golfer plays each), so each hole is written as soon as it is
proven, to DATA/generated/nine-SEED/ (hole-1.yaml ... hole-9.yaml, then courses.yaml), with a
manifest, nine.json, saying what built them. The next time the same seed is asked for, the course is
loaded from there at once; a build stopped part-way goes on from the holes already written. A folder
built by another generator version or from another tile library is built again: a seed names a
course only for one generator and one library.

Hole k of seed S is `generate --seed S --hole k` proven at the same preset (`NINE_KNOBS`), so
friends with the same seed play the same holes.
"""

from __future__ import annotations

import hashlib
import json
import multiprocessing
import os
import random
from collections.abc import Callable, Iterator
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from pathlib import Path

from polygolf.engine.golf.generate import Prove, generate, golfer_proof, schema_ref
from polygolf.engine.golf.holes import RANDOM_NINE_ID, Course, load_courses, load_hole
from polygolf.engine.loading.course import TileLibrary, load_library
from polygolf.engine.loading.limits import MAX_FILE_BYTES
from polygolf.engine.loading.paths import data_dir, exclusive
from polygolf.engine.loading.yamlsource import ContentError, read_at_most

GENERATOR_VERSION = 1  # bump when the same seed would draw other holes
NINE = 9
NINE_KNOBS = "fast"  # the preset the holes are proven at (play is at any preset)
NINE_EFFORT = "quick"
COURSE_ID = RANDOM_NINE_ID  # the choice's name on the command line and in the settings
MAX_MANIFEST_BYTES = 1_000_000  # nine.json: a few hundred bytes as the game writes it
SEED_RANGE = (1, 99_999)  # new seeds are short enough to read out to a friend


class BuildCancelled(RuntimeError):
    """The build was asked to stop; the holes already written are kept for next time."""


def new_seed() -> int:
    """A fresh seed for a new course (not part of any hole's drawing, so not from a seeded stream)."""
    return random.SystemRandom().randint(*SEED_RANGE)


def course_id(seed: int) -> str:
    return f"{COURSE_ID}-{seed}"


def course_name(seed: int) -> str:
    return f"Random nine · seed {seed}"


def nine_folder(seed: int) -> Path:
    return data_dir() / "generated" / f"nine-{seed}"


def _library_key(library: TileLibrary) -> str:
    return hashlib.sha256(library.model_dump_json().encode()).hexdigest()[:16]


def _manifest(seed: int, library: TileLibrary) -> dict:
    return {"seed": seed, "generator": GENERATOR_VERSION, "library": _library_key(library), "knobs": NINE_KNOBS,
            "effort": NINE_EFFORT, "holes": {}}


def _read_manifest(folder: Path) -> dict | None:
    try:  # (as content files are read: a FIFO or a device in its place is not waited on or read for ever)
        text = read_at_most(folder / "nine.json", MAX_MANIFEST_BYTES)
        data = json.loads(text) if len(text) <= MAX_MANIFEST_BYTES else None
    except (OSError, ValueError, RecursionError):  # missing, not a file, not JSON, nested too deep
        return None
    return data if isinstance(data, dict) and isinstance(data.get("holes"), dict) else None


def _same_build(found: dict | None, wanted: dict) -> bool:
    return found is not None and all(found.get(k) == wanted[k] for k in wanted if k != "holes")


def _write(path: Path, text: str) -> None:
    """Whole or not at all: a build stopped mid-write leaves no half file (the part file is this
    process's own)."""
    part = path.with_name(f"{path.name}.{os.getpid()}.part")
    try:
        part.write_text(text, encoding="utf-8")
        os.replace(part, path)
    except OSError:
        part.unlink(missing_ok=True)  # (a full disk: nothing half written is left behind)
        raise


def _digest(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def _as_built(folder: Path, k: int, manifest: dict) -> bool:
    """Whether hole k's file is the one the build wrote (its digest in the manifest): a hole edited
    by hand since is built again, not played under the seed's name (QA: a par edited to 9 was
    played, and its rounds kept, as the seed's hole). A manifest written before the digests were
    kept vouches for its files as they are."""
    entry = manifest["holes"].get(str(k))
    if not isinstance(entry, dict):
        return False
    if "sha256" not in entry:
        return True
    try:
        data = read_at_most(folder / f"hole-{k}.yaml", MAX_FILE_BYTES)
    except OSError:
        return False
    return _digest(data) == entry["sha256"]


def _loads(path: Path, library: TileLibrary) -> bool:
    """Whether a hole built before is there and loads (one broken since is built again)."""
    try:
        load_hole(path, library)
    except (ContentError, OSError, ValueError):
        return False
    return True


def load_nine(seed: int, library: TileLibrary | None = None) -> Course | None:
    """The course of `seed` if it is fully built by this generator from this library and every hole
    loads; else None (then `build_nine`)."""
    library = library or load_library()
    folder = nine_folder(seed)
    manifest = _read_manifest(folder)
    if not _same_build(manifest, _manifest(seed, library)) or len(manifest["holes"]) < NINE \
            or not (folder / "courses.yaml").exists() or not all(_as_built(folder, k, manifest)
                                                                 for k in range(1, NINE + 1)):
        return None
    try:
        courses = load_courses(folder / "courses.yaml", library)
    except ContentError:
        return None
    if len(courses) != 1 or len(courses[0].playable) != NINE:
        return None
    course = courses[0]
    course.id = course_id(seed)  # not the name's: the name has a '·'
    return course


def _make_hole(job: tuple[int, int, TileLibrary, Prove | None, str]) -> tuple[int, str, dict]:
    """Hole k of the seed, drawn and proven (in a worker process when the golfer is the real one)."""
    seed, k, library, prove, schema = job
    made = generate(seed, library, number=k, prove=prove or golfer_proof(NINE_KNOBS, NINE_EFFORT), schema=schema)
    proof = made.proof
    return k, made.text, {"name": made.plan.name, "draw": made.plan.draw, "tiles": len(made.plan.tiles),
                          "par": made.plan.par if proof is None else int(proof.estimated_par),
                          "best_strokes": None if proof is None else proof.best_strokes,
                          "seconds": round(made.seconds, 2), "sha256": _digest(made.text.encode("utf-8"))}


def _made(jobs: list, workers: int, cancelled: Callable[[], bool]) -> Iterator[tuple[int, str, dict]]:
    """The holes as they are made: here one by one, or `workers` processes at a time (each a fresh
    interpreter, "spawn": nothing of a window or its threads is copied into it; a worker that dies
    is an error here, not a hang). Stopping kills the workers; a hole is only kept once it is whole."""
    if workers <= 1:
        for job in jobs:
            if cancelled():
                raise BuildCancelled(f"stopped before hole {job[1]} of {NINE}")
            yield _make_hole(job)
        return
    pool = ProcessPoolExecutor(max_workers=workers, mp_context=multiprocessing.get_context("spawn"))
    whole = False
    try:
        pending = {pool.submit(_make_hole, job) for job in jobs}
        while pending:
            finished, pending = wait(pending, timeout=0.1, return_when=FIRST_COMPLETED)
            for future in finished:
                yield future.result()
            if pending and cancelled():
                raise BuildCancelled("stopped")
        whole = True
    finally:
        if whole:
            pool.shutdown()
        else:
            _kill(pool)


def _kill(pool: ProcessPoolExecutor) -> None:
    """Stop the workers now, mid-proof (a proof can take many seconds)."""
    terminate = getattr(pool, "terminate_workers", None)  # Python 3.14
    if terminate is not None:
        terminate()
        return
    processes = list((getattr(pool, "_processes", None) or {}).values())
    pool.shutdown(wait=False, cancel_futures=True)
    for process in processes:
        process.terminate()
    for process in processes:
        process.join(5)


def build_nine(seed: int, *, library: TileLibrary | None = None, prove: Prove | None = None,
               progress: Callable[[int, int], None] | None = None,
               cancelled: Callable[[], bool] | None = None, workers: int | None = None,
               waiting: Callable[[], None] | None = None) -> Course:
    """The course of `seed`: from the data folder, else generated and proven, in `workers` processes
    at once (default: one a core for the real golfer; a given `prove`, here, unless `workers` says).
    `progress(k, 9)` says hole k is being made (k - 1 are done); `cancelled()` is asked while it
    works (then BuildCancelled; the holes finished are kept); `waiting()` is called once if another
    game is building the seed and this one waits for it. Raises GenerateError if a hole cannot be
    made, OSError if the data folder cannot be written."""
    library = library or load_library()
    cached = load_nine(seed, library)
    if cached is not None:
        return cached
    folder = nine_folder(seed)
    folder.mkdir(parents=True, exist_ok=True)
    cancelled = cancelled or (lambda: False)

    told = False

    def wait() -> None:
        nonlocal told
        if cancelled():
            raise BuildCancelled("stopped while another game built this seed")
        if not told and waiting is not None:
            waiting()
        told = True

    # One game builds a seed at a time: another that asks for it meanwhile (two friends on one machine)
    # waits, then loads what the first built, or goes on from the holes it finished.
    with exclusive(folder / ".building", wait):
        return _build_nine(seed, folder, library, prove, progress, cancelled, workers)


def _build_nine(seed: int, folder: Path, library: TileLibrary, prove: Prove | None,
                progress: Callable[[int, int], None] | None, cancelled: Callable[[], bool],
                workers: int | None) -> Course:
    """`build_nine`'s work, while it alone builds the seed."""
    cached = load_nine(seed, library)  # (another game may have built it while this one waited)
    if cached is not None:
        return cached
    wanted = _manifest(seed, library)
    manifest = _read_manifest(folder)
    if not _same_build(manifest, wanted):
        manifest = wanted
    schema = schema_ref(folder)
    todo = [k for k in range(1, NINE + 1) if not (_as_built(folder, k, manifest)
                                                  and _loads(folder / f"hole-{k}.yaml", library))]
    done = NINE - len(todo)
    workers = min(len(todo), workers or (1 if prove is not None else os.cpu_count() or 1))
    if todo and progress is not None:
        progress(done + 1, NINE)
    for k, text, entry in _made([(seed, k, library, prove, schema) for k in todo], workers, cancelled):
        _write(folder / f"hole-{k}.yaml", text)
        manifest["holes"][str(k)] = entry
        _write(folder / "nine.json", json.dumps(manifest, indent=1, sort_keys=True) + "\n")
        done += 1
        if done < NINE and progress is not None:
            progress(done + 1, NINE)
    holes = ", ".join(f"hole-{k}" for k in range(1, NINE + 1))
    _write(folder / "courses.yaml", f"# Random nine, seed {seed}: made by the game; delete the folder to build it "
                                    f"again.\ncourses:\n  - name: {course_name(seed)}\n    holes: [{holes}]\n")
    course = load_nine(seed, library)
    if course is None:
        raise ContentError(folder / "courses.yaml", 1, "courses", "the course just built does not load")
    return course
