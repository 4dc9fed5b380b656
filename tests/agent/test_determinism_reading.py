"""Reading a manual and running an episode on the reading give the same model and the same
trace under every hash seed (Python orders sets of strings differently per process): the
reader, the display reader (``agent/perception.py``, ``agent/estimate.py``) and the agent
decide nothing by the order of a set."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

# the reader's fallback when a variable's reading cannot be checked: every feature stepping it
# becomes a toggle per key, written (and noted) in one order whatever the hash seed
DROP = """
from apbot.read.reader import _drop
keys = ["north", "east", "south", "west", "up", "down"]
data = {
    "controls": [{"id": k, "label": k.upper()} for k in keys],
    "actions": {f"press_{k}": {"control": k} for k in keys},
    "variables": {"level": {"type": "discrete", "values": ["1", "2", "3"]}},
    "features": {f"step_{k}": [{"actions": [f"press_{k}"], "variable": "level"}] for k in keys},
    "guards": [],
    "display": {"idle": "{level}"},
}
notes = []
_drop(data, ("variables", "level"), notes, "unreadable")
print([n.subject for n in notes])
print(list(data["features"]), list(data["variables"]))
"""

# a dev manual read afresh (no cache) and a task run on the reading, with the goal read from
# the user's sentence: a washing machine with many settings, lamps and repairs on the way
EPISODE = """
import json
from apbot.bench.beliefs import belief_model
from apbot.bench.runner import cached_suite, run_task_learning
from apbot.model.load import model_to_yaml
appliance = cached_suite("bundled").get("washing_machine_4")
model, _ = belief_model(appliance, "read", 0)
print(model_to_yaml(model))
record, _ = run_task_learning(
    appliance, appliance.tasks[3], "apbot", "read", goal_mode="read",
    belief_of=lambda spec: (model, []),
)
print(record.parsed_goal, record.success, record.repairs)
print(json.dumps(record.trace))
"""


def _outputs(script: str, seeds: tuple[str, ...]) -> set[str]:
    found = set()
    for seed in seeds:
        env = {
            **os.environ,
            "PYTHONHASHSEED": seed,
            "PYTHONPATH": f"{ROOT / 'src'}:{ROOT}",
            "APBOT_CACHE_DIR": "off",
        }
        done = subprocess.run(
            [sys.executable, "-c", script], env=env, capture_output=True, text=True, check=True
        )
        found.add(done.stdout)
    return found


def test_the_readers_fallback_writes_its_toggles_in_one_order_under_every_hash_seed() -> None:
    (output,) = _outputs(DROP, ("1", "2", "3", "4", "5"))
    assert output.splitlines()[0] == str(
        [f"features.step_{k}" for k in sorted(["north", "east", "south", "west", "up", "down"])]
    )


def test_a_manual_read_and_an_episode_run_on_it_are_the_same_under_every_hash_seed() -> None:
    (output,) = _outputs(EPISODE, ("1", "2", "3"))
    assert "features:" in output and '"kind": "action"' in output
