"""Does a remark around an instruction change the goal the offline parser reads?

    python benchmarks/goal_remarks.py [--categories kettle,microwave] [--tasks 3] [--show]

Real users say more than what they ask of the appliance: "…, I'll be back in an hour",
"…, we are 4 at the table". For each appliance of the chosen categories (by default the nine
development categories) this reads the belief from the manual with the offline reader, parses
each of its first ``--tasks`` task sentences alone and again with each remark below appended,
and counts the goals that differ. A remark should change nothing: the parser reads only what
the user asks of the appliance. Prints changed / total per remark and overall; ``--show``
also prints each changed goal (the settings that differ).
"""

from __future__ import annotations

import argparse
from collections import Counter

from apbot.bench.suite import READER_DEVELOPMENT_CATEGORIES, load_suite
from apbot.read.goal import GoalParseError, parse_instruction
from apbot.read.reader import read_manual

DEV_CATEGORIES = READER_DEVELOPMENT_CATEGORIES

REMARKS = (
    ", I'll be back in 10 minutes",
    ", I'll be back in an hour",
    ", it's for 2 people",
    ", my kids are 5 and 7",
    " - put the dish on the lower rack",
    ", dinner is at 7",
    ", we are 4 at the table",
    ", the last one took 20 minutes",
    ", my old one had 3 settings",
    " — my sister arrives at 6:30",
    "; we're 3 adults and a baby",
    ", I got it 2 years ago",
)
"""Remarks with numbers, times, people, ages and sizes that ask nothing of the appliance."""


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--categories", default=",".join(DEV_CATEGORIES))
    parser.add_argument("--tasks", type=int, default=3, help="task sentences per appliance")
    parser.add_argument("--show", action="store_true", help="print each changed goal")
    args = parser.parse_args(argv)
    categories = {c.strip() for c in args.categories.split(",") if c.strip()}
    suite = load_suite("bundled")
    changed: Counter[str] = Counter()
    total: Counter[str] = Counter()
    for appliance in suite.appliances:
        if appliance.category not in categories:
            continue
        belief = read_manual(appliance.manual, list(appliance.model.actions)).model
        for task in appliance.tasks[: args.tasks]:
            base = task.instruction.rstrip().rstrip(".")
            try:
                alone = parse_instruction(belief, base, appliance.manual, outside=[])
            except GoalParseError:
                continue
            for remark in REMARKS:
                total[remark] += 1
                try:
                    goal = parse_instruction(belief, base + remark, appliance.manual, outside=[])
                except GoalParseError as exc:
                    goal = {"<error>": str(exc)}
                differ = {k: v for k, v in goal.items() if alone.get(k) != v}
                differ.update({k: None for k in alone if k not in goal})
                if differ:
                    changed[remark] += 1
                    if args.show:
                        print(f"{appliance.id} {base[:50]!r} {remark!r} -> {differ}")
    for remark in REMARKS:
        print(f"{changed[remark]:4d} / {total[remark]:4d}  {remark!r}")
    print(f"{sum(changed.values()):4d} / {sum(total.values()):4d}  changed in all")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
