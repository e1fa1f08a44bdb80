"""Watching content files while a hole is played (`polygolf play FILE.yaml --watch`)."""

from __future__ import annotations

import os
import threading
from pathlib import Path
from typing import TYPE_CHECKING

import watchfiles

from polygolf.engine.golf.holes import load_hole_file
from polygolf.engine.loading.yamlsource import ContentError

if TYPE_CHECKING:  # (the watcher itself needs no window: importing the screens imports arcade.gui)
    from polygolf.game.flow import ScreenFlow


class FileWatcher:
    """Watches some files from a thread (watchfiles) and says whether any changed since last asked.

    Their folders are watched, and those folders' own folders for the folders themselves: a folder
    deleted or renamed and made again (a `git checkout`, a sync tool) is watched anew (QA: watching
    the old one's inode, the watch saw no save again, and said nothing). A file is known by its path
    as given as well as by where it leads, so a file made a link to itself, or to nothing, is a change
    the reload then names (QA: those were passed over in silence)."""

    def __init__(self, *paths: Path) -> None:
        given = {Path(os.path.abspath(p)) for p in paths}
        self.paths = given | {p.resolve() for p in paths}
        self._folders = {p.parent for p in given}
        self._changed = threading.Event()
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True, name="polygolf-watch")
        self._thread.start()

    def _run(self) -> None:
        while not self._stop.is_set():
            roots = self._roots()
            if not roots:  # (all gone: look again in a moment)
                self._stop.wait(0.2)
                continue
            try:
                # (woken every half second with no change, to see whether a folder came or went)
                for changes in watchfiles.watch(*roots, stop_event=self._stop, debounce=150, recursive=False,
                                                watch_filter=lambda _change, path: self._watched(path),
                                                rust_timeout=500, yield_on_timeout=True):
                    if changes:
                        self._changed.set()
                    if self._roots() != roots or any(Path(path) in self._folders for _, path in changes):
                        self._changed.set()  # a folder gone or made again: watch what is there now (a save
                        break  # into it may have come before the watch)
                else:
                    return  # (stopped)
            except (OSError, RuntimeError):  # a root gone as the watch began: look again
                self._stop.wait(0.2)

    def _roots(self) -> list[str]:
        """The watched files' folders and their folders, those that are there."""
        return sorted({str(f) for f in self._folders | {f.parent for f in self._folders} if f.is_dir()})

    def _watched(self, path: str) -> bool:
        """Whether a change is to a watched file or to one of their folders (another file that cannot
        be resolved, a link to itself say, is not one, and must not end the watching)."""
        if Path(path) in self.paths or Path(path) in self._folders:
            return True
        try:
            return Path(path).resolve() in self.paths
        except (OSError, RuntimeError):
            return False

    def changed(self) -> bool:
        """True once after each batch of changes."""
        if self._changed.is_set():
            self._changed.clear()
            return True
        return False

    def close(self) -> None:
        self._stop.set()


class HoleReloader:
    """Scheduled every few frames: when the hole file (or its library) changed, the flow plays the
    new version; a broken save is shown on the hole, and the last good version plays on."""

    def __init__(self, flow: ScreenFlow, path: Path, watcher: FileWatcher) -> None:
        self.flow, self.path, self.watcher = flow, path, watcher

    def __call__(self, _dt: float = 0.0) -> None:
        if not self.watcher.changed():
            return
        try:
            self.flow.replace_hole(0, load_hole_file(self.path))
        except ContentError as exc:
            if self.flow.playing is not None:
                self.flow.playing.show_banner(f"{exc}\n(the last good version plays on: fix it and save)", 30.0)
