"""Kill a benchmark mid-run, resume it, and check it ends exactly like an uninterrupted run.

    python benchmarks/resume_check.py [--full] [--after 200] [--signal KILL|INT] [--workers 2]
                                      [--methods a,b] [--belief true] [--keep DIR]

Starts ``apbot bench`` (default: the first 2 tasks of every appliance; ``--full``: all of them)
into a temporary directory, sends the signal to its process group once ``--after`` records
exist (KILL: a crash, workers included; INT: Ctrl-C, which must stop cleanly with exit code
130), runs the same command again to completion, then runs the same benchmark uninterrupted
into another directory and compares: the same set of keys, no duplicate lines, identical
records except ``timings``, and a byte-identical ``summary.json``. Exits 1 on any difference.
"""

from __future__ import annotations

import argparse
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


def interrupt(args: argparse.Namespace, out: Path) -> tuple[int, int, float]:
    """Start the run, signal it after ``--after`` records; (exit code, records then, seconds)."""
    started = time.perf_counter()
    process = subprocess.Popen(
        bench_command(args, out),
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        start_new_session=True,
    )
    results = out / RESULTS
    try:
        while count_lines(results) < args.after:
            if process.poll() is not None:
                sys.exit(
                    f"the run ended (exit {process.returncode}) before {args.after} "
                    f"records existed; lower --after\n{process.stderr.read().decode()}"
                )
            time.sleep(0.02)
        seen = count_lines(results)
        os.killpg(process.pid, getattr(signal, f"SIG{args.signal}"))
        code = process.wait(timeout=120)
    finally:
        if process.poll() is None:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
    return code, seen, time.perf_counter() - started


def run(command: list[str]) -> float:
    started = time.perf_counter()
    done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed (exit {done.returncode}):\n{done.stderr}")
    return time.perf_counter() - started


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
    if (resumed / "summary.json").read_bytes() != (straight / "summary.json").read_bytes():
        problems.append("summary.json differs")
    return problems


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--full", action="store_true", help="all 450 tasks, not 2 per appliance")
    parser.add_argument("--after", type=int, default=200, help="records before the signal")
    parser.add_argument("--signal", choices=["KILL", "INT", "TERM"], default="KILL")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--methods", default=None, help="comma-separated (default: all)")
    parser.add_argument("--belief", default="true")
    parser.add_argument(
        "--keep",
        type=Path,
        default=None,
        help="put the two run directories here instead of a temporary one",
    )
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="apbot-resume-") as temporary:
        base = args.keep or Path(temporary)
        resumed, straight = base / "resumed", base / "uninterrupted"
        for directory in (resumed, straight):
            if directory.exists():
                sys.exit(f"{directory} exists; choose an empty --keep directory")
        code, seen, first = interrupt(args, resumed)
        kept = count_lines(resumed / RESULTS)
        expected = 130 if args.signal == "INT" else -getattr(signal, f"SIG{args.signal}")
        second = run(bench_command(args, resumed))
        total = len(load_lines(resumed / RESULTS))
        third = run(bench_command(args, straight))
        problems = compare(resumed, straight)
        if code != expected:
            problems.append(f"the interrupted run exited {code}, expected {expected}")
        print(
            f"SIG{args.signal} after {seen} records ({first:.1f} s): exit {code}, "
            f"{kept} complete record(s) kept"
        )
        print(
            f"resumed to {total} records in {second:.1f} s; uninterrupted run: "
            f"{count_lines(straight / RESULTS)} records in {third:.1f} s"
        )
        if problems:
            print("DIFFERENT:\n  " + "\n  ".join(problems))
            sys.exit(1)
        print(
            "identical: same keys, no duplicates, same records (timings aside), same summary.json"
        )


if __name__ == "__main__":
    main()
