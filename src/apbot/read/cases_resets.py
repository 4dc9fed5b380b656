"""Programmes that reset settings: "choosing a programme loads its defaults".

Split out of ``cases.py``: a sentence, not a table, says the programme's steps reset the
other settings, so it is read on its own after the programme tables.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.reset_key_names import key_named_only
from apbot.read.shapes import CHOICE_WORDS, GROUP_PLURALS
from apbot.read.text import Unit

STAY_RE = re.compile(
    r"\b(?:stays?|remains?|kept|keeps?|unchanged|not (?:reset|lost|changed?|cleared))\b", re.I
)
RESET_NOUN_RE = re.compile(rf"\b(?:{GROUP_PLURALS})\b", re.I)
RESET_RE = re.compile(
    rf"\b(?:{GROUP_PLURALS}|selector)\b"
    r"[^.]*\b(?:defaults?|standard values|reset|go(?:es)? back|return|wipes?|clear|lost|forget)"
    r"|\b(?:defaults?|reset|go(?:es)? back|return|wipes?|clear|lost)\b[^.]*"
    rf"\b(?:{GROUP_PLURALS})\b",
    re.IGNORECASE,
)


# the list wrapping round, no reset: "after TA the display returns to A1", "after the last
# menu the display goes back to the beginning of the list"
WRAP_RE = re.compile(
    r"\bafter\s+(?:the\s+)?[\w -]{1,20}?,?\s+(?:the\s+)?(?:display|list|it)\s+"
    r"(?:returns|goes back|comes back|starts again)\b",
    re.IGNORECASE,
)


# a reset beside a named value: "the timer is cleared and the fan goes back to AUTO"
_CLEARS_RE = re.compile(
    r"\b(?:defaults?|standard values|reset\w*|clear\w*|cancel\w*|wipe\w*|lost|forget\w*|"
    r"all (?:other )?settings)\b",
    re.IGNORECASE,
)
# "The timer stays at 0 until you press TIMER": the value a setting is reset to, not kept
_STAYS_AT = re.compile(r"\b(?:stays?|remains?)\s+(?:at\s+)?(?:\d|off\b|zero\b|blank\b)", re.I)
_NAMED_RESET_RE = re.compile(
    r"\bresets?\s+(?:the\s+)?[\w-]+(?:\s[\w-]+)?\s+(?:back\s+)?to\b", re.IGNORECASE
)


# "after 4 seconds the display returns to the mode name": the view comes back, nothing is reset
_VIEW_BACK_RE = re.compile(
    r"\b(?:display|screen)\s+(?:returns|goes\s+back|comes\s+back|switches\s+back)\s+to\b", re.I
)


def _view_back(text: str) -> bool:
    """The display going back to its usual view, with no word of a reset (defaults, cleared)."""
    return bool(_VIEW_BACK_RE.search(text)) and not _CLEARS_RE.search(text)


# "the level returns to that mode's starting value": one setting named as the subject
_ONE_RETURNS_RE = re.compile(
    r"\bthe\s+([a-z]{3,})\s+(?:returns|goes\s+back|is\s+reset|resets)\s+to\b", re.I
)


def _named_subject(b: Builder, text: str, others: list[str]) -> list[str]:
    """The settings a reset sentence names as its one subject ("the level returns to …"):
    those whose name or printed label has that noun; every one in ``others`` when the subject
    is a group ("all settings return to …") or the sentence names none."""
    m = _ONE_RETURNS_RE.search(text)
    if m is None or RESET_NOUN_RE.fullmatch(m.group(1)) or _CLEARS_RE.search(text):
        # ("the timer is cleared and the fan goes back to AUTO": a clear besides the one)
        return others
    noun = m.group(1).lower()
    return [
        n
        for n in others
        if noun in words(n.replace("_", " ")) + words(str(b.variables[n].get("label") or ""))
    ]


def _wraps(text: str) -> bool:
    """A list wrapping round ("after TA the display returns to A1"), not a reset: a sentence
    that returns to defaults ("After a mode change, it returns to the default temperature")
    is a reset however it starts."""
    return bool(WRAP_RE.search(text)) and not _CLEARS_RE.search(_NAMED_RESET_RE.sub("", text))


def apply_resets(b: Builder) -> None:
    """ "Choosing a programme loads its defaults": the programme's steps reset the settings."""
    units = b.manual.units
    at = next(
        (
            i
            for i, u in enumerate(units)
            if RESET_RE.search(u.text)
            and not STAY_RE.search(u.text)
            and not _wraps(u.text)
            and not _view_back(u.text)
            and not key_named_only(b, u.text, RESET_NOUN_RE)  # "Hold MODE … to go back"
        ),
        None,
    )
    if at is None:
        return
    kept = {  # "your taste choice stays the same when you change the mode"; the sentence
        # right after the reset ("… return to their standard values. The dial position and the
        # auto switch-off setting are kept."), or an item of its list before it ("When you
        # switch off: • brightness and colour are kept; • the mode returns to therapy")
        n
        for k, u in enumerate(units)
        if STAY_RE.search(u.text)
        and (
            RESET_NOUN_RE.search(u.text)
            or (0 < abs(k - at) <= 2 and not _STAYS_AT.search(u.text) and _one_list(units, at, k))
        )
        for n in b.variables
        if set(words(n.replace("_", " "))) & set(words(u.text))
    }
    fixed = {v for g in b.guards for v in g["when"]}
    parents = {s.get("depends_on") for s in b.variables.values()} - {None}
    choices = [
        n
        for n, s in b.variables.items()
        if s.get("type") == "discrete"
        and n not in fixed
        and (n in parents or set(words(n.replace("_", " "))) & CHOICE_WORDS)
    ]
    if not choices:
        return
    choice = choices[0]
    others = [
        n
        for n, s in b.variables.items()
        if n != choice
        and n not in fixed
        and n not in kept
        and s.get("depends_on") is None
        and n != "running"
    ]
    sets = _set_back(b, units[at].text, choice, fixed)
    if sets:  # "the zone goes back to FULL": that setting to that value, the others stay
        for steps in b.features.values():
            for step in steps:
                if step.get("variable") == choice:
                    step["set"] = {**step.get("set", {}), **sets}
        shown = ", ".join(f"{n} to {v}" for n, v in sets.items())
        b.note(f"variables.{choice}", f"choosing it sets {shown}", at)
        if not _CLEARS_RE.search(_NAMED_RESET_RE.sub("", units[at].text)):
            return  # ("resets the texture to Regular" names its value: no other reset)
        others = [n for n in others if n not in sets]  # "… the timer is cleared and the fan …"
    elif _NAMED_RESET_RE.search(units[at].text) and not _CLEARS_RE.search(
        _NAMED_RESET_RE.sub("", units[at].text)
    ):
        return  # "resets the set point to the mode's starting value": that one, no others
    others = _named_subject(b, units[at].text, others)
    if not others:
        return
    for steps in b.features.values():
        for step in steps:
            if step.get("variable") == choice:
                step["reset"] = [n for n in others if n != step.get("variable")]
    b.note(f"variables.{choice}", f"choosing it resets {', '.join(others)}", at)


def _set_back(b: Builder, text: str, choice: str, fixed: set[str]) -> dict[str, str]:
    """The settings a reset sentence puts back to a value it names, by name ("the zone goes
    back to FULL", "resets the texture to Regular"): each such setting and that value."""
    out: dict[str, str] = {}
    for name, spec in b.variables.items():
        values = [str(v) for v in spec.get("values") or []]
        for case in (spec.get("cases") or {}).values():  # a per-programme setting: any case's
            values += [str(v) for v in case.get("values") or [] if str(v) not in values]
        if name in (choice, "running") or name in fixed or spec.get("type") != "discrete":
            continue
        noun = r"[\s_-]+".join(re.escape(w) for w in words(name.replace("_", " ")))
        if not noun:
            continue
        said = re.search(
            rf"\b{noun}\b[^.;]{{0,30}}?\b(?:back\s+)?to\s+(?:the\s+)?([\w+-]+(?: [\w+-]+)?)",
            text,
            re.IGNORECASE,
        )
        if not said and {"off", "on"} <= set(values):  # "… switches the heating off"
            said = re.search(rf"\b(?:switch|turn)\w*\s+the\s+{noun}\s+(off)\b", text, re.I)
        if not said:
            continue
        told = said.group(1).lower()
        value = next((v for v in values if v == told or told.split()[0] == v), None)
        if value is not None:
            out[name] = value
    return out


def _one_list(units: list[Unit], at: int, k: int) -> bool:
    """Unit ``k`` speaks with the reset at ``at``: after it, as before; before it only as an
    item of the same bulleted list (the reset an item too, no other sentence between)."""
    if k > at:
        return True
    return all(units[j].bullet for j in range(k, at + 1))
