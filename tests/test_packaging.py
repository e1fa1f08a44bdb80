"""The package as a user installs it: one import package `polygolf` with its content inside, a
version, and `python -m polygolf`."""

from __future__ import annotations

import subprocess
import sys
import zipfile
from pathlib import Path

import polygolf
from polygolf.game.sound import SOUND_NAMES

ROOT = Path(__file__).resolve().parent.parent


def test_python_m_polygolf_prints_the_version():
    result = subprocess.run([sys.executable, "-m", "polygolf", "--version"], capture_output=True, text=True,
                            timeout=60, cwd="/")
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == f"polygolf {polygolf.__version__}"
    assert polygolf.__version__[0].isdigit()


def test_the_wheel_holds_one_import_package_with_its_content(tmp_path):
    subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "-q", "-w",
                    str(tmp_path), str(ROOT)], check=True, capture_output=True, timeout=300)
    wheel, = tmp_path.glob("polygolf-*.whl")
    names = zipfile.ZipFile(wheel).namelist()
    top = {n.split("/")[0] for n in names}
    assert top == {"polygolf", wheel.name.split("-py3")[0] + ".dist-info"}, top
    shipped = {n.removeprefix("polygolf/") for n in names if n.endswith(".yaml")}
    source = {str(p.relative_to(ROOT)) for p in (ROOT / "content").rglob("*.yaml")}
    assert shipped == source
    sounds = {n.removeprefix("polygolf/") for n in names if n.startswith("polygolf/game/sounds/")}
    assert sounds == {f"game/sounds/{name}.wav" for name in SOUND_NAMES} | {"game/sounds/LICENSE.md"}
    for name in SOUND_NAMES:
        assert len(zipfile.ZipFile(wheel).read(f"polygolf/game/sounds/{name}.wav")) < 50_000
    metadata = zipfile.ZipFile(wheel).read(wheel.name.split("-py3")[0] + ".dist-info/METADATA").decode()
    assert "License-Expression: MIT" in metadata
    requires = [line for line in metadata.splitlines() if line.startswith("Requires-Dist:")]
    runtime = [r for r in requires if "extra ==" not in r]
    assert not any(lib in r for r in runtime for lib in ("matplotlib", "tqdm", "pytest")), runtime
