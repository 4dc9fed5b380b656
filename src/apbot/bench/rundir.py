"""The run directory of a benchmark: where it may be, what it pins, who may write it.

``--out`` is checked before any work: empty, a file, a path under a file, or a directory
that cannot be created or written is a one-line error naming the path (a probe file is
created and removed: the one test of writability that holds for root, and for immutable or
read-only mounts, too).

``run.json`` pins the suite, belief, seed and feedback mode of a directory: mixing runs with
different ones would make the records' keys ambiguous. It also records the code version and
the suite's digest (:mod:`apbot.bench.provenance`): a directory written by other code or from
another state of the suite is not resumed, since its records would not be comparable.

One ``apbot bench`` at a time writes a directory (an exclusive ``flock`` on ``.lock``). The
lock is the process's own and dies with it: a forked child (a worker) closes its inherited
copy at once, so a killed run never leaves its lock behind in a worker that outlives it.
"""

from __future__ import annotations

import errno
import json
import os
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager, suppress
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from apbot.bench.provenance import describe_code, same_code

RUN_FILE = "run.json"
LOCK_FILE = ".lock"
PINNED = ("suite", "belief", "seed", "feedback", "goal", "learn")  # what a run cannot mix


class BenchError(ValueError):
    """A benchmark that cannot start as asked (here: its run directory); the message says what
    to change. Defined here, the first place a run can fail, and re-exported by the runner."""


# --- where ---------------------------------------------------------------------------------


def run_directory(out: str | os.PathLike[str]) -> Path:
    """The run directory ``out`` names; :class:`BenchError` when it cannot be one.

    Nothing is created here (a run refused for another reason leaves no directory behind).
    """
    text = os.fspath(out)
    if not text.strip():
        raise BenchError("--out is empty; name a run directory, e.g. --out runs/latest")
    path = Path(text)
    try:
        for place in (path, *path.parents):
            if place.is_dir():
                return path
            if place.exists() or place.is_symlink():
                what = "a file" if place.is_file() else "not a directory"
                if place == path:
                    raise BenchError(f"the run directory {path} is {what}; use another --out")
                raise BenchError(
                    f"{place} is {what}, so the run directory {path} cannot be created; "
                    "use another --out"
                )
    except OSError as exc:
        raise BenchError(f"cannot reach the run directory {path}: {exc.strerror}") from None
    return path


def make_writable(path: Path) -> None:
    """Create the run directory if need be and prove it can be written."""
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise BenchError(
            f"cannot create the run directory {path}: {exc.strerror}; use another --out"
        ) from None
    try:
        with tempfile.NamedTemporaryFile(dir=path, prefix=".write-test-"):
            pass
    except OSError as exc:
        raise BenchError(
            f"the run directory {path} is not writable ({exc.strerror}); use another --out"
        ) from None


# --- the lock ---------------------------------------------------------------------------------

_HELD_LOCKS: set[int] = set()  # descriptors of the locks this process holds


def _close_held_locks() -> None:
    """In a freshly forked child: drop the parent's lock descriptors (the lock stays the
    parent's: closing one copy of a descriptor does not unlock it)."""
    for descriptor in list(_HELD_LOCKS):
        with suppress(OSError):
            os.close(descriptor)
    _HELD_LOCKS.clear()


if hasattr(os, "register_at_fork"):
    os.register_at_fork(after_in_child=_close_held_locks)


@contextmanager
def exclusive(directory: Path) -> Iterator[None]:
    """Hold an exclusive lock on the run directory (where the platform has ``fcntl``)."""
    try:
        import fcntl
    except ImportError:  # pragma: no cover - not POSIX
        yield
        return
    try:
        descriptor = os.open(directory / LOCK_FILE, os.O_WRONLY | os.O_CREAT | os.O_CLOEXEC, 0o644)
    except OSError as exc:
        raise BenchError(f"cannot lock {directory / LOCK_FILE}: {exc.strerror}") from None
    _HELD_LOCKS.add(descriptor)
    try:
        try:
            fcntl.flock(descriptor, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError as exc:
            if exc.errno in (errno.EWOULDBLOCK, errno.EAGAIN, errno.EACCES):
                raise BenchError(
                    f"another `apbot bench` is writing to {directory}; "
                    "wait for it or use another --out"
                ) from None
            raise BenchError(f"cannot lock {directory / LOCK_FILE}: {exc.strerror}") from None
        try:
            yield
        finally:
            fcntl.flock(descriptor, fcntl.LOCK_UN)
    finally:
        _HELD_LOCKS.discard(descriptor)
        os.close(descriptor)


# --- run.json ---------------------------------------------------------------------------------


def _now() -> str:
    return datetime.now(UTC).isoformat(timespec="seconds")


def prepare(
    out: Path,
    pinned: dict[str, Any],
    provenance: dict[str, Any],
    details: dict[str, Any],
    rerun: bool,
    results_file: str,
) -> None:
    """Write ``run.json``; refuse to mix another suite, belief, seed, code version or state of
    the suite into the directory.

    ``pinned`` and ``provenance`` (``code``, ``suite_digest``) must match what the directory
    holds (unless ``rerun``); ``details`` (methods, selection, task count) are recorded as
    they are now.
    """
    run_file = out / RUN_FILE
    previous: dict[str, Any] = {}
    if run_file.exists() and not rerun:
        try:
            previous = json.loads(run_file.read_text(encoding="utf-8"))
            if not isinstance(previous, dict):
                raise ValueError("not a JSON object")
        except (OSError, ValueError) as exc:
            why = exc.strerror if isinstance(exc, OSError) else exc
            raise BenchError(
                f"{run_file} cannot be read ({why}); use --rerun or another --out"
            ) from None
        differ = [
            f"{k} {previous.get(k)!r} (asked: {pinned[k]!r})"
            for k in PINNED
            if previous.get(k) != pinned[k]
        ]
        if differ:
            raise BenchError(
                f"{out} holds a run with {'; '.join(differ)}; use another --out, "
                "or --rerun to discard its results"
            )
        changed = _provenance_changes(previous, provenance)
        if changed:
            raise BenchError(
                f"{out}: {'; '.join(changed)}; its records are not comparable with new ones: "
                "use another --out, or --rerun to discard them"
            )
    elif (out / results_file).exists() and not rerun:
        raise BenchError(
            f"{out} has {results_file} but no {RUN_FILE}, so its suite, belief "
            "and seed are unknown; use another --out, or --rerun to discard it"
        )
    make_writable(out)
    info = {
        **pinned,
        **provenance,
        **details,
        "started": previous.get("started", _now()),
        "updated": _now(),
    }
    write_json(run_file, info)


def _provenance_changes(previous: dict[str, Any], now: dict[str, Any]) -> list[str]:
    """What differs between the code and suite that wrote ``previous`` and those of ``now``."""
    changes = []
    if not same_code(previous.get("code"), now["code"]):
        changes.append(
            f"it was written by {describe_code(previous.get('code'))} and this is "
            f"{describe_code(now['code'])}"
        )
    before, after = previous.get("suite_digest"), now["suite_digest"]
    if before != after:
        was = f"is {str(before)[:19]}…" if before else "was not recorded"
        changes.append(
            f"its suite digest {was} and the suite's is now {str(after)[:19]}… (the suite's "
            "models, tasks or manuals changed)"
        )
    return changes


def write_json(path: Path, data: Any) -> None:
    """Write JSON atomically (a reader never sees half a file)."""
    temporary = path.with_name(path.name + ".tmp")
    try:
        temporary.write_text(
            json.dumps(data, indent=2, sort_keys=True, ensure_ascii=False) + "\n",
            encoding="utf-8",
        )
        os.replace(temporary, path)
    except OSError as exc:
        raise BenchError(f"cannot write {path}: {exc.strerror}") from None
