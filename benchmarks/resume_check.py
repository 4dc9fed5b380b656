"""Kill a benchmark mid-run in every way a user can, resume it, and check it ends exactly like
an uninterrupted run.

    python benchmarks/resume_check.py [--full] [--after 200] [--cases KILL:main,TERM:main,...]
                                      [--workers 2] [--methods a,b] [--belief true] [--keep DIR]

The kill matrix (``--cases``, default all of them), each case on its own run directory:

* ``KILL:main``  SIGKILL to the main process alone (its workers must die with it and leave
  the directory's lock free);
* ``KILL:group`` SIGKILL to the whole process group, workers included (a crash);
* ``TERM:main``  SIGTERM to the main process (a plain ``kill``): it must stop cleanly, keep
  every finished record and exit 143;
* ``TERM:group`` SIGTERM to the group (a shutdown): the workers die, the main process stops
  cleanly and exits 143;
* ``INT:group``  SIGINT to the group (Ctrl-C in a terminal): exit 130.

Each starts ``apbot bench`` (default: the first 2 tasks of every appliance; ``--full``: all of
them), sends the signal once ``--after`` records exist, checks that no process of the run is
left a few seconds later, runs the same command again to completion, and compares the result
with one uninterrupted run of the same benchmark: the same set of keys, no duplicate lines,
identical records except ``timings``, and a byte-identical ``summary.json``. Exits 1 on any
difference.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

RESULTS = "results.jsonl"
CASES = ("KILL:main", "KILL:group", "TERM:main", "TERM:group", "INT:group")
EXPECTED_EXIT = {"KILL": -signal.SIGKILL, "TERM": 128 + signal.SIGTERM, "INT": 130}
GRACE = 10.0  # seconds the run's processes may take to be gone after the signal


def bench_command(args: argparse.Namespace, out: Path) -> list[str]:
    command = [
        sys.executable,
        "-m",
        "apbot.cli",
        "bench",
        "--out",
        str(out),
        "--no-report",
        "--workers",
        str(args.workers),
        "--belief",
        args.belief,
    ]
    if not args.full:
        command += ["--sample", "2"]
    if args.methods:
        command += ["--methods", args.methods]
    return command


def count_lines(path: Path) -> int:
    return path.read_bytes().count(b"\n") if path.exists() else 0


def group_members(group: int) -> list[int]:
    """Live (not zombie) processes of a process group."""
    proc = Path("/proc")
    if not proc.is_dir():  # not Linux: ask the kernel whether anyone is left
        try:
            os.killpg(group, 0)
        except ProcessLookupError:
            return []
        return [group]
    members = []
    for entry in proc.iterdir():
        if not entry.name.isdigit():
            continue
        try:
            fields = (entry / "stat").read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        state, pgrp = fields[0], int(fields[2])
        if pgrp == group and state != "Z":
            members.append(int(entry.name))
    return members


def interrupt(args: argparse.Namespace, case: str, out: Path) -> dict[str, Any]:
    """Start the run, signal it after ``--after`` records; what happened."""
    name, target = case.split(":")
    number = getattr(signal, f"SIG{name}")
    started = time.perf_counter()
    # stderr to a file, not a pipe: a process left behind would keep a pipe open forever
    with tempfile.TemporaryFile() as errors:
        process = subprocess.Popen(
            bench_command(args, out),
            stdout=subprocess.DEVNULL,
            stderr=errors,
            start_new_session=True,
        )
        results = out / RESULTS
        left: list[int] = []
        try:
            while count_lines(results) < args.after:
                if process.poll() is not None:
                    sys.exit(
                        f"{case}: the run ended (exit {process.returncode}) before {args.after} "
                        f"records existed; lower --after\n{last_lines(errors, 20)}"
                    )
                time.sleep(0.02)
            seen = count_lines(results)
            if target == "group":
                os.killpg(process.pid, number)
            else:
                os.kill(process.pid, number)
            code = process.wait(timeout=120)
            deadline = time.monotonic() + GRACE
            while (left := group_members(process.pid)) and time.monotonic() < deadline:
                time.sleep(0.05)
        finally:
            if process.poll() is None:
                os.killpg(process.pid, signal.SIGKILL)
                process.wait()
        return {
            "code": code,
            "expected": EXPECTED_EXIT[name],
            "seen": seen,
            "kept": count_lines(results),
            "left": left,
            "seconds": time.perf_counter() - started,
            "stderr": last_lines(errors, 1),
        }


def last_lines(stream: Any, count: int) -> str:
    stream.seek(0)
    return "\n".join(stream.read().decode(errors="replace").strip().splitlines()[-count:])


def run(command: list[str]) -> tuple[float, str]:
    """Run to completion: (seconds, the error's last line or "")."""
    started = time.perf_counter()
    with tempfile.TemporaryFile() as errors:
        code = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=errors).returncode
        error = f"exit {code}: {last_lines(errors, 1)}" if code else ""
    return time.perf_counter() - started, error


def load_lines(path: Path) -> list[dict[str, Any]]:
    return [json.loads(line) for line in path.read_text(encoding="utf-8").splitlines() if line]


def compare(resumed: Path, straight: Path) -> list[str]:
    """Every difference between the resumed run and the uninterrupted one."""
    problems = []
    a, b = load_lines(resumed / RESULTS), load_lines(straight / RESULTS)
    for name, lines in (("resumed", a), ("uninterrupted", b)):
        keys = [r["key"] for r in lines]
        if len(keys) != len(set(keys)):
            problems.append(f"{name}: {len(keys) - len(set(keys))} duplicate line(s)")
    by_key_a = {r["key"]: r for r in a}
    by_key_b = {r["key"]: r for r in b}
    if by_key_a.keys() != by_key_b.keys():
        problems.append(
            f"key sets differ: {len(by_key_a.keys() - by_key_b.keys())} only "
            f"resumed, {len(by_key_b.keys() - by_key_a.keys())} only uninterrupted"
        )
    differing = [
        k
        for k in sorted(by_key_a.keys() & by_key_b.keys())
        if {**by_key_a[k], "timings": None} != {**by_key_b[k], "timings": None}
    ]
    if differing:
        problems.append(f"{len(differing)} record(s) differ, e.g. {differing[0]}")
    summary = resumed / "summary.json"
    if not summary.exists():
        problems.append("no summary.json")
    elif summary.read_bytes() != (straight / "summary.json").read_bytes():
        problems.append("summary.json differs")
    return problems


def check_case(args: argparse.Namespace, case: str, base: Path, straight: Path) -> list[str]:
    """Interrupt, resume and compare one case; print one line; the problems found."""
    resumed = base / case.replace(":", "-")
    what = interrupt(args, case, resumed)
    try:
        seconds, error = run(bench_command(args, resumed))  # while any leftover still runs
    finally:
        for pid in what["left"]:  # reported as a failure below; do not leave them running
            with contextlib.suppress(ProcessLookupError):
                os.kill(pid, signal.SIGKILL)
    total = len(load_lines(resumed / RESULTS))
    problems = [f"the resumed run failed ({error})"] if error else []
    problems += compare(resumed, straight)
    if what["code"] != what["expected"]:
        problems.append(f"exited {what['code']}, expected {what['expected']} {what['stderr']}")
    if what["left"]:
        problems.append(f"{len(what['left'])} process(es) of the run left after {GRACE:g} s")
    verdict = "identical" if not problems else "DIFFERENT: " + "; ".join(problems)
    print(
        f"{case:<11} after {what['seen']:>4} records ({what['seconds']:.1f} s): exit "
        f"{what['code']}, {what['kept']} kept, {len(what['left'])} process(es) left; "
        f"resumed to {total} in {seconds:.1f} s: {verdict}",
        flush=True,
    )
    return problems


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--full", action="store_true", help="all 450 tasks, not 2 per appliance")
    parser.add_argument("--after", type=int, default=200, help="records before the signal")
    parser.add_argument(
        "--cases", default=",".join(CASES), help=f"comma-separated, of {', '.join(CASES)}"
    )
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--methods", default=None, help="comma-separated (default: all)")
    parser.add_argument("--belief", default="true")
    parser.add_argument(
        "--keep",
        type=Path,
        default=None,
        help="put the run directories here instead of a temporary one",
    )
    args = parser.parse_args()
    cases = [case.strip() for case in args.cases.split(",") if case.strip()]
    unknown = [case for case in cases if case not in CASES]
    if unknown or not cases:
        parser.error(f"unknown case(s) {', '.join(unknown)}; known: {', '.join(CASES)}")
    with tempfile.TemporaryDirectory(prefix="apbot-resume-") as temporary:
        base = args.keep or Path(temporary)
        straight = base / "uninterrupted"
        for directory in [straight, *(base / case.replace(":", "-") for case in cases)]:
            if directory.exists():
                sys.exit(f"{directory} exists; choose an empty --keep directory")
        seconds, error = run(bench_command(args, straight))
        if error:
            sys.exit(f"the uninterrupted run failed ({error})")
        print(f"uninterrupted: {count_lines(straight / RESULTS)} records in {seconds:.1f} s")
        failed = [case for case in cases if check_case(args, case, base, straight)]
        if failed:
            print(f"DIFFERENT in {len(failed)} of {len(cases)} case(s): {', '.join(failed)}")
            sys.exit(1)
        print(
            f"all {len(cases)} case(s) identical: same keys, no duplicates, same records "
            "(timings aside), same summary.json, no process left behind"
        )


if __name__ == "__main__":
    main()
