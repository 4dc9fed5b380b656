"""SR and pass^k from k benchmark runs of the same tasks (tau-bench's reliability measure).

    for i in 0 1 2; do APBOT_LLM_REPEAT=$i apbot bench --methods llm-policy --llm URL:MODEL \
        --appliances kettle_1 --sample 3 --workers 1 --out runs/rep$i --no-report; done
    python benchmarks/llm_pass_k.py runs/rep0 runs/rep1 runs/rep2

``APBOT_LLM_REPEAT=i`` gives repeat i its own cache entries (the repeat index is in the cache
key), so a non-deterministic server is asked anew for each repeat and a rerun of a repeat is
free. SR is the mean success over all k × n runs; pass^k is the share of tasks that succeed
in all k repeats (with k = 1 they are equal). A deterministic server (temperature 0 on one
machine) gives the same answer k times: then pass^k = SR.
"""

from __future__ import annotations

import argparse
import json
from collections import defaultdict
from pathlib import Path


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("runs", nargs="+", type=Path, help="run directories, one per repeat")
    args = parser.parse_args()
    outcomes: dict[tuple[str, str], list[bool]] = defaultdict(list)
    for run in args.runs:
        for line in (run / "results.jsonl").read_text().splitlines():
            if line.strip():
                record = json.loads(line)
                outcomes[(record["method"], record["key"])].append(bool(record["success"]))
    k = len(args.runs)
    methods = sorted({m for m, _ in outcomes})
    print(f"k = {k} repeats")
    for method in methods:
        rows = [v for (m, _), v in outcomes.items() if m == method and len(v) == k]
        if not rows:
            continue
        sr = sum(sum(v) for v in rows) / (k * len(rows))
        pass_k = sum(all(v) for v in rows) / len(rows)
        print(f"{method:16s} tasks {len(rows):4d}  SR {sr:.3f}  pass^{k} {pass_k:.3f}")


if __name__ == "__main__":
    main()
