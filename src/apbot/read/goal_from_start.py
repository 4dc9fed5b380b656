"""A setting said as a distance from where it starts.

"Bring the tempo ten beats below where it starts", "raise the discrimination two steps from
where it starts", "the backlight one step dimmer than it comes": the value is counted from the
setting's start — by steps of the panel ("steps", "notches", "clicks", "levels", "presses") or by
its own units ("ten beats", "5 degrees") — the way named ("below", "dimmer", "lower" down;
"above", "brighter", "higher" up; "from" takes its way from the verb before: "raise", "lower").

The setting is the one whose words stand last within a few words before the distance. The
phrase is rewritten to "to <value>" before the sentence is read, so its number is no value of
another setting ("two steps" is no sensitivity 2). A setting kept per mode counts from the
start of the mode the sentence names (else the mode's own start). Nothing is rewritten when the
value falls off the setting's range.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.model.domain import Domain, build_domain, case_domains
from apbot.model.schema import DiscreteVariable
from apbot.model.values import words_to_number
from apbot.read.goal_view import Model, own_stems
from apbot.read.goal_vocab import stem

_DOWN = frozenset({"below", "under", "lower", "down", "less", "dimmer", "darker", "slower"})
_UP = frozenset({"above", "over", "higher", "up", "more", "brighter", "faster", "louder"})
_STEPS = frozenset({"step", "notch", "click", "level", "press", "position", "setting", "mark"})
_RAISE = re.compile(r"\b(raise|increase|turn\s+up|bump\s+up|push\s+up|up)\b", re.IGNORECASE)
_LOWER = re.compile(r"\b(lower|reduce|decrease|drop|turn\s+down|cut|down)\b", re.IGNORECASE)
_PHRASE = re.compile(
    r"\b(?P<n>\d+|(?:[a-z]+[\s-]+){0,2}?[a-z]+)\s+(?:(?P<own>[a-z]+)\s+)?(?P<unit>(?!(?:down|up|from)\b)[a-z]+)\s+"
    r"(?P<way>below|under|lower|down|less|dimmer|darker|slower|above|over|higher|up|more"
    r"|brighter|faster|louder|from)\s+(?:than\s+|from\s+)?"
    r"(?P<ref>(?:where|what|how)\s+it\s+(?:starts|comes|came|is)(?:\s+(?:at|on|set))?"
    r"|it\s+(?:starts|comes|came)(?:\s+(?:at|on|set))?|its\s+start(?:ing)?(?:\s+(?:value|point))?"
    r"|the\s+start(?:ing)?\s+(?:value|point|setting)|the\s+factory\s+setting)\b",
    re.IGNORECASE,
)
_BEFORE = 6
"""Words before the distance searched for the setting's own words."""


def _setting(view: Model, before: str) -> str | None:
    """The setting whose words stand last in ``before`` (its last few words)."""
    words = re.findall(r"[a-z]+", before.casefold())[-_BEFORE:]
    for word in reversed(words):
        key = stem(word)
        named = [
            n
            for n, info in view.infos.items()
            if info.role == "setting" and info.vocab.get(key, 0.0) >= 1.0
        ]
        if len(named) == 1:
            return named[0]
        if named:
            return None
    return None


def _domain(view: Model, name: str, said: str) -> Domain | None:
    """The setting's domain: for one kept per mode, the case the sentence names, else the
    mode's start."""
    var = view.infos[name].var
    if not var.depends_on:
        return build_domain(var)
    cases = case_domains(var)
    words = set(re.findall(r"[a-z0-9]+", said.casefold()))
    named = [c for c in cases if str(c).casefold().replace("_", " ") in words]
    if len(named) == 1:
        return cases[named[0]]
    parent = view.model.variables.get(var.depends_on)
    start: Any = None
    if isinstance(parent, DiscreteVariable):
        start = (
            parent.initial if parent.initial is not None else next(iter(parent.values or []), None)
        )
    return cases.get(start)


def said_from_start(view: Model, instruction: str) -> str:
    """ "the tempo ten beats below where it starts" as "the tempo to 110"."""

    def counted(m: re.Match[str]) -> str:
        words, own = m["n"].split(), m["own"] or ""
        if own and (own.casefold() in ("a", "an") or words_to_number(own) is not None):
            words, own = [*words, own], ""  # "go one bank down": the count, no setting's word
        for first in range(len(words)):
            count = words_to_number(" ".join(words[first:]))
            if count is not None:
                break
        else:
            if words[-1].casefold() not in ("a", "an"):
                return m[0]
            first, count = len(words) - 1, 1.0
        head = " ".join(words[:first])
        before = instruction[: m.start()] + head + " " + own
        name = _setting(view, before) or _setting(view, m["unit"])  # "one bank down"
        if name is None or not count or count != int(count):
            return m[0]
        way = m["way"].casefold()
        if way == "from":
            clause = re.split(r"[,;.]", before)[-1]
            up, down = bool(_RAISE.search(clause)), bool(_LOWER.search(clause))
            if up == down:
                return m[0]
            sign = 1 if up else -1
        else:
            sign = -1 if way in _DOWN else 1
        domain = _domain(view, name, instruction)
        if domain is None:
            return m[0]
        unit = m["unit"].casefold()
        unit = unit[:-2] if unit.endswith("hes") else unit.rstrip("s")
        if stem(unit) in own_stems(view.infos[name]):
            unit = "step"  # "one bank down": a step of the setting the unit names
        if unit in _STEPS or domain.magnitudes is None:
            if unit not in _STEPS:
                return m[0]
            at = domain.initial + sign * int(count)
            if domain.wrap and abs(count) < len(domain.values):
                at %= len(domain.values)  # "one bank down" from A on a ring of banks: F
            if not 0 <= at < len(domain.values):
                return m[0]
            value = domain.values[at]
        elif domain.kind == "numeric":
            target = domain.magnitudes[domain.initial] + sign * count
            if target not in domain.magnitudes:
                return m[0]
            value = domain.values[domain.magnitudes.index(target)]
        else:
            return m[0]
        return f"{head}{' ' if head else ''}to {value}"

    return _PHRASE.sub(counted, instruction)
