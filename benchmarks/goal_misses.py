"""Every newcats task the offline goal parser misses on the TRUE model, with what differs.

Usage: python benchmarks/goal_misses.py [SUITE_DIR]   (default benchmarks/data/newcats; a dev
suite only — never the bundled held-out six). Per miss: the sentence, then the settings the
parser added (EXTRA, with the model's initial value beside), left out (MISSING) and got wrong
(WRONG: stored, parsed), or the parse error. Group the misses by cause before writing a rule.
"""

from __future__ import annotations

import sys

from apbot.bench.suite import load_suite
from apbot.model.goal import parse_goal
from apbot.read.goal import GoalParseError, parse_instruction
from apbot.sim.compiled import compiled_model


def main(path: str = "benchmarks/data/newcats") -> None:
    for app in load_suite(path).appliances:
        compiled = compiled_model(app.model)
        initial = compiled.assignment(compiled.initial_state())
        for task in app.tasks:
            stored = parse_goal(app.model, task.goal)
            try:
                parsed, error = parse_instruction(app.model, task.instruction, app.manual), ""
            except (GoalParseError, ValueError) as exc:
                parsed, error = {}, str(exc)
            if parsed == stored and not error:
                continue
            extra = {k: v for k, v in parsed.items() if k not in stored}
            missing = {k: v for k, v in stored.items() if k not in parsed}
            wrong = {
                k: (stored[k], parsed[k]) for k in stored if k in parsed and parsed[k] != stored[k]
            }
            print(f"{app.id} {task.id}: {task.instruction}")
            print(
                f"   EXTRA {extra} (initial { ({k: initial.get(k) for k in extra}) })"
                f"  MISSING {missing}  WRONG {wrong} {error}"
            )


if __name__ == "__main__":
    main(*sys.argv[1:2])
