"""A number whose meaning a mode gives: a treadmill's one GOAL figure is minutes, kilometres
or calories as TIME / DIST / CAL is chosen, so "5 km" is that figure in the distance mode."""

from __future__ import annotations

from typing import Any

from apbot.model.domain import build_domain
from apbot.model.schema import NumericVariable
from apbot.read.goal_text import Text
from apbot.read.goal_values import name_words, unit_text
from apbot.read.goal_view import Goal, Model
from apbot.read.numbers import Mention

_KIND_OF_CASE = {
    **dict.fromkeys(("time", "duration", "min", "minutes", "mins"), "time"),
    **dict.fromkeys(("distance", "dist", "km", "kilometres", "kilometers"), "distance"),
    **dict.fromkeys(("calories", "calorie", "cal", "kcal", "energy"), "calories"),
}
_KIND_OF_UNIT = {
    **dict.fromkeys(
        ("km", "kms", "kilometre", "kilometres", "kilometer", "kilometers", "k"), "distance"
    ),
    **dict.fromkeys(("calories", "calorie", "cal", "cals", "kcal", "kcals"), "calories"),
}


def kind_numbers(
    view: Model,
    text: Text,
    mentions: list[Mention],
    goal: Goal,
    claimed: set[int],
    where: dict[str, int],
) -> list[Mention]:
    """Give a quantity of a kind that one mode's case names ("40 minutes", "5 km", "750 kcal")
    to the unitless setting those cases share, in that case; the mentions left over.

    The mode is set too unless it starts there (the first case is what it shows anyway).
    Only for a setting with no unit whose parent's cases are at least two such kinds."""
    for name, info in view.infos.items():
        var = info.var
        if name in goal or info.role != "setting" or not isinstance(var, NumericVariable):
            continue
        parent = var.depends_on
        if not parent or not var.cases or unit_text(var) or parent not in view.infos:
            continue
        kinds = {case: _case_kind(case) for case in var.cases}
        if sum(1 for k in kinds.values() if k) < 2:
            continue
        found: list[tuple[int, Any, Any]] = []
        for i, mention in enumerate(mentions):
            kind, number = _kind_said(text, mention)
            case = next((c for c, k in kinds.items() if k and k == kind), None)
            if case is None or number is None or _relative(text, mention):
                continue  # "in 30 minutes" says when, not how long
            if parent in goal and str(goal[parent]) != str(case):
                continue
            value = _in_case(var, var.cases[case], number)
            if value is not None:
                found.append((i, case, value))
        if len({str(case) for _i, case, _v in found}) > 1:
            # "5 minutes to warm up, then 8 km": two kinds, no telling which counts; a figure
            # with its kind's unit ("8 km") is still this setting's, never another's
            said = {i for i, _c, _v in found if mentions[i].kind != "duration"}
            mentions = [m for i, m in enumerate(mentions) if i not in said]
            continue
        if found:
            i, case, value = found[0]
            mention = mentions[i]
            goal[name] = value
            where[name] = mention.start
            claimed.update(range(mention.start, mention.end))
            if parent not in goal and str(case) != str(_first(view, parent)):
                goal[parent] = case
            mentions = mentions[:i] + mentions[i + 1 :]
    return mentions


def _relative(text: Text, mention: Mention) -> bool:
    """A duration counted from now ("in 30 minutes", "5 min from now"): a when, not an amount."""
    after = " ".join(text.word(mention.end + d) for d in range(2))
    return mention.kind == "duration" and (
        text.word(mention.start - 1) in ("in", "within", "after") or after == "from now"
    )


def _case_kind(case: Any) -> str | None:
    words = [w.casefold() for w in name_words(str(case))]
    return _KIND_OF_CASE.get(words[0]) if len(words) == 1 else None


def _kind_said(text: Text, mention: Mention) -> tuple[str | None, float | None]:
    """ "40 minutes" a time in minutes, "5 km" a distance, "750 kcal" calories."""
    if mention.kind == "duration":
        return "time", mention.value / 60
    if mention.kind == "number":
        return _KIND_OF_UNIT.get(text.word(mention.end)), mention.value
    return None, None


def _in_case(var: NumericVariable, spec: Any, number: float) -> Any:
    try:
        values = build_domain(var, spec).values
    except ValueError:
        return None
    return next((v for v in values if abs(float(v) - number) < 1e-9), None)


def _first(view: Model, name: str) -> Any:
    """The value a setting starts at: its initial, else its first."""
    initial = getattr(view.infos[name].var, "initial", None)
    if initial is not None:
        return initial
    values = view.infos[name].values
    return values[0] if values else None
