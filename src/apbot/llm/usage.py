"""Token accounting: what one call, one task and one run used.

``calls`` counts answers (from the server or the cache), so a rerun from the cache reports the
same usage as the first run — the records stay identical; ``requests`` and ``cached`` say what
was actually sent over the wire, and are reported for the run, not stored in task records.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass


@dataclass
class Usage:
    prompt_tokens: int = 0
    completion_tokens: int = 0
    calls: int = 0
    requests: int = 0
    cached: int = 0

    @property
    def total_tokens(self) -> int:
        return self.prompt_tokens + self.completion_tokens

    def add(self, other: Usage) -> Usage:
        self.prompt_tokens += other.prompt_tokens
        self.completion_tokens += other.completion_tokens
        self.calls += other.calls
        self.requests += other.requests
        self.cached += other.cached
        return self

    def record(self) -> dict[str, int]:
        """What goes into a task record: the same on a cached rerun."""
        return {
            "prompt_tokens": self.prompt_tokens,
            "completion_tokens": self.completion_tokens,
            "calls": self.calls,
        }

    def as_dict(self) -> dict[str, int]:
        return asdict(self)


def add_records(into: dict[str, int], usage: Usage) -> dict[str, int]:
    """Sum a usage into a record-style dict (``Episode.llm_usage``)."""
    for name, value in usage.record().items():
        into[name] = into.get(name, 0) + value
    return into
