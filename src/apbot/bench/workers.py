"""Worker processes that never outlive the benchmark that started them.

SIGKILL cannot be caught, so a killed main process cannot stop its workers; left alone they
live on, blocked writing a result into a pipe nobody reads. On Linux each worker asks the
kernel to kill it when its parent dies (``prctl(PR_SET_PDEATHSIG)``): immediate, and it works
whatever the worker is doing, even blocked in a system call, with no thread to keep. Elsewhere
a daemon thread polls the parent's pid once a second.
"""

from __future__ import annotations

import ctypes
import multiprocessing
import os
import signal
import sys
import threading
import time
from concurrent.futures import ProcessPoolExecutor

_PR_SET_PDEATHSIG = 1  # from <linux/prctl.h>


def _kill_me_with_parent() -> bool:
    """Ask the Linux kernel for SIGKILL when the parent dies; False where that is not offered."""
    if not sys.platform.startswith("linux"):
        return False
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        return int(libc.prctl(_PR_SET_PDEATHSIG, int(signal.SIGKILL), 0, 0, 0)) == 0
    except (OSError, AttributeError):
        return False


def _watch_parent(parent: int, every: float = 1.0) -> None:
    def watch() -> None:
        while os.getppid() == parent:
            time.sleep(every)
        os._exit(1)

    threading.Thread(target=watch, name="apbot-parent-watch", daemon=True).start()


def die_with_parent(parent: int) -> None:
    """End this process as soon as ``parent`` (the pid that started it) is gone."""
    if not _kill_me_with_parent():
        _watch_parent(parent)
    if os.getppid() != parent:  # the parent died before the kernel was asked to tell us
        os._exit(1)


def worker_init(parent: int) -> None:
    """Set a worker up: Ctrl-C is the main process's to handle (it stops the workers cleanly);
    SIGTERM ends a worker at once (a forked worker would otherwise inherit the main process's
    handler and ignore it); and the worker dies with its parent."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    die_with_parent(parent)


def worker_pool(workers: int) -> ProcessPoolExecutor:
    """A pool whose workers die with this process.

    On Linux the workers are forked (whatever Python's default start method): they inherit
    the loaded suite instead of loading it again, and their parent is this process, the one
    whose death must end them.
    """
    context = multiprocessing.get_context("fork") if sys.platform.startswith("linux") else None
    return ProcessPoolExecutor(
        workers, mp_context=context, initializer=worker_init, initargs=(os.getpid(),)
    )
