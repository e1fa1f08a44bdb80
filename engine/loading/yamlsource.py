"""YAML that remembers where each value came from, and validation errors that say so in one line.

Content files are parsed to plain data plus a map from each value's path (("bodies", 0, "velocity"))
to its line, then validated with pydantic; the first error becomes
`file:line: field: message`, which is all an author needs to fix it.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, TypeVar

import yaml
from pydantic import BaseModel, ValidationError

Loc = tuple[str | int, ...]
M = TypeVar("M", bound=BaseModel)


class ContentError(ValueError):
    """A content file that cannot be used; str() is the one-line message."""

    def __init__(self, file: str | Path, line: int, field: str, message: str) -> None:
        self.file, self.line, self.field, self.message = str(file), line, field, message
        super().__init__(f"{self.file}:{line}: {field}: {message}")


def format_loc(loc: Loc) -> str:
    out = ""
    for part in loc:
        if isinstance(part, int):
            out += f"[{part}]"
        else:
            out += f".{part}" if out else str(part)
    return out or "(top level)"


def _to_data(node: yaml.Node, loc: Loc, lines: dict[Loc, int], file: str) -> Any:
    """Plain data of `node`; records the line of every key (where an author looks) and list item."""
    if isinstance(node, yaml.MappingNode):
        out: dict[Any, Any] = {}
        for key_node, value_node in node.value:
            key = _scalar(key_node) if isinstance(key_node, yaml.ScalarNode) else None
            if not isinstance(key, str | int):
                raise ContentError(file, key_node.start_mark.line + 1, format_loc(loc), "keys must be names")
            if key in out:
                raise ContentError(file, key_node.start_mark.line + 1, format_loc((*loc, key)), "duplicate key")
            lines[(*loc, key)] = key_node.start_mark.line + 1
            out[key] = _to_data(value_node, (*loc, key), lines, file)
        return out
    if isinstance(node, yaml.SequenceNode):
        items = []
        for i, child in enumerate(node.value):
            lines[(*loc, i)] = child.start_mark.line + 1
            items.append(_to_data(child, (*loc, i), lines, file))
        return items
    return _scalar(node)


def _scalar(node: yaml.Node) -> Any:
    return yaml.constructor.SafeConstructor().construct_object(node, deep=True)


def load_yaml(path: str | Path) -> tuple[Any, dict[Loc, int]]:
    """Parse a YAML file to plain data and a map from value paths to 1-based line numbers."""
    file = str(path)
    try:
        text = Path(path).read_text(encoding="utf-8")
    except OSError as exc:
        raise ContentError(file, 0, "(file)", exc.strerror or str(exc)) from None
    try:
        root = yaml.compose(text, Loader=yaml.SafeLoader)
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        line = mark.line + 1 if mark else 0
        raise ContentError(file, line, "(yaml)", f"{exc.problem or exc}") from None
    if root is None:
        return None, {(): 1}
    lines: dict[Loc, int] = {(): root.start_mark.line + 1}
    return _to_data(root, (), lines, file), lines


def line_of(loc: Loc, lines: dict[Loc, int]) -> int:
    """Line of the deepest part of `loc` that exists in the file (a missing key points at its parent)."""
    for end in range(len(loc), -1, -1):
        if loc[:end] in lines:
            return lines[loc[:end]]
    return 1


def validate(model: type[M], data: Any, lines: dict[Loc, int], file: str | Path) -> M:
    """Validate `data` into `model`, turning the first pydantic error into a ContentError."""
    try:
        return model.model_validate(data)
    except ValidationError as exc:
        err = exc.errors(include_url=False)[0]
        loc = tuple(p for p in err["loc"] if not (isinstance(p, str) and p.startswith("function-")))
        message = err["msg"]
        if message.startswith("Value error, "):
            message = message[len("Value error, "):]
        if err["type"] == "extra_forbidden":
            message = "unknown key"
        elif err["type"] == "missing":
            message = "missing (required)"
        elif "input" in err and err["type"].endswith("_type"):
            message += f", got {err['input']!r}"
        raise ContentError(file, line_of(loc, lines), format_loc(loc), message) from None


def load(model: type[M], path: str | Path) -> M:
    data, lines = load_yaml(path)
    return validate(model, data, lines, path)
