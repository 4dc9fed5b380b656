"""Stopping a benchmark early without losing what it finished: Ctrl-C, ``kill`` and the like.

SIGINT (Ctrl-C) and SIGTERM (a plain ``kill``, a service manager, a shutdown) are handled
alike: the first one lets the running tasks finish and starts no more, a second one abandons
the running tasks too. Either way every finished record is already on disk and the same
command resumes the run.
"""

from __future__ import annotations

import signal
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

HANDLED = (signal.SIGINT, signal.SIGTERM)
WORKER_DIED = "a worker process died"


class Stop:
    """What the run was asked to do about stopping; the handler of the signals in ``HANDLED``.

    ``in_process``: the tasks run in this process, so abandoning one means raising
    :class:`KeyboardInterrupt` inside it.
    """

    def __init__(self, in_process: bool) -> None:
        self.in_process = in_process
        self.reason = ""  # why the run stopped early: "SIGINT", "SIGTERM" or WORKER_DIED
        self.signum: int | None = None
        self.hard = False
        self.notice: Callable[[str], None] = lambda message: None

    @property
    def requested(self) -> bool:
        return bool(self.reason)

    def request(self, reason: str) -> None:
        """Stop without a handled signal: a worker died, or a KeyboardInterrupt arrived."""
        if not self.reason:
            self.reason = reason
            if reason in signal.Signals.__members__:
                self.signum = signal.Signals[reason]

    def __call__(self, signum: int, frame: Any) -> None:
        if self.signum is not None:
            self.hard = True
            if self.in_process:
                raise KeyboardInterrupt
            return
        # first signal (a worker may have died of the same one a moment before: this is why)
        name = signal.Signals(signum).name
        self.reason, self.signum = name, signum
        again = "Ctrl-C" if signum == signal.SIGINT else name
        self.notice(
            f"stopping ({name}): finishing the running tasks ({again} again to abandon them)"
        )

    @property
    def exit_code(self) -> int:
        """The shell's convention: 128 + the signal's number; 1 when a worker died."""
        return 128 + self.signum if self.signum is not None else 1


@contextmanager
def handling_signals(stop: Stop) -> Iterator[None]:
    """Route SIGINT and SIGTERM to ``stop`` for the duration, then restore what was there."""
    previous: dict[int, Any] = {}
    try:
        for signum in HANDLED:
            previous[signum] = signal.signal(signum, stop)
    except ValueError:  # not the main thread: signals are not ours to take
        pass
    try:
        yield
    finally:
        for number, handler in previous.items():
            signal.signal(number, handler)
