"""What every fault kind shares: the :class:`Fault` record, model data access and validity.

A kind works on the model as plain data (``model_dump``), yields candidate copies with the
fault that describes them, and the injector keeps the first candidate that is still a valid
model (:func:`valid`).
"""

from __future__ import annotations

import copy
import random
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import Any

from pydantic import ValidationError

from apbot.model.effects import default_effect
from apbot.model.schema import Add, ApplianceModel
from apbot.model.validate import check_model

Data = dict[str, Any]
Candidates = Iterator[tuple[Data, "Fault"]]


@dataclass(frozen=True)
class Fault:
    """One mutation: its kind, the variable, feature or guard it hits, and what changed."""

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


def fault_kind(text: str) -> str:
    """The kind of a fault stored as text (``"KIND target: detail"``, as records keep them).

    >>> fault_kind("wrap delay: stops at its ends instead of wrapping")
    'wrap'
    """
    return text.split(" ", 1)[0]


def dump(model: ApplianceModel) -> Data:
    """The model as plain, mutable data (what a kind edits)."""
    return model.model_dump(mode="json", exclude_none=True)


def valid(data: Data) -> ApplianceModel | None:
    """The model if ``data`` passes the schema and every semantic check, else None."""
    try:
        model = ApplianceModel.model_validate(data)
    except ValidationError:
        return None
    if any(p.severity == "error" for p in check_model(model)):
        return None
    return model


RUN_STATES = frozenset({"power", "running", "heating", "dispensing", "status"})


def protected(name: str) -> bool:
    """Power, locks and the run state (``running``, a kettle's ``heating``, a rice cooker's
    ``status``): a reader rarely gets an on/off wrong, and a fault there is not a setting."""
    return name in RUN_STATES or "lock" in name


def case_keys(var: Data, rng: random.Random) -> list[str | None]:
    """Where a variable's domain lives: itself (None), or each of its cases in random order."""
    if "cases" not in var:
        return [None]
    return rng.sample(list(var["cases"]), len(var["cases"]))


def domain_spec(data: Data, name: str, case: str | None) -> Data:
    """The mutable domain spec (the variable, or one case in long form) inside ``data``."""
    var = data["variables"][name]
    if case is None:
        return var
    found = var["cases"][case]
    if isinstance(found, list):  # short form: initial is the first value
        found = var["cases"][case] = {"values": found, "initial": found[0]}
    return found


def read_spec(data: Data, name: str, case: str | None) -> Data:
    """The domain spec to read (not to change): a short-form case reads as ``{values: [...]}``."""
    var = data["variables"][name]
    found = var if case is None else var["cases"][case]
    return {"values": found} if isinstance(found, list) else found


def case_note(var: Data, case: str | None) -> str:
    """`` (when programme is 'cotton')`` for a case, nothing for the variable itself."""
    return "" if case is None else f" (when {var['depends_on']} is {case!r})"


def directional(effect: Any) -> bool:
    """Whether an effect moves a value up or down (next, prev, add)."""
    return effect in ("next", "prev") or isinstance(effect, Add)


def adjusting_steps(model: ApplianceModel, name: str) -> list[tuple[str, int]]:
    """Steps that move ``name`` up or down (next, prev, add): where direction and wrap matter."""
    return [
        (feature, i)
        for feature, steps in model.features.items()
        for i, step in enumerate(steps)
        if step.variable == name
        and any(directional(default_effect(step, a, model)) for a in step.actions)
    ]


def plain(effect: Any) -> Any:
    """An effect as model data (``{add: 5}``, ``next``)."""
    return effect.model_dump(mode="json") if hasattr(effect, "model_dump") else effect


def effect_text(effect: Any) -> str:
    """An effect for a fault's detail: ``next``, ``add 5``, ``to on``."""
    effect = plain(effect)
    if isinstance(effect, dict):
        key, value = next(iter(effect.items()))
        return f"{key} {value}"
    return str(effect)


def actions_text(actions: Sequence[str]) -> str:
    """A step's actions for a fault's detail, shortened for a keypad."""
    if len(actions) <= 4:
        return ", ".join(actions)
    return f"{actions[0]} … {actions[-1]}: {len(actions)} actions"


def copied(data: Data) -> Data:
    """A deep copy to mutate into one candidate."""
    return copy.deepcopy(data)


def by_mode(groups: list[list[tuple[Data, Fault]]], rng: random.Random) -> Candidates:
    """Candidates of several sub-kinds: the sub-kinds in a random order, each one's candidates
    shuffled, so a sub-kind with many candidates is not chosen more often than another."""
    present = [g for g in groups if g]
    for group in rng.sample(present, len(present)):
        yield from rng.sample(group, len(group))
