"""Time `apbot check`'s work (parse, schema, semantic checks) on models at each size limit.

Each case is a model exactly at a limit of ``apbot.model.limits`` (and one just past it, which
must be refused at once). Run: ``python benchmarks/check_limits.py``.
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable
from typing import Any

from apbot.model.limits import (
    MAX_MODEL_VALUES,
    MAX_PARTS,
    MAX_STEPS,
    MAX_VALUES,
    MAX_YAML_NODES,
)
from apbot.model.load import loads_model
from apbot.model.problems import ModelError
from apbot.model.values import format_hms


def _model(variables: dict[str, Any], n_actions: int = 0) -> dict[str, Any]:
    names = list(variables)
    return {
        "appliance": {"id": "big", "category": "test"},
        "controls": [{"id": f"c{i}", "label": f"C{i}"} for i in range(max(len(names), n_actions))],
        "variables": variables,
        "actions": {f"a{i}": {"control": f"c{i}"} for i in range(len(names))},
        "features": {
            f"f{i}": [{"actions": [f"a{i}"], "variable": name, "effect": "next"}]
            for i, name in enumerate(names)
        },
    }


def discrete_at_limit(extra: int = 0) -> dict[str, Any]:
    values = [f"v{i}" for i in range(MAX_VALUES + extra)]
    return _model({"mode": {"type": "discrete", "values": values}})


def numeric_at_limit(extra: int = 0) -> dict[str, Any]:
    return _model({"x": {"type": "numeric", "ranges": [[1, MAX_VALUES + extra, 1]]}})


def time_at_limit(extra: int = 0) -> dict[str, Any]:
    end = format_hms(MAX_VALUES - 1 + extra)
    return _model({"t": {"type": "time", "ranges": [["00:00:00", end, 1]]}})


def model_values_at_limit(extra: int = 0) -> dict[str, Any]:
    count = MAX_MODEL_VALUES // MAX_VALUES
    variables = {f"x{i}": {"type": "numeric", "ranges": [[1, MAX_VALUES, 1]]} for i in range(count)}
    if extra:
        variables["more"] = {"type": "numeric", "ranges": [[1, extra, 1]]}
    return _model(variables)


def dependent_at_limit(extra: int = 0) -> dict[str, Any]:
    programmes = [f"p{i}" for i in range(MAX_PARTS)]
    per_case = (MAX_MODEL_VALUES - MAX_PARTS) // MAX_PARTS
    cases = {p: {"ranges": [[1, per_case, 1]]} for p in programmes}
    cases[programmes[0]] = {"ranges": [[1, per_case + extra, 1]]}
    return _model(
        {
            "programme": {"type": "discrete", "values": programmes},
            "setting": {"type": "numeric", "depends_on": "programme", "cases": cases},
        },
    )


def parts_at_limit(extra: int = 0) -> dict[str, Any]:
    n = MAX_PARTS + extra
    assert MAX_PARTS <= MAX_STEPS
    variables = {f"v{i}": {"type": "discrete", "values": ["a", "b"]} for i in range(n)}
    return _model(variables, n)


CASES: dict[str, Callable[[int], dict[str, Any]]] = {
    f"discrete variable, {MAX_VALUES:,} values": discrete_at_limit,
    f"numeric variable, {MAX_VALUES:,} values": numeric_at_limit,
    f"time variable, {MAX_VALUES:,} values": time_at_limit,
    f"{MAX_MODEL_VALUES:,} values in all": model_values_at_limit,
    f"dependent: {MAX_PARTS:,} programmes x 999 settings": dependent_at_limit,
    f"{MAX_PARTS:,} controls, actions, variables, features, steps": parts_at_limit,
}


def _time(text: str) -> tuple[float, float, str]:
    wall, cpu = time.perf_counter(), time.process_time()
    try:
        loads_model(text)
        outcome = "ok"
    except ModelError as exc:
        outcome = exc.problems[0].message[:70]
    return time.perf_counter() - wall, time.process_time() - cpu, outcome


def main() -> None:
    print(f"YAML node limit {MAX_YAML_NODES:,}; times are wall / CPU seconds")
    for name, build in CASES.items():
        at = json.dumps(build(0))
        past = json.dumps(build(1))
        wall, cpu, outcome = _time(at)
        past_wall, _, past_outcome = _time(past)
        print(f"{name:58} {len(at) / 1e6:4.1f} MB  {wall:5.2f} / {cpu:5.2f} s  {outcome}")
        print(f"{'  one more':58} {'':7}  {past_wall:5.2f} s        {past_outcome}")


if __name__ == "__main__":
    main()
