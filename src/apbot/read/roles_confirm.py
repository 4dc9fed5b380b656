"""What a confirming key's number is: the noun its legend says it ends the entry of.

A key that only closes an entry typed on the number keys ("OK  Ends the entry of a stitch
number", "ENTER confirms the programme number") names no setting itself; the setting is the
thing whose number is typed, so the variable takes that noun rather than "ok" or "enter".
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder

_CONFIRMS = re.compile(
    r"\b(?:ends?|confirms?|completes?|finish(?:es)?|closes?|accepts?)\s+(?:the\s+)?"
    r"(?:(?:entry|input)\s+of\s+(?:a|an|the)\s+)?([a-z]{3,})\s+(?:number|no\.|code)\b",
    re.IGNORECASE,
)


def _legend_tails(b: Builder, key: ActionInfo, lead: str) -> Iterator[str]:
    """What each of the key's own legend rows says after its printed name (a row or sentence
    that starts with the name once ``lead`` is stripped); nothing for a key that is not one
    pressed control with a label."""
    if key.skill != "press" or len(key.controls) != 1 or key.controls[0] not in b.labels:
        return
    label = b.labels[key.controls[0]].text
    if not label:
        return
    for i in b.labels[key.controls[0]].mentions:
        text = re.sub(lead, "", b.manual.units[i].text)
        if text.upper().startswith(label.upper()):
            yield text[len(label) :]


def confirmed_noun(b: Builder, key: ActionInfo) -> str:
    """The noun of the number this key confirms, read from the key's own legend (a row or
    sentence that starts with its printed name); "" when the legend says no such thing."""
    for tail in _legend_tails(b, key, r"^[ *|\-•]*"):
        m = _CONFIRMS.search(tail)
        if m and m.group(1).lower() not in {"the", "your", "this", "key"}:
            return m.group(1).lower()
    return keypad_noun(b, key) if ends_entry(b, key) else ""


# the number keys named in a legend: "Number keys 0-9 and OK - design number", "0 – 9: the
# programme number"
KEYPAD_RE = re.compile(
    r"(?:number|digit|numeric|numeral)\s+(?:keys|buttons|pad)|keypad"
    r"|(?<![\d.,])0\s*(?:-|–|to)\s*9(?![\d.,])",
    re.IGNORECASE,
)
_NOUN_NUMBER_RE = re.compile(r"\b([a-z]{3,})\s+(?:number|no\.)(?!\s+keys)\b", re.IGNORECASE)
_NOT_NOUNS = frozenset({"the", "your", "this", "key", "keys", "phone", "serial", "model", "part"})


def keypad_noun(b: Builder, key: ActionInfo) -> str:
    """The noun of the number the number keys type, when a legend row naming the number keys
    and this key says it ("Number keys 0-9 and OK - design number"); "" when none does."""
    if key.skill != "press" or len(key.controls) != 1 or key.controls[0] not in b.labels:
        return ""
    label = b.labels[key.controls[0]].text
    if not label:
        return ""
    named = re.compile(rf"(?<!\w){re.escape(label)}(?!\w)")
    for unit in b.manual.units:
        if not (KEYPAD_RE.search(unit.text) and named.search(unit.text)):
            continue
        for m in _NOUN_NUMBER_RE.finditer(unit.text):
            if m.group(1).lower() not in _NOT_NOUNS:
                return m.group(1).lower()
    return ""


# "OK  Confirms an entry", "ENTER  ends the input": a key that closes whatever is being typed
_ENDS_ENTRY = re.compile(
    r"\b(?:ends?|confirms?|completes?|finish(?:es)?|closes?|accepts?|stores?)\s+"
    r"(?:the\s+|an?\s+|your\s+|each\s+)?(?:entry|entries|input|value\s+typed"
    r"|(?:typed|entered|keyed(?:-in)?)\s+[a-z]{3,})\b",  # "confirms a typed address"
    re.IGNORECASE,
)

# "Press ENTER to finish." (a numbered step after the digits): the bare verb, nothing after it
_FINISH = re.compile(r"finish(?:\s+(?:the\s+)?(?:typing|entry))?\s*(?:[.;(]|$)", re.IGNORECASE)

_USED_TO = re.compile(r"^(?:(?:press|touch|push)(?:\s+it)?|used)\s+to\s+", re.IGNORECASE)


def ends_entry(b: Builder, key: ActionInfo) -> bool:
    """Whether the key's own legend says it closes an entry without naming a setting: such a key
    is the last step of what the number keys type, never a setting the number keys type."""
    # a legend row, also a table's ("⑥ | OK | Confirms an entry."): its number dropped
    if _pressed_to_end(b, key):
        return True
    for tail in _legend_tails(b, key, r"^[^A-Za-z]*"):
        # the legend must BEGIN with the closing verb: "TIMER | Sets the time …, then press
        # TIMER again to confirm the entry" is a setting key, not a bare OK
        legend = re.sub(r"^[\s|:.\-–—=]*", "", tail)
        if _ENDS_ENTRY.match(_USED_TO.sub("", legend)):
            return True
    return False


# "Press OK to close the entry.": a step whose only job for the key is to end what was typed
_PRESS_TO_END = r"^\W*(?:\d+\.\s*)?(?:press|touch|push)\s+{label}\s+to\s+"


def _pressed_to_end(b: Builder, key: ActionInfo) -> bool:
    """Whether a sentence tells to press the key to end the entry ("Press OK to close the
    entry."), the key having no legend of its own that says otherwise."""
    if key.skill != "press" or len(key.controls) != 1 or key.controls[0] not in b.labels:
        return False
    label = b.labels[key.controls[0]]
    if not label.text:
        return False
    lead = re.compile(_PRESS_TO_END.format(label=re.escape(label.text)), re.IGNORECASE)
    for i in label.mentions:
        text = b.manual.units[i].text
        m = lead.match(text)
        if m and (_ENDS_ENTRY.match(text[m.end() :]) or _FINISH.match(text[m.end() :])):
            return True
    return False
