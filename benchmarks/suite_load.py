"""How long loading the whole bundled suite takes (manuals, models, panels, tasks).

    python benchmarks/suite_load.py [--repeat 5] [--check]

Each repetition runs in a fresh interpreter so no cache helps. ``--check`` also runs every
semantic model check while loading.
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys

PROBE = """
import time
started = time.perf_counter()
from apbot.bench.suite import load_suite
suite = load_suite(check={check})
print(time.perf_counter() - started, len(suite.appliances), len(suite.tasks))
"""


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    seconds = []
    for _ in range(args.repeat):
        out = subprocess.run(
            [sys.executable, "-c", PROBE.format(check=args.check)],
            capture_output=True,
            text=True,
            check=True,
        ).stdout.split()
        seconds.append(float(out[0]))
    print(
        f"loaded {out[1]} appliances, {out[2]} tasks; cold import + load: median "
        f"{statistics.median(seconds):.2f} s, worst {max(seconds):.2f} s over {args.repeat} "
        f"runs (target < 2 s){' with semantic checks' if args.check else ''}"
    )


if __name__ == "__main__":
    main()
