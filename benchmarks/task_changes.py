"""Which tasks changed between two suites: instruction, goal, optimal count, allow entries.

    python benchmarks/task_changes.py OLD_SUITE_DIR [NEW_SUITE_DIR] > docs/suite-task-changes.md

``NEW_SUITE_DIR`` defaults to the bundled suite. Prints a Markdown report: the tasks whose
instruction or goal changed (old -> new), the optimal counts that changed, and how many tasks
record an ``allow`` exception and for which finding.
"""

from __future__ import annotations

import argparse
from collections import Counter
from pathlib import Path

from apbot.bench.suite import Task, TaskFile, bundled_suite_dir
from apbot.model.load import read_yaml


def _tasks(suite: Path) -> dict[tuple[str, str], Task]:
    found = {}
    for path in sorted(suite.glob("*/tasks.yaml")):
        data = TaskFile.model_validate(read_yaml(path.read_text(encoding="utf-8"), str(path)))
        for task in data.tasks:
            found[(data.appliance, task.id)] = task
    return found


def _goal(task: Task) -> str:
    return ", ".join(f"{k}={v}" for k, v in task.goal.items())


def _cell(text: str) -> str:
    return text.replace("|", "\\|")


def report(old_dir: Path, new_dir: Path) -> str:
    old, new = _tasks(old_dir), _tasks(new_dir)
    lines = ["# Task changes", ""]
    changed = [
        k
        for k in new
        if k in old and (old[k].goal, old[k].instruction) != (new[k].goal, new[k].instruction)
    ]
    lines += [f"{len(changed)} of {len(new)} tasks changed their instruction or goal.", ""]
    lines += ["| task | old | new |", "|---|---|---|"]
    for key in changed:
        before, after = old[key], new[key]
        parts_old, parts_new = [], []
        if before.instruction != after.instruction:
            parts_old.append(f"*{before.instruction}*")
            parts_new.append(f"*{after.instruction}*")
        if before.goal != after.goal:
            parts_old.append(f"`{_goal(before)}`")
            parts_new.append(f"`{_goal(after)}`")
        lines.append(
            f"| {key[0]} {key[1]} | {_cell('<br>'.join(parts_old))} | "
            f"{_cell('<br>'.join(parts_new))} |"
        )
    counts = [k for k in new if k in old and old[k].optimal_steps != new[k].optimal_steps]
    lines += ["", f"## Optimal counts: {len(counts)} changed", ""]
    lines += ["| task | old | new |", "|---|---|---|"]
    lines += [
        f"| {k[0]} {k[1]} | {old[k].optimal_steps} | {new[k].optimal_steps} |" for k in counts
    ]
    allowed = Counter(key.partition(":")[0] for t in new.values() for key in t.allow)
    with_allow = sum(bool(t.allow) for t in new.values())
    lines += ["", f"## Recorded exceptions: {with_allow} tasks", ""]
    lines += [f"- `{name}`: {count}" for name, count in sorted(allowed.items())]
    return "\n".join(lines) + "\n"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("old", type=Path)
    parser.add_argument("new", type=Path, nargs="?", default=bundled_suite_dir())
    args = parser.parse_args()
    print(report(args.old, args.new), end="")


if __name__ == "__main__":
    main()
