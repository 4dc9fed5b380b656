"""How long the offline reader takes to read every bundled manual.

    python benchmarks/read_time.py [--categories a,b]

Reads each manual of the bundled suite with its appliance's action names (``read_manual``, no
evaluation) and prints the wall and CPU time, in all and per manual. The target is under 15 s
for all 75 manuals on the 2-core development machine; CPU time is the figure to compare while
other jobs share the machine.
"""

from __future__ import annotations

import argparse
import time

from apbot.bench.runner import cached_suite
from apbot.read import read_manual


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--categories", default="", help="comma-separated (default: all)")
    args = parser.parse_args()
    wanted = set(filter(None, args.categories.split(",")))
    appliances = [
        a for a in cached_suite("bundled").appliances if not wanted or a.category in wanted
    ]
    wall, cpu = time.perf_counter(), time.process_time()
    for appliance in appliances:
        read_manual(appliance.manual, list(appliance.model.actions))
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    n = max(len(appliances), 1)
    print(
        f"{len(appliances)} manuals read: {wall:.2f} s wall ({wall / n * 1000:.0f} ms each), "
        f"{cpu:.2f} s CPU ({cpu / n * 1000:.0f} ms each)"
    )


if __name__ == "__main__":
    main()
