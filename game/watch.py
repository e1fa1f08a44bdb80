"""Watching content files while a hole is played (`polygolf play FILE.yaml --watch`)."""

from __future__ import annotations

import threading
from pathlib import Path
from typing import TYPE_CHECKING

import watchfiles

from polygolf.engine.golf.holes import load_hole_file
from polygolf.engine.loading.yamlsource import ContentError

if TYPE_CHECKING:  # (the watcher itself needs no window: importing the screens imports arcade.gui)
    from polygolf.game.flow import ScreenFlow


class FileWatcher:
    """Watches some files from a thread (watchfiles) and says whether any changed since last asked."""

    def __init__(self, *paths: Path) -> None:
        self.paths = {p.resolve() for p in paths}
        self._changed = threading.Event()
        self._stop = threading.Event()
        folders = sorted({str(p.parent) for p in self.paths})
        self._thread = threading.Thread(target=self._run, args=(folders,), daemon=True, name="polygolf-watch")
        self._thread.start()

    def _run(self, folders: list[str]) -> None:
        for _ in watchfiles.watch(*folders, stop_event=self._stop, debounce=150, recursive=False,
                                  watch_filter=lambda _change, path: self._watched(path)):
            self._changed.set()

    def _watched(self, path: str) -> bool:
        """Whether a change is to a watched file (another file in the folder that cannot be resolved, a
        link to itself say, is not one, and must not end the watching)."""
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
