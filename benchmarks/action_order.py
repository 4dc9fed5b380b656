"""The reader under other orders of the action names: the same manual, its actions listed
another way.

    python benchmarks/action_order.py [--suite bundled|DIR ...] [--appliances a_1,b_1]
        [--seed 14] [--e2e] [--methods apbot] [--workers 1] [--out runs/action_order] [--json]

A robot's grounding lists the actions in whatever order it finds the controls; an environment's
author lists them as they like. Nothing about the appliance changes with that order, so neither
should the read model: this reads every manual with its action list as given, reversed and
shuffled (a fixed seed per appliance), and reports how many read models differ from the one read
in the given order, and where. What carries no meaning is canonicalised first: the order of keys
in a mapping (the model's action list, its variables) and the order of the controls. A difference
left only in the order of a list (the values of a setting, say) is counted apart ("order") from
one in what the model says ("substantive").

By default the bundled suite and ``benchmarks/data/newcats`` are read. On the bundled suite the
nine development categories get a line each; the held-out six are counted only in one aggregate
line (they stay the test: no per-appliance line, no difference path is printed for them).
``--e2e`` also runs the end-to-end benchmark on copies of the suites whose models list their
actions in each order (the manual, panel and tasks unchanged) and prints SR / SPL per order (the
held-out six are not run).
"""

from __future__ import annotations

import argparse
import json
import random
import sys
from pathlib import Path
from typing import Any

from apbot.bench.suite import (
    HELD_OUT_CATEGORIES,
    SuiteAppliance,
    load_suite,
)
from apbot.read import read_manual

sys.path.insert(0, str(Path(__file__).resolve().parent))

from renamed_actions import e2e_figures, rewritten_suite

ORDERS = ("given", "reversed", "shuffled")
MAX_PATHS = 4


def ordered(actions: list[str], order: str, seed: str) -> list[str]:
    """The action names in ``order``: as given, reversed, or shuffled by ``seed``."""
    if order == "reversed":
        return actions[::-1]
    if order == "shuffled":
        out = list(actions)
        random.Random(seed).shuffle(out)
        return out
    return list(actions)


def canonical(node: Any, path: str = "") -> Any:
    """The model data with what carries no meaning put in one order: mapping keys, controls."""
    if isinstance(node, dict):
        return {k: canonical(node[k], f"{path}.{k}" if path else str(k)) for k in sorted(node)}
    if isinstance(node, list):
        items = [canonical(v, path) for v in node]
        if path == "controls":  # the panel's controls: a set, listed as the actions came
            items.sort(key=lambda c: json.dumps(c, sort_keys=True))
        return items
    return node


def _unordered(node: Any) -> Any:
    """The data with every list sorted: equal only when the two differ at most in list order."""
    if isinstance(node, dict):
        return {k: _unordered(v) for k, v in node.items()}
    if isinstance(node, list):
        return sorted((_unordered(v) for v in node), key=lambda v: json.dumps(v, sort_keys=True))
    return node


def differences(a: Any, b: Any, path: str = "") -> list[str]:
    """The paths where two canonical models differ (the deepest mapping key that differs)."""
    if isinstance(a, dict) and isinstance(b, dict):
        out: list[str] = []
        for key in sorted(set(a) | set(b)):
            sub = f"{path}.{key}" if path else str(key)
            if key not in a or key not in b:
                out.append(sub)
            elif a[key] != b[key]:
                out.extend(differences(a[key], b[key], sub))
        return out
    return [path] if a != b else []


def compare(base: dict[str, Any], other: dict[str, Any]) -> tuple[str, list[str]]:
    """How a read model differs from the base one: "same", "order" (only in the order of a list)
    or "substantive", with the paths that differ."""
    if base == other:
        return "same", []
    kind = "order" if _unordered(base) == _unordered(other) else "substantive"
    return kind, differences(base, other)


def read_canonical(appliance: SuiteAppliance, actions: list[str]) -> dict[str, Any]:
    """The canonical read model of the appliance's manual with ``actions`` in that order."""
    reading = read_manual(appliance.manual, actions, appliance.id, appliance.category)
    return canonical(reading.model.model_dump(mode="json", exclude_none=True))


def study(appliance: SuiteAppliance, seed: int) -> dict[str, Any]:
    """The appliance read in each order, compared with the reading in the given order."""
    actions = list(appliance.model.actions)
    base = read_canonical(appliance, actions)
    out: dict[str, Any] = {}
    for order in ORDERS[1:]:
        other = read_canonical(appliance, ordered(actions, order, f"{seed}/{appliance.id}"))
        kind, paths = compare(base, other)
        out[order] = {"kind": kind, "paths": paths}
    return out


def held_out(appliance: SuiteAppliance) -> bool:
    return appliance.category in HELD_OUT_CATEGORIES


def _chosen(suite_name: str, wanted: set[str] | None) -> list[SuiteAppliance]:
    suite = load_suite(suite_name)
    return [a for a in suite.appliances if wanted is None or a.id in wanted]


def _tally(rows: list[dict[str, Any]]) -> dict[str, Any]:
    """How many readings differ, per order and in any order."""
    tally: dict[str, Any] = {"appliances": len(rows)}
    for order in ORDERS[1:]:
        kinds = [r[order]["kind"] for r in rows]
        tally[order] = {k: kinds.count(k) for k in ("same", "order", "substantive")}
    tally["differ_any"] = sum(any(r[o]["kind"] != "same" for o in ORDERS[1:]) for r in rows)
    tally["substantive_any"] = sum(
        any(r[o]["kind"] == "substantive" for o in ORDERS[1:]) for r in rows
    )
    return tally


def order_suite(appliances: list[SuiteAppliance], order: str, seed: int, directory: Path) -> Path:
    """A suite directory of the appliances, each model listing its actions in ``order``."""

    def reorder(appliance: SuiteAppliance, data: dict[str, Any]) -> dict[str, Any]:
        names = ordered(list(data["actions"]), order, f"{seed}/{appliance.id}")
        return {**data, "actions": {name: data["actions"][name] for name in names}}

    return rewritten_suite(appliances, reorder, directory)


def main(argv: list[str] | None = None) -> dict[str, Any]:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--suite", action="append", help="bundled or a directory (repeatable)")
    parser.add_argument("--appliances", default=None, help="comma-separated ids")
    parser.add_argument("--seed", type=int, default=14)
    parser.add_argument("--e2e", action="store_true", help="also end-to-end SR / SPL per order")
    parser.add_argument("--methods", default="apbot")
    parser.add_argument("--workers", type=int, default=1)
    parser.add_argument("--out", default="runs/action_order")
    parser.add_argument("--json", action="store_true", help="print JSON")
    args = parser.parse_args(argv)
    suites = args.suite or ["bundled", "benchmarks/data/newcats"]
    wanted = set(args.appliances.split(",")) if args.appliances else None
    result: dict[str, Any] = {"seed": args.seed, "suites": {}}
    for name in suites:
        chosen = _chosen(name, wanted)
        dev = [a for a in chosen if not held_out(a)]
        held = [a for a in chosen if held_out(a)]
        dev_rows = {a.id: study(a, args.seed) for a in dev}
        entry: dict[str, Any] = {
            "development": _tally(list(dev_rows.values())),
            "appliances": dev_rows,
        }
        if held:  # one aggregate, nothing per appliance
            entry["held_out"] = _tally([study(a, args.seed) for a in held])
        if args.e2e and dev:
            ids = [a.id for a in dev]
            out = Path(args.out) / Path(name).name
            methods = args.methods.split(",")
            entry["e2e"] = {
                order: e2e_figures(
                    str(order_suite(dev, order, args.seed, out / f"suite-{order}")),
                    ids,
                    methods,
                    out / order,
                    args.workers,
                )
                for order in ORDERS
            }
        result["suites"][name] = entry
    if not any(e["development"]["appliances"] for e in result["suites"].values()):
        print("error: no appliance chosen", file=sys.stderr)
        raise SystemExit(2)
    print(json.dumps(result, indent=2) if args.json else _render(result))
    return result


def _line(label: str, tally: dict[str, Any]) -> str:
    cells = "".join(f"{tally[o]['order']:>7}{tally[o]['substantive']:>7}" for o in ORDERS[1:])
    return (
        f"{label:<30}{tally['appliances']:>4}{cells}"
        f"{tally['differ_any']:>8}{tally['substantive_any']:>8}"
    )


def _render(result: dict[str, Any]) -> str:
    lines = [f"read models vs the given order of actions (shuffle seed {result['seed']})"]
    head = "".join(f"{'ord':>7}{'sub':>7}" for _ in ORDERS[1:])
    lines.append(f"{'':<34}{'reversed':>14}{'shuffled':>14}{'any':>8}{'any':>8}")
    lines.append(f"{'':<30}{'n':>4}{head}{'differ':>8}{'subst':>8}")
    for name, entry in result["suites"].items():
        lines.append(_line(f"{Path(name).name} development", entry["development"]))
        if "held_out" in entry:
            lines.append(_line(f"{Path(name).name} held out (aggregate)", entry["held_out"]))
        for ident, row in entry["appliances"].items():
            for order in ORDERS[1:]:
                if row[order]["kind"] == "same":
                    continue
                paths = row[order]["paths"]
                more = f" (+{len(paths) - MAX_PATHS})" if len(paths) > MAX_PATHS else ""
                shown = ", ".join(paths[:MAX_PATHS])
                lines.append(f"  {ident:<22}{order:<9}{row[order]['kind']:<12}{shown}{more}")
        for order, figures in entry.get("e2e", {}).items():
            for method, fig in figures.items():
                lines.append(
                    f"  e2e {order:<9}{method:<16}SR {fig['sr']:.3f}  SPL {fig['spl']:.3f}"
                    f"  ({fig['n']} tasks)"
                )
    return "\n".join(lines)


if __name__ == "__main__":
    main()
