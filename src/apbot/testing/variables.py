"""Random variables for the generator: plain ones (discrete, numeric, time; ranges, wrap,
clamp) and programme-dependent ones, with the value helpers the builder draws from."""

from __future__ import annotations

import random
from typing import Any

from pydantic import TypeAdapter

from apbot.model.domain import all_values, build_domain
from apbot.model.schema import ApplianceModel, Variable

_VARIABLE: TypeAdapter[Any] = TypeAdapter(Variable)


def _ranges(rng: random.Random) -> list[list[int]]:
    start = rng.choice([0, 1, 5, 10])
    step = rng.choice([1, 2, 5])
    first = [start, start + step * rng.randint(1, 3), step]
    if rng.random() < 0.5:
        return [first]
    step2 = step * rng.choice([2, 3])
    return [first, [first[1], first[1] + step2 * rng.randint(1, 3), step2]]


def plain_variable(rng: random.Random) -> dict[str, Any]:
    wrap = rng.random() < 0.5
    kind = rng.choice(
        ["discrete", "discrete", "numeric", "time", "keypad", "time keypad", "large", "mode"]
    )
    if kind == "discrete":
        values = [f"x{j}" for j in range(rng.randint(2, 4))]
        return {"type": "discrete", "values": values, "wrap": wrap, "initial": rng.choice(values)}
    if kind == "mode":
        return {"type": "discrete", "values": ["m0", "m1"]}
    if kind == "numeric":
        return {"type": "numeric", "ranges": _ranges(rng), "wrap": wrap, "unit": "min"}
    if kind == "large":  # more values than the planner enumerates cheaply (> 64)
        return {"type": "numeric", "ranges": [[0, rng.choice([70, 100]), 1]], "wrap": wrap}
    if kind == "time":
        return {
            "type": "time",
            "wrap": wrap,
            "ranges": [["00:00:00", "00:02:00", 30], ["00:02:00", "00:04:00", 60]],
        }
    if kind == "time keypad":
        fmt, digits, ranges = rng.choice(
            [
                ("mm:ss", 3, [["00:00:00", "00:01:30", 30]]),
                ("mm:ss", 2, [["00:00:10", "00:00:50", 10], ["00:00:50", "00:02:00", 70]]),
                ("minutes", rng.choice([1, 2]), [["00:00:00", "00:05:00", 60]]),
            ]
        )
        overflow = rng.choice(["shift", "ignore"])
        entry = {"format": fmt, "max_digits": digits, "overflow": overflow}
        if rng.random() < 0.4:
            entry["other_keys"] = "clear"
        if rng.random() < 0.4:
            entry["shows"] = "typed"
        return {"type": "time", "ranges": ranges, "entry": entry}
    top, step = rng.choice([(9, 1), (12, 3), (20, 5), (120, 30)])
    return {
        "type": "numeric",
        "ranges": [[0, top, step]],
        "entry": {
            "format": "number",
            "max_digits": rng.choice([2, 2, 3]),
            "overflow": rng.choice(["shift", "ignore"]),
            "other_keys": rng.choice(["keep", "keep", "clear"]),
            "shows": rng.choice(["value", "value", "typed"]),
        },
    }


def dependent_variable(
    rng: random.Random, parent: str, variables: dict[str, Any]
) -> dict[str, Any]:
    """A setting with one domain per programme (sometimes none for one): value names shared
    across programmes with different defaults, so changing programme can be a shortcut."""
    parent_values = variables[parent]["values"]
    wrap = rng.random() < 0.5
    numeric = rng.random() < 0.3
    cases: dict[str, Any] = {}
    for value in parent_values:
        if rng.random() < 0.15 and (cases or value != parent_values[-1]):
            continue  # this programme has no such setting
        if numeric:
            top = rng.randint(2, 4)
            cases[value] = {"ranges": [[0, top, 1]], "initial": rng.randint(0, top)}
        else:
            size = rng.randint(2, 4)
            cases[value] = {
                "values": [f"y{j}" for j in range(size)],
                "initial": f"y{rng.randrange(size)}",
            }
    kind = "numeric" if numeric else "discrete"
    return {"type": kind, "depends_on": parent, "cases": cases, "wrap": wrap}


def case_domains(model: ApplianceModel, name: str) -> list[Any]:
    var = model.variables[name]
    if var.depends_on is None:
        return [build_domain(var)]
    return [build_domain(var, case) for case in (var.cases or {}).values()]


def value_count(var: dict[str, Any]) -> int:
    if "values" in var:
        return len(var["values"])
    return 0


def some_values(var: dict[str, Any]) -> list[Any]:
    """Values a ``to:`` or ``set:`` may name: in every case of a dependent variable."""
    if "values" in var:
        return list(var["values"])
    if "cases" in var:
        domains = [build_domain(schema_var(var), case) for case in schema_var(var).cases.values()]
        common = set(domains[0].values).intersection(*(d.values for d in domains[1:]))
        return sorted(common, key=str) or list(domains[0].values)
    return all_values(schema_var(var))


def schema_var(var: dict[str, Any]) -> Any:
    return _VARIABLE.validate_python(var)


def add_amount(rng: random.Random, var: dict[str, Any]) -> Any:
    if var["type"] == "time":
        return rng.choice([30, 60, -30, "00:01:00"])
    return rng.choice([1, 2, 5, 10, -1])
