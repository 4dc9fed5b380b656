"""Faults in a variable's values: its range, its list of values, its ends and its keys' direction.

A reader gets a step or a range end wrong, misses a value or invents one, lists values in the
wrong order, confuses wrap and clamp, reverses what a key does, or misses that a
programme-dependent setting exists for one programme.
"""

from __future__ import annotations

import random
import re
from decimal import Decimal
from typing import Any

from apbot.bench.faults.common import (
    Candidates,
    Data,
    Fault,
    adjusting_steps,
    case_keys,
    case_note,
    copied,
    directional,
    domain_spec,
    dump,
    effect_text,
    plain,
    read_spec,
)
from apbot.model.domain import build_domain
from apbot.model.effects import default_effect
from apbot.model.schema import Add, ApplianceModel, time_step_seconds
from apbot.model.values import format_hms, normalise_text, parse_hms, tidy_number
from apbot.sim.compiled import compiled_model

MAX_FAULTY_VALUES = 20_000  # a range end pushed "too high" stays a plausible reading


# --- numbers and times ---------------------------------------------------------------------------


def _magnitudes(var: Data, spec: Data) -> tuple[list[tuple[Decimal, Decimal, Decimal]], Decimal]:
    """The ranges as exact numbers (seconds for a time) and the initial value's magnitude."""
    if var["type"] == "time":
        ranges = [
            (Decimal(parse_hms(a)), Decimal(parse_hms(b)), Decimal(time_step_seconds(s)))
            for a, b, s in spec["ranges"]
        ]
        initial = spec.get("initial")
        return ranges, Decimal(parse_hms(initial)) if initial is not None else ranges[0][0]
    ranges = [(Decimal(str(a)), Decimal(str(b)), Decimal(str(s))) for a, b, s in spec["ranges"]]
    initial = spec.get("initial")
    return ranges, Decimal(str(initial)) if initial is not None else ranges[0][0]


def _write_ranges(var: Data, spec: Data, ranges: list[tuple[Decimal, Decimal, Decimal]]) -> None:
    if var["type"] == "time":
        spec["ranges"] = [[format_hms(int(a)), format_hms(int(b)), int(s)] for a, b, s in ranges]
    else:
        spec["ranges"] = [[tidy_number(a), tidy_number(b), tidy_number(s)] for a, b, s in ranges]


def _members(ranges: list[tuple[Decimal, Decimal, Decimal]]) -> set[Decimal]:
    """Every value the ranges hold (sizes are bounded by :func:`_holds`)."""
    return {a + k * s for a, b, s in ranges for k in range(int((b - a) / s) + 1)}


def _show(var: Data, amount: Decimal, step: bool = False) -> str:
    """A value (or, with ``step``, a step) as a reader would write it: 40 °C, 00:30:00, 5 min."""
    if var["type"] == "time":
        if not step:
            return format_hms(int(amount))
        for unit, size in (("h", 3600), ("min", 60), ("s", 1)):
            if amount % size == 0:
                return f"{int(amount) // size} {unit}"
    unit = var.get("unit", "")
    return f"{tidy_number(amount)}{' ' + unit if unit else ''}"


def _holds(ranges: list[tuple[Decimal, Decimal, Decimal]], initial: Decimal) -> bool:
    """Whether the ranges are well formed, contain ``initial`` and stay a plausible size."""
    previous = None
    count = 0
    for a, b, s in ranges:
        if s <= 0 or b < a or (b - a) % s or (previous is not None and a < previous):
            return False
        previous = b
        count += int((b - a) / s) + 1
    if count > MAX_FAULTY_VALUES:
        return False
    return any(a <= initial <= b and (initial - a) % s == 0 for a, b, s in ranges)


# --- the fault kinds -----------------------------------------------------------------------------
# Each kind takes the current (valid) model, the site and the site's generator, and yields
# candidate mutated copies in order of preference; the first valid one is kept.


def step_size(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """One range's step doubled or halved (5 → 10, 10 → 5), its end kept aligned."""
    original = dump(model)
    var = original["variables"][name]
    if var["type"] == "discrete":
        return
    for case in case_keys(var, rng):
        ranges, initial = _magnitudes(var, read_spec(original, name, case))
        for r in rng.sample(range(len(ranges)), len(ranges)):
            a, b, s = ranges[r]
            steps = [s * 2]
            if s % 2 == 0 or (var["type"] == "numeric" and s % 1):
                steps.append(s / 2)  # 10 → 5 or 0.5 → 0.25, never 1 → 0.5 rinses
            for new_step in rng.sample(steps, len(steps)):
                end = a + ((b - a) // new_step) * new_step
                if end == a and b > a and r == len(ranges) - 1:
                    end = a + new_step  # keep at least two values in the range
                changed = [*ranges[:r], (a, end, new_step), *ranges[r + 1 :]]
                if not _holds(changed, initial) or _members(changed) == _members(ranges):
                    continue  # malformed, or the same values (a one-value range before another)
                data = copied(original)
                _write_ranges(var, domain_spec(data, name, case), changed)
                where = f" of range {r + 1}" if len(ranges) > 1 else ""
                yield (
                    data,
                    Fault(
                        "step_size",
                        name,
                        f"step{where} {_show(var, s, True)} → "
                        f"{_show(var, new_step, True)}{case_note(var, case)}",
                    ),
                )


def range_end(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """The last range's end (the maximum) read too low or too high, by whole steps."""
    original = dump(model)
    var = original["variables"][name]
    if var["type"] == "discrete":
        return
    for case in case_keys(var, rng):
        ranges, initial = _magnitudes(var, read_spec(original, name, case))
        a, b, s = ranges[-1]
        count = int((b - a) / s)
        most = max(1, round(count / 4))
        for direction in rng.sample([-1, 1], 2):
            end = b + direction * rng.randint(1, most) * s
            floor = max(initial, a + s if len(ranges) == 1 else a)
            if direction < 0 and end < floor:
                end = floor
            changed = [*ranges[:-1], (a, end, s)]
            if end == b or not _holds(changed, initial):
                continue
            data = copied(original)
            _write_ranges(var, domain_spec(data, name, case), changed)
            word = "too low" if end < b else "too high"
            yield (
                data,
                Fault(
                    "range_end",
                    name,
                    f"ends at {_show(var, end)} instead of "
                    f"{_show(var, b)} ({word}){case_note(var, case)}",
                ),
            )


def missing_value(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """A discrete value left out (never the initial one, nor one that selects a dependent
    setting's case: a missed programme would take its settings with it)."""
    original = dump(model)
    var = original["variables"][name]
    if var["type"] != "discrete":
        return
    selects = {
        key
        for other in original["variables"].values()
        if other.get("depends_on") == name
        for key in other.get("cases", {})
    }
    for case in case_keys(var, rng):
        spec = read_spec(original, name, case)
        values = list(spec["values"])
        if len(values) < 3:
            continue
        initial = spec.get("initial", values[0])
        options = [v for v in values if v != initial and v not in selects]
        for value in rng.sample(options, min(3, len(options))):
            data = copied(original)
            target = domain_spec(data, name, case)
            target["values"] = [v for v in values if v != value]
            target["initial"] = initial
            yield (
                data,
                Fault(
                    "missing_value",
                    name,
                    f"{value!r} is missing from the values{case_note(var, case)}",
                ),
            )


_NUMBERED = re.compile(r"^(\D*?)(\d+(?:\.\d+)?)(\D*)$")
_WORD_FORMS = ("{} plus", "{} pro", "super {}", "{} express", "extra {}")
_NOT_A_NAME = {"none", "off", "on", "----", "--"}


def _new_value(values: list[str], rng: random.Random) -> tuple[str, int] | None:
    """A plausible value that is not in ``values``, and where a reader would list it."""
    taken = {normalise_text(v) for v in values}
    groups: dict[tuple[str, str], list[int]] = {}
    for i, value in enumerate(values):
        match = _NUMBERED.match(value)
        if match:
            groups.setdefault((match.group(1), match.group(3)), []).append(i)
    numbered = [g for g in groups.values() if len(g) >= 2]
    proposals: list[tuple[str, int]] = []
    if numbered:
        members = rng.choice(numbered)
        parts = [_NUMBERED.match(values[i]).groups() for i in members]  # type: ignore[union-attr]
        numbers = [Decimal(number) for _, number, _ in parts]
        prefix, _, suffix = parts[0]
        decimals = max(len(n.partition(".")[2]) for _, n, _ in parts)
        width = min(len(n) for _, n, _ in parts) if decimals == 0 else 0  # "05" stays padded
        k = rng.randrange(len(members) - 1)
        middle = (numbers[k] + numbers[k + 1]) / 2
        beyond = numbers[-1] + (numbers[-1] - numbers[-2])
        for number, index in ((middle, members[k] + 1), (beyond, members[-1] + 1)):
            if number < 0 or number != round(number, decimals):
                continue
            text = f"{number:.{decimals}f}".zfill(width)
            proposals.append((f"{prefix}{text}{suffix}", index))
    names = [
        i for i, v in enumerate(values) if v.lower() not in _NOT_A_NAME and not _NUMBERED.match(v)
    ]
    if names:
        base = rng.choice(names)
        proposals.append((rng.choice(_WORD_FORMS).format(values[base]), base + 1))
    proposals = [p for p in proposals if normalise_text(p[0]) not in taken]
    return rng.choice(proposals) if proposals else None


def extra_value(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """A plausible value that does not exist inserted in a discrete list ("eco plus", "50")."""
    original = dump(model)
    var = original["variables"][name]
    if var["type"] != "discrete":
        return
    for case in case_keys(var, rng):
        spec = read_spec(original, name, case)
        values = list(spec["values"])
        proposal = _new_value(values, rng)
        if proposal is None:
            continue
        value, index = proposal
        data = copied(original)
        target = domain_spec(data, name, case)
        target["values"] = [*values[:index], value, *values[index:]]
        target["initial"] = spec.get("initial", values[0])
        yield (
            data,
            Fault(
                "extra_value",
                name,
                f"{value!r} added after {values[index - 1]!r}{case_note(var, case)}",
            ),
        )


def value_order(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """Discrete values in the wrong order: two neighbours swapped, or the list reversed."""
    original = dump(model)
    var = original["variables"][name]
    if var["type"] != "discrete" or not adjusting_steps(model, name):
        return  # go-to keys and toggles do not care about the order
    for case in case_keys(var, rng):
        spec = read_spec(original, name, case)
        values = list(spec["values"])
        if len(values) < 2 or (len(values) == 2 and var.get("wrap", True)):
            continue  # two values in a cycle come round in either order
        i = rng.randrange(len(values) - 1)
        swapped = [*values[:i], values[i + 1], values[i], *values[i + 2 :]]
        orders = [(swapped, f"{values[i]!r} and {values[i + 1]!r} swapped")]
        if len(values) >= 3:
            orders.append((values[::-1], "the list reversed"))
        for order, text in rng.sample(orders, len(orders)):
            data = copied(original)
            target = domain_spec(data, name, case)
            target["values"] = order
            target["initial"] = spec.get("initial", values[0])
            yield data, Fault("value_order", name, f"{text}{case_note(var, case)}")


def wrap(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """Wrap and clamp confused (only where a key steps the value, so it matters)."""
    if not adjusting_steps(model, name):
        return
    data = dump(model)
    var = data["variables"][name]
    wraps = var.get("wrap", var["type"] == "discrete")
    var["wrap"] = not wraps
    text = (
        "stops at its ends instead of wrapping"
        if wraps
        else "wraps round instead of stopping at its ends"
    )
    yield data, Fault("wrap", name, text)


def _reverse(effect: Any) -> Any:
    if effect in ("next", "prev"):
        return "prev" if effect == "next" else "next"
    if isinstance(effect, Add):
        amount = effect.add
        if isinstance(amount, str):
            return {"add": amount[1:] if amount.startswith("-") else f"-{amount}"}
        return {"add": tidy_number(-Decimal(str(amount)))}
    return plain(effect)


def effect_direction(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """Every up/down effect of one step reversed: next ↔ prev (for a +/- pair both, so the
    belief thinks "+" goes down), ``{add: 5}`` → ``{add: -5}``."""
    places = adjusting_steps(model, name)
    var = compiled_model(model).vars[compiled_model(model).var_index[name]]
    if var.spec.wrap and all(d is None or len(d) <= 2 for d in var.domains):
        return  # up and down are the same move round a cycle of two
    for feature, index in rng.sample(places, len(places)):
        step = model.features[feature][index]
        effects = {a: default_effect(step, a, model) for a in step.actions}
        data = dump(model)
        data["features"][feature][index]["effect"] = {a: _reverse(e) for a, e in effects.items()}
        changes = ", ".join(
            f"{a} {effect_text(e)} → {effect_text(_reverse(e))}"
            for a, e in effects.items()
            if directional(e)
        )
        yield data, Fault("effect_direction", name, f"features.{feature}[{index}]: {changes}")


def missing_case(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """A programme-dependent setting missing one programme's case: the reader did not see that
    the wool programme has a temperature, so the belief has none there (shown as ``--``).
    Not the starting programme's case: the belief starts where the appliance starts."""
    original = dump(model)
    var = original["variables"][name]
    if "cases" not in var:
        return
    parent = model.variables[var["depends_on"]]
    first = build_domain(parent).values[build_domain(parent).initial]
    cases = [c for c in var["cases"] if c != first]
    if not cases or len(var["cases"]) < 2:
        return
    for case in rng.sample(cases, len(cases)):
        data = copied(original)
        del data["variables"][name]["cases"][case]
        detail = f"no case for {var['depends_on']} {case!r} (the setting is believed absent there)"
        yield data, Fault("missing_case", name, detail)
