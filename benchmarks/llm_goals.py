"""Goal extraction with an LLM beside the offline parser: exact accuracy and seconds per task.

    python benchmarks/llm_goals.py --llm local --appliances '*_1,*_2,*_3,*_4' --sample 2 \
        --out /work/runs/llm/goals [--form list|object]

Each instruction is read against the TRUE model (as ``apbot eval-goals``) by the LLM (with the
offline parser's answer as a hint) and by the offline parser alone; a task is right when the
goal equals the stored one exactly after normalisation. One JSON line per task is appended to
``OUT/goals.jsonl`` as it finishes, so a stopped run resumes; the answers are in the LLM
response cache, so a rerun costs nothing (and its seconds are then the cache's, not the
model's: the figures below are from the first run). ``--form`` picks the answer's shape
(:mod:`apbot.read.llm_goal`: the settings named as a list, the default, or an object with every
setting); use one output directory per form.
"""

from __future__ import annotations

import argparse
import json
import time
from fnmatch import fnmatchcase
from pathlib import Path
from statistics import fmean, median

from apbot.bench.suite import load_suite
from apbot.llm.client import configured_client
from apbot.llm.config import configure_env
from apbot.llm.structured import StructuredError
from apbot.model.goal import parse_goal
from apbot.read.goal import GoalParseError, parse_instruction
from apbot.read.llm_goal import GOAL_FORMS, llm_parse_instruction


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--llm", required=True)
    parser.add_argument("--appliances", default="*")
    parser.add_argument("--sample", type=int, default=2, help="tasks per appliance")
    parser.add_argument("--out", type=Path, required=True)
    parser.add_argument("--no-hint", action="store_true", help="no offline answer as a hint")
    parser.add_argument("--form", choices=GOAL_FORMS, default="list", help="the answer's shape")
    args = parser.parse_args()
    configure_env(args.llm)
    client = configured_client()
    assert client is not None
    args.out.mkdir(parents=True, exist_ok=True)
    path = args.out / "goals.jsonl"
    done = {}
    if path.exists():
        for line in path.read_text().splitlines():
            row = json.loads(line)
            if row.get("form", "object") != args.form:
                parser.error(f"{path} holds answers in the {row.get('form', 'object')} form")
            done[row["key"]] = row
    patterns = args.appliances.split(",")
    rows = []
    for appliance in load_suite().appliances:
        if not any(fnmatchcase(appliance.id, p) for p in patterns):
            continue
        for task in appliance.tasks[: args.sample]:
            key = f"{appliance.id}/{task.id}"
            if key in done:
                rows.append(done[key])
                continue
            expected = parse_goal(appliance.model, task.goal)
            try:
                offline = parse_instruction(appliance.model, task.instruction, appliance.manual)
            except GoalParseError:
                offline = None
            start = time.perf_counter()
            try:
                read = llm_parse_instruction(
                    appliance.model,
                    task.instruction,
                    client,
                    use_hint=not args.no_hint,
                    manual=appliance.manual,
                    form=args.form,
                )
                got, usage, attempts, error = read.goal, read.usage, read.attempts, ""
            except StructuredError as exc:
                got, usage, attempts, error = None, exc.usage, 4, str(exc)
            seconds = time.perf_counter() - start
            row = {
                "key": key,
                "form": args.form,
                "category": appliance.category,
                "llm_right": got == expected,
                "offline_right": offline == expected,
                "seconds": round(seconds, 2),
                "attempts": attempts,
                "cached": usage.cached == usage.calls,
                "prompt_tokens": usage.prompt_tokens,
                "completion_tokens": usage.completion_tokens,
                "expected": expected,
                "llm": got,
                "offline": offline,
                "error": error,
            }
            with path.open("a", encoding="utf-8") as stream:
                stream.write(json.dumps(row, default=str) + "\n")
            rows.append(row)
            mark = "✓" if row["llm_right"] else "✗"
            print(f"{mark} {key} {seconds:.1f}s attempts={attempts}", flush=True)
    report(rows)


def miss_kinds(rows: list[dict]) -> dict[str, int]:
    """How the answered misses differ from the stored goal (settings as text: the rows were
    written as JSON)."""
    kinds = {"extra setting": 0, "missing setting": 0, "wrong value": 0}
    for r in rows:
        if r["llm_right"] or r["llm"] is None:
            continue
        got = {k: str(v) for k, v in r["llm"].items()}
        want = {k: str(v) for k, v in r["expected"].items()}
        kinds["extra setting"] += bool(got.keys() - want.keys())
        kinds["missing setting"] += bool(want.keys() - got.keys())
        kinds["wrong value"] += any(got[k] != want[k] for k in got.keys() & want.keys())
    return kinds


def report(rows: list[dict]) -> None:
    n = len(rows)
    fresh = [r["seconds"] for r in rows if not r["cached"]]
    print(f"tasks: {n} (answer form: {rows[0].get('form', 'object') if rows else '-'})")
    print(f"LLM goal accuracy: {sum(r['llm_right'] for r in rows) / n:.3f}")
    print(f"offline parser on the same tasks: {sum(r['offline_right'] for r in rows) / n:.3f}")
    both = sum(r["llm_right"] and r["offline_right"] for r in rows)
    print(
        f"both right: {both}; LLM only: {sum(r['llm_right'] for r in rows) - both}; "
        f"offline only: {sum(r['offline_right'] for r in rows) - both}"
    )
    print(f"no valid answer after feedback: {sum(bool(r['error']) for r in rows)}")
    kinds = miss_kinds(rows)
    print(
        "misses with an answer: "
        + ", ".join(f"{kinds[k]} {k}" for k in ("extra setting", "missing setting", "wrong value"))
        + " (a miss may have several)"
    )
    print(f"attempts: mean {fmean(r['attempts'] for r in rows):.2f}")
    if fresh:
        print(
            f"seconds per task (answered by the model, {len(fresh)}): mean {fmean(fresh):.1f}, "
            f"median {median(fresh):.1f}, max {max(fresh):.1f}"
        )
    print(
        f"tokens per task: prompt {fmean(r['prompt_tokens'] for r in rows):.0f}, "
        f"completion {fmean(r['completion_tokens'] for r in rows):.0f}"
    )
    per: dict[str, list[dict]] = {}
    for r in rows:
        per.setdefault(r["category"], []).append(r)
    for category, items in sorted(per.items()):
        llm = sum(r["llm_right"] for r in items) / len(items)
        off = sum(r["offline_right"] for r in items) / len(items)
        print(f"  {category:18s} LLM {llm:.2f}  offline {off:.2f}  (n={len(items)})")


if __name__ == "__main__":
    main()
