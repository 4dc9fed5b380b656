"""The variable finder: a setting the goal names and the belief lacks altogether.

A reader can miss a setting entirely — its variable, its procedure, even its keys. The panel
still has the keys (the environment's action names), and the display still shows the setting
when one of them is pressed. The finder tries the keys the belief gives no role, those named
like the setting first; a key whose display the belief cannot read is walked until the text
repeats, and what varies from text to text is the setting's value
(:func:`apbot.agent.infer.infer_template`). From the walk it writes a new variable (its values
or ranges, unit, display template), the key's action and a one-step procedure into the belief —
a data edit the checker validates like any other.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from apbot.agent.guards import GuardLearner
from apbot.agent.infer import infer_template, ranges_from_values
from apbot.agent.reader import DisplayReader
from apbot.agent.repair import RepairError, add_indicator, add_setting
from apbot.agent.session import Executed, Session, summary
from apbot.model.display import display_value
from apbot.model.domain import ValueProblem, parse_value
from apbot.model.schema import DiscreteVariable, NumericVariable, TimeVariable
from apbot.model.values import parse_hms
from apbot.plan.plan import PlannedAction

MAX_WALK = 60  # presses of one key while looking at a new setting
MAX_KEYS = 6  # keys tried for one setting
TIME_STYLES = ("h:mm", "mm:ss", "hh:mm", "hh:mm:ss", "min", "h")
_NUMBER = re.compile(r"^\s*([-+]?\d+(?:\.\d+)?)\s?(.*?)\s*$")
_GAP = re.compile(r"\s{2,}")


@dataclass(frozen=True)
class Learnt:
    """A setting read off a walk: its definition (model data), the key's effect, where the walk
    left it."""

    variable: dict[str, Any]
    effect: str
    current: Any
    note: str


class VariableFinder:
    """Find a setting the belief lacks by pressing the keys it gives no role."""

    def __init__(self, session: Session, guards: GuardLearner) -> None:
        self.session = session
        self.guards = guards

    def find(self, name: str, goal_value: Any, attempt: int = 1) -> bool:
        """Look for ``name`` on the panel (once per attempt); True when the belief now has it."""
        session = self.session
        if not session.budget.once("discover", f"{name}:{attempt}"):
            return False
        kind = _kind_of(goal_value)
        for key in self._candidates(name):
            self.guards.lift_all()
            before = session.last.text
            texts, changed = self._walk(key)
            last = texts[-1] if texts else ""
            opposite = self._opposite(key)
            if len(set(texts)) < 2 and opposite is not None:  # stuck at an end: walk back
                back, _ = self._walk(opposite)
                last = back[-1] if back else last
                texts = list(reversed(back)) + texts
            if len(set(texts)) < 2:
                continue
            learnt = infer_setting(name, texts, kind, changed, last)
            if learnt is None:
                continue
            try:
                new = add_setting(
                    session.belief.model, name, learnt.variable, key, learnt.effect, opposite
                )
            except RepairError as exc:
                session.episode.log("repair", f"could not add {name}: {exc}")
                continue
            new = self._as_lamp(new, name, before)
            session.adopt(new, f"{name}: found under {key}; {learnt.note}", (f"set_{name}", 0))
            if new.variables[name].depends_on is not None:
                session.guessed_initial.add(name)
            session.belief.set_value(name, learnt.current)
            session.evidence[name] = learnt.current  # the walk showed it
            session.reread()
            return True
        return False

    def _as_lamp(self, model: Any, name: str, text: str) -> Any:
        """The new setting also as a lamp, when the display showed it after its main text
        before its key was pressed (``P1  3:00  CRUST medium``)."""
        reader = DisplayReader(model)
        for segment in _GAP.split(text.strip())[1:]:
            if any(
                h.screen.variable == name and name in h.values
                for h in reader.read(segment).hypotheses
            ):
                try:
                    return add_indicator(model, name)
                except RepairError:
                    return model
        return model

    def _candidates(self, name: str) -> list[str]:
        """Keys the belief does not know or gives no procedure, those named like the setting
        first."""
        session = self.session
        model = session.belief.model
        used = {a for steps in model.features.values() for s in steps for a in s.actions}
        unknown = [a for a in session.context.actions or session.offered if a not in used]
        words = {w for w in name.split("_") if len(w) >= 3}

        def alike(action: str) -> bool:
            parts = [p for p in action.split("_") if len(p) >= 3]
            return any(w.startswith(p) or p.startswith(w) for w in words for p in parts)

        ranked = sorted(unknown, key=lambda a: (not alike(a), unknown.index(a)))
        return [a for a in ranked if not _is_reverse(a)][:MAX_KEYS]

    def _walk(self, key: str) -> tuple[list[str], bool]:
        """Press ``key`` until the display repeats a text the belief cannot read; the texts,
        and whether the first press changed the display at all."""
        session = self.session
        before = session.last.text
        action = _planned(key)
        texts: list[str] = []
        for _ in range(MAX_WALK):
            done: Executed = session.press(action, exploring=True)
            text = _main(done.feedback.text, session.perceiver.reader.lamp_texts())
            if not done.feedback.accepted or not text or (done.seen and not done.seen.unknown):
                break  # refused, dark, or a screen the belief knows: not the missing setting
            if text in texts:
                texts.append(text)
                break
            texts.append(text)
        return texts, bool(texts) and texts[0] != before

    def _opposite(self, key: str) -> str | None:
        """The key that walks the other way (``turn_x_ccw`` for ``turn_x_cw``), if the panel
        has it."""
        pairs = (("_cw", "_ccw"), ("_up", "_down"), ("_plus", "_minus"), ("_next", "_prev"))
        offered = self.session.context.actions or tuple(self.session.offered)
        for forward, backward in pairs:
            if key.endswith(forward):
                other = key[: -len(forward)] + backward
                return other if other in offered else None
        return None


def infer_setting(
    name: str, texts: Sequence[str], kind: str, changed: bool, last: str | None = None
) -> Learnt | None:
    """A setting's definition from the texts one key showed, press after press (the last one
    may repeat an earlier one: the walk went round, or stopped at an end); ``last`` is the text
    the display shows now (where the setting is).

    >>> learnt = infer_setting("temperature", ["TEMP 180°C", "TEMP 190°C", "TEMP 200°C",
    ...                                        "TEMP 200°C"], "numeric", True)
    >>> learnt.variable["ranges"], learnt.variable["unit"], learnt.variable["label"]
    ([[180, 200, 10]], '°C', 'TEMP')
    >>> flow = infer_setting("airflow", ["FLOW high", "FLOW low", "FLOW high"], "discrete", True)
    >>> flow.variable["values"], flow.variable["wrap"], flow.variable["label"]
    (['high', 'low'], True, 'FLOW')
    """
    distinct = list(dict.fromkeys(texts))
    if len(distinct) < 2:
        return None
    wrap = len(texts) > len(distinct) and texts[-1] == distinct[0] and len(distinct) > 1
    readers = {"time": _time_setting, "numeric": _numeric_setting, "discrete": _discrete_setting}
    order = [kind, *(k for k in ("numeric", "time", "discrete") if k != kind)]
    found = None
    for candidate in order:
        found = readers[candidate](distinct)
        if found is not None:
            break
    if found is None:
        return None
    variable, values, template = found
    variable["wrap"] = wrap
    label, _, rest = template.partition(" ")
    if rest == "{value}" and "{" not in label:
        variable["label"] = label
    else:
        variable["show"] = template
    effect = "next"
    numbers = [v for v in values if isinstance(v, int | float)]
    if len(numbers) == len(values) and numbers != sorted(numbers) and not wrap:
        effect = "prev"
    variable["initial"] = values[0]
    note = f"values {summary([str(v) for v in values])}" + (", wraps" if wrap else "")
    shown_last = last if last in distinct else texts[-1]
    return Learnt(variable, effect, values[distinct.index(shown_last)], note)


def _split(distinct: Sequence[str], words: bool) -> tuple[str, list[str], str] | None:
    """The common text around the varying part of each text."""
    template = infer_template(distinct, lambda v: v, lambda t: t or None, words=words)
    if template is None:
        return None
    prefix, _, suffix = template.partition("{value}")
    middles = [t[len(prefix) : len(t) - len(suffix)] for t in distinct]
    return prefix, middles, suffix


def _numeric_setting(distinct: Sequence[str]) -> tuple[dict[str, Any], list[Any], str] | None:
    split = _split(distinct, words=False)
    if split is None:
        return None
    prefix, middles, suffix = split
    numbers: list[float] = []
    units = set()
    for middle in middles:
        match = _NUMBER.match(middle)
        if match is None:
            return None
        numbers.append(float(match.group(1)))
        units.add(match.group(2))
    if len(units) != 1:
        return None
    unit = units.pop()
    if suffix and not unit and not suffix[0].isspace():  # "180°C": the unit stayed outside
        unit, suffix = suffix.strip(), ""
    values = [int(n) if n.is_integer() else n for n in numbers]
    variable: dict[str, Any] = {
        "type": "numeric",
        "ranges": [list(r) for r in ranges_from_values(values)],
        "unit": unit,
    }
    spec = NumericVariable.model_validate(variable)
    if any(
        prefix + display_value(spec, v) + suffix != t for v, t in zip(values, distinct, strict=True)
    ):
        return None
    return variable, values, prefix + "{value}" + suffix


def _time_setting(distinct: Sequence[str]) -> tuple[dict[str, Any], list[Any], str] | None:
    split = _split(distinct, words=False)
    if split is None:
        return None
    prefix, middles, suffix = split
    for style in TIME_STYLES:
        probe = TimeVariable(type="time", ranges=[("00:00:00", "99:00:00", 1)], format=style)
        try:
            values = [parse_value(probe, m) for m in middles]
        except ValueProblem:
            continue
        if any(display_value(probe, v) != m for v, m in zip(values, middles, strict=True)):
            continue
        seconds = [parse_hms(v) for v in values]
        ranges = [
            [
                f"{a // 3600:02d}:{a % 3600 // 60:02d}:{a % 60:02d}",
                f"{b // 3600:02d}:{b % 3600 // 60:02d}:{b % 60:02d}",
                int(s),
            ]
            for a, b, s in ((int(x), int(y), int(z)) for x, y, z in ranges_from_values(seconds))
        ]
        variable = {"type": "time", "ranges": ranges, "format": style}
        return variable, values, prefix + "{value}" + suffix
    return None


def _discrete_setting(distinct: Sequence[str]) -> tuple[dict[str, Any], list[Any], str] | None:
    split = _split(distinct, words=True)
    if split is None:
        return None
    prefix, middles, suffix = split
    values = [m.strip() for m in middles]
    if any(not v for v in values) or len(set(values)) != len(values):
        return None
    return {"type": "discrete", "values": values}, values, prefix + "{value}" + suffix


def _kind_of(goal_value: Any) -> str:
    """What kind of setting a goal value is most likely for: a clock-like time, a number (with
    a unit or not: "20 min" may be either, which the display decides), or a word."""
    text = str(goal_value).strip()
    if re.fullmatch(r"\d+:\d{2}(:\d{2})?", text):
        return "time"
    if isinstance(goal_value, int | float) and not isinstance(goal_value, bool):
        return "numeric"
    return "numeric" if re.match(r"^\s*[-+]?\d", text) else "discrete"


def _is_reverse(action: str) -> bool:
    """The backward key of a pair: the finder walks the forward one."""
    return action.endswith(("_ccw", "_down", "_minus", "_prev"))


def _planned(action: str) -> PlannedAction:
    """An action the belief does not know, as the panel would take it (a hold held long)."""
    if action.startswith("hold"):
        return PlannedAction(action, "hold", (), 5.0)
    skill = (
        "turn_ccw" if action.endswith("_ccw") else "turn_cw" if action.endswith("_cw") else "press"
    )
    return PlannedAction(action, skill, (), None)


def _main(text: str, lamps: set[str]) -> str:
    """The main display: the text without the lamps the belief knows at its end."""
    parts = _GAP.split(text.strip())
    while len(parts) > 1 and parts[-1].casefold() in lamps:
        parts.pop()
    return "  ".join(parts)


__all__ = ["DiscreteVariable", "VariableFinder", "infer_setting"]
