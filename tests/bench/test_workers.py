"""Worker processes die with the process that started them, however it dies."""

from __future__ import annotations

import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

pytestmark = pytest.mark.skipif(not Path("/proc").is_dir(), reason="reads /proc (Linux)")


def alive(pid: int) -> bool:
    """Running, not a zombie waiting to be reaped."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return False
    return stat.rsplit(")", 1)[1].split()[0] != "Z"


def run_script(script: str, tmp_path: Path) -> tuple[int, str]:
    """Run ``script`` in a fresh interpreter; (exit code, what it printed). Its output goes to
    a file, so a child that (wrongly) outlives it cannot keep this waiting."""
    output = tmp_path / "stdout"
    with output.open("w") as handle:
        done = subprocess.run(
            [sys.executable, "-c", textwrap.dedent(script)],
            stdout=handle,
            stderr=subprocess.STDOUT,
            timeout=30,
        )
    return done.returncode, output.read_text()


def orphan_after_parent_is_killed(script: str, tmp_path: Path) -> int:
    """Run ``script`` (which prints a child's pid, then SIGKILLs itself); the child's pid."""
    code, printed = run_script(script, tmp_path)
    assert code == -9, printed
    return int(printed.split()[0])


def gone_within(pid: int, seconds: float) -> bool:
    deadline = time.monotonic() + seconds
    while alive(pid):
        if time.monotonic() > deadline:
            subprocess.run(["kill", "-9", str(pid)], check=False)  # do not leave it behind
            return False
        time.sleep(0.02)
    return True


def test_a_pool_worker_dies_when_the_main_process_is_killed(tmp_path: Path) -> None:
    worker = orphan_after_parent_is_killed(
        """
        import os, signal
        from apbot.bench.workers import worker_pool
        pool = worker_pool(1)
        print(pool.submit(os.getpid).result(), flush=True)
        os.kill(os.getpid(), signal.SIGKILL)
        """,
        tmp_path,
    )
    assert gone_within(worker, 3.0), "the worker outlived its parent"


def test_where_the_kernel_cannot_tell_a_thread_watches_the_parent(tmp_path: Path) -> None:
    child = orphan_after_parent_is_killed(
        """
        import os, signal, time
        from apbot.bench.workers import _watch_parent
        parent = os.getpid()
        pid = os.fork()
        if pid == 0:
            _watch_parent(parent, every=0.02)
            time.sleep(30)
            os._exit(0)
        print(pid, flush=True)
        time.sleep(0.2)
        os.kill(parent, signal.SIGKILL)
        """,
        tmp_path,
    )
    assert gone_within(child, 3.0), "the watched child outlived its parent"


def test_workers_leave_ctrl_c_to_the_main_process_but_die_of_sigterm(tmp_path: Path) -> None:
    code, printed = run_script(
        """
        import os, signal
        from apbot.bench.workers import worker_pool

        def dispositions():
            return (
                signal.getsignal(signal.SIGINT) == signal.SIG_IGN,
                signal.getsignal(signal.SIGTERM) == signal.SIG_DFL,
            )

        signal.signal(signal.SIGTERM, lambda *a: None)  # the main process's own handler
        print(*worker_pool(1).submit(dispositions).result())
        """,
        tmp_path,
    )
    assert (code, printed.split()) == (0, ["True", "True"]), printed
