"""Progress of a benchmark run: a live bar on a terminal, plain lines in a log.

On a terminal (stderr) each method gets a bar with its live success count. When stdout is
not a terminal (``apbot bench > log``, CI, ``nohup``), or no bar can be shown, one line goes
to stdout every few seconds with the counts so far: finished, ✓ (success), ✗ (failure) and
errors (a method that raised). Lines rather than one per finished appliance: the work is
interleaved (every appliance's first task, then the second…), so appliances finish only at
the very end.
"""

from __future__ import annotations

import sys
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any, Protocol, TextIO

from apbot.bench.records import TaskRecord

LINE_EVERY = 5.0  # seconds between two progress lines


class Reporter(Protocol):
    def __call__(self, record: TaskRecord) -> None: ...

    def notice(self, message: str) -> None: ...


def is_error(record: TaskRecord) -> bool:
    """A run that raised (in the method or building its belief), not a plain failure."""
    return record.failure.startswith("error:")


@dataclass
class Counts:
    """Tasks finished so far: successes, failures and errors (failures are not errors)."""

    total: int
    ok: int = 0
    failed: int = 0
    errors: int = 0

    @property
    def finished(self) -> int:
        return self.ok + self.failed + self.errors

    def add(self, record: TaskRecord) -> None:
        if record.success:
            self.ok += 1
        elif is_error(record):
            self.errors += 1
        else:
            self.failed += 1


@dataclass
class LineReporter:
    """One line of counts every ``every`` seconds (and a last one), to a stream."""

    stream: TextIO
    counts: Counts
    every: float = LINE_EVERY
    clock: Callable[[], float] = time.monotonic
    started: float = field(init=False)
    printed_at: float = field(init=False)
    printed: int = field(init=False, default=-1)
    marks: tuple[str, str] = field(init=False)

    def __post_init__(self) -> None:
        self.started = self.printed_at = self.clock()
        self.marks = ("✓", "✗") if _can_write(self.stream, "✓✗") else ("ok", "failed")

    def begin(self, resumed: int) -> None:
        left = self.counts.total - resumed
        self._write(
            f"bench: {self.counts.total} task(s), {resumed} already finished, {left} to run"
        )
        self.printed = self.counts.finished

    def __call__(self, record: TaskRecord) -> None:
        self.counts.add(record)
        if self.clock() - self.printed_at >= self.every:
            self.line()

    def line(self) -> None:
        """The counts now (skipped when nothing changed since the last line)."""
        counts = self.counts
        if counts.finished == self.printed:
            return
        seconds = int(self.clock() - self.started)
        ok, failed = self.marks
        self._write(
            f"bench: {counts.finished}/{counts.total} finished "
            f"({seconds // 60}:{seconds % 60:02d}): {counts.ok} {ok}, {counts.failed} "
            f"{failed}, {counts.errors} error(s)"
        )
        self.printed, self.printed_at = counts.finished, self.clock()

    def notice(self, message: str) -> None:
        print(message, file=sys.stderr, flush=True)

    def _write(self, text: str) -> None:
        print(text, file=self.stream, flush=True)


def _can_write(stream: TextIO, text: str) -> bool:
    try:
        text.encode(getattr(stream, "encoding", None) or "utf-8")
    except (UnicodeEncodeError, LookupError):
        return False
    return True


class _Bars:
    """One rich bar per method with its live success count."""

    def __init__(self, bar: Any, tasks: dict[str, Any], ok: dict[str, int]) -> None:
        self.bar, self.tasks, self.ok = bar, tasks, ok

    def __call__(self, record: TaskRecord) -> None:
        self.ok[record.method] += record.success
        self.bar.update(self.tasks[record.method], advance=1, ok=self.ok[record.method])

    def notice(self, message: str) -> None:
        self.bar.console.print(f"[yellow]{message}[/yellow]", soft_wrap=True)


class _Quiet:
    def __call__(self, record: TaskRecord) -> None:
        pass

    def notice(self, message: str) -> None:
        print(message, file=sys.stderr, flush=True)


class _Both:
    """Bars on the terminal and lines in the log."""

    def __init__(self, bars: Reporter, lines: LineReporter) -> None:
        self.bars, self.lines = bars, lines

    def __call__(self, record: TaskRecord) -> None:
        self.bars(record)
        self.lines(record)

    def notice(self, message: str) -> None:
        self.bars.notice(message)


@contextmanager
def progress(
    enabled: bool, methods: list[str], done: list[TaskRecord], total: dict[str, int]
) -> Iterator[Reporter]:
    """Report a run's progress. ``done``: records finished before (resumed); ``total``: tasks
    per method. Without ``enabled`` only notices are shown (on stderr)."""
    if not enabled:
        yield _Quiet()
        return
    from rich.console import Console

    terminal = Console(stderr=True)
    counts = Counts(sum(total.values()))
    for record in done:
        counts.add(record)
    lines: LineReporter | None = None
    if not terminal.is_terminal or not Console(file=sys.stdout).is_terminal:
        lines = LineReporter(sys.stdout, counts)
        lines.begin(len(done))
    if not terminal.is_terminal:
        assert lines is not None
        try:
            yield lines
        finally:
            lines.line()
        return
    with _bars(terminal, methods, done, total) as bars:
        try:
            yield _Both(bars, lines) if lines is not None else bars
        finally:
            if lines is not None:
                lines.line()


@contextmanager
def _bars(
    console: Any, methods: list[str], done: list[TaskRecord], total: dict[str, int]
) -> Iterator[_Bars]:
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

    names = list(dict.fromkeys(methods))
    ok = {m: sum(r.success for r in done if r.method == m) for m in names}
    with Progress(
        TextColumn("{task.description}"),
        BarColumn(),
        MofNCompleteColumn(),
        TextColumn("[green]{task.fields[ok]} ok"),
        TimeElapsedColumn(),
        console=console,
    ) as bar:
        width = max(map(len, names), default=0)
        tasks = {
            m: bar.add_task(
                m.ljust(width),
                total=total.get(m, 0),
                completed=sum(r.method == m for r in done),
                ok=ok[m],
            )
            for m in names
        }
        yield _Bars(bar, tasks, ok)
