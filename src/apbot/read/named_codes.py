"""A setting named by what the manual spells out, when the key prints only a short code.

* "F1 ♫ — sound on / off": a key printed as a letter and a figure (F0, F1, P2) names nothing a
  user says; the thing its legend switches on and off ("sound", "headlights") is the setting.
* "DISC — opens the discrimination level": a key printed as the first letters of a longer word
  (DISC, TEMP, VOL) opens the setting that word names; the whole word is what a user says
  ("the discrimination at twenty"), the key's letters are not.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.labels import Label, words
from apbot.read.shapes import SETTING_NOUNS

# a letter and a figure or two: a function key's code, no word
_CODE_RE = re.compile(r"[A-Z]\d{1,2}")
# another code key printed in the same unit
_CODE_IN_RE = re.compile(r"(?<![\w-])[A-Z]\d{1,2}(?![\w-])")
# "sound on / off", "headlights on/off", "the display light on or off"
_NOUN_ON_OFF_RE = re.compile(
    r"^[\s|:—–-]*(?:the\s+)?([a-z][a-z-]{2,}(?:\s+[a-z][a-z-]{2,})?)\s+on\s*(?:/|or)\s*off\b", re.I
)


def code_key_noun(b: Builder, lab: Label) -> str:
    """The noun a code-printed key's own legend switches on and off, as a variable name; ""
    when the key prints a word, or its legend says no such thing."""
    printed = lab.text.split()[0] if lab.text.split() else ""
    if not _CODE_RE.fullmatch(printed):
        return ""
    for i in lab.mentions:
        text = b.manual.units[i].text
        k = text.find(printed)
        if k < 0 or len(set(_CODE_IN_RE.findall(text))) > 1:
            continue  # ("Z1 / Z2 / Z3 … each zone on or off": several keys' one legend)
        rest = re.sub(r"^[^\w]*", " ", text[k + len(printed) :])  # (its sign: "♫ — sound …")
        m = _NOUN_ON_OFF_RE.match(rest)
        if m:
            return "_".join(words(m.group(1).replace("-", " ")))
    return ""


# "opens the discrimination level": the setting a key's legend says it opens
_WORKS_ON_RE = re.compile(r"\bopens?\s+(?:the\s+|its\s+)?([a-z]{6,})\b", re.I)


def spelled_out(b: Builder, lab: Label) -> str:
    """The word a key printed as one short word shortens (DISC, whose legend "opens the
    discrimination level"), as the setting's name; "" when the legend lengthens no word."""
    printed = [w for w in words(lab.text) if w.isalpha()]
    if len(printed) != 1 or not 3 <= len(printed[0]) <= 5:
        return ""
    short = printed[0]
    for i in lab.mentions:
        text = b.manual.units[i].text
        k = text.upper().find(lab.text.upper())
        if k < 0:
            continue
        m = _WORKS_ON_RE.search(text, k + len(lab.text))
        word = m.group(1).lower() if m else ""
        if word.startswith(short) and len(word) > len(short) + 2 and word not in SETTING_NOUNS:
            return word  # (a noun the reader knows, "temperature" for TEMP, keeps the key's)
    return ""
