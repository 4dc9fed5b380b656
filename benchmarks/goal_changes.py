"""Which development goals does a goal-parser change move? The GENERALITY RULE's check.

    python benchmarks/goal_changes.py dump OUT.json      # with the code as it is now
    python benchmarks/goal_changes.py diff BEFORE.json AFTER.json [--all]

A goal rule is kept only if it changes the outcome on appliances of two different sets or
writers. ``dump`` parses every task sentence of the development appliances — the nine
development categories of the bundled suite, the new categories (``benchmarks/data/newcats``)
and the styled manuals (``benchmarks/data/styled``) — against the true model (``*-true``) and
against the belief the offline reader reads from the manual (``*-read``, the benchmark's way:
quantities the belief lacks kept as said), and writes each parsed goal next to the stored one.
The six held-out categories are never parsed. ``diff`` lists the tasks whose parsed goal
differs between two dumps (``+`` exact before → after), grouped by set, and counts the
appliances per set whose outcome changed. Exact matches of read beliefs are rare (their names
differ from the truth), so ``--all`` also lists read goals that changed without a change in
exactness.
"""

from __future__ import annotations

import argparse
import json
from collections import defaultdict
from pathlib import Path
from typing import Any

from apbot.bench.reading import read_belief
from apbot.bench.suite import READER_DEVELOPMENT_CATEGORIES, SuiteAppliance, load_suite
from apbot.model.goal import parse_goal
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

ROOT = Path(__file__).resolve().parent
NEWCATS = ROOT / "data" / "newcats"
STYLED = ROOT / "data" / "styled"


def _goals(
    tag: str, appliance: SuiteAppliance, model: ApplianceModel, manual: str, read: bool
) -> dict[str, dict[str, Any]]:
    out: dict[str, dict[str, Any]] = {}
    for task in appliance.tasks:
        try:
            parsed = parse_instruction(model, task.instruction, manual, [] if read else None)
            goal: dict[str, str] = {k: str(v) for k, v in parsed.items()}
        except ValueError as exc:
            goal = {"ERROR": str(exc)[:100]}
        stored = parse_goal(appliance.model, task.goal)
        out[f"{tag}/{appliance.id}/{task.id}"] = {
            "instruction": task.instruction,
            "parsed": goal,
            "expected": {k: str(v) for k, v in stored.items()},
        }
    return out


def dump() -> dict[str, dict[str, Any]]:
    """Every development task's parsed goal, true and read, keyed set/appliance/task."""
    styled = {p.stem: p.read_text() for p in STYLED.glob("*.md") if p.stem != "README"}
    out: dict[str, dict[str, Any]] = {}
    for tag, suite in (("suite", load_suite("bundled")), ("newcats", load_suite(NEWCATS))):
        for a in suite.appliances:
            if tag == "suite" and a.category not in READER_DEVELOPMENT_CATEGORIES:
                continue  # the six held out are never parsed here
            actions = list(a.model.actions)
            out |= _goals(f"{tag}-true", a, a.model, a.manual, read=False)
            belief = read_belief(a.manual, actions, a.id, a.category).model
            out |= _goals(f"{tag}-read", a, belief, a.manual, read=True)
            if tag == "suite" and a.id in styled:
                belief = read_belief(styled[a.id], actions, a.id, a.category).model
                out |= _goals("styled-read", a, belief, styled[a.id], read=True)
    return out


def diff(before: dict[str, Any], after: dict[str, Any], show_all: bool = False) -> list[str]:
    """One line per changed goal, then the appliances per set whose exactness changed."""
    lines: list[str] = []
    moved: dict[str, set[str]] = defaultdict(set)
    for key, old in before.items():
        new = after.get(key)
        if new is None or new["parsed"] == old["parsed"]:
            continue
        was, now = old["parsed"] == old["expected"], new["parsed"] == new["expected"]
        if was == now and not show_all:
            continue
        tag, appliance, _task = key.split("/")
        if was != now:
            moved[tag].add(appliance)
        mark = "+" if now and not was else "-" if was and not now else "="
        lines.append(f"{mark} {key}: {old['instruction'][:90]}")
        lines.append(f"    before {old['parsed']}")
        lines.append(f"    after  {new['parsed']}")
        lines.append(f"    stored {old['expected']}")
    for tag in sorted(moved):
        lines.append(
            f"{tag}: outcome changed on {len(moved[tag])}: {', '.join(sorted(moved[tag]))}"
        )
    return lines


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    d = sub.add_parser("dump", help="parse every development task; write JSON")
    d.add_argument("out", type=Path)
    c = sub.add_parser("diff", help="compare two dumps")
    c.add_argument("before", type=Path)
    c.add_argument("after", type=Path)
    c.add_argument("--all", action="store_true", help="also goals whose exactness did not change")
    args = parser.parse_args(argv)
    if args.command == "dump":
        goals = dump()
        args.out.write_text(json.dumps(goals, indent=0, ensure_ascii=False))
        print(f"{len(goals)} goals written to {args.out}")
    else:
        before = json.loads(args.before.read_text())
        after = json.loads(args.after.read_text())
        print("\n".join(diff(before, after, args.all)) or "no goal changed")


if __name__ == "__main__":
    main()
