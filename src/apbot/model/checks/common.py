"""What several checks share: name lists with fast lookup, and the "unknown name; did you
mean …?" message."""

from __future__ import annotations

from collections.abc import Iterable

from apbot.model.values import closest_matches


class Names(list[str]):
    """Names in order (for "did you mean" hints) with a set for O(1) ``in``."""

    def __init__(self, names: Iterable[str]) -> None:
        super().__init__(names)
        self.members = frozenset(self)

    def __contains__(self, name: object) -> bool:
        return name in self.members


def unknown_name(kind: str, name: str, options: list[str]) -> str:
    close = closest_matches(name, options, limit=1)
    hint = f"did you mean {close[0]!r}?" if close else f"declare it under `{kind}s`"
    return f"unknown {kind} {name!r}; {hint}"
