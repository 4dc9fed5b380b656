"""The run directory: one writer at a time, and a lock that dies with its process."""

from __future__ import annotations

import os
import shutil
import stat
import subprocess
import sys
import textwrap
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
from typer.testing import CliRunner

from apbot.bench.rundir import LOCK_FILE, BenchError, exclusive, make_writable, run_directory
from apbot.cli import app


def _writable(directory: Path) -> bool:
    try:
        (directory / "probe").touch()
    except OSError:
        return False
    (directory / "probe").unlink()
    return True


@pytest.fixture
def read_only(tmp_path: Path) -> Iterator[Path]:
    """A directory nobody can write: by its mode, or (for root, whom modes do not stop)
    by the immutable attribute; skipped where neither is possible."""
    directory = tmp_path / "read-only"
    directory.mkdir()
    directory.chmod(stat.S_IRUSR | stat.S_IXUSR)
    immutable = False
    if _writable(directory) and shutil.which("chattr"):
        immutable = (
            subprocess.run(["chattr", "+i", str(directory)], capture_output=True).returncode == 0
        )
    try:
        if _writable(directory):
            pytest.skip("cannot make a directory read-only here")
        yield directory
    finally:
        if immutable:
            subprocess.run(["chattr", "-i", str(directory)], check=True)
        directory.chmod(stat.S_IRWXU)


def test_out_must_name_a_directory_that_can_be_made(tmp_path: Path) -> None:
    afile = tmp_path / "afile"
    afile.write_text("not a directory")
    for out, message in (
        ("", "--out is empty"),
        ("  ", "--out is empty"),
        (afile, f"the run directory {afile} is a file; use another --out"),
        (afile / "sub", f"{afile} is a file, so the run directory {afile / 'sub'} cannot be"),
        (afile / "a" / "b", f"{afile} is a file, so the run directory"),
    ):
        with pytest.raises(BenchError, match=message.replace("(", r"\(")):
            run_directory(out)
    assert run_directory(tmp_path / "new" / "deeper") == tmp_path / "new" / "deeper"
    assert not (tmp_path / "new").exists()  # checking creates nothing


def test_a_read_only_directory_is_refused_with_its_name(read_only: Path) -> None:
    with pytest.raises(BenchError, match=f"the run directory {read_only} is not writable"):
        make_writable(read_only)
    with pytest.raises(BenchError, match=f"cannot create the run directory {read_only / 'x'}"):
        make_writable(read_only / "x")


@pytest.mark.parametrize("where", ["", "afile", "afile/sub", "read-only", "read-only/sub"])
def test_the_bench_command_says_what_is_wrong_with_out_in_one_line(
    tmp_path: Path, where: str, monkeypatch: pytest.MonkeyPatch, request: pytest.FixtureRequest
) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "afile").write_text("x")
    if where.startswith("read-only"):
        request.getfixturevalue("read_only")
    command = ["bench", "--methods", "oracle", "--appliances", "kettle_1", "--sample", "1"]
    result = CliRunner().invoke(app, [*command, "--workers", "1", "--no-report", "--out", where])
    assert result.exit_code == 2, result.output
    assert result.output.startswith("error: ") and result.output.count("\n") == 1, result.output
    assert "--out" in result.output and "Traceback" not in result.output
    made = {"afile", "read-only"} if where.startswith("read-only") else {"afile"}
    assert {p.name for p in tmp_path.iterdir()} == made  # nothing written, not even in "."


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
    deadline = time.monotonic() + 3  # the child closes its copy as soon as it is scheduled
    try:
        while True:
            try:
                with exclusive(tmp_path):
                    break
            except BenchError:
                if time.monotonic() > deadline:
                    raise
                time.sleep(0.02)
    finally:
        os.kill(child, 9)
