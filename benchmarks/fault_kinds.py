"""Fault kinds on the bundled suite: how many appliances and sites each kind can hit, whether
each single fault shows (some presses tell it from the truth), and faults per model at a rate.

    python benchmarks/fault_kinds.py [--rate 0.3] [--seeds 0,1,2] [--kinds guard,display]

For every appliance, site and kind of that site, the kind's first valid candidate on the true
model (one fault alone) is searched for a difference with
:func:`apbot.bench.faults.evidence.first_difference`; a fault it cannot tell apart within its
budget is listed (most are deep in a long range, some are dead weight). Then the faults
:func:`inject_faults` puts in each model at ``--rate`` (every kind mixed), per seed.
"""

from __future__ import annotations

import argparse
import random
import sys
import time
from collections import Counter, defaultdict
from statistics import fmean

from rich.console import Console
from rich.table import Table

from apbot.bench.faults import FAULT_KINDS, SITE_KINDS, fault_sites, first_valid, inject_faults
from apbot.bench.faults.evidence import first_difference
from apbot.bench.suite import load_suite


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--rate", type=float, default=0.3)
    parser.add_argument("--seeds", default="0,1,2")
    parser.add_argument("--kinds", default=",".join(FAULT_KINDS))
    args = parser.parse_args()
    kinds = [k.strip() for k in args.kinds.split(",") if k.strip()]
    unknown = [k for k in kinds if k not in FAULT_KINDS]
    if unknown:
        parser.error(f"unknown fault kind(s) {', '.join(unknown)}; known: {', '.join(FAULT_KINDS)}")
    suite = load_suite()
    started = time.perf_counter()
    appliances: dict[str, set[str]] = defaultdict(set)
    sites: Counter[str] = Counter()
    hidden: dict[str, list[str]] = defaultdict(list)
    for appliance in suite.appliances:
        for section, name in fault_sites(appliance.model):
            for kind, make in SITE_KINDS[section].items():
                if kind not in kinds:
                    continue
                rng = random.Random(f"survey|{appliance.id}|{name}|{kind}")
                found = first_valid(make(appliance.model, name, rng))
                if found is None:
                    continue
                appliances[kind].add(appliance.id)
                sites[kind] += 1
                if first_difference(appliance.model, found[0]) is None:
                    hidden[kind].append(f"{appliance.id}: {found[1]}")
    console = Console() if sys.stdout.isatty() else Console(width=120)
    table = Table(title=f"Fault kinds on the bundled suite ({len(suite.appliances)} appliances)")
    for column in ("kind", "appliances", "sites", "no difference found"):
        table.add_column(column, justify="left" if column == "kind" else "right")
    for kind in kinds:
        table.add_row(kind, str(len(appliances[kind])), str(sites[kind]), str(len(hidden[kind])))
    console.print(table)
    for kind in kinds:
        for line in hidden[kind]:
            console.print(f"  no difference found: {line}")
    surveyed = time.perf_counter() - started
    seeds = [int(s) for s in args.seeds.split(",") if s.strip()]
    per_model, sites_per_model, by_kind = [], [], Counter()
    for seed in seeds:
        for appliance in suite.appliances:
            _, faults = inject_faults(appliance.model, args.rate, f"{seed}/{appliance.id}")
            per_model.append(len(faults))
            sites_per_model.append(len(fault_sites(appliance.model)))
            by_kind.update(f.kind for f in faults)
    console.print(
        f"rate {args.rate:g}, seeds {args.seeds}: {fmean(per_model):.2f} faults per model "
        f"({fmean(sites_per_model):.1f} sites per model); "
        + ", ".join(f"{k} {by_kind[k]}" for k in FAULT_KINDS if by_kind[k])
    )
    console.print(
        f"survey {surveyed:.0f} s, injection {time.perf_counter() - started - surveyed:.0f} s"
    )


if __name__ == "__main__":
    main()
