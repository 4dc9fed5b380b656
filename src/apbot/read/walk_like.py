"""Fields of a walk that are copies of one another, each shown by its display code.

Manuals that walk several like settings (the alarm times of a day, the two ends of a curfew,
the programmes of a timer) write the first in full and the rest in one line: "1. Press SET.
The display shows A1 and its time. 2. Press ▲ or ▼ … 3. Press SET. The display shows A2 and
its time. 4. Set A2 in the same way, then SET for A3, and SET for A4." Each field is named by
the code the display shows beside its value ("LOCK AT and its time": lock_at); a code of a
letter and a number is named by the word of the section it abbreviates ("A2" under "Setting
the alarm times": alarm_2), the word a user says.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.held_guesses import drop_unused

# the display's code beside the field's value: "shows A1 and its time", "shows LOCK AT and its
# time", "displays P2 and its temperature"
_ITS_CODE_RE = re.compile(
    r"\b(?:shows|displays)\s+(?-i:([A-Z][A-Z0-9]{0,5}(?:\s[A-Z][A-Z0-9]{1,5})?))\s+and\s+its\s+"
    r"[a-z]+",
    re.I,
)
# a space between a channel's letter and its arrow: "A ▲" for the key labelled A▲
_SPACED_ARROW_RE = re.compile(r"(?<![\w])([A-Z0-9]{1,2})\s+(?=[▲▼△▽◄►◀▶])")
# a code of letters and a number: "A2", "P3", "T1"
_LETTER_NUMBER_RE = re.compile(r"([A-Z]{1,2})(\d{1,2})")


def squeezed_arrows(text: str) -> str:
    """The text with a key's letter joined to its arrow ("A ▲ / A ▼": "A▲ / A▼"), as keys
    with a letter and an arrow are labelled; the spaced form is how the steps print them."""
    return _SPACED_ARROW_RE.sub(r"\1", text)


def its_code(shown: str) -> str:
    """The display code a step says is shown beside the field's value, else ""."""
    m = _ITS_CODE_RE.search(shown)
    return m.group(1) if m else ""


def code_name(code: str, heading: str) -> str:
    """The field's name for its display code: the section's word its letters begin ("A2"
    under "SETTING THE ALARM TIMES": alarm_2), else the code's own words ("LOCK AT": lock_at)."""
    m = _LETTER_NUMBER_RE.fullmatch(code)
    if m:
        words = re.findall(r"[a-z]{3,}", heading.lower())
        word = next((w for w in words if w.startswith(m.group(1).lower())), None)
        if word:
            return f"{re.sub(r's$', '', word)}_{int(m.group(2))}"
    return "_".join(code.lower().split())


def further_like(text: str, label: str, last: dict[str, Any], heading: str) -> list[dict[str, Any]]:
    """The fields a step set "in the same way" goes on to by the walk's key, each named by its
    code: "Set A2 in the same way, then SET for A3, and SET for A4" gives A3 and A4 as A2."""
    out: list[dict[str, Any]] = []
    pattern = rf"(?<!\w){re.escape(label)}\s+(?:for|to)\s+(?-i:([A-Z]{{1,2}}\d{{1,2}}))\b"
    for m in re.finditer(pattern, text, re.I):
        code = m.group(1)
        field = {k: v for k, v in last.items() if k not in ("name", "label", "optional")}
        out.append({**field, "name": code_name(code, heading), "label": code, "optional": False})
    return out


def named_by_code(field: dict[str, Any], shown: str, heading: str) -> dict[str, Any]:
    """The field named and labelled by the code its opening step shows beside its value, when
    the step names it no other way."""
    code = its_code(shown)
    if not code:
        return field
    if field.get("name") not in ("time", "setting"):
        return {**field, "label": code}
    return {**field, "name": code_name(code, heading), "label": code}


def absorb_pair_setting(b: Builder, steps: list[dict[str, Any]], at: int) -> None:
    """Fold into a walk the time its pair was read to set without it — from the keys' legend
    ("+  later: +30 minutes (held 2 s: +3 hours)"), or as the walk key's press then the pair:
    the pair sets the walk's times, and its holds step them too. Without this the user's
    time went to that lone setting (or the walk, starting as it does, was never used)."""
    walk_feature = next(n for n, s in b.features.items() if s is steps)
    walked = [s for s in steps if isinstance(s.get("effect"), dict)]
    times = [s for s in walked if b.variables.get(str(s.get("variable")), {}).get("type") == "time"]
    if not times:
        return
    pair = set(times[0]["actions"])
    ranges = b.variables[str(times[0]["variable"])].get("ranges")
    for fname, old in list(b.features.items()):
        if fname == walk_feature or not 1 <= len(old) <= 2 or old[:-1] not in ([], steps[:1]):
            continue
        var = str(old[-1].get("variable"))
        spec = b.variables.get(var, {})
        effect = old[-1].get("effect")
        if not isinstance(effect, dict) or not pair <= set(effect):
            continue
        if spec.get("type") != "time" or spec.get("ranges") != ranges:
            continue
        if any(v in ("next", "prev") for a, v in effect.items() if a not in pair):
            continue
        holds = {a: v for a, v in effect.items() if a not in pair}
        del b.features[fname]
        drop_unused(b, var)
        for step in times:
            step["actions"] = [*step["actions"], *holds]
            step["effect"] = {**step["effect"], **holds}
        b.note(f"features.{walk_feature}", f"the pair's own time {var} is the walk's", at)
        return


def drop_opener_setting(b: Builder, steps: list[dict[str, Any]]) -> None:
    """Drop the setting the walk's key then the pair were read to set when it is named only
    by the key ("set" for SET): the walk read from the steps is what that press opens."""
    opener = steps[0].get("actions", [])
    tokens = {c for i in b.infos if i.name in opener for c in i.controls}
    for fname, old in list(b.features.items()):
        if old is steps or len(old) != 2 or old[0] != steps[0]:
            continue
        var = str(old[1].get("variable"))
        if var in tokens or var in {b.labels[t].text.lower() for t in tokens if t in b.labels}:
            del b.features[fname]
            drop_unused(b, var)
