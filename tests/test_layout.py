"""The layout holds: layers import only downwards, no module imports one that imports it back (imports
inside functions count), and the installed package lists every package folder of the source tree."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

tomllib = pytest.importorskip("tomllib")  # Python 3.11+

ROOT = Path(__file__).resolve().parent.parent
# Source folder -> the import package it is installed as (pyproject's package-dir).
FOLDERS = {"polygolf": "polygolf", "engine": "polygolf.engine", "game": "polygolf.game", "content": "polygolf.content"}

# engine's layers, bottom to top: a module may import its own layer and the ones below.
LAYERS = ["physics", "components", "systems", "assembly", "loading", "golf"]
THIRD_PARTY_BELOW = {  # what a layer may not import from outside the project
    "physics": {"esper", "yaml", "pydantic", "arcade", "pyglet"},
    "components": {"esper", "yaml", "pydantic", "arcade", "pyglet"},
    "systems": {"yaml", "pydantic", "arcade", "pyglet"},
    "assembly": {"yaml", "pydantic", "arcade", "pyglet"},
    "loading": {"arcade", "pyglet"},
    "golf": {"arcade", "pyglet"},
}


def modules() -> dict[str, Path]:
    found = {}
    for folder, package in FOLDERS.items():
        for path in (ROOT / folder).rglob("*.py"):
            parts = list(path.relative_to(ROOT / folder).with_suffix("").parts)
            if parts[-1] == "__init__":
                parts.pop()
            found[".".join([package, *parts])] = path
    return found


MODULES = modules()


def imports(name: str) -> set[str]:
    """Every module `name` imports anywhere in its file (inside functions too)."""
    tree = ast.parse(MODULES[name].read_text())
    out: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            out.add(node.module)
            out |= {f"{node.module}.{alias.name}" for alias in node.names if f"{node.module}.{alias.name}" in MODULES}
    return out


def project_imports(name: str) -> set[str]:
    return {target for target in imports(name) if target in MODULES and target != name}


def test_no_module_imports_one_that_imports_it_back():
    graph = {name: project_imports(name) for name in MODULES}
    # Packages' __init__ only re-export their own modules; an edge into a package means its __init__.
    cycles, index, low, stack, on_stack, counter = [], {}, {}, [], set(), [0]

    def visit(v: str) -> None:  # Tarjan's strongly connected components
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on_stack.add(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                cycles.append(sorted(component))

    for name in sorted(graph):
        if name not in index:
            visit(name)
    assert cycles == []


def _layer(name: str) -> str | None:
    parts = name.split(".")
    return parts[2] if len(parts) > 2 and parts[1] == "engine" and parts[2] in LAYERS else None


@pytest.mark.parametrize("name", sorted(n for n in MODULES if _layer(n)))
def test_engine_layers_import_only_downwards(name):
    mine = LAYERS.index(_layer(name))
    for target in project_imports(name):
        assert not target.startswith("polygolf.game"), f"{name} imports the front end ({target})"
        layer = _layer(target)
        if layer is not None:
            assert LAYERS.index(layer) <= mine, f"{name} ({LAYERS[mine]}) imports {target} ({layer}), a layer above"
    forbidden = {t.split(".")[0] for t in imports(name)} & THIRD_PARTY_BELOW[_layer(name)]
    assert not forbidden, f"{name} imports {forbidden}"


def test_no_screen_imports_another():
    views = [n for n in MODULES if n.startswith("polygolf.game.views.")]
    for name in views:
        others = {t for t in project_imports(name) if t in views} - {"polygolf.game.views.navigation",
                                                                     "polygolf.game.views.widgets"}
        assert others == set(), f"{name} imports {others}: screens go through the flow"


def test_every_package_folder_is_installed():
    config = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]
    assert config["package-dir"] == {package: folder for folder, package in FOLDERS.items()}
    packages = {n for n, p in MODULES.items() if p.name == "__init__.py"}
    assert set(config["packages"]) == packages
