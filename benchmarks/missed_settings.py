"""Which goal settings the offline reader misses, by the panel mechanism that sets them.

    python benchmarks/missed_settings.py [--suite bundled|DIR] [--held-out] [--list] [--why]

MEASURING ONLY — this script uses privileged inputs: the ground-truth model (to say how each
setting is reached on the panel) and the tasks' stored goals (which settings matter). No method
ever sees what it computes.

Each manual is read with its appliance's action names; every setting a stored goal names counts
once per task that names it, and is *missed* when no read variable aligns with it under the
reader's evaluation alignment (:func:`apbot.read.evaluate.align_variables`). Settings are tagged
by how the truth's procedures reach them:

- ``own-key``: the keys that set it set nothing else;
- ``shared-adjuster``: a key that sets it also sets another setting (▲ / ▼ shared by fields);
- ``after-entry-step``: a step that sets nothing comes first (press SET, hold CLOCK);
- ``walk-after-other-var``: another setting is set earlier in the same procedure (a walk of
  fields: hour, then minutes);
- ``hold``, ``dial``, ``digits``: a held key, a turned dial, a keypad;
- ``type:…``: the setting's type.

A mechanism missed far more often than the rest is where the reader's rules are thinnest: on 6
December (late) walks of fields were missed 41 % of the time on the newcats against 4 % for a
setting with a key of its own. On the bundled suite the nine development categories are judged
by default; ``--held-out`` judges the six held out instead and prints only the aggregate table
(never a line per appliance), so they stay a test set.

``--why`` adds a second aggregate table: for each missed setting, what the reader made of the
keys that set it in the truth — nothing (``keys-unread``), a variable already aligned with
another setting (``keys-set-other``: two settings conflated), or a variable of its own that did
not align, tagged by the two kinds (``onoff`` for a two-valued switch, ``levels`` for bare numbers,
``names``, ``range``, ``time``) and whether any value is shared; and whether the truth's value
names occur in the manual's text at all (``values-in-manual:none`` means the manual words them
differently from the stored model, which no reader can fix). Aggregate, so it may be run on the
held out: it says *which kind* of rule the unseen manuals need without showing any of them.
"""

from __future__ import annotations

import argparse
import re
from collections import Counter, defaultdict

from apbot.bench.suite import HELD_OUT_CATEGORIES, load_suite
from apbot.model.domain import all_values
from apbot.model.schema import ApplianceModel, DiscreteVariable, TimeVariable
from apbot.read.evaluate import align_variables, value_set
from apbot.read.reader import read_manual


def mechanisms(model: ApplianceModel, variable: str) -> set[str]:
    """How the truth's procedures reach ``variable`` (the tags above)."""
    adjusts: defaultdict[str, set[str]] = defaultdict(set)
    for steps in model.features.values():
        for step in steps:
            if step.variable:
                for action in step.actions:
                    adjusts[action].add(step.variable)
    tags: set[str] = set()
    for steps in model.features.values():
        for k, step in enumerate(steps):
            if step.variable != variable:
                continue
            if any(s.variable is None for s in steps[:k]):
                tags.add("after-entry-step")
            if any(s.variable and s.variable != variable for s in steps[:k]):
                tags.add("walk-after-other-var")
            shared = any(len(adjusts[a]) > 1 for a in step.actions)
            tags.add("shared-adjuster" if shared else "own-key")
            skills = {model.actions[a].skill for a in step.actions if a in model.actions}
            tags |= {"hold"} & skills | ({"dial"} if "turn" in skills else set())
            if any(ch.isdigit() for a in step.actions for ch in a):
                tags.add("digits")
    kind = type(model.variables[variable]).__name__.removesuffix("Variable").lower()
    return tags | {f"type:{kind}"}


def kind(model: ApplianceModel, variable: str) -> str:
    """A coarse kind for the ``--why`` table."""
    var = model.variables[variable]
    if isinstance(var, TimeVariable):
        return "time"
    if not isinstance(var, DiscreteVariable):
        return "range"
    values = [str(v).lower() for v in all_values(var)]
    if len(values) == 2:
        return "onoff"
    if all(re.fullmatch(r"[a-z]?\d+", v) for v in values):
        return "levels"
    return "names"


def setters(model: ApplianceModel) -> defaultdict[str, set[str]]:
    """action → the variables a procedure step with that action sets."""
    out: defaultdict[str, set[str]] = defaultdict(set)
    for steps in model.features.values():
        for step in steps:
            if step.variable:
                for action in step.actions:
                    out[action].add(step.variable)
    return out


def why_missed(
    read: ApplianceModel,
    truth: ApplianceModel,
    variable: str,
    aligned: dict[str, str],
    manual: str,
) -> list[str]:
    """Reasons (``--why`` tags) the reader missed ``variable``."""
    keys = {a for a, vs in setters(truth).items() if variable in vs}
    read_setters = setters(read)
    candidates = {v for a in keys for v in read_setters.get(a, set())}
    tags: list[str] = []
    if not candidates:
        tags.append("keys-unread")
    elif all(c in aligned for c in candidates):
        tags.append("keys-set-other")
    else:
        mine = sorted(c for c in candidates if c not in aligned)[0]
        shared = value_set(read, mine) & value_set(truth, variable)
        tags.append(
            f"keys-set-own read:{kind(read, mine)} true:{kind(truth, variable)}"
            f" {'some' if shared else 'no'}-value-shared"
        )
    var = truth.variables[variable]
    if isinstance(var, DiscreteVariable):
        text = manual.lower()
        names = [str(v).lower().replace("_", " ") for v in all_values(var)]
        found = [name in text for name in names]
        share = "all" if all(found) else "some" if any(found) else "none"
        tags.append(f"values-in-manual:{share}")
        if any(found):
            tags.append(f"values-written-in:{value_shape(manual, names)}")
    return tags


def value_shape(manual: str, names: list[str]) -> str:
    """How the manual writes a setting's values: the shape of the line holding most of them."""
    best, line = 0, ""
    for candidate in manual.splitlines():
        low = candidate.lower()
        hits = sum(1 for name in names if re.search(rf"(?<![a-z]){re.escape(name)}(?![a-z])", low))
        if hits > best:
            best, line = hits, candidate.strip()
    if best == 0:
        return "inside-words"
    together = "one-line" if best == len(names) else "spread"
    if line.count("|") >= 2:
        shape = "table-row"
    elif re.match(r"([-*•·▪●○◦]|\d+[.)]|\(?[a-z]\))\s", line):
        shape = "list-item"
    elif line.startswith("#") or line.isupper():
        shape = "heading"
    else:
        shape = "prose"
    return f"{shape}/{together}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--suite", default="bundled")
    parser.add_argument("--held-out", action="store_true", help="the six held out, aggregate only")
    parser.add_argument("--list", action="store_true", help="each missed setting (development)")
    parser.add_argument("--why", action="store_true", help="what the reader made of missed keys")
    args = parser.parse_args()
    suite = load_suite(args.suite)
    total: Counter[str] = Counter()
    missed: Counter[str] = Counter()
    lines: list[str] = []
    reasons: Counter[str] = Counter()
    for appliance in suite.appliances:
        if (appliance.category in HELD_OUT_CATEGORIES) != args.held_out:
            continue
        truth = appliance.model
        read = read_manual(appliance.manual, list(truth.actions)).model
        aligned = align_variables(read, truth)
        found = set(aligned.values())
        uses = Counter(v for task in appliance.tasks for v in task.goal or {})
        for variable, n in sorted(uses.items()):
            if variable not in truth.variables:
                continue
            tags = mechanisms(truth, variable) | {"ALL"}
            for tag in tags:
                total[tag] += n
                missed[tag] += 0 if variable in found else n
            if variable not in found and args.why:
                why = why_missed(read, truth, variable, aligned, appliance.manual)
                for reason in why:
                    reasons[reason] += n
                shapes = [w.split(":", 1)[1] for w in why if w.startswith("values-written-in")]
                reasons[f"{why[0]} + {shapes[0] if shapes else 'values-not-named'}"] += n
            if variable not in found:
                lines.append(
                    f"  {appliance.id} {variable} ×{n}: {', '.join(sorted(tags - {'ALL'}))}"
                )
    print(f"{'mechanism':24s} {'missed':>7s} {'of':>6s}  share")
    for tag in sorted(total, key=lambda t: (-missed[t] / total[t], t)):
        print(f"{tag:24s} {missed[tag]:7d} {total[tag]:6d}  {missed[tag] / total[tag]:.2f}")
    if args.why:
        print(f"\n{'why missed (task uses)':60s} {'n':>5s}")
        for reason, n in sorted(reasons.items(), key=lambda kv: (-kv[1], kv[0])):
            print(f"{reason:60s} {n:5d}")
    if args.list and not args.held_out:
        print(
            "\n".join(["", "missed settings (appliance, setting, task uses, mechanisms):", *lines])
        )


if __name__ == "__main__":
    main()
