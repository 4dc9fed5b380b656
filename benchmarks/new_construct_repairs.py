"""ApBot on faulty beliefs of the small models that use the format's newer constructs.

    python benchmarks/new_construct_repairs.py

The models and goals of tests/agent/test_new_constructs.py (hold-to-scroll, conditional
effects, one-position guards, remembered settings, values declared unreachable), each belief
a faulty copy (``inject_faults`` at rate 0.5, seeds 0-5), display feedback. Prints the
episodes that miss the goal and how many reach it: a probe of the repairs on these
constructs, not a benchmark figure (the faults at this rate can remove a goal variable).
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # the tests package

import apbot.agent.methods  # noqa: F401  (registers the methods)
from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import TaskContext
from apbot.agent.registry import get_method
from apbot.bench.faults.injection import inject_faults
from apbot.model.goal import parse_goal
from tests.agent.test_new_constructs import CASES
from tests.helpers import model_from


def main() -> None:
    ok = total = 0
    for text, goal in CASES:
        truth = model_from(text)
        for seed in range(6):
            belief, faults = inject_faults(truth, 0.5, seed)
            env = SimulatorEnvironment(truth, feedback="display")
            context = TaskContext(
                "unit", "test", "t", "do it", goal, belief, actions=tuple(env.actions)
            )
            episode = get_method("apbot").run(context, env)
            reached = env.simulator.satisfies(parse_goal(truth, goal))
            total += 1
            ok += reached
            if not reached:
                print("miss", goal, [f.kind for f in faults], episode.failure[:90])
    print(f"{ok}/{total} reached")


if __name__ == "__main__":
    main()
