"""YAML that remembers where each value came from, and validation errors that say so in one line.

Content files are parsed to plain data plus a map from each value's path (("bodies", 0, "velocity"))
to its line, then validated with pydantic; every error becomes `file:line: field: message`, which is
all an author needs to fix it.

Nothing a file says gets past this module as anything but a ContentError: only a regular file is read,
and no more of it than the size limit, the text must be UTF-8 without control characters, the event
stream is checked for depth and size before anything is built (so no recursion runs deep), aliases are
expanded against a budget (no "billion laughs") and may not refer to themselves, and only YAML's
standard tags are accepted.
"""

from __future__ import annotations

import datetime
import errno
import math
import os
import re
import stat
from collections.abc import Sequence
from pathlib import Path
from typing import Any, TypeVar

import yaml
from pydantic import BaseModel, ValidationError

from polygolf.engine.loading.limits import MAX_DEPTH, MAX_FILE_BYTES, MAX_NODES

Loc = tuple[str | int, ...]
M = TypeVar("M", bound=BaseModel)
_STANDARD_TAGS = {f"tag:yaml.org,2002:{name}" for name in
                  ("str", "int", "float", "bool", "null", "map", "seq", "timestamp", "binary", "merge")}


class ContentError(ValueError):
    """A content file that cannot be used; str() is the one-line message of the first problem, and
    `problems` lists every one found (a file can have several)."""

    def __init__(self, file: str | Path, line: int, field: str, message: str) -> None:
        self.file, self.line, self.field, self.message = str(file), line, field, message
        self.problems: list[ContentError] = [self]
        super().__init__(f"{self.file}:{line}: {field}: {message}")

    @classmethod
    def of(cls, problems: Sequence[ContentError]) -> ContentError:
        """One error standing for several: raised, it reads as the first; `problems` has them all."""
        first = problems[0]
        first.problems = list(problems)
        return first


def format_loc(loc: Loc) -> str:
    out = ""
    for part in loc:
        if isinstance(part, int):
            out += f"[{part}]"
        else:
            out += f".{key_text(part)}" if out else key_text(part)
    return out or "(top level)"


def key_text(key: object) -> str:
    """A key as an error line names it: as written if it is short, printable and unpadded; else quoted
    with its escapes, cut short (an unknown key can be anything: a line break, a terminal's escape
    code, a direction override, 400 KB)."""
    text = str(key)
    if text and text.isprintable() and text.strip() == text and len(text) <= 40:
        return text
    shown = repr(text[:40])
    return shown + "..." if len(text) > 40 else shown


class _Loader(yaml.SafeLoader):
    """YAML's safe loader, reading `1e-9` and `2E5` as numbers as YAML 1.2 does (YAML 1.1, which PyYAML
    follows, wants a dot in a float, so an author's `1e-9` was the string '1e-9')."""


_Loader.add_implicit_resolver("tag:yaml.org,2002:float",
                              re.compile(r"^[-+]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)[eE][-+]?[0-9]+$"),
                              list("-+0123456789."))


MERGE_TAG = "tag:yaml.org,2002:merge"
_NUMBER_TAGS = {"tag:yaml.org,2002:int", "tag:yaml.org,2002:float"}
# Python's own limit on an integer's digits: no number a content file needs comes near it, and PyYAML's
# base-60 integers (`1:59:59:...`) cost time quadratic in their length (900 KB of them took 46 s).
MAX_NUMBER_CHARACTERS = 4300


_READ_AS = {bool: "true or false", float: "a number", datetime.date: "a date", datetime.datetime: "a date and time"}


def _read_as(key: Any, node: yaml.Node) -> str:
    """Why a key that looks like a name is not one: YAML reads `1e5`, `2024-01-01` or `yes` as
    something else (the author meant the name; quoting it says so)."""
    kind = _READ_AS.get(type(key))
    return f": {key_text(node.value)} reads as {kind} in YAML (quote it)" if kind else ""


class _Builder:
    """Plain data from composed nodes, with the line of every key and list item."""

    def __init__(self, file: str) -> None:
        self.file = file
        self.lines: dict[Loc, int] = {}
        self.budget = MAX_NODES
        self.active: set[int] = set()  # nodes being built: meeting one again is an alias to itself
        self.duplicates: list[ContentError] = []  # every key written twice (the first one's value kept)

    def fail(self, node: yaml.Node, loc: Loc, message: str) -> ContentError:
        return ContentError(self.file, node.start_mark.line + 1, format_loc(loc), message)

    def build(self, node: yaml.Node, loc: Loc) -> Any:
        self.budget -= 1
        if self.budget < 0:
            raise self.fail(node, loc, f"more than {MAX_NODES:,} values (aliases expanded): too large")
        if node.tag not in _STANDARD_TAGS:
            raise self.fail(node, loc, f"tag {node.tag} is not allowed (only YAML's standard types)")
        if isinstance(node, yaml.ScalarNode):
            return self.scalar(node, loc)
        if id(node) in self.active:
            raise self.fail(node, loc, "an alias refers to the value that contains it")
        self.active.add(id(node))
        try:
            if isinstance(node, yaml.MappingNode):
                return self.mapping(node, loc)
            return self.sequence(node, loc)
        finally:
            self.active.discard(id(node))

    def mapping(self, node: yaml.MappingNode, loc: Loc) -> dict[Any, Any]:
        out: dict[Any, Any] = {}
        merges = []
        for key_node, value_node in node.value:
            if key_node.tag == MERGE_TAG:  # `<<: *anchor` (or a list of them): taken after the keys written here
                merges.append((key_node, value_node))
                continue
            key = self.scalar(key_node, loc) if isinstance(key_node, yaml.ScalarNode) else None
            if not isinstance(key, str | int) or isinstance(key, bool):
                raise self.fail(key_node, loc, "keys must be names" + _read_as(key, key_node))
            if key in out:
                self.duplicates.append(self.fail(key_node, (*loc, key), "duplicate key"))
                continue
            self.lines[(*loc, key)] = key_node.start_mark.line + 1
            out[key] = self.build(value_node, (*loc, key))
        for key_node, value_node in merges:  # YAML's merge keys: a key written here wins, then the first merged
            merged = self.build(value_node, (*loc, "<<"))  # (its lines apart: the keys written here keep theirs)
            for part in merged if isinstance(merged, list) else [merged]:
                if not isinstance(part, dict):
                    raise self.fail(value_node, loc, "<< merges mappings only (an alias of one, or a list of them)")
                for key, value in part.items():
                    if key not in out:
                        out[key] = value
                        self.lines[(*loc, key)] = key_node.start_mark.line + 1
        return out

    def sequence(self, node: yaml.SequenceNode, loc: Loc) -> list[Any]:
        items = []
        for i, child in enumerate(node.value):
            self.lines[(*loc, i)] = child.start_mark.line + 1
            items.append(self.build(child, (*loc, i)))
        return items

    def scalar(self, node: yaml.Node, loc: Loc) -> Any:
        # Refused unread: PyYAML's base-60 loop is quadratic, and Python will not read a longer integer.
        if node.tag in _NUMBER_TAGS and len(str(node.value)) > MAX_NUMBER_CHARACTERS:
            raise self.fail(node, loc, f"a number of {len(str(node.value))} digits: too long")
        try:
            return yaml.constructor.SafeConstructor().construct_object(node, deep=True)
        except (yaml.YAMLError, ValueError, OverflowError) as exc:
            raise self.fail(node, loc, f"not a valid value: {getattr(exc, 'problem', None) or exc}") from None
        except Exception:  # PyYAML's constructors on a tag's bad text: `!!int ""`, `!!bool foo`, `!!timestamp x`
            kind = node.tag.rsplit(":", 1)[-1]
            raise self.fail(node, loc, f"not a valid value: {key_text(node.value)} is not a YAML {kind}") from None


def _check_events(text: str, file: str) -> None:
    """Depth and size from the event stream, before a node is built (the composer recurses)."""
    depth = events = 0
    for event in yaml.parse(text, Loader=_Loader):
        events += 1
        if isinstance(event, yaml.CollectionStartEvent):
            depth += 1
            if depth > MAX_DEPTH:
                raise ContentError(file, event.start_mark.line + 1, "(yaml)", f"nested more than {MAX_DEPTH} deep")
        elif isinstance(event, yaml.CollectionEndEvent):
            depth -= 1
        if events > 2 * MAX_NODES:
            raise ContentError(file, event.start_mark.line + 1, "(yaml)", f"more than {MAX_NODES:,} values")


_NOT_REGULAR = ((stat.S_ISDIR, "a folder"), (stat.S_ISFIFO, "a pipe (FIFO)"), (stat.S_ISSOCK, "a socket"))


def read_at_most(path: str | Path, limit: int) -> bytes:
    """A regular file's bytes, at most `limit` + 1 of them: more than `limit` means too large, whatever
    its size said (a file can grow while it is read). Anything else is refused before a byte is read: a
    FIFO would wait for a writer for ever and a device such as /dev/zero never ends (its size says 0).
    Raises OSError, whose strerror says why in a few words."""
    # Non-blocking, so opening a FIFO returns at once rather than waiting for a writer.
    fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0))
    try:
        mode = os.fstat(fd).st_mode
        if not stat.S_ISREG(mode):
            kind = next((name for is_kind, name in _NOT_REGULAR if is_kind(mode)), "a device")
            raise OSError(errno.EINVAL, f"not a regular file but {kind}")
        with open(fd, "rb", closefd=False) as file:
            return file.read(limit + 1)
    finally:
        os.close(fd)


def read_text(path: str | Path) -> str:
    """A content file's text: at most MAX_FILE_BYTES of UTF-8 without control characters."""
    file = str(path)
    try:
        data = read_at_most(path, MAX_FILE_BYTES)
    except OSError as exc:
        raise ContentError(file, 0, "(file)", exc.strerror or str(exc)) from None
    if len(data) > MAX_FILE_BYTES:
        raise ContentError(file, 0, "(file)", f"more than {MAX_FILE_BYTES:,} bytes: content files are at most "
                                              f"{MAX_FILE_BYTES // 1024} KiB")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = data[:exc.start].count(b"\n") + 1
        raise ContentError(file, line, "(file)", f"not UTF-8 text (byte 0x{data[exc.start]:02x})") from None
    # Lines as an editor counts them (str.splitlines would also break at a form feed, a separator or
    # U+2028, hiding them from the check and moving the numbers); U+2028 and U+2029 are refused too:
    # YAML breaks lines there, so every line number after one would differ from the editor's.
    for number, line_text in enumerate(re.split(r"\r\n|\r|\n", text), 1):
        bad = next((c for c in line_text if (ord(c) < 32 and c != "\t") or 0x7F <= ord(c) < 0xA0
                    or c in "\ufffe\uffff\u2028\u2029"), None)
        if bad is not None:
            raise ContentError(file, number, "(file)", f"control character U+{ord(bad):04X} in the text")
    return text


def load_yaml(path: str | Path, text: str | None = None) -> tuple[Any, dict[Loc, int]]:
    """Parse a YAML file to plain data and a map from value paths to 1-based line numbers; `text`:
    the file's text made in memory (a generated hole), `path` only naming it."""
    file = str(path)
    text = read_text(path) if text is None else text
    try:
        _check_events(text, file)
        root = yaml.compose(text, Loader=_Loader)
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        line = mark.line + 1 if mark else 0
        raise ContentError(file, line, "(yaml)", f"{exc.problem or exc}") from None
    except yaml.YAMLError as exc:  # reader errors: unprintable characters the text check missed
        raise ContentError(file, 0, "(yaml)", str(exc).splitlines()[0]) from None
    if root is None:
        return None, {(): 1}
    builder = _Builder(file)
    builder.lines[()] = root.start_mark.line + 1
    data = builder.build(root, ())
    if builder.duplicates:
        raise ContentError.of(builder.duplicates)
    return data, builder.lines


def line_of(loc: Loc, lines: dict[Loc, int]) -> int:
    """Line of the deepest part of `loc` that exists in the file (a missing key points at its parent)."""
    for end in range(len(loc), -1, -1):
        if loc[:end] in lines:
            return lines[loc[:end]]
    return 1


def _message(err: dict) -> str:
    message = re.sub(r"a valid dictionary or instance of (\w+)", r"a mapping (\1)", err["msg"])
    if message.startswith("Value error, "):
        message = message[len("Value error, "):]
    if err["type"] == "extra_forbidden":
        message = "unknown key"
    elif err["type"] == "missing":
        message = "missing (required)"
    elif "input" in err and err["type"].endswith("_type"):
        shown = _shown(err["input"])
        message += f", got {shown if len(shown) <= 40 else shown[:37] + '...'}"
    return message


def _shown(value: Any) -> str:
    """repr(value), but an integer too long for Python to write (over 4300 digits: a hex or base-60
    one gets past the digits check) by its size."""
    try:
        return repr(value)
    except ValueError:
        return f"an integer of about {int(value.bit_length() * math.log10(2)) + 1} digits"


_TYPE_TAGS = {"str", "int", "float", "bool", "list", "tuple", "dict", "none", "set"}
_KINDS = {type(None): "nothing (an empty file)", list: "a list", str: "text", int: "a number", float: "a number",
          bool: "true or false"}


def _field_path(loc: tuple, data: Any) -> Loc:
    """pydantic's error location without its union-branch and validator tags, followed through the
    data itself: a key or index the data has is part of the path whatever it looks like (a pattern
    named `slope-east`); one it lacks is a missing field if it looks like ours (snake_case), else a tag
    (a class name, `type[...]`, `kind-of-check` or a type's name)."""
    out: list[str | int] = []
    node = data
    for part in loc:
        if isinstance(node, dict) and part in node:
            node = node[part]
        elif isinstance(node, list) and isinstance(part, int) and 0 <= part < len(node):
            node = node[part]
        elif isinstance(part, int) or (part.islower() and "[" not in part and "-" not in part
                                       and part not in _TYPE_TAGS):
            node = None
        else:
            continue
        out.append(part)
    return tuple(out)


def validate(model: type[M], data: Any, lines: dict[Loc, int], file: str | Path) -> M:
    """Validate `data` into `model`; every pydantic error becomes a line of the ContentError. Where a
    union's branches disagree, the deepest explanation wins ("n: should be 'open' or 'wall'" over
    "should be a string")."""
    if not isinstance(data, dict) and model.model_fields:  # the file is not a mapping of the model's keys
        what = _KINDS.get(type(data), f"a {type(data).__name__}")
        keys = ", ".join(name for name, info in model.model_fields.items() if info.is_required())
        raise ContentError(file, line_of((), lines), "(top level)",
                           f"the file should be a mapping of keys{f' ({keys}, ...)' if keys else ''}, not {what}")
    try:
        return model.model_validate(data)
    except ValidationError as exc:
        found = [(_field_path(err["loc"], data), err) for err in exc.errors(include_url=False)]
        messages: dict[Loc, list[str]] = {}
        for loc, err in found:
            deeper = any(len(other) > len(loc) and other[:len(loc)] == loc for other, _ in found)
            if deeper and err["type"].endswith("_type"):
                continue
            text = _message(err)
            if text not in messages.setdefault(loc, []):
                messages[loc].append(text)
        problems = [ContentError(file, line_of(loc, lines), format_loc(loc), "; or ".join(texts))
                    for loc, texts in messages.items()]
        raise ContentError.of(problems) from None


def load(model: type[M], path: str | Path) -> M:
    data, lines = load_yaml(path)
    return validate(model, data, lines, path)
