"""The results store: one JSON line per finished (method, task), appended and synced at once.

Each record is appended with one ``write`` and synced before the next, so a run killed at
any moment loses at most the line being written; that torn last line is cut silently on the
next run. Any other line that is not a valid record (a garbage line in the middle, a record
whose key does not match its fields) is real damage, but it must not strand the run:
:meth:`ResultStore.recover` moves such lines, with their line numbers and bytes, to
``results.quarantine.jsonl`` and keeps every valid record; their tasks simply run again.
"""

from __future__ import annotations

import base64
import json
import os
from dataclasses import dataclass, field
from datetime import UTC, datetime
from pathlib import Path

from pydantic import ValidationError

from apbot.bench.records import TaskRecord, record_key

RESULTS_FILE = "results.jsonl"
QUARANTINE_FILE = "results.quarantine.jsonl"
_RECORD_START = b'{"key":'  # how every line this store writes begins


class ResultsError(ValueError):
    """A results file that cannot be read or trusted; the message names it and what to do."""


@dataclass(frozen=True)
class BadLine:
    """A line of a results file that is not a valid record."""

    number: int
    reason: str
    data: bytes

    def to_json(self) -> dict[str, object]:
        """The line as a quarantine entry: its text, or base64 when it is not UTF-8."""
        entry: dict[str, object] = {"line": self.number, "reason": self.reason}
        try:
            entry["text"] = self.data.decode("utf-8")
        except UnicodeDecodeError:
            entry["base64"] = base64.b64encode(self.data).decode("ascii")
        return entry


@dataclass
class Scan:
    """What a results file holds: valid records (first one per key wins), bad lines, and an
    unfinished last line (``torn``: a record cut off by a kill)."""

    records: dict[str, TaskRecord] = field(default_factory=dict)
    lines: list[bytes] = field(default_factory=list)  # the valid lines, as written
    bad: list[BadLine] = field(default_factory=list)
    torn: bool = False
    unterminated: bool = False  # the last line is a valid record without its newline


def parse_record(line: bytes) -> TaskRecord | str:
    """The record on one line, or why it is not one."""
    try:
        record = TaskRecord.model_validate_json(line)
    except ValidationError as exc:
        error = exc.errors()[0]
        where = ".".join(str(part) for part in error["loc"])
        return f"{where}: {error['msg']}" if where else str(error["msg"])
    except (ValueError, RecursionError) as exc:  # pragma: no cover - pydantic reports these
        return f"not a record ({type(exc).__name__})"
    expected = record_key(record.method, record.belief, record.appliance, record.task)
    if record.key != expected:
        return f"key {record.key!r} does not match its method, belief, appliance and task"
    return record


def _take(scan: Scan, number: int, line: bytes, parsed: TaskRecord | str) -> None:
    if isinstance(parsed, str):
        scan.bad.append(BadLine(number, parsed, line))
        return
    scan.records.setdefault(parsed.key, parsed)
    scan.lines.append(line)


class ResultStore:
    """Append-only JSON-lines store of :class:`TaskRecord`, keyed by ``record.key``."""

    def __init__(self, path: Path) -> None:
        self.path = path
        self.quarantine = path.with_name(
            QUARANTINE_FILE if path.name == RESULTS_FILE else path.name + ".quarantine"
        )

    def _read(self) -> bytes:
        try:
            return self.path.read_bytes()
        except FileNotFoundError:
            return b""
        except OSError as exc:
            raise ResultsError(f"{self.path}: cannot be read ({exc.strerror})") from None

    def scan(self) -> Scan:
        """Read the file without changing it."""
        data = self._read()
        scan = Scan()
        *complete, tail = data.split(b"\n")
        for number, line in enumerate(complete, start=1):
            if line.strip():
                _take(scan, number, line, parse_record(line))
        if tail and not tail.strip():  # blanks after the last newline: nothing to keep
            scan.torn = True
        elif tail:
            parsed = parse_record(tail)
            if isinstance(parsed, TaskRecord):  # complete, only its newline is missing
                scan.unterminated = True
            elif tail.lstrip().startswith(_RECORD_START):  # one of ours, cut off mid-write
                scan.torn = True
                return scan
            _take(scan, len(complete) + 1, tail, parsed)
        return scan

    def recover(self) -> Scan:
        """Make the file hold only valid, newline-terminated records, and say what was done.

        A torn last line is cut; bad lines are appended to the quarantine file (synced first,
        so a kill in between loses nothing: they are only quarantined again) and then the
        results file is replaced by its valid lines. Valid records are never dropped.
        """
        scan = self.scan()
        try:
            if scan.bad:
                self._quarantine(scan.bad)
                self._replace(b"".join(line + b"\n" for line in scan.lines))
            elif scan.torn or scan.unterminated:
                data = self._read()
                cut = data.rfind(b"\n") + 1
                with self.path.open("r+b") as handle:
                    if scan.torn:
                        handle.truncate(cut)
                    else:
                        handle.seek(0, os.SEEK_END)
                        handle.write(b"\n")
        except OSError as exc:
            where = exc.filename or self.path
            raise ResultsError(
                f"{where}: cannot be written to repair {self.path.name} ({exc.strerror})"
            ) from None
        return scan

    def _quarantine(self, bad: list[BadLine]) -> None:
        when = datetime.now(UTC).isoformat(timespec="seconds")
        text = "".join(
            json.dumps({**line.to_json(), "file": self.path.name, "quarantined": when}) + "\n"
            for line in bad
        )
        with self.quarantine.open("a", encoding="utf-8") as handle:
            handle.write(text)
            handle.flush()
            os.fsync(handle.fileno())

    def _replace(self, data: bytes) -> None:
        temporary = self.path.with_name(self.path.name + ".tmp")
        with temporary.open("wb") as handle:
            handle.write(data)
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(temporary, self.path)

    def load(self, repair: bool = True) -> dict[str, TaskRecord]:
        """Every valid record by key (first one wins).

        With ``repair``, as :meth:`recover`. Without, the file is only read (a report may be
        written while a bench is still appending): a torn last line is skipped and a bad line
        raises :class:`ResultsError` naming it.
        """
        if repair:
            return self.recover().records
        scan = self.scan()
        if scan.bad:
            first = scan.bad[0]
            raise ResultsError(
                f"{self.path}:{first.number}: not a valid result record ({first.reason}); "
                f"{len(scan.bad)} bad line(s) in all. Running the same `apbot bench` command "
                f"again moves them to {self.quarantine.name} and reruns their tasks"
            )
        return scan.records

    def append(self, record: TaskRecord) -> None:
        """Write one record durably (one write, synced before returning)."""
        line = json.dumps(record.model_dump(mode="json"), ensure_ascii=False, separators=(",", ":"))
        data = (line + "\n").encode("utf-8")
        try:
            descriptor = os.open(self.path, os.O_WRONLY | os.O_APPEND | os.O_CREAT, 0o644)
            try:
                written = 0
                while written < len(data):
                    written += os.write(descriptor, data[written:])
                os.fsync(descriptor)
            finally:
                os.close(descriptor)
        except OSError as exc:
            raise ResultsError(
                f"{self.path}: cannot write a record ({exc.strerror}); the finished records "
                "are kept: fix that and run the same command again"
            ) from None

    def clear(self) -> None:
        """Forget every record (``--rerun``); quarantined lines are kept."""
        self.path.unlink(missing_ok=True)


def describe_recovery(store: ResultStore, scan: Scan) -> str:
    """One line for the user about quarantined lines ("" when there were none)."""
    if not scan.bad:
        return ""
    numbers = ", ".join(str(line.number) for line in scan.bad[:5])
    more = f" and {len(scan.bad) - 5} more" if len(scan.bad) > 5 else ""
    return (
        f"{store.path}: {len(scan.bad)} bad line(s) (line {numbers}{more}; first: "
        f"{scan.bad[0].reason}) moved to {store.quarantine}; their tasks run again"
    )


def read_records(directory: Path) -> list[TaskRecord]:
    """The records of a run directory, in the order they were written — only read, never
    repaired (a bench may still be appending to the file)."""
    return list(ResultStore(directory / RESULTS_FILE).load(repair=False).values())
