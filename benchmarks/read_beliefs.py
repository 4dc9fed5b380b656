"""The closed loop on read beliefs: ``apbot`` working from the offline reader's model.

    python benchmarks/read_beliefs.py [--tasks 2] [--categories kettle,microwave] [--method apbot]
        [--no-true] [--why] [--json OUT] [--trace APPLIANCE/TASK]

For every bundled appliance the manual is read (``apbot.read``) and the agent runs each stored
task against the TRUE simulator, success judged on the true goal. The goal handed to the agent
is the stored goal translated into the read model's names through the evaluation alignment
(:func:`apbot.read.evaluate.translate_goal`) — a PRIVILEGED input, used here only to measure
the reader in the loop; a real run would parse the instruction against the belief instead.
The same tasks on the true model are run alongside, for reference (``--no-true`` skips them).
``--why`` prints, for each failed task, the agent's own reason and the goal it was given;
``--trace`` prints one task's whole trace; ``--json`` writes every task's outcome.
"""

from __future__ import annotations

import argparse
import json
import time
from collections import defaultdict
from typing import Any

from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import Episode, TaskContext
from apbot.agent.registry import get_method
from apbot.bench.suite import HELD_OUT_CATEGORIES, READER_DEVELOPMENT_CATEGORIES, load_suite
from apbot.model.goal import parse_goal
from apbot.read import read_manual
from apbot.read.evaluate import translate_goal

NINE = ",".join(READER_DEVELOPMENT_CATEGORIES)
SIX = ",".join(HELD_OUT_CATEGORIES)


def run(appliance: Any, task: Any, belief: Any, goal: dict, method: str) -> tuple[bool, str, Any]:
    """Success on the true goal, the agent's reason when it failed, and the episode."""
    env = SimulatorEnvironment(appliance.model, "display")
    context = TaskContext(
        appliance.id, appliance.category, task.id, task.instruction, goal, belief,
        appliance.manual, tuple(env.actions),
    )  # fmt: skip
    try:
        episode = get_method(method).run(context, env)
    except Exception as error:
        return False, f"crash: {type(error).__name__}: {error}", Episode()
    truth = parse_goal(appliance.model, task.goal)
    wrong = {n: env.simulator.value(n) for n, v in truth.items() if env.simulator.value(n) != v}
    reached = not wrong and episode.reasoning_steps <= context.max_reasoning_steps
    why = ""
    if not reached:
        claim = "claimed success" if episode.claimed_success else f"failure: {episode.failure}"
        why = f"{claim}; wrong on the truth: {wrong}"
    return reached, why, episode


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--tasks", type=int, default=2, help="first N tasks of each appliance")
    parser.add_argument("--categories", default=NINE, help="comma-separated, or 'six'")
    parser.add_argument("--appliances", default="", help="comma-separated appliance ids")
    parser.add_argument("--method", default="apbot")
    parser.add_argument("--no-true", action="store_true", help="skip the true-model runs")
    parser.add_argument("--why", action="store_true", help="print why each failed task failed")
    parser.add_argument("--trace", default="", help="APPLIANCE/TASK: print that task's trace")
    parser.add_argument("--json", default="", help="write every task's outcome to this file")
    args = parser.parse_args()
    wanted = set({"six": SIX, "nine": NINE}.get(args.categories, args.categories).split(","))
    only = set(filter(None, args.appliances.split(",")))
    suite = load_suite("bundled")
    won: dict[str, list[int]] = defaultdict(lambda: [0, 0, 0])  # read, true, tasks
    outcomes: list[dict[str, Any]] = []
    started = time.perf_counter()
    for appliance in suite.appliances:
        if appliance.category not in wanted or (only and appliance.id not in only):
            continue
        read = read_manual(appliance.manual, list(appliance.model.actions)).model
        for task in appliance.tasks[: args.tasks]:
            key = f"{appliance.id}/{task.id}"
            if args.trace and key != args.trace:
                continue
            goal = translate_goal(read, appliance.model, dict(task.goal))
            ok_read, why, episode = run(appliance, task, read, goal, args.method)
            ok_true = True
            if not args.no_true:
                ok_true = run(appliance, task, appliance.model, dict(task.goal), args.method)[0]
            row = won[appliance.category]
            row[0] += ok_read
            row[1] += ok_true
            row[2] += 1
            mark = {True: "ok", False: "--"}
            print(f"{key}: read {mark[ok_read]}  true {mark[ok_true]}")
            if args.why and not ok_read:
                print(f"    goal {goal}\n    {why}")
            if args.trace:
                print(f"    goal {goal}")
                for event in episode.trace:
                    print("   ", event.to_dict())
            outcomes.append({"task": key, "ok": ok_read, "why": why, "goal": goal})
    total = [sum(r[i] for r in won.values()) for i in range(3)]
    if not total[2]:
        print("no tasks")
        return
    print(f"\n{'category':<18}{'SR read':>10}{'SR true':>10}{'tasks':>7}")
    for category, (r, t, n) in sorted(won.items()):
        print(f"{category:<18}{r / n:>10.2f}{t / n:>10.2f}{n:>7}")
    print(f"{'overall':<18}{total[0] / total[2]:>10.2f}{total[1] / total[2]:>10.2f}{total[2]:>7}")
    print(f"{time.perf_counter() - started:.0f} s")
    if args.json:
        with open(args.json, "w") as out:
            json.dump(outcomes, out, indent=1, default=str)


if __name__ == "__main__":
    main()
