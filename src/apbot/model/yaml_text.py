"""YAML text in and out: read a file safely, parse it refusing hostile or ambiguous documents,
dump it, and find the line of a node.

Kept apart from schema loading so that every YAML file the project reads (models, panels,
task lists, suites) gets the same size limits, repeated-key check and alias-bomb guard.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any

import yaml

from apbot.model.limits import MAX_FILE_BYTES, MAX_YAML_DEPTH, MAX_YAML_NODES, SIZE_LIMITS_DOC
from apbot.model.problems import ModelError, PathPart, Problem

try:  # the C loader is ~10x faster; fall back when libyaml is missing
    from yaml import CSafeDumper as _Dumper
    from yaml import CSafeLoader as _Loader
except ImportError:  # pragma: no cover - depends on the platform's wheel
    from yaml import SafeDumper as _Dumper  # type: ignore[assignment]
    from yaml import SafeLoader as _Loader  # type: ignore[assignment]


def read_text(path: Path, source: str | None = None, limit: int = MAX_FILE_BYTES) -> str:
    """A file's UTF-8 text, or a :class:`ModelError` saying why it cannot be read.

    At most ``limit`` bytes are ever read (a regular file's size is checked first), so a
    multi-gigabyte file or an endless device such as ``/dev/zero`` costs nothing.
    """
    where = source or str(path)

    def too_large(size: str) -> ModelError:
        return ModelError(
            [
                Problem(
                    (),
                    f"the file has {size} bytes; at most {limit:,} are allowed "
                    f"(see {SIZE_LIMITS_DOC})",
                    "size",
                )
            ],
            where,
        )

    try:
        if path.is_file() and path.stat().st_size > limit:
            raise too_large(f"{path.stat().st_size:,}")
        with path.open("rb") as handle:
            data = handle.read(limit + 1)
        if len(data) > limit:
            raise too_large(f"more than {limit:,}")
        text = data.decode("utf-8")
    except IsADirectoryError:
        raise ModelError([Problem((), "is a directory, not a file", "io")], where) from None
    except OSError as exc:
        reason = exc.strerror or str(exc)
        raise ModelError([Problem((), f"cannot read the file: {reason}", "io")], where) from None
    except UnicodeDecodeError as exc:
        raise ModelError([Problem((), f"not UTF-8 text (byte {exc.start})", "io")], where) from None
    return text.replace("\r\n", "\n").replace("\r", "\n")  # as text mode reads it


def read_yaml(text: str, source: str | None = None) -> Any:
    """Parse YAML, reporting a syntax error or a repeated key as a problem with its line.

    PyYAML silently keeps the last of two equal keys; in a model that hides a whole variable
    or action, so a repeated key is an error here. Hostile documents are refused before any
    object is built: more than :data:`MAX_YAML_NODES` nodes once aliases are expanded (a
    "billion laughs" is ten lines of text), an alias inside its own anchor, or nesting deeper
    than :data:`MAX_YAML_DEPTH`.
    """
    if not isinstance(text, str):
        raise TypeError(f"read_yaml takes the text of a document (str), not {type(text).__name__}")
    if len(text) > MAX_FILE_BYTES:
        raise ModelError(
            [
                Problem(
                    (),
                    f"the text has {len(text):,} characters; at most {MAX_FILE_BYTES:,} are "
                    f"allowed (see {SIZE_LIMITS_DOC})",
                    "size",
                )
            ],
            source,
        )
    try:
        problems = _scan(text)
        if problems:
            raise ModelError(problems, source)
        return yaml.load(text, Loader=_Loader)
    except yaml.YAMLError as exc:
        raise ModelError([_syntax_problem(exc, text)], source) from None
    except RecursionError:  # the pure-Python parser, when libyaml is missing
        raise ModelError(
            [Problem((), "YAML nested too deeply to read", "yaml", line=1)], source
        ) from None


def _syntax_problem(exc: yaml.YAMLError, text: str) -> Problem:
    """One line saying what the YAML parser found and where (its messages span lines)."""
    mark = getattr(exc, "problem_mark", None) or getattr(exc, "context_mark", None)
    line = mark.line + 1 if mark is not None else None
    reason = getattr(exc, "problem", None) or getattr(exc, "context", None)
    if isinstance(exc, yaml.reader.ReaderError):
        position = int(exc.position)
        line = text.count("\n", 0, position) + 1
        column = position - (text.rfind("\n", 0, position) + 1) + 1
        code = (
            exc.character if isinstance(exc.character, int) else ord(str(exc.character)[:1] or "?")
        )
        reason = f"{exc.reason}: U+{code:04X} in column {column}"
    if not reason:
        reason = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
    return Problem((), f"YAML syntax: {reason}", "yaml", line=line)


_NODE_EVENTS = (yaml.ScalarEvent, yaml.AliasEvent, yaml.SequenceStartEvent, yaml.MappingStartEvent)


@dataclass
class _Open:
    """A collection being read: where it started (in nodes) and which child is being read."""

    anchor: str | None
    start: int
    mapping: bool
    items: int = 0  # children begun (a mapping's keys and values both count)
    key: PathPart = "?"  # the key whose value is being read (mappings)
    seen: dict[str, int] = field(default_factory=dict)  # key -> its line (mappings)


def _scan(text: str) -> list[Problem]:
    """Problems found in the event stream, before any object is built.

    The stream is read once; a node's expanded size is known when it ends, so an alias adds
    its anchor's size in O(1) and a bomb is stopped after at most :data:`MAX_YAML_NODES`
    events, whatever it would expand to.
    """
    stack: list[_Open] = []
    open_anchors: dict[str, int] = {}
    sizes: dict[str, int] = {}
    nodes = 0
    aliased = 0
    problems: list[Problem] = []
    for event in yaml.parse(text, Loader=_Loader):
        kind = type(event)
        if kind in _NODE_EVENTS:
            node: Any = event  # a NodeEvent: it has an anchor (and a scalar, a value)
            line = node.start_mark.line + 1
            if stack:
                parent = stack[-1]
                if parent.mapping and parent.items % 2 == 0:  # a key
                    name = node.value if kind is yaml.ScalarEvent else "?"
                    if name in parent.seen and kind is yaml.ScalarEvent:
                        problems.append(_repeated(stack, name, parent.seen[name], line))
                    parent.seen.setdefault(name, line)
                    parent.key = name
                parent.items += 1
            anchor = node.anchor
            if kind is yaml.AliasEvent:
                if anchor in open_anchors:
                    return [
                        Problem(
                            _path(stack),
                            f"alias *{anchor} is inside the node its anchor &{anchor} "
                            "names (a recursive alias); write the value out instead",
                            "yaml",
                            line=line,
                        )
                    ]
                size = sizes.get(anchor, 1)
                nodes += size
                aliased += size
            elif kind is yaml.ScalarEvent:
                nodes += 1
                if anchor is not None:
                    sizes[anchor] = 1
            else:
                stack.append(_Open(anchor, nodes, kind is yaml.MappingStartEvent))
                nodes += 1
                if anchor is not None:
                    open_anchors[anchor] = open_anchors.get(anchor, 0) + 1
                if len(stack) > MAX_YAML_DEPTH:
                    return [
                        Problem(
                            (),
                            f"collections nested more than {MAX_YAML_DEPTH} deep; a model "
                            "needs fewer than ten levels",
                            "yaml",
                            line=line,
                        )
                    ]
            if nodes > MAX_YAML_NODES:
                return [_too_many_nodes(stack, line, aliased)]
        elif kind is yaml.SequenceEndEvent or kind is yaml.MappingEndEvent:
            done = stack.pop()
            if done.anchor is not None:
                sizes[done.anchor] = nodes - done.start
                open_anchors[done.anchor] -= 1
                if not open_anchors[done.anchor]:
                    del open_anchors[done.anchor]
    return problems


def _path(stack: list[_Open]) -> tuple[PathPart, ...]:
    """Where the next node goes: the key or index being read in each open collection."""
    return tuple(o.key if o.mapping else o.items - 1 for o in stack)


def _repeated(stack: list[_Open], name: str, first: int, line: int) -> Problem:
    return Problem(
        (*_path(stack[:-1]), name),
        f"key {name!r} is given twice (first on line {first}); the second would silently "
        "replace the first",
        "yaml",
        line=line,
    )


def _too_many_nodes(stack: list[_Open], line: int, aliased: int) -> Problem:
    limit = f"{MAX_YAML_NODES:,}"
    if aliased > MAX_YAML_NODES // 2:
        message = (
            f"aliases expand the document past {limit} nodes (an alias bomb, or "
            "'billion laughs'?); refused before expanding them — write the values out"
        )
    else:
        message = (
            f"the document has more than {limit} nodes (keys, values and list items); "
            f"see {SIZE_LIMITS_DOC}"
        )
    return Problem(_path(stack), message, "size", line=line)


def dump_yaml(data: Any) -> str:
    """YAML text in block style with keys in their given order."""
    return yaml.dump(
        data,
        Dumper=_Dumper,
        sort_keys=False,
        allow_unicode=True,
        width=100,
        default_flow_style=None,
    )


def line_of(text: str | None, path: tuple[PathPart, ...]) -> int | None:
    """1-based line of the YAML node at ``path`` (the deepest one that exists)."""
    if not text:
        return None
    index = _line_index(text)
    return index.line(path) if index is not None else None


class _LineIndex:
    """A composed document with a key index per mapping, built when first asked: a model
    with many problems looks up many paths, each in O(depth)."""

    def __init__(self, root: Any) -> None:
        self.root = root
        self.keys: dict[int, dict[Any, tuple[Any, Any]]] = {}

    def _children(self, node: Any) -> dict[Any, tuple[Any, Any]]:
        found = self.keys.get(id(node))
        if found is None:
            found = {}
            for key, value in node.value:
                found.setdefault(
                    key.value if isinstance(key, yaml.ScalarNode) else None, (key, value)
                )
            self.keys[id(node)] = found
        return found

    def line(self, path: tuple[PathPart, ...]) -> int | None:
        node = self.root
        line = node.start_mark.line + 1 if node is not None else None
        for part in path:
            if isinstance(node, yaml.MappingNode):
                found = self._children(node).get(part)
                if found is None:
                    break
                line, node = found[0].start_mark.line + 1, found[1]
            elif isinstance(node, yaml.SequenceNode) and isinstance(part, int):
                if not 0 <= part < len(node.value):
                    break
                node = node.value[part]
                line = node.start_mark.line + 1
            else:
                break
        return line


@lru_cache(maxsize=2)
def _line_index(text: str) -> _LineIndex | None:
    if len(text) > MAX_FILE_BYTES:
        return None
    try:
        if _scan(text):
            return None  # a bomb stays unexpanded; a repeated key has its own line
        return _LineIndex(yaml.compose(text, Loader=_Loader))
    except (yaml.YAMLError, RecursionError):
        return None
