"""Where the closed loop's answer to a missed setting breaks, for the "lacks setting" failures.

    python benchmarks/lack_chain.py RUN_DIR [--categories a,b] [--examples N]

A read belief can miss a setting the task needs. The loop's answer is a chain: the goal parser
keeps the request as an *open entry* (a name the belief lacks, ``read/goal_open.py``), the
variable finder (``agent/discovery.py``) presses keys the belief gives no role, walks one whose
display it cannot read and writes the setting into the belief, then the plan sets it. For each
failed record whose first cause is ``lacks setting`` (``benchmarks/e2e_failures.py``) this
says where that chain broke:

- ``a`` the parsed goal holds no open entry at all (``a1``: the keys that really set the
  setting have a role in the belief — the reader gave them to another setting; ``a2``: they
  have none);
- ``b`` an open entry, never found, and the finder never pressed a key of the setting;
- ``c`` an open entry, never found, though the finder pressed a key of the setting;
- ``d`` an open entry not reported unfound: learnt (or the episode stopped before), and the
  task failed after.

MEASURING ONLY — it reads the ground-truth model (which keys set the missing setting) and the
stored goal; no method sees any of it. Held-out categories: pass ``--categories`` with
development categories only on the bundled suite, or ``--examples 0``.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections import Counter, defaultdict
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))  # e2e_failures, beside this file

from e2e_failures import NINE, classify, first_cause, run_suite

from apbot.model.schema import ApplianceModel

UNFOUND = "which the model does not have"  # the loop's log when the finder gave up


def setting_keys(model: ApplianceModel, name: str) -> set[str]:
    """The keys that reach and adjust ``name``: the first step's keys of each procedure with
    a step adjusting it, and that step's own keys."""
    keys: set[str] = set()
    for steps in model.features.values():
        for step in steps:
            if step.variable == name:
                keys |= set(steps[0].actions) | set(step.actions)
    return keys


def roles(model: ApplianceModel) -> dict[str, set[str]]:
    """Key → the settings the model's steps adjust with it."""
    out: dict[str, set[str]] = defaultdict(set)
    for steps in model.features.values():
        for step in steps:
            if step.variable is not None:
                for key in step.actions:
                    out[key].add(step.variable)
    return out


def chain_break(record: dict[str, Any], belief: ApplianceModel, truth: ApplianceModel) -> str:
    """Where the chain broke for one lacks-setting failure (``a1``, ``a2``, ``b``, ``c``, ``d``)."""
    causes = classify(belief, truth, record["goal"], record.get("parsed_goal"))
    missing = next(c for c in causes if c.kind == "lacks setting")
    keys = setting_keys(truth, missing.setting)
    parsed = record.get("parsed_goal") or {}
    if not any(name not in belief.variables for name in parsed):
        held = roles(belief)
        return "a1" if any(held.get(k) for k in keys) else "a2"
    trace = record.get("trace", [])
    if not any(UNFOUND in t.get("text", "") for t in trace if t["kind"] == "explore"):
        return "d"
    pressed = {t["action"] for t in trace if t["kind"] == "action" and t.get("exploring")}
    return "c" if keys & pressed else "b"


def main(argv: list[str] | None = None) -> None:
    from apbot.bench.reading import read_belief
    from apbot.bench.runner import cached_suite

    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("run", type=Path)
    parser.add_argument("--categories", default=None, help="comma list (default: nine / all)")
    parser.add_argument("--examples", type=int, default=0)
    args = parser.parse_args(argv)
    suite_name = run_suite(args.run)
    suite = cached_suite(suite_name)
    chosen = (
        {c.strip() for c in args.categories.split(",")}
        if args.categories
        else (set(NINE) if suite_name == "bundled" else None)
    )
    beliefs: dict[str, ApplianceModel] = {}
    counts: Counter[str] = Counter()
    per: dict[str, Counter[str]] = defaultdict(Counter)
    examples: list[str] = []
    for line in (args.run / "results.jsonl").read_text(encoding="utf-8").splitlines():
        record = json.loads(line)
        if record["method"] != "apbot" or record["success"]:
            continue
        if chosen is not None and record["category"] not in chosen:
            continue
        appliance = suite.get(record["appliance"])
        if appliance.id not in beliefs:
            read = read_belief(
                appliance.manual, list(appliance.model.actions), appliance.id, appliance.category
            )
            beliefs[appliance.id] = read.model
        belief = beliefs[appliance.id]
        causes = classify(belief, appliance.model, record["goal"], record.get("parsed_goal"))
        if first_cause(causes) != "lacks setting":
            continue
        where = chain_break(record, belief, appliance.model)
        counts[where] += 1
        per[where][record["appliance"]] += 1
        examples.append(f"  {where} {record['appliance']}/{record['task']}: {causes[0].setting}")
    print(f"lacks-setting failures: {sum(counts.values())}")
    for where in ("a1", "a2", "b", "c", "d"):
        print(
            f"{where:<3}{counts[where]:>5}  "
            + ", ".join(f"{a} {n}" for a, n in per[where].most_common())
        )
    print("\n".join(examples[: args.examples]))


if __name__ == "__main__":
    main()
