"""A code one step past the end of a numbered scale: "Raise the zone past 9 with + to reach P".

Panels often add a position beyond the numbers of a scale, printed as a code: a hob's boost P
after level 9, a dehumidifier's CO (continuous) below its lowest humidity. The manual says so
in one sentence that steps past the end with a key and names the code. The setting is then a
list: the numbers up to that end, and the code one step beyond it, so that a user asking for
boost or continuous drying gets a value the panel can show.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder

_PAST = re.compile(
    r"\b(?i:past|beyond)\s+(?:the\s+)?(?:(?i:level|setting|step|value|number)\s+)?"
    r"(?P<end>\d+|lowest|highest|smallest|largest)\b[^.]{0,60}?"
    r"\b(?:reach(?:es)?|changes?\s+to|shows?|displays?|switch(?:es)?\s+to|get|until)\s+\**"
    r"(?P<code>[A-Z]{1,3})\b"
)
_LOW = frozenset({"lowest", "smallest"})
# a sentence saying the press past the end is refused: the code is a warning, no position
_REFUSED = re.compile(
    r"\b(?:stays?|remains?|does\s+nothing|changes\s+nothing|nothing\s+happens|no\s+effect|"
    r"cannot|can\s*not|can't|not\s+possible|only\s+beeps?|error|fault)\b",
    re.I,
)


def _sentence(text: str, match: re.Match[str]) -> str:
    """The sentence of ``text`` the match stands in."""
    start = max(text.rfind(". ", 0, match.start()), text.rfind(".\n", 0, match.start())) + 1
    end = text.find(".", match.end())
    return text[start : end if end >= 0 else len(text)]


def _past_end(text: str) -> re.Match[str] | None:
    """The first sentence stepping past a scale's end to a code, when it is no refusal."""
    for match in _PAST.finditer(text):
        if not _REFUSED.search(_sentence(text, match)):
            return match
    return None


def read_range_codes(b: Builder) -> None:
    """Give a numbered scale the code a sentence puts one step past its end."""
    for unit in b.manual.units:
        match = _past_end(unit.text)
        if not match:
            continue
        keys = {a for a in _actions_said(b, unit.text)}
        for var, spec in b.variables.items():
            if (
                spec.get("type") != "numeric"
                or "cases" in spec
                or len(spec.get("ranges") or []) != 1
            ):
                continue
            if not keys & _actions_of(b, var):
                continue
            values = _with_code(spec, match.group("end"), match.group("code"), var in b.unread)
            if values is None:
                continue
            _make_list(spec, values)
            at = b.manual.units.index(unit)
            b.note(f"variables.{var}.values", f"{match.group('code')} one step past the end", at)


def _actions_said(b: Builder, text: str) -> set[str]:
    """The actions whose key's label the sentence names."""
    found = set()
    for info in b.infos:
        for token in info.controls:
            label = b.labels.get(token)
            if (
                label is not None
                and label.text
                and re.search(rf"(?<![A-Za-z0-9]){re.escape(label.text)}(?![A-Za-z0-9])", text)
            ):
                found.add(info.name)
    return found


def _actions_of(b: Builder, var: str) -> set[str]:
    return {
        a
        for steps in b.features.values()
        for step in steps
        if step.get("variable") == var
        for a in step.get("actions") or []
    }


def _with_code(
    spec: dict[str, Any], end: str, code: str, guessed: bool = False
) -> list[str] | None:
    """The numbers up to the end the sentence names, and the code beyond it; None when the end
    is not on the scale, or is inside a range the manual gave (``guessed``: the reader's own
    default range, which the sentence's end corrects), or the scale is not of whole numbers."""
    low, high, step = spec["ranges"][0]
    if not all(float(x).is_integer() for x in (low, high, step)) or step <= 0:
        return None
    numbers = list(range(int(low), int(high) + 1, int(step)))
    if len(numbers) > 40:
        return None
    if end in _LOW:
        return [code, *map(str, numbers)]
    if end.isdigit():
        if int(end) not in numbers or int(end) == numbers[0]:
            return None
        if int(end) != numbers[-1] and not guessed:
            return None  # "+ beyond 6" of a 1..6 heat says nothing of a read 1..9 smoke level
        return [*map(str, numbers[: numbers.index(int(end)) + 1]), code]
    return [*map(str, numbers), code]  # past the highest


def _make_list(spec: dict[str, Any], values: list[str]) -> None:
    initial = spec.get("initial")
    for key in ("ranges", "unit"):
        spec.pop(key, None)
    spec["type"] = "discrete"
    spec["values"] = values
    spec["wrap"] = False
    if initial is not None and str(_tidy(initial)) in values:
        spec["initial"] = str(_tidy(initial))
    else:
        spec.pop("initial", None)


def _tidy(x: Any) -> Any:
    return int(x) if isinstance(x, float) and x.is_integer() else x


def code_past_top(manual: str, values: list[Any]) -> str | None:
    """The code a sentence of the manual puts one step past the highest number of this list
    of values, right after it in the list (the hob's P after 9): the top of the panel's scale
    for "full" or "the highest", as the reader made it. A code below the lowest number (CO,
    continuous drying) is left out: it names a way of working more than a lower value."""
    texts = [str(v) for v in values]
    numbers = [float(t) for t in texts if _NUMBER.fullmatch(t)]
    if len(numbers) < 3:
        return None
    top = max(numbers)
    for match in _PAST.finditer(manual):
        if _REFUSED.search(_sentence(manual, match)):
            continue
        end, code = match.group("end"), match.group("code")
        if end in _LOW or code not in texts or texts.index(code) == 0:
            continue
        before = texts[texts.index(code) - 1]
        if end.isdigit() and float(end) != top:
            continue
        if _NUMBER.fullmatch(before) and float(before) == top:
            return code
    return None


_NUMBER = re.compile(r"-?\d+(?:\.\d+)?")
