"""Why end-to-end tasks failed: the first cause of each failure in a bench run on read beliefs.

    python benchmarks/e2e_failures.py RUN_DIR [--method apbot] [--categories a,b] [--examples 6]
                                      [--suite bundled|DIR]

The suite is the run's own (its run.json names it; ``--suite`` overrides). On the bundled suite
the nine development categories are judged by default, on another suite every category.

MEASURING ONLY — this script uses privileged inputs: the ground-truth model and the task's stored
goal, aligned with the read belief through the reader's evaluation alignment
(:func:`apbot.read.evaluate.translate_goal`). No method ever sees what it computes.

For each failed record of the method, every setting of the stored goal is judged in the belief's
names, and the failure is filed under the first cause in this order (reader first, then parser,
then agent):

1. ``lacks setting``  — the read model has no variable aligned with a goal setting;
2. ``lacks value``    — it has the variable, but not the goal's value in its domain;
3. ``parser refused`` — the goal parser gave no goal at all for the instruction;
4. ``parser dropped`` — the belief holds the goal value, the parsed goal leaves the setting out;
5. ``wrong value``    — the parsed goal sets the setting to another value;
6. ``extra setting``  — the parsed goal sets a setting the stored goal does not ask for;
7. ``agent``          — the parsed goal is the stored one, yet the agent could not operate the
   read model (a display it cannot read, a key placed wrong, …).

It prints the counts per cause (first cause, and any cause), then examples per cause: the
appliance/task and the setting and value concerned, with a glimpse of the read domain.
Only the goal settings the task ended with wrong are judged (where the record keeps its final
values): a setting dropped or misread yet reached anyway — an unsaid ``power: on`` every other
setting needs — explains no failure, so its cause is not counted (before 7 December, fifth
session, it was, which filed some agent failures under ``parser dropped``).
The belief is read again (through the read cache); a belief whose hash is not the record's is
counted and said, since the reader changed after the run.

``--claims`` judges the false claims instead (records whose method claimed success on a goal
that does not hold), on the settings the claim got wrong only: a claim whose wrong setting the
parsed goal left out or set otherwise was an honest claim on the goal the method was given
(the parser's or the reader's error); one whose wrong setting the parsed goal held as asked is
the agent's own (it believed a display, or its belief, that did not show the truth).
"""

from __future__ import annotations

import argparse
import json
from collections import Counter, defaultdict
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from apbot.bench.suite import READER_DEVELOPMENT_CATEGORIES
from apbot.model.domain import all_values
from apbot.model.goal import parse_goal
from apbot.model.schema import ApplianceModel

CAUSES = (
    "lacks setting",
    "lacks value",
    "parser refused",
    "parser dropped",
    "wrong value",
    "extra setting",
    "agent",
)
NINE = READER_DEVELOPMENT_CATEGORIES
MAX_DOMAIN = 10_000  # a belief domain listed beyond this is not listed (a huge numeric range)


@dataclass(frozen=True)
class Cause:
    """One reason a goal setting is not what the method got: the kind, the belief's setting
    name (or the truth's, when the belief lacks it) and the value asked for."""

    kind: str
    setting: str
    value: Any
    detail: str = ""


def _canonical(model: ApplianceModel, name: str, value: Any) -> Any | None:
    """A value as the model's goal parser normalises it, or None when it is not one."""
    try:
        return parse_goal(model, {name: value})[name]
    except Exception:  # any refusal means: not a value of this variable
        return None


def _domain(model: ApplianceModel, name: str) -> list[Any] | None:
    try:
        values = all_values(model.variables[name])
    except Exception:  # a domain that cannot be listed
        return None
    out: list[Any] = []
    for value in values:
        out.append(value)
        if len(out) > MAX_DOMAIN:
            return None
    return out


def _glimpse(values: list[Any] | None) -> str:
    if values is None:
        return "domain not listable"
    if len(values) <= 8:
        return "has " + ", ".join(str(v) for v in values)
    return f"has {values[0]} … {values[-1]} ({len(values)} values)"


def classify(
    belief: ApplianceModel,
    truth: ApplianceModel,
    stored: dict[str, Any],
    parsed: dict[str, Any] | None,
) -> list[Cause]:
    """Every cause found for one task, sorted by the documented order (first = the cause).

    ``stored`` is the task's goal in the truth's names; ``parsed`` the parser's goal in the
    belief's names (None: the parser refused the instruction). An empty list: the goal the
    method got was right.
    """
    from apbot.read.evaluate import translate_goal

    wanted = translate_goal(belief, truth, stored)
    got = parsed or {}
    causes: list[Cause] = []
    if parsed is None:
        causes.append(Cause("parser refused", "", None))
    for name, value in wanted.items():
        if name not in belief.variables:
            causes.append(Cause("lacks setting", name, value))
            continue
        canon = _canonical(belief, name, value)
        domain = _domain(belief, name)
        if canon is None or (domain is not None and canon not in domain):
            causes.append(Cause("lacks value", name, value, _glimpse(domain)))
            continue
        if name not in got:
            if parsed is not None:
                causes.append(Cause("parser dropped", name, value))
            continue
        if _canonical(belief, name, got[name]) != canon:
            causes.append(Cause("wrong value", name, value, f"parsed {got[name]!r}"))
    causes += [Cause("extra setting", n, v) for n, v in got.items() if n not in wanted]
    return sorted(causes, key=lambda c: CAUSES.index(c.kind))


def wrong_settings(
    belief: ApplianceModel, truth: ApplianceModel, stored: dict[str, Any], final: dict[str, Any]
) -> set[str]:
    """The stored goal's settings whose final value is not the one asked for, in the belief's
    names (a truth name when the belief has no partner for it)."""
    from apbot.read.evaluate import align_variables

    back = {t: b for b, t in align_variables(belief, truth).items()}
    return {
        back.get(name, name)
        for name, value in stored.items()
        if _canonical(truth, name, value) != _canonical(truth, name, final.get(name))
    }


def claim_causes(causes: list[Cause], wrong: set[str]) -> list[Cause]:
    """The causes that bear on a false claim: those of the settings it got wrong (none: the
    parsed goal held them as asked, so the claim is the agent's own)."""
    return [c for c in causes if c.setting in wrong]


_UNTIED = ("parser refused", "extra setting")
"""Causes not tied to one goal setting: they bear on any failure."""


def failure_causes(causes: list[Cause], wrong: set[str]) -> list[Cause]:
    """The causes that bear on a failure: a goal setting the task ended with as asked explains
    nothing (an unsaid ``power: on`` the parse dropped, reached anyway because every other
    setting needs it), whatever the parser made of it; a refusal and an extra setting stay."""
    return [c for c in causes if c.kind in _UNTIED or c.setting in wrong]


def first_cause(causes: list[Cause]) -> str:
    return causes[0].kind if causes else "agent"


@dataclass
class Tally:
    first: Counter[str]
    any: Counter[str]
    examples: dict[str, list[str]]
    failed: int
    records: int
    stale: int
    label: str = "failed"


def tally(
    records: Iterable[dict[str, Any]], suite_name: str = "bundled", claims: bool = False
) -> Tally:
    """Classify the failed records (dicts as in results.jsonl); ``claims``: only the false
    claims, on the settings they got wrong (:func:`claim_causes`)."""
    from apbot.bench.reading import read_belief
    from apbot.bench.runner import cached_suite

    suite = cached_suite(suite_name)
    beliefs: dict[str, tuple[ApplianceModel, str]] = {}
    first: Counter[str] = Counter()
    anyc: Counter[str] = Counter()
    examples: dict[str, list[str]] = defaultdict(list)
    failed = total = stale = 0
    for record in records:
        total += 1
        if record["success"] or (claims and not record.get("claimed_success")):
            continue
        failed += 1
        appliance = suite.get(record["appliance"])
        if appliance.id not in beliefs:
            read = read_belief(
                appliance.manual, list(appliance.model.actions), appliance.id, appliance.category
            )
            beliefs[appliance.id] = (read.model, read.digest)
        belief, digest = beliefs[appliance.id]
        stale += record.get("belief_hash", digest) != digest
        causes = classify(belief, appliance.model, record["goal"], record.get("parsed_goal"))
        if claims:
            final = record.get("final_values", {})
            causes = claim_causes(
                causes, wrong_settings(belief, appliance.model, record["goal"], final)
            )
        elif "final_values" in record:
            final = record["final_values"]
            causes = failure_causes(
                causes, wrong_settings(belief, appliance.model, record["goal"], final)
            )
        kind = first_cause(causes)
        first[kind] += 1
        for k in {c.kind for c in causes} or {kind}:
            anyc[k] += 1
        where = f"{record['appliance']}/{record['task']}"
        if causes:
            c = causes[0]
            text = f"{where}: {c.setting}={c.value!r}" + (f" ({c.detail})" if c.detail else "")
        else:
            text = f"{where}: {record.get('failure', '')[:90]}"
        examples[kind].append(text)
    return Tally(
        first, anyc, examples, failed, total, stale, "false claims" if claims else "failed"
    )


def render(t: Tally, examples: int) -> str:
    lines = [f"{t.label} {t.failed} of {t.records} records"]
    if t.stale:
        lines.append(
            f"NOTE: {t.stale} failed records ran on a belief other than the one read now "
            "(the reader changed since the run); causes are judged on today's reading"
        )
    lines.append(f"{'cause':<16}{'first':>7}{'any':>7}")
    for kind in CAUSES:
        lines.append(f"{kind:<16}{t.first[kind]:>7}{t.any[kind]:>7}")
    for kind in CAUSES:
        if t.examples.get(kind) and examples:
            lines.append(f"\n{kind} (first {min(examples, len(t.examples[kind]))}):")
            lines += [f"  {e}" for e in t.examples[kind][:examples]]
    return "\n".join(lines)


def _records(run: Path, method: str, categories: set[str] | None) -> list[dict[str, Any]]:
    path = run / "results.jsonl" if run.is_dir() else run
    if not path.is_file():
        raise SystemExit(f"e2e_failures: no results file at {path}")
    out = []
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if not line.strip():
            continue
        try:
            record = json.loads(line)
        except json.JSONDecodeError as exc:
            raise SystemExit(f"e2e_failures: {path}:{number}: not JSON ({exc.msg})") from None
        if record.get("method") != method:
            continue
        if categories is not None and record.get("category") not in categories:
            continue
        out.append(record)
    return out


def run_suite(run: Path) -> str:
    """The suite a bench run used, from its run.json (``bundled`` when the run does not say)."""
    manifest = (run if run.is_dir() else run.parent) / "run.json"
    try:
        suite = json.loads(manifest.read_text(encoding="utf-8")).get("suite")
    except (OSError, json.JSONDecodeError):
        return "bundled"
    return suite if isinstance(suite, str) and suite else "bundled"


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("run", type=Path, help="a bench run directory (or its results.jsonl)")
    parser.add_argument("--method", default="apbot")
    parser.add_argument(
        "--categories",
        default=None,
        help="comma list, 'nine', 'six' or 'all' (default: nine on the bundled suite, else all)",
    )
    parser.add_argument("--suite", default=None, help="'bundled' or a suite directory")
    parser.add_argument("--examples", type=int, default=6, help="examples printed per cause")
    parser.add_argument(
        "--claims",
        action="store_true",
        help="judge the false claims only, on the settings each got wrong",
    )
    args = parser.parse_args(argv)
    suite = args.suite or run_suite(args.run)
    if args.categories is None:
        args.categories = "nine" if suite == "bundled" else "all"
    if args.categories == "all":
        chosen: set[str] | None = None
    elif args.categories == "nine":
        chosen = set(NINE)
    elif args.categories == "six":
        from apbot.bench.runner import cached_suite

        chosen = {a.category for a in cached_suite("bundled").appliances} - set(NINE)
    else:
        chosen = {c.strip() for c in args.categories.split(",") if c.strip()}
    records = _records(args.run, args.method, chosen)
    if not records:
        raise SystemExit(
            f"e2e_failures: no {args.method} records in {args.run} for those categories"
        )
    print(render(tally(records, suite, claims=args.claims), args.examples))


if __name__ == "__main__":
    main()
