"""Limits shared by every process of a run: a concurrency cap and a spending budget.

Benchmark workers are separate processes, so both live in files locked with ``fcntl.flock``:
``Slots`` hands out at most N slot files at a time (a crashed holder's lock goes with it), and
``Budget`` keeps the run's request and token counts in one small JSON file updated under an
exclusive lock. Without a budget file the counts are this process's own.
"""

from __future__ import annotations

import fcntl
import json
import os
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import IO, Any


class BudgetSpent(RuntimeError):
    """The run's LLM budget is spent: stop cleanly, keep what finished."""


class Slots:
    """At most ``count`` requests at a time across the processes sharing ``directory``."""

    def __init__(self, directory: Path, count: int) -> None:
        self.directory = Path(directory)
        self.count = max(1, count)
        self._local = threading.BoundedSemaphore(self.count)

    @contextmanager
    def hold(self) -> Iterator[None]:
        with self._local:
            self.directory.mkdir(parents=True, exist_ok=True)
            delay = 0.005
            while True:
                for index in range(self.count):
                    stream = open(self.directory / f"slot-{index}", "a+")  # noqa: SIM115
                    try:
                        fcntl.flock(stream, fcntl.LOCK_EX | fcntl.LOCK_NB)
                    except OSError:
                        stream.close()
                        continue
                    try:
                        yield
                    finally:
                        fcntl.flock(stream, fcntl.LOCK_UN)
                        stream.close()
                    return
                time.sleep(delay)
                delay = min(delay * 2, 0.2)


class Budget:
    """Requests and tokens spent so far against optional limits (``None``: no limit)."""

    def __init__(
        self,
        max_requests: int | None = None,
        max_tokens: int | None = None,
        path: Path | None = None,
    ) -> None:
        self.max_requests = max_requests
        self.max_tokens = max_tokens
        self.path = path
        self._counts = {"requests": 0, "tokens": 0}
        self._lock = threading.Lock()

    @contextmanager
    def _locked(self) -> Iterator[dict[str, int]]:
        with self._lock:
            if self.path is None:
                yield self._counts
                return
            self.path.parent.mkdir(parents=True, exist_ok=True)
            with open(self.path, "a+", encoding="utf-8") as stream:
                fcntl.flock(stream, fcntl.LOCK_EX)
                counts = _read_counts(stream)
                yield counts
                stream.seek(0)
                stream.truncate()
                stream.write(json.dumps(counts))
                stream.flush()
                os.fsync(stream.fileno())

    def spent(self) -> dict[str, int]:
        with self._locked() as counts:
            return dict(counts)

    def check(self) -> None:
        """Raise :class:`BudgetSpent` when another request would go over a limit."""
        with self._locked() as counts:
            if self.max_requests is not None and counts["requests"] >= self.max_requests:
                raise BudgetSpent(
                    f"the LLM budget is spent: {counts['requests']} of {self.max_requests} "
                    "requests made"
                )
            if self.max_tokens is not None and counts["tokens"] >= self.max_tokens:
                raise BudgetSpent(
                    f"the LLM budget is spent: {counts['tokens']} of {self.max_tokens} tokens used"
                )

    def charge(self, tokens: int) -> None:
        with self._locked() as counts:
            counts["requests"] += 1
            counts["tokens"] += tokens


def _read_counts(stream: IO[str]) -> dict[str, int]:
    stream.seek(0)
    try:
        data: Any = json.loads(stream.read() or "{}")
    except ValueError:
        data = {}
    return {
        "requests": int(data.get("requests", 0)) if isinstance(data, dict) else 0,
        "tokens": int(data.get("tokens", 0)) if isinstance(data, dict) else 0,
    }
