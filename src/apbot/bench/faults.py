"""Model faults: a ground-truth model mutated the way a reader gets a manual wrong.

The fault study asks whether the closed loop recovers from a wrong belief, so the faults are
the mistakes an LLM or an offline parser makes when reading a manual: a wrong step or range
end, a value missed or invented, a list in the wrong order, wrap and clamp confused, a key's
direction reversed, a step of a procedure skipped. Every faulty model is still a valid model
(the agent plans on it); goal values may fall outside a faulty domain, which is what the agent
must repair.

Rate semantics
--------------
The *sites* are the model's adjustable variables, in file order (those a feature steps, adds
to or types: not ``power``, locks, or variables only set as side effects such as ``running``),
then its features with two or more steps. Each site has its own generator, seeded by
``(seed, appliance id, site)``; it draws one uniform number and is faulted when that number is
below ``rate``, with a kind chosen uniformly among those that apply and keep the model valid
(the kinds are tried in a random order; the first that gives a valid model is kept). A site's
draws depend neither on the rate nor on the other sites, so the faults at a lower rate are a
subset of those at a higher rate with the same seed (validity is judged with the earlier
faults in place, so an earlier fault could in principle rule a later choice out; on the
bundled suite it never does, which the tests check). Rate 0 returns the model unchanged and
rate 1 faults every site that can be faulted.
"""

from __future__ import annotations

import copy
import random
import re
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from decimal import Decimal
from typing import Any

from pydantic import ValidationError

from apbot.model.schema import Add, ApplianceModel, time_step_seconds
from apbot.model.validate import check_model
from apbot.model.values import format_hms, normalise_text, parse_hms, tidy_number
from apbot.sim.compiled import default_effect

Data = dict[str, Any]
Candidates = Iterator[tuple[Data, "Fault"]]
MAX_FAULTY_VALUES = 20_000  # a range end pushed "too high" stays a plausible reading


@dataclass(frozen=True)
class Fault:
    """One mutation: its kind, the variable or feature it hits, and what changed."""

    kind: str
    target: str
    detail: str

    def __str__(self) -> str:
        return f"{self.kind} {self.target}: {self.detail}"


def describe(faults: Sequence[Fault]) -> str:
    """The faults, one per line, for a log or a report."""
    if not faults:
        return "no faults"
    noun = "fault" if len(faults) == 1 else "faults"
    return f"{len(faults)} {noun}:\n" + "\n".join(f"  - {fault}" for fault in faults)


# --- helpers -------------------------------------------------------------------------------------


def _dump(model: ApplianceModel) -> Data:
    return model.model_dump(mode="json", exclude_none=True)


def _valid(data: Data) -> ApplianceModel | None:
    """The model if ``data`` passes the schema and every semantic check, else None."""
    try:
        model = ApplianceModel.model_validate(data)
    except ValidationError:
        return None
    if any(p.severity == "error" for p in check_model(model)):
        return None
    return model


def _case_keys(var: Data, rng: random.Random) -> list[str | None]:
    """Where a variable's domain lives: itself (None), or each of its cases in random order."""
    if "cases" not in var:
        return [None]
    return rng.sample(list(var["cases"]), len(var["cases"]))


def _spec(data: Data, name: str, case: str | None) -> Data:
    """The mutable domain spec (the variable, or one case in long form) inside ``data``."""
    var = data["variables"][name]
    if case is None:
        return var
    spec = var["cases"][case]
    if isinstance(spec, list):  # short form: initial is the first value
        spec = var["cases"][case] = {"values": spec, "initial": spec[0]}
    return spec


def _peek(data: Data, name: str, case: str | None) -> Data:
    """The domain spec to read (not to change): a short-form case reads as ``{values: [...]}``."""
    var = data["variables"][name]
    spec = var if case is None else var["cases"][case]
    return {"values": spec} if isinstance(spec, list) else spec


def _where(var: Data, case: str | None) -> str:
    return "" if case is None else f" (when {var['depends_on']} is {case!r})"


def _directional(effect: Any) -> bool:
    return effect in ("next", "prev") or isinstance(effect, Add)


def _adjusting_steps(model: ApplianceModel, name: str) -> list[tuple[str, int]]:
    """Steps that move ``name`` up or down (next, prev, add): where direction and wrap matter."""
    return [
        (feature, i)
        for feature, steps in model.features.items()
        for i, step in enumerate(steps)
        if step.variable == name
        and any(_directional(default_effect(step, a, model)) for a in step.actions)
    ]


def _plain(effect: Any) -> Any:
    return effect.model_dump(mode="json") if hasattr(effect, "model_dump") else effect


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
    original = _dump(model)
    var = original["variables"][name]
    if var["type"] == "discrete":
        return
    for case in _case_keys(var, rng):
        ranges, initial = _magnitudes(var, _peek(original, name, case))
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
                if not _holds(changed, initial):
                    continue
                data = copy.deepcopy(original)
                _write_ranges(var, _spec(data, name, case), changed)
                where = f" of range {r + 1}" if len(ranges) > 1 else ""
                yield (
                    data,
                    Fault(
                        "step_size",
                        name,
                        f"step{where} {_show(var, s, True)} → "
                        f"{_show(var, new_step, True)}{_where(var, case)}",
                    ),
                )


def range_end(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """The last range's end (the maximum) read too low or too high, by whole steps."""
    original = _dump(model)
    var = original["variables"][name]
    if var["type"] == "discrete":
        return
    for case in _case_keys(var, rng):
        ranges, initial = _magnitudes(var, _peek(original, name, case))
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
            data = copy.deepcopy(original)
            _write_ranges(var, _spec(data, name, case), changed)
            word = "too low" if end < b else "too high"
            yield (
                data,
                Fault(
                    "range_end",
                    name,
                    f"ends at {_show(var, end)} instead of "
                    f"{_show(var, b)} ({word}){_where(var, case)}",
                ),
            )


def missing_value(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """A discrete value left out (never the initial one, nor one that selects a dependent
    setting's case: a missed programme would take its settings with it)."""
    original = _dump(model)
    var = original["variables"][name]
    if var["type"] != "discrete":
        return
    selects = {
        key
        for other in original["variables"].values()
        if other.get("depends_on") == name
        for key in other.get("cases", {})
    }
    for case in _case_keys(var, rng):
        spec = _peek(original, name, case)
        values = list(spec["values"])
        if len(values) < 3:
            continue
        initial = spec.get("initial", values[0])
        options = [v for v in values if v != initial and v not in selects]
        for value in rng.sample(options, min(3, len(options))):
            data = copy.deepcopy(original)
            target = _spec(data, name, case)
            target["values"] = [v for v in values if v != value]
            target["initial"] = initial
            yield (
                data,
                Fault(
                    "missing_value",
                    name,
                    f"{value!r} is missing from the values{_where(var, case)}",
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
    original = _dump(model)
    var = original["variables"][name]
    if var["type"] != "discrete":
        return
    for case in _case_keys(var, rng):
        spec = _peek(original, name, case)
        values = list(spec["values"])
        proposal = _new_value(values, rng)
        if proposal is None:
            continue
        value, index = proposal
        data = copy.deepcopy(original)
        target = _spec(data, name, case)
        target["values"] = [*values[:index], value, *values[index:]]
        target["initial"] = spec.get("initial", values[0])
        yield (
            data,
            Fault(
                "extra_value",
                name,
                f"{value!r} added after {values[index - 1]!r}{_where(var, case)}",
            ),
        )


def value_order(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """Discrete values in the wrong order: two neighbours swapped, or the list reversed."""
    original = _dump(model)
    var = original["variables"][name]
    if var["type"] != "discrete":
        return
    for case in _case_keys(var, rng):
        spec = _peek(original, name, case)
        values = list(spec["values"])
        if len(values) < 2:
            continue
        i = rng.randrange(len(values) - 1)
        swapped = [*values[:i], values[i + 1], values[i], *values[i + 2 :]]
        orders = [(swapped, f"{values[i]!r} and {values[i + 1]!r} swapped")]
        if len(values) >= 3:
            orders.append((values[::-1], "the list reversed"))
        for order, text in rng.sample(orders, len(orders)):
            data = copy.deepcopy(original)
            target = _spec(data, name, case)
            target["values"] = order
            target["initial"] = spec.get("initial", values[0])
            yield data, Fault("value_order", name, f"{text}{_where(var, case)}")


def wrap(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """Wrap and clamp confused (only where a key steps the value, so it matters)."""
    if not _adjusting_steps(model, name):
        return
    data = _dump(model)
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
    return _plain(effect)


def _effect_text(effect: Any) -> str:
    if isinstance(effect, dict):
        key, value = next(iter(effect.items()))
        return f"{key} {value}"
    return str(effect)


def effect_direction(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """Every up/down effect of one step reversed: next ↔ prev (for a +/- pair both, so the
    belief thinks "+" goes down), ``{add: 5}`` → ``{add: -5}``."""
    places = _adjusting_steps(model, name)
    for feature, index in rng.sample(places, len(places)):
        step = model.features[feature][index]
        effects = {a: default_effect(step, a, model) for a in step.actions}
        data = _dump(model)
        data["features"][feature][index]["effect"] = {a: _reverse(e) for a, e in effects.items()}
        changes = ", ".join(
            f"{a} {_effect_text(_plain(e))} → {_effect_text(_reverse(e))}"
            for a, e in effects.items()
            if _directional(e)
        )
        yield data, Fault("effect_direction", name, f"features.{feature}[{index}]: {changes}")


def _actions(actions: Sequence[str]) -> str:
    if len(actions) <= 4:
        return ", ".join(actions)
    return f"{actions[0]} … {actions[-1]}: {len(actions)} actions"


def missing_step(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """A feature with two or more steps loses one (e.g. "press TIMER before ▲/▼").

    Steps that only press a key (entry, confirm) are tried first: that is what a reader skips.
    When the step's actions are used nowhere else they stay in the model (so it remains valid)
    as no-op actions of the neighbouring step: the belief then thinks ▲ works without TIMER,
    and that TIMER does nothing.
    """
    steps = model.features.get(name, [])
    if len(steps) < 2:
        return
    keys = [i for i, s in enumerate(steps) if s.variable is None]  # entry or confirm steps
    others = [i for i, s in enumerate(steps) if s.variable is not None]
    for i in rng.sample(keys, len(keys)) + rng.sample(others, len(others)):
        step = steps[i]
        data = _dump(model)
        del data["features"][name][i]
        used = {a for feature in data["features"].values() for s in feature for a in s["actions"]}
        orphans = [a for a in step.actions if a not in used]
        label = f"step {i + 1} of {len(steps)} ({_actions(step.actions)}) is missing"
        if not orphans:
            yield data, Fault("missing_step", name, label)
            continue
        if step.variable is not None or step.set or step.reset:
            continue  # a step that changes values cannot become a no-op
        j = i if i < len(steps) - 1 else i - 1  # the neighbour, indexed after the removal
        neighbour = steps[j + 1 if j >= i else j]
        target = data["features"][name][j]
        target["actions"] = [*orphans, *target["actions"]]
        if neighbour.variable is not None or neighbour.effect is not None:
            target["effect"] = {
                **{a: "none" for a in orphans},
                **{a: _plain(default_effect(neighbour, a, model)) for a in neighbour.actions},
            }
        side = "next" if j >= i else "previous"
        yield (
            data,
            Fault(
                "missing_step",
                name,
                f"{label}; {', '.join(orphans)} kept as a no-op of the {side} step",
            ),
        )


Kind = Callable[[ApplianceModel, str, random.Random], Candidates]
VARIABLE_KINDS: dict[str, Kind] = {
    "step_size": step_size,
    "range_end": range_end,
    "missing_value": missing_value,
    "extra_value": extra_value,
    "value_order": value_order,
    "wrap": wrap,
    "effect_direction": effect_direction,
}
FEATURE_KINDS: dict[str, Kind] = {"missing_step": missing_step}
FAULT_KINDS: tuple[str, ...] = (*VARIABLE_KINDS, *FEATURE_KINDS)
MAX_TRIES_PER_KIND = 6  # candidates tried before a kind counts as not applicable here


# --- injection -----------------------------------------------------------------------------------


def _protected(name: str) -> bool:
    """Power, locks and run state: a reader rarely gets an on/off wrong."""
    return name in ("power", "running") or "lock" in name


def fault_sites(model: ApplianceModel) -> list[tuple[str, str]]:
    """The places a fault can hit, in a fixed order: ``("variables", name)`` for each adjustable
    variable (stepped, added to or typed by some step), then ``("features", name)`` for each
    feature with two or more steps."""
    adjusted: set[str] = set()
    for steps in model.features.values():
        for step in steps:
            if step.variable is not None and any(
                _directional(e) or e == "digit"
                for e in (default_effect(step, a, model) for a in step.actions)
            ):
                adjusted.add(step.variable)
    variables = [("variables", n) for n in model.variables if n in adjusted and not _protected(n)]
    features = [("features", n) for n, steps in model.features.items() if len(steps) >= 2]
    return variables + features


def inject_faults(
    model: ApplianceModel, rate: float, seed: str | int
) -> tuple[ApplianceModel, list[Fault]]:
    """A valid faulty copy of ``model`` and the faults in it (see the module doc for ``rate``).

    The same (model, rate, seed) always gives the same faults; string seeds are deterministic
    across processes.
    """
    if not 0.0 <= rate <= 1.0:
        raise ValueError(f"fault rate {rate} is outside 0..1")
    current, faults = model, []
    for section, name in fault_sites(model):
        base = f"{seed}|{model.appliance.id}|{section}.{name}"
        site_rng = random.Random(base)
        if site_rng.random() >= rate:
            continue
        kinds = VARIABLE_KINDS if section == "variables" else FEATURE_KINDS
        for kind in site_rng.sample(list(kinds), len(kinds)):
            found = _first_valid(kinds[kind](current, name, random.Random(f"{base}|{kind}")))
            if found is not None:
                current = found[0]
                faults.append(found[1])
                break
    return current, faults


def _first_valid(candidates: Candidates) -> tuple[ApplianceModel, Fault] | None:
    for _, (data, fault) in zip(range(MAX_TRIES_PER_KIND), candidates, strict=False):
        faulty = _valid(data)
        if faulty is not None:
            return faulty, fault
    return None
