"""Where content and user data live.

Content: the shipped package data (found with importlib.resources, so a wheel installed anywhere
finds it; an installed package is a folder on disk, not a zip), unless `POLYGOLF_CONTENT` points
elsewhere; then the player's own content folder, `DATA/content`, whose holes, courses and themes are
added to the shipped ones. User data (DATA): the platform's user data folder (platformdirs), unless
`POLYGOLF_DATA` points elsewhere.
"""

from __future__ import annotations

import os
import stat
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from importlib.resources import files
from pathlib import Path

from platformdirs import user_data_path

from polygolf.engine.loading.yamlsource import ContentError


def content_dir() -> Path:
    """The content root: `POLYGOLF_CONTENT` if set, else the installed `polygolf.content`."""
    override = os.environ.get("POLYGOLF_CONTENT")
    return Path(override) if override else Path(str(files("polygolf.content")))


CONTENT_DIR = content_dir()
HOLES_DIR = CONTENT_DIR / "holes"
THEMES_DIR = CONTENT_DIR / "themes"
SCENES_DIR = CONTENT_DIR / "scenes"


def data_dir() -> Path:
    """The player's data folder: `POLYGOLF_DATA` if set, else the platform's user data folder."""
    override = os.environ.get("POLYGOLF_DATA")
    return Path(override) if override else user_data_path("polygolf", appauthor=False)


def user_content_dir() -> Path:
    """The player's own content (holes/, themes/), added to the shipped content."""
    return data_dir() / "content"


def misplaced_folders(*names: str) -> list[ContentError]:
    """A problem for each of the player's content folders `names` (in `content`; "" is `content`
    itself) that is a file: nothing in it is read, which the game and `validate` say rather than
    pass over."""
    user = user_content_dir()
    return [ContentError(user / name, 0, "(file)", "a file where a folder belongs: nothing in it is read (make it "
                                                   "a folder)")
            for name in names if (user / name).exists() and not (user / name).is_dir()]


def content_roots() -> list[Path]:
    """Every content folder, shipped first; the player's only if it exists."""
    user = user_content_dir()
    return [CONTENT_DIR] + ([user] if user.is_dir() and user.resolve() != CONTENT_DIR.resolve() else [])


def named_file(arg: str | Path, folder: str) -> Path:
    """The content file a command line names: the path itself if it is there; else a bare name
    (`pile`, `pile.yaml`) in the content folders' `folder` (the player's first), or a path written
    from the source tree (`content/scenes/pile.yaml`) in the shipped content, as the README writes
    them; else the path as given (its loader says it is missing)."""
    path = Path(arg)
    if is_file(path) or path.is_absolute():
        return path
    if len(path.parts) == 1:
        name = path.name if path.suffix in (".yaml", ".yml") else f"{path.name}.yaml"
        for root in reversed(content_roots()):
            if is_file(root / folder / name):
                return root / folder / name
    elif path.parts and path.parts[0] == "content" and is_file(CONTENT_DIR.joinpath(*path.parts[1:])):
        return CONTENT_DIR.joinpath(*path.parts[1:])
    return path


def is_file(path: Path) -> bool:
    """`path.is_file()`, False where asking fails (a name longer than the system allows raises)."""
    try:
        return path.is_file()
    except OSError:
        return False


def content_names(folder: str) -> list[str]:
    """The names (file stems) of the content folders' files in `folder` (scenes, themes), sorted."""
    return sorted({path.stem for root in content_roots() for path in (root / folder).glob("*.yaml")})


@contextmanager
def exclusive(path: Path, waiting: Callable[[], None] | None = None) -> Iterator[None]:
    """An exclusive lock between processes (two games on one machine) on the file `path`, made if
    need be, for as long as the block runs. While another process holds it, `waiting()` is called
    every 50 ms (it may raise, to give up). Where the platform has no `fcntl`, or the file cannot be
    made (a read-only folder refuses what the block would do too), there is no lock to take."""
    try:
        import fcntl

        # A link in its place is not followed (the lock never makes or opens a file elsewhere), and
        # opening does not wait (a FIFO there would wait for a reader for ever: it is no lock file).
        flags = os.O_WRONLY | os.O_APPEND | os.O_CREAT | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_NONBLOCK", 0)
        fd = os.open(path, flags, 0o644)
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            os.close(fd)
            raise OSError(f"{path}: not a regular file")
        handle = os.fdopen(fd, "a")
    except (ImportError, OSError):
        yield
        return
    with handle:
        while True:
            try:
                fcntl.flock(handle, fcntl.LOCK_EX | (fcntl.LOCK_NB if waiting is not None else 0))
                break
            except BlockingIOError:
                waiting()  # type: ignore[misc]
                time.sleep(0.05)
        try:
            yield
        finally:
            fcntl.flock(handle, fcntl.LOCK_UN)
