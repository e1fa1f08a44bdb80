"""Shared fixtures. esper keeps its worlds in module state: every test gets a clean slate, and the
worlds a test created are deleted afterwards. Window tests run under Xvfb (pytest-xvfb); tests that
only render use ARCADE_HEADLESS where no GUI widget is involved."""

from __future__ import annotations

import os
from pathlib import Path

import esper
import pytest

ROOT = Path(__file__).resolve().parent.parent
SCENES = ROOT / "content" / "scenes"
PRESET_NAMES = ("fast", "balanced", "accurate")


def pytest_sessionstart(session: pytest.Session) -> None:
    """Compile (or load) every physics kernel once per process, before any test. With pytest-xdist
    the controller runs this before it starts its workers, so they, and the processes tests start
    (workers, the command line), load the kernels from the cache rather than each compiling them."""
    from polygolf.engine.physics.jit import compile_kernels

    compile_kernels()
    # arcade reads ARCADE_HEADLESS once, when it is imported. `render` run in-process sets it for its
    # offscreen context: had it been first to import arcade in a worker, every window test after it
    # there failed (pyglet without xlib). Imported here, under Xvfb, arcade keeps real windows and
    # `render` draws in a hidden one.
    if not os.environ.get("ARCADE_HEADLESS"):
        try:
            import arcade  # noqa: F401
        except Exception:  # noqa: BLE001 (no display at all: the window tests are skipped or fail on their own)
            pass


@pytest.fixture(autouse=True)
def isolated_user_data(tmp_path_factory, monkeypatch) -> Path:
    """Every test gets its own empty data folder: nothing is read from or written to the real one."""
    folder = tmp_path_factory.mktemp("data")
    monkeypatch.setenv("POLYGOLF_DATA", str(folder))
    return folder


@pytest.fixture(autouse=True)
def isolated_esper_worlds():
    before = set(esper.list_worlds())
    yield
    esper.switch_world("default")
    for name in set(esper.list_worlds()) - before - {"default"}:
        esper.delete_world(name)


@pytest.fixture
def world():
    """A fresh named esper world for a test that assembles processors by hand."""
    esper.switch_world("test-world")
    yield "test-world"
    esper.switch_world("default")
    esper.delete_world("test-world")
