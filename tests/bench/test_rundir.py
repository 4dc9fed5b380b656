"""The run directory: one writer at a time, and a lock that dies with its process."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from apbot.bench.rundir import LOCK_FILE, BenchError, exclusive


def test_a_second_writer_is_refused_until_the_first_is_done(tmp_path: Path) -> None:
    with (
        exclusive(tmp_path),
        pytest.raises(BenchError, match=f"another .* {tmp_path}"),
        exclusive(tmp_path),
    ):
        pass
    with exclusive(tmp_path):  # free again
        pass


@pytest.mark.skipif(not Path("/proc/self/fd").is_dir(), reason="reads /proc (Linux)")
def test_a_forked_child_does_not_inherit_the_lock(tmp_path: Path) -> None:
    lock = str(tmp_path / LOCK_FILE)
    with exclusive(tmp_path):
        read, write = os.pipe()
        pid = os.fork()
        if pid == 0:  # the child: does any descriptor still point at the lock file?
            held = any(
                os.path.realpath(f"/proc/self/fd/{fd}") == lock
                for fd in os.listdir("/proc/self/fd")
            )
            os.write(write, b"held" if held else b"free")
            os._exit(0)
        os.close(write)
        answer = os.read(read, 4)
        os.close(read)
        os.waitpid(pid, 0)
    assert answer == b"free"


def test_a_killed_run_leaves_no_lock_behind_in_its_children(tmp_path: Path) -> None:
    """The lock holder forks a long-lived child, then dies by SIGKILL: the lock is free."""
    script = f"""
        import os, signal, time
        from pathlib import Path
        from apbot.bench.rundir import exclusive
        with exclusive(Path({str(tmp_path)!r})):
            pid = os.fork()
            if pid == 0:
                time.sleep(30)
                os._exit(0)
            print(pid, flush=True)
            os.kill(os.getpid(), signal.SIGKILL)
    """
    printed = tmp_path / "stdout"
    with printed.open("w") as handle:  # a file, not a pipe the child would keep open
        done = subprocess.run(
            [sys.executable, "-c", textwrap.dedent(script)], stdout=handle, timeout=30
        )
    assert done.returncode == -9
    child = int(printed.read_text().split()[0])
    try:
        with exclusive(tmp_path):
            pass
    finally:
        os.kill(child, 9)
