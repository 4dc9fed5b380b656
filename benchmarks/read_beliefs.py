"""The closed loop on read beliefs: ``apbot`` working from the offline reader's model.

    python benchmarks/read_beliefs.py [--tasks 2] [--categories kettle,microwave] [--method apbot]

For every bundled appliance the manual is read (``apbot.read``) and the agent runs each stored
task against the TRUE simulator, success judged on the true goal. The goal handed to the agent
is the stored goal translated into the read model's names through the evaluation alignment
(:func:`apbot.read.evaluate.translate_goal`) — a PRIVILEGED input, used here only to measure
the reader in the loop; a real run would parse the instruction against the belief instead.
The same tasks on the true model are run alongside, for reference.
"""

from __future__ import annotations

import argparse
import time
from collections import defaultdict

from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import TaskContext
from apbot.agent.registry import get_method
from apbot.bench.suite import load_suite
from apbot.model.goal import parse_goal
from apbot.read import read_manual
from apbot.read.evaluate import translate_goal

NINE = (
    "air_fryer,bottle_washer,bread_maker,dehumidifier,induction_cooker,kettle,microwave,"
    "rice_cooker,washing_machine"
)


def run(appliance, task, belief, goal, method: str) -> bool:
    env = SimulatorEnvironment(appliance.model, "display")
    context = TaskContext(
        appliance.id, appliance.category, task.id, task.instruction, goal, belief,
        appliance.manual, tuple(env.actions),
    )  # fmt: skip
    try:
        episode = get_method(method).run(context, env)
    except Exception:
        return False
    truth = parse_goal(appliance.model, task.goal)
    reached = all(env.simulator.value(n) == v for n, v in truth.items())
    return reached and episode.reasoning_steps <= context.max_reasoning_steps


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--tasks", type=int, default=2, help="first N tasks of each appliance")
    parser.add_argument("--categories", default=NINE)
    parser.add_argument("--method", default="apbot")
    args = parser.parse_args()
    wanted = set(args.categories.split(","))
    suite = load_suite("bundled")
    won: dict[str, list[int]] = defaultdict(lambda: [0, 0, 0])  # read, true, tasks
    started = time.perf_counter()
    for appliance in suite.appliances:
        if appliance.category not in wanted:
            continue
        read = read_manual(appliance.manual, list(appliance.model.actions)).model
        for task in appliance.tasks[: args.tasks]:
            goal = translate_goal(read, appliance.model, dict(task.goal))
            ok_read = run(appliance, task, read, goal, args.method)
            ok_true = run(appliance, task, appliance.model, dict(task.goal), args.method)
            row = won[appliance.category]
            row[0] += ok_read
            row[1] += ok_true
            row[2] += 1
            mark = {True: "ok", False: "--"}
            print(f"{appliance.id}/{task.id}: read {mark[ok_read]}  true {mark[ok_true]}")
    total = [sum(r[i] for r in won.values()) for i in range(3)]
    print(f"\n{'category':<18}{'SR read':>10}{'SR true':>10}{'tasks':>7}")
    for category, (r, t, n) in sorted(won.items()):
        print(f"{category:<18}{r / n:>10.2f}{t / n:>10.2f}{n:>7}")
    print(f"{'overall':<18}{total[0] / total[2]:>10.2f}{total[1] / total[2]:>10.2f}{total[2]:>7}")
    print(f"{time.perf_counter() - started:.0f} s")


if __name__ == "__main__":
    main()
