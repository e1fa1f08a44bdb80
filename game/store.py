"""What the game keeps between launches, in SQLite (standard library) in the data folder: every finished
round with each player's card, the bests (worked out from those cards, so they can never disagree with
them), and the settings.

Nothing here may stop a round: a locked, unwritable or corrupted database costs one warning line (kept
in `warnings` for the screens, and printed to stderr) and the game goes on. A file that is not a
database is set aside as `polygolf.db.corrupt-<timestamp>`, never overwritten, and a fresh one is made.

Schema (version 1):

    meta(key PRIMARY KEY, value)                      schema version
    settings(key PRIMARY KEY, value)                  JSON values: theme, shape, course, players, volume, guide_seen
    rounds(id PRIMARY KEY, finished_at, course, course_name, shape, preset, players, complete, fingerprint, replay)
    cards(round_id, seat, name, strokes, par)         a player's totals for a round
    holes(round_id, seat, position, hole, name, par, strokes, penalties, picked_up)
"""

from __future__ import annotations

import json
import sqlite3
import sys
import time
from dataclasses import dataclass
from pathlib import Path

from polygolf.engine.loading.limits import MAX_ENTRIES, MAX_NAME
from polygolf.engine.loading.paths import data_dir, exclusive
from polygolf.game.record import utc_stamp

DB_NAME = "polygolf.db"
SCHEMA_VERSION = 1
LOCK_TIMEOUT = 2.0  # s to wait for another process's write before giving up on this one
# After a lock was met, for LOCK_BACKOFF s the calls a screen makes (settings, bests) wait only BRIEF_WAIT
# for it: each waited the whole LOCK_TIMEOUT on the window's thread (QA: a database held locked by
# another program froze the menu 2 s a click). A round is still waited for in full.
LOCK_BACKOFF, BRIEF_WAIT = 10.0, 0.05
# The settings are read once, at launch (before the window opens): a lock is waited for in full, up to
# this many times (QA8: a game launched while another saved began with the defaults).
SETTINGS_READS = 3

SCHEMA = """
CREATE TABLE IF NOT EXISTS meta (key TEXT PRIMARY KEY, value TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS settings (key TEXT PRIMARY KEY, value TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS rounds (
    id INTEGER PRIMARY KEY, finished_at TEXT NOT NULL, course TEXT NOT NULL, course_name TEXT NOT NULL,
    shape TEXT NOT NULL, preset TEXT NOT NULL, players INTEGER NOT NULL, complete INTEGER NOT NULL,
    fingerprint TEXT NOT NULL, replay TEXT);
CREATE TABLE IF NOT EXISTS cards (
    round_id INTEGER NOT NULL REFERENCES rounds(id), seat INTEGER NOT NULL, name TEXT NOT NULL,
    strokes INTEGER NOT NULL, par INTEGER NOT NULL, PRIMARY KEY (round_id, seat));
CREATE TABLE IF NOT EXISTS holes (
    round_id INTEGER NOT NULL REFERENCES rounds(id), seat INTEGER NOT NULL, position INTEGER NOT NULL,
    hole TEXT NOT NULL, name TEXT NOT NULL, par INTEGER NOT NULL, strokes INTEGER NOT NULL,
    penalties INTEGER NOT NULL, picked_up INTEGER NOT NULL, PRIMARY KEY (round_id, seat, position));
CREATE INDEX IF NOT EXISTS holes_best ON holes (hole, strokes);
"""
# The indexes a best of one hole or course is found by (QA8): made where they can be, when a game first
# opens the database; where they cannot (a read-only file, another game holding the write lock), the
# bests are worked out from the whole history as before, never not read.
INDEXES = {"holes_best_at": "holes (hole, position, strokes)", "cards_best": "cards (strokes)",
           "rounds_best": "rounds (course, shape, finished_at)"}


@dataclass(frozen=True, slots=True)
class Best:
    """The fewest strokes on a hole (or a whole course), with that shape, and who played them first."""

    course: str
    hole: str | None  # None: the whole course
    position: int | None
    name: str  # the hole's or course's name
    shape: str
    strokes: int
    par: int
    player: str
    when: str


# Columns a best is read from, with the type each must hold: SQLite keeps whatever is written, so a
# row edited by hand to another type is passed over rather than shown (or sorted, or subtracted) wrongly.
HOLE_TYPES = {"r.course": "text", "h.hole": "text", "h.position": "integer", "h.name": "text", "r.shape": "text",
              "h.strokes": "integer", "h.par": "integer", "h.penalties": "integer", "h.picked_up": "integer",
              "c.name": "text", "r.finished_at": "text"}
ROUND_TYPES = {"r.course": "text", "r.course_name": "text", "r.shape": "text", "c.strokes": "integer",
               "c.par": "integer", "c.name": "text", "r.finished_at": "text"}
# ... and the values a round can hold (a hole's strokes up to its most, 99; its par 1 to 20; a course of at
# most MAX_ENTRIES holes, its card the sum of its holes' rows): a row edited by hand to -3 strokes is no best.
MAX_STROKES, MAX_PAR = 99, 20
# Names (a player's, a hole's, a course's, a shape's) as long as a name may be (QA: a name of 100 000
# characters edited in froze the scorecard as it was cut to fit, and `scores` printed it whole).
_NAMED = " AND ".join(f"length({column}) BETWEEN 1 AND {MAX_NAME}" for column in ("c.name", "r.shape"))
HOLE_VALUES = (f"h.strokes BETWEEN 1 AND {MAX_STROKES} AND h.par BETWEEN 1 AND {MAX_PAR} AND h.position BETWEEN 0 AND "
               f"{MAX_ENTRIES - 1} AND h.penalties >= 0 AND h.picked_up IN (0, 1) AND {_NAMED} AND "
               f"length(h.name) BETWEEN 1 AND {MAX_NAME}")
ROUND_VALUES = (f"c.strokes BETWEEN 1 AND {MAX_STROKES * MAX_ENTRIES} AND c.par BETWEEN 1 AND {MAX_PAR * MAX_ENTRIES}"
                f" AND {_NAMED} AND length(r.course_name) BETWEEN 1 AND {MAX_NAME} AND (c.strokes, c.par) = "
                "(SELECT SUM(strokes), SUM(par) FROM holes WHERE holes.round_id = c.round_id AND holes.seat = c.seat)")
# (The same, with the ranges kept from the planner, which would take them for a search of the index
# over the equalities best_hole gives it.)
_INDEXED_HOLE_VALUES = HOLE_VALUES.replace("h.strokes BETWEEN", "+h.strokes BETWEEN").replace(
    "h.position BETWEEN", "+h.position BETWEEN")
_INDEXED_ROUND_VALUES = ROUND_VALUES.replace("c.strokes BETWEEN", "+c.strokes BETWEEN")
# Rows tied on a best above which who was first is found by walking the rounds in order, not by sorting them.
MANY_TIES = 200


_GONE = object()


def not_a_folder(folder: Path) -> str | None:
    """'X is a file, not a folder' when the data folder or one above it is a file, 'X is a link that
    leads nowhere' when it is a link to nothing or a loop of links (mkdir says only 'File exists')
    (else None)."""
    for place in (folder, *folder.parents):
        if place.is_symlink() and not place.exists():
            return f"{place} is a link that leads nowhere (to nothing, or round a loop of links)"
        if place.exists():
            return None if place.is_dir() else f"{place} is a file, not a folder"
    return None


def _typed(columns: dict[str, str]) -> str:
    return " AND ".join(f"typeof({column}) = '{kind}'" for column, kind in columns.items())


class OtherSchema(Exception):
    """The database was written by another version of the game (a newer one, as a rule)."""


class Store:
    """The database in `folder` (default: the data folder). Every method swallows storage trouble
    into `warnings` and returns what a fresh, empty store would."""

    def __init__(self, folder: Path | None = None, echo: bool = True) -> None:
        self.folder = folder if folder is not None else data_dir()
        self.path = self.folder / DB_NAME
        self.echo = echo
        self.warnings: list[str] = []
        # Whether the last call did its work: a damaged file set aside and its work done on a fresh one
        # did (with a warning); a database that could not be read at all did not.
        self.done = True
        self._locked_until = 0.0  # (time.monotonic(): until then, a lock is waited for briefly)
        self._indexed = False  # whether the last connection found every one of INDEXES
        # Settings chosen but not written yet (the database was locked): written with the next save,
        # or by `flush_settings` (the game's close), and read back over what the database holds.
        self.pending: dict[str, object] = {}

    def warn(self, message: str, again: bool = False) -> None:
        """One line on stderr, once: the same trouble on every menu click is said only the first time
        (unless `again`: a choice not saved is said each time)."""
        line = f"polygolf: {message}"
        if line in self.warnings and not again:
            return
        self.warnings.append(line)
        if self.echo:
            print(line, file=sys.stderr)

    # -- connection -------------------------------------------------------------------------------

    def _connect(self, write: bool, wait: float) -> sqlite3.Connection:
        """A connection inside a transaction: a write one (BEGIN IMMEDIATE: the lock is taken now or
        never), or a read one, which does not keep another game's writes waiting; another's lock is
        waited for `wait` s."""
        self.folder.mkdir(parents=True, exist_ok=True)
        db = sqlite3.connect(self.path, timeout=wait, isolation_level=None)
        try:
            db.executescript(SCHEMA)
            self._indexed = self._index(db)
            db.execute("BEGIN IMMEDIATE" if write else "BEGIN")
            row = db.execute("SELECT value FROM meta WHERE key = 'schema'").fetchone()
            if row is None:
                db.execute("INSERT INTO meta VALUES ('schema', ?)", (str(SCHEMA_VERSION),))
            elif row[0] != str(SCHEMA_VERSION):
                raise OtherSchema(f"{self.path} is written in schema version {row[0]}, this game reads "
                                  f"{SCHEMA_VERSION}: left as it is")
        except BaseException:
            db.close()
            raise
        return db

    def _index(self, db: sqlite3.Connection) -> bool:
        """Make the INDEXES not made yet (if the database can be written now); whether all are there."""
        made = {row[0] for row in db.execute("SELECT name FROM sqlite_master WHERE type = 'index'")}
        for name, on in INDEXES.items():
            if name not in made:
                try:
                    db.execute(f"CREATE INDEX IF NOT EXISTS {name} ON {on}")
                    made.add(name)
                except sqlite3.OperationalError:  # (read-only, or locked: another time)
                    pass
        return made >= set(INDEXES)

    def _identity(self) -> tuple[int, int] | None:
        """Which file the database is now (device and inode), None if there is none."""
        try:
            found = self.path.stat()
        except OSError:
            return None
        return found.st_dev, found.st_ino

    def _set_aside(self, why: str, damaged: tuple[int, int] | None) -> None:
        """Set the damaged file aside, if it is still the one at the database's path: another game may
        have found it damaged at the same time, set it aside first and begun a fresh one, which is not
        to be set aside in its turn (the lock file makes the look and the move one step for both)."""
        deadline = time.monotonic() + LOCK_TIMEOUT

        def waiting() -> None:  # (a game stopped while it held the lock must not hold this one for ever)
            if time.monotonic() > deadline:
                self.warn(f"{self.path} is damaged ({why}) and another game is setting it aside; nothing saved")
                raise OSError("the lock is held")

        with exclusive(self.path.with_name(DB_NAME + ".lock"), waiting):
            if damaged is None or self._identity() != damaged:
                return  # (gone already, or another game's fresh one: the work is tried again on it)
            stamp = time.strftime("%Y%m%d-%H%M%S")
            target = self.path.with_name(f"{DB_NAME}.corrupt-{stamp}")
            n = 1
            while target.exists():
                n += 1
                target = self.path.with_name(f"{DB_NAME}.corrupt-{stamp}-{n}")
            try:
                # Its journals first, while the damaged file still stands at the path (no game can begin
                # a fresh one there, whose journal this would take): left, one would be played into the
                # fresh database.
                for suffix in ("-journal", "-wal", "-shm"):
                    journal = self.path.with_name(DB_NAME + suffix)
                    if journal.exists():
                        journal.rename(target.with_name(target.name + suffix))
                self.path.rename(target)
            except OSError as exc:
                self.warn(f"{self.path} is damaged ({why}) and cannot be set aside ({exc.strerror}); nothing saved")
                raise
        self.warn(f"{self.path} was damaged ({why}); kept as {target.name}, starting a fresh one")

    def _transaction(self, work, default, what: str, write: bool = True, patient: bool = False,
                     again: bool = False):
        """Run `work(db)` in one transaction (`write`: one that writes); on trouble warn once (each
        time if `again`) and return `default` (and `done` is False). A damaged file is set aside and
        the work tried once more on a fresh one. A lock is waited for LOCK_TIMEOUT s, or BRIEF_WAIT s
        within LOCK_BACKOFF s of the last one met unless `patient`."""
        self.done = False
        warn = self.warn
        if again:
            def warn(message: str) -> None:
                self.warn(message, again=True)
        wait = LOCK_TIMEOUT if patient or time.monotonic() >= self._locked_until else BRIEF_WAIT
        for attempt in (1, 2):
            damage = None
            opened = self._identity()
            try:
                db = self._connect(write, wait)
            except sqlite3.OperationalError as exc:  # locked, unwritable folder or file
                self._met(exc)
                warn(f"cannot {what}: {self.path}: {exc}")
                return default
            except OtherSchema as exc:  # another version's: not damaged, and not this game's to change
                warn(f"cannot {what}: {exc}")
                return default
            except sqlite3.DatabaseError as exc:  # not a database, or a damaged one
                damage = exc
            except OSError as exc:
                warn(f"cannot {what}: {self.folder}: {not_a_folder(self.folder) or exc.strerror or exc}")
                return default
            if damage is None:
                try:
                    result = work(db)
                    db.execute("COMMIT")
                    self.done = True
                    self._locked_until = 0.0
                    return result
                except (sqlite3.OperationalError, sqlite3.IntegrityError) as exc:  # (a constraint refused it)
                    self._met(exc)
                    warn(f"cannot {what}: {self.path}: {exc}")
                    return default
                except sqlite3.DatabaseError as exc:
                    damage = exc
                finally:
                    try:
                        if db.in_transaction:
                            db.execute("ROLLBACK")
                    except sqlite3.Error:
                        pass  # a damaged file may refuse even this; closing drops the transaction
                    db.close()
            if attempt == 2:
                warn(f"cannot {what}: {self.path} is damaged ({damage})")
                return default
            try:
                self._set_aside(str(damage), opened)
            except OSError:
                return default
        return default

    def _met(self, exc: sqlite3.Error) -> None:
        """Note a lock met (SQLITE_BUSY or SQLITE_LOCKED): the next LOCK_BACKOFF s wait briefly."""
        if (getattr(exc, "sqlite_errorcode", 0) & 0xFF) in (5, 6) or "locked" in str(exc):  # (BUSY, LOCKED)
            self._locked_until = time.monotonic() + LOCK_BACKOFF

    # -- settings ---------------------------------------------------------------------------------

    def load_settings(self) -> dict[str, object]:
        """The settings kept (with any chosen since and not written yet over them). Read at launch: a
        lock is waited for in full, SETTINGS_READS times, before the defaults are taken."""
        def work(db: sqlite3.Connection) -> dict[str, object]:
            out = {}
            for key, value in db.execute("SELECT key, value FROM settings"):
                try:
                    out[key] = json.loads(value)
                except (ValueError, TypeError, RecursionError):  # not JSON, not text, nested too deep
                    continue  # one unreadable setting falls back to its default
            return out

        for _ in range(SETTINGS_READS):
            out = self._transaction(work, {}, "read the settings", write=False, patient=True)
            if self.done or time.monotonic() >= self._locked_until:  # (read, or trouble other than a lock)
                break
        return {**out, **self.pending}

    def save_settings(self, settings: dict[str, object]) -> bool:
        """Write these settings, with any an earlier save could not write (none is dropped: QA8, two
        games on one data folder lost clicks to 'database is locked'). When it cannot be written now,
        it is kept for the next save (or `flush_settings`), and a line says so each time."""
        self.pending.update(settings)
        return self.flush_settings(patient=False)

    def flush_settings(self, patient: bool = True) -> bool:
        """Write the settings not written yet (none: True); a lock waited for in full if `patient`."""
        if not self.pending:
            return True
        chosen = dict(self.pending)

        def work(db: sqlite3.Connection) -> bool:
            db.executemany("INSERT OR REPLACE INTO settings VALUES (?, ?)",
                           [(key, json.dumps(value)) for key, value in chosen.items()])
            return True

        if not self._transaction(work, False, "save the settings",
                                 patient=patient, again=True):
            return False
        for key, value in chosen.items():
            if self.pending.get(key, _GONE) is value:
                del self.pending[key]
        return True

    # -- rounds and bests -------------------------------------------------------------------------

    def save_round(self, round_, record, replay: Path | None) -> int | None:
        """Keep a finished round (a `session.Round` and its `record.RoundRecord`); its id, or None. It
        is stamped when it is kept, not when it began (its record's time): of equal scores the best
        is the one finished first, also when two windows play at once (QA: Ann's round, begun 2 s
        before Bob's and finished after it, took the tied best); in one second, the one kept first."""
        def work(db: sqlite3.Connection) -> int:
            cursor = db.execute(
                "INSERT INTO rounds (finished_at, course, course_name, shape, preset, players, complete, "
                "fingerprint, replay) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)",
                (utc_stamp(), round_.course.id, round_.course.name, record.shape_label, record.preset,
                 len(round_.players), int(round_.complete), record.fingerprint,
                 str(replay) if replay is not None else None))
            round_id = cursor.lastrowid
            holes = {h.position: h.hole for h in record.holes}
            for seat, name in enumerate(round_.players):
                db.execute("INSERT INTO cards VALUES (?, ?, ?, ?, ?)",
                           (round_id, seat, name, round_.total_strokes(seat), round_.total_par(seat)))
                db.executemany("INSERT INTO holes VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)",
                               [(round_id, seat, r.number - 1, holes.get(r.number - 1, ""), r.name, r.par,
                                 r.strokes, r.penalties, int(r.picked_up))
                                for r in round_.played(seat)])
            return round_id

        return self._transaction(work, None, "save the round", patient=True)

    def bests(self, course: str | None = None, shape: str | None = None) -> list[Best]:
        """Per hole and per whole course: the fewest strokes with each shape, the earliest first on a
        tie. Course bests count only rounds that played every hole."""
        return self._transaction(lambda db: _every_best(db, course, shape), [], "read the bests", write=False)

    def _every_best_of(self, db: sqlite3.Connection, course: str, shape: str, hole: str | None) -> Best | None:
        """Where the INDEXES are not there: the best from the whole history, as `bests` finds it."""
        return next((b for b in _every_best(db, course, shape) if b.hole == hole), None)

    def best_hole(self, course: str, hole: str, shape: str) -> Best | None:
        """The best `bests(course, shape)` gives for `hole` (the same row, by the same rules: the
        hole's first place in the course, the fewest strokes, the round finished first, then kept
        first, then the lower seat), found by the indexes rather than from the whole history: the
        screens ask on the window's thread (QA8: 3 s at 10 000 rounds). The place and strokes first
        (walking holes_best_at in order, stopping at the first row that holds), then who was first
        to them: among the rows of those strokes, or, when many tie, walking the rounds in the order
        they were finished (rounds_best) to the first that has one."""
        checks = f"{_typed(HOLE_TYPES)} AND {_INDEXED_HOLE_VALUES} AND r.course = ? AND r.shape = ?"
        tables = ("FROM holes h INDEXED BY holes_best_at JOIN rounds r ON r.id = h.round_id JOIN cards c "
                  "ON c.round_id = h.round_id AND c.seat = h.seat")
        by_round = ("FROM rounds r INDEXED BY rounds_best CROSS JOIN holes h CROSS JOIN cards c "
                    "ON h.round_id = r.id AND c.round_id = h.round_id AND c.seat = h.seat")

        def work(db: sqlite3.Connection) -> Best | None:
            if not self._indexed:
                return self._every_best_of(db, course, shape, hole)
            found = db.execute(f"SELECT h.position, h.strokes {tables} WHERE h.hole = ? AND {checks} "
                               "ORDER BY h.position, h.strokes LIMIT 1", (hole, course, shape)).fetchone()
            if found is None:
                return None
            ties = db.execute("SELECT COUNT(*) FROM holes INDEXED BY holes_best_at WHERE hole = ? AND position = ? "
                              "AND strokes = ?", (hole, *found)).fetchone()[0]
            row = db.execute(
                f"SELECT h.position, h.name, h.strokes, h.par, c.name, r.finished_at "
                f"{tables if ties <= MANY_TIES else by_round} WHERE h.hole = ? AND h.position = ? AND h.strokes = ? "
                f"AND {checks} ORDER BY r.finished_at, r.id, h.seat LIMIT 1", (hole, *found, course, shape)).fetchone()
            return Best(course, hole, row[0], row[1], shape, row[2], row[3], row[4], row[5])

        return self._transaction(work, None, "read the bests", write=False)

    def best_course(self, course: str, shape: str) -> Best | None:
        """The course's best `bests(course, shape)` gives (fewest strokes in a round that played every
        hole, the round finished first, kept first, the lower seat), found by the indexes: each card's
        strokes in turn from the fewest (cards_best), its checks (the card the sum of its holes) made
        only on the cards of those strokes, until one holds; when many tie, walking the rounds in
        the order they were finished (rounds_best)."""
        cheap = f"r.complete = 1 AND r.course = ? AND r.shape = ? AND {_typed(ROUND_TYPES)}"
        tables = "FROM cards c INDEXED BY cards_best JOIN rounds r ON r.id = c.round_id"
        by_round = "FROM rounds r INDEXED BY rounds_best CROSS JOIN cards c ON c.round_id = r.id"

        def work(db: sqlite3.Connection) -> Best | None:
            if not self._indexed:
                return self._every_best_of(db, course, shape, None)
            after = None
            while True:
                above = "" if after is None else " AND c.strokes > ?"
                found = db.execute(f"SELECT c.strokes {tables} WHERE {cheap}{above} ORDER BY c.strokes LIMIT 1",
                                   (course, shape, *(() if after is None else (after,)))).fetchone()
                if found is None:
                    return None
                ties = db.execute("SELECT COUNT(*) FROM cards INDEXED BY cards_best WHERE strokes = ?",
                                  found).fetchone()[0]
                row = db.execute(
                    f"SELECT r.course_name, c.strokes, c.par, c.name, r.finished_at "
                    f"{tables if ties <= MANY_TIES else by_round} WHERE {cheap} AND c.strokes = ? AND "
                    f"{_INDEXED_ROUND_VALUES} ORDER BY r.finished_at, r.id, c.seat LIMIT 1",
                    (course, shape, found[0])).fetchone()
                if row is not None:
                    return Best(course, None, None, row[0], shape, row[1], row[2], row[3], row[4])
                after = found[0]

        return self._transaction(work, None, "read the bests", write=False)

    def round_count(self) -> int:
        return self._transaction(lambda db: db.execute("SELECT COUNT(*) FROM rounds").fetchone()[0], 0,
                                 "count the rounds", write=False)


def _every_best(db: sqlite3.Connection, course: str | None, shape: str | None) -> list[Best]:
    """Every best (per hole, then per course) of `course` and `shape` (None: any), from the whole history."""
    where, args = [], []
    if course is not None:
        where.append("r.course = ?")
        args.append(course)
    if shape is not None:
        where.append("r.shape = ?")
        args.append(shape)
    cond = (" AND " + " AND ".join(where)) if where else ""
    out = []
    holes = db.execute(
        "SELECT r.course, h.hole, h.position, h.name, r.shape, h.strokes, h.par, c.name, r.finished_at "
        "FROM holes h JOIN rounds r ON r.id = h.round_id JOIN cards c ON c.round_id = h.round_id "
        f"AND c.seat = h.seat WHERE {_typed(HOLE_TYPES)} AND {HOLE_VALUES}{cond} "
        "ORDER BY r.course, h.position, r.shape, h.strokes, r.finished_at, r.id, h.seat", args).fetchall()
    seen = set()
    for row in holes:
        key = (row[0], row[1], row[4])
        if key not in seen:
            seen.add(key)
            out.append(Best(row[0], row[1], row[2], row[3], row[4], row[5], row[6], row[7], row[8]))
    rounds = db.execute(
        "SELECT r.course, r.course_name, r.shape, c.strokes, c.par, c.name, r.finished_at FROM cards c "
        f"JOIN rounds r ON r.id = c.round_id WHERE r.complete = 1 AND {_typed(ROUND_TYPES)} AND {ROUND_VALUES}"
        f"{cond} "
        "ORDER BY r.course, r.shape, c.strokes, r.finished_at, r.id, c.seat", args).fetchall()
    seen = set()
    for row in rounds:
        if (row[0], row[2]) not in seen:
            seen.add((row[0], row[2]))
            out.append(Best(row[0], None, None, row[1], row[2], row[3], row[4], row[5], row[6]))
    return out
