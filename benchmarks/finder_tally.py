"""What became of each goal setting the read belief lacks altogether: the variable finder's tally.

    python benchmarks/finder_tally.py RUN_DIR [--suite DIR] [--categories a,b] [--list]

MEASURING ONLY — like :mod:`e2e_failures` (whose classification it reuses) it reads the true
model and the stored goal. For every failed record whose first cause is ``lacks setting`` it
asks, of the setting the belief lacks:

- *hand-off*: did the goal parser give the agent anything for it — an open entry (a goal name the
  belief does not have, :mod:`apbot.read.goal_open`), the value put on another belief setting
  (``absorbed``: a wrong value or an extra setting beside the lacking one), or nothing at all;
- *finder*: did the variable finder find a setting (a ``found under`` / ``selects one`` repair),
  look and give up (the loop's "which the model does not have"), or never run;
- which keys were pressed while exploring before the first plan (the finder runs there) and the
  reason the run stopped.

It prints the counts of each hand-off × finder outcome, then (``--list``) one line per record.
"""

from __future__ import annotations

import argparse
import sys
from collections import Counter
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

from e2e_failures import _records, classify, run_suite


def hand_off(belief_vars: set[str], parsed: dict[str, Any] | None, causes: list[Any]) -> str:
    """How the parser handed the lacking setting to the agent."""
    open_names = [n for n in (parsed or {}) if n not in belief_vars]
    if open_names:
        return "open entry"
    if any(c.kind in ("wrong value", "extra setting") for c in causes):
        return "absorbed"
    return "nothing"


def finder_outcome(record: dict[str, Any]) -> str:
    """found / gave up / not run, from the record's repairs and trace."""
    if any(" found under " in r or " selects one (" in r for r in record.get("repairs", [])):
        return "found"
    for entry in record.get("trace", []):
        if entry.get("kind") == "explore" and "which the model does not have" in entry.get(
            "text", ""
        ):
            return "gave up"
    return "not run"


def keys_tried(record: dict[str, Any]) -> list[str]:
    """The keys pressed while exploring before the first plan (the finder's first look)."""
    keys: list[str] = []
    for entry in record.get("trace", []):
        if entry.get("kind") == "plan":
            break
        exploring = entry.get("kind") == "action" and entry.get("exploring")
        if exploring and entry["action"] not in keys:
            keys.append(entry["action"])
    return keys


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("run", type=Path)
    parser.add_argument("--suite", default=None)
    parser.add_argument("--categories", default=None, help="comma list (default: all)")
    parser.add_argument("--method", default="apbot")
    parser.add_argument("--list", action="store_true", help="one line per record")
    args = parser.parse_args(argv)

    from apbot.bench.reading import read_belief
    from apbot.bench.runner import cached_suite

    suite_name = args.suite or run_suite(args.run)
    chosen = {c for c in args.categories.split(",")} if args.categories else None
    suite = cached_suite(suite_name)
    beliefs: dict[str, Any] = {}
    table: Counter[tuple[str, str]] = Counter()
    lines: list[str] = []
    for record in _records(args.run, args.method, chosen):
        if record["success"]:
            continue
        appliance = suite.get(record["appliance"])
        if appliance.id not in beliefs:
            beliefs[appliance.id] = read_belief(
                appliance.manual, list(appliance.model.actions), appliance.id, appliance.category
            ).model
        belief = beliefs[appliance.id]
        parsed = record.get("parsed_goal")
        causes = classify(belief, appliance.model, record["goal"], parsed)
        if not causes or causes[0].kind != "lacks setting":
            continue
        how = hand_off(set(belief.variables), parsed, causes)
        outcome = finder_outcome(record)
        table[(how, outcome)] += 1
        lacking = ", ".join(f"{c.setting}={c.value!r}" for c in causes if c.kind == "lacks setting")
        opened = {n: v for n, v in (parsed or {}).items() if n not in belief.variables}
        lines.append(
            f"{record['appliance']}/{record['task']}: lacks {lacking} | {how} {opened or ''} | "
            f"finder {outcome} {keys_tried(record)} | {record.get('failure', '')[:110]}"
        )
    total = sum(table.values())
    print(f"lacks setting (first cause): {total} records")
    print(f"{'hand-off':<12}{'found':>8}{'gave up':>9}{'not run':>9}")
    for how in ("open entry", "absorbed", "nothing"):
        row = [table[(how, o)] for o in ("found", "gave up", "not run")]
        print(f"{how:<12}{row[0]:>8}{row[1]:>9}{row[2]:>9}")
    if args.list:
        print()
        print("\n".join(sorted(lines)))


if __name__ == "__main__":
    main()
