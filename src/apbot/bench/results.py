"""The results store: one JSON line per finished (method, task), appended and synced at once.

Appending whole lines and syncing after each means a run killed at any moment loses at most
the line being written; :meth:`ResultStore.load` drops such a torn last line (and cuts it from
the file) so resuming never duplicates or corrupts a record.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

from pydantic import ValidationError

from apbot.bench.records import TaskRecord

RESULTS_FILE = "results.jsonl"


class ResultsError(ValueError):
    """A results file that cannot be trusted (not a torn last line: real damage)."""


class ResultStore:
    """Append-only JSON-lines store of :class:`TaskRecord`, keyed by ``record.key``."""

    def __init__(self, path: Path) -> None:
        self.path = path

    def load(self, repair: bool = True) -> dict[str, TaskRecord]:
        """Every complete record by key (first one wins); a torn final line is skipped, and
        with ``repair`` cut from the file (without, the file is only read: a report may be
        written while a bench is still appending)."""
        if not self.path.exists():
            return {}
        data = self.path.read_bytes()
        records: dict[str, TaskRecord] = {}
        lines = data.split(b"\n")
        complete, tail = lines[:-1], lines[-1]
        for number, line in enumerate(complete, start=1):
            if not line.strip():
                continue
            try:
                record = TaskRecord.model_validate_json(line)
            except ValidationError as exc:
                raise ResultsError(
                    f"{self.path}:{number}: not a valid result record "
                    f"({exc.errors()[0]['msg']}); move the file away or run "
                    "with --rerun into a new directory"
                ) from None
            records.setdefault(record.key, record)
        if repair and tail.strip():  # written without its newline: the run died mid-write
            with self.path.open("r+b") as handle:
                handle.truncate(len(data) - len(tail))
        return records

    def append(self, record: TaskRecord) -> None:
        """Write one record durably (flushed and synced before returning)."""
        self.path.parent.mkdir(parents=True, exist_ok=True)
        line = json.dumps(record.model_dump(mode="json"), ensure_ascii=False, separators=(",", ":"))
        with self.path.open("a", encoding="utf-8") as handle:
            handle.write(line + "\n")
            handle.flush()
            os.fsync(handle.fileno())

    def clear(self) -> None:
        """Forget every record (``--rerun``)."""
        self.path.unlink(missing_ok=True)


def read_records(directory: Path) -> list[TaskRecord]:
    """The records of a run directory, in the order they were written — only read, never
    repaired (a bench may still be appending to the file)."""
    return list(ResultStore(directory / RESULTS_FILE).load(repair=False).values())
