"""A control's context — the units naming it and the two after each, plus a table a sentence points
to — and the start value said among its values ("MEDIUM is set at the factory", "600 (start
setting)"). Apart from evidence_lists.py because finding where a control is written about is one
job and reading the lists written there is another; ``ListReader`` builds on this class."""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.evidence_owners import OwnWords
from apbot.read.labels import Label, words
from apbot.read.shapes import (
    DOWN_WORDS,
    UP_WORDS,
    Evidence,
    _same_word,
)
from apbot.read.text import Manual, Unit


class ContextReader(OwnWords):
    """The manual's units about the controls, and the start value said among their values."""

    manual: Manual
    infos: list[ActionInfo]
    labels: dict[str, Label]

    def context(self, tokens: list[str]) -> list[int]:
        """Units mentioning the controls, each followed by the next two of its section (and a
        table the sentence points to)."""
        seen: list[int] = []
        units = self.manual.units
        for token in tokens:
            for i in self.labels[token].mentions:
                for j in range(i, min(i + 3, len(units))):
                    if j > i and (
                        units[j].heading != units[i].heading or units[j].text == units[j].heading
                    ):
                        break
                    if j > i and _next_row_named(units[i], units[j]):
                        continue  # "| Brightness | 0 – 100 % |" under "| CCT step | 100 K |"
                    if j not in seen:
                        seen.append(j)
                    if re.search(r"\btable\b", units[j].text, re.I):
                        self._table_after(j, seen, 3)
                    nxt = j + 1
                    if (  # "The order is:" then the list it introduces, one unit further on
                        j > i
                        and units[j].text.rstrip().endswith(":")
                        and not any(  # ("Press MOTION to go on:": MOTION's list)
                            j in lab.mentions for t, lab in self.labels.items() if t not in tokens
                        )
                        and nxt < len(units)
                        and units[nxt].heading == units[i].heading
                        and nxt not in seen
                    ):
                        seen.append(nxt)
                if units[i].text.rstrip().endswith(":"):
                    self._table_after(i, seen, 1)  # "Touch COLOUR to change the colour:"
        for token in tokens:
            tw = [w for w in words(token.replace("_", " ")) if len(w) >= 4]
            for i, unit in enumerate(units):
                if unit.text != unit.heading or not tw:
                    continue
                hw = words(unit.heading)
                if any(
                    _same_word(h, t) for t in tw for h in hw if len(h) >= 4
                ) and not self._other_head(token, tw, unit.heading):
                    # ("Cookware" is no heading of COOK: a word, not a prefix)
                    if i not in seen:
                        seen.append(i)  # the heading itself: bullets below it list values
                    for j in range(i + 1, min(i + 6, len(units))):
                        if units[j].heading != unit.heading:
                            break
                        if j not in seen:
                            seen.append(j)
                        if units[j].text.rstrip().endswith(":"):
                            self._table_after(j, seen, 1)  # "The time changes in these steps:"
        return seen

    def _table_after(self, j: int, seen: list[int], gap: int) -> None:
        """The rows of the table that starts within ``gap`` units after unit ``j``, added to
        ``seen``: the table a sentence points to."""
        units = self.manual.units
        k = j + 1
        while k < len(units) and not units[k].cells and k < j + gap:
            k += 1
        while k < len(units) and units[k].cells:
            if k not in seen:
                seen.append(k)
            k += 1

    def _pair_steps(self, tokens: list[str], mentions: set[int]) -> set[int]:
        """Units that press only the stepping pair right after a unit pressing this key ("1.
        Press DAYS. …" then "2. Press ▲ or ▼ to set 1 to 14 days"): the pair moves what the
        key opened, so that step speaks of this key's setting, not of another key's."""
        pair = {
            t
            for t in self.labels
            if t not in tokens and set(t.split("_")) & (UP_WORDS | DOWN_WORDS)
        }
        if not pair or not mentions:
            return set()
        by_unit: dict[int, set[str]] = {}
        for t, lab in self.labels.items():
            for i in lab.mentions:
                by_unit.setdefault(i, set()).add(t)
        units = self.manual.units
        found: set[int] = set()
        for i, named in by_unit.items():
            if i in mentions or not named or not named <= pair or units[i].cells:
                continue
            for k in range(i - 1, max(i - 4, -1), -1):
                if units[k].heading != units[i].heading or units[k].cells:
                    break
                if k in mentions:
                    text = units[k].text
                    for t in tokens:  # (a key printed HOLD is no hold of it)
                        if t in self.labels and self.labels[t].text:
                            text = text.replace(self.labels[t].text, " ")
                    held = bool(re.search(r"\b(?:hold|held)\b", text, re.I))  # ("holding time")
                    held = held and not self._only_held(tokens)  # (no press of its own)
                    if by_unit.get(k, set()) - pair <= set(tokens) and not held:
                        found.add(i)  # (a step after holding the key is the hold's)
                    break
                if by_unit.get(k, set()) - pair:
                    break  # another key's step came in between
        return found

    def _only_held(self, tokens: list[str]) -> bool:
        """Whether the controls are only ever held (no press action of their own): a step of
        the pair after holding the key is then the hold's, and so the key's."""
        skills = {i.skill for i in self.infos if set(i.controls) & set(tokens)}
        return skills == {"hold"}

    def _two_key_hold(self, text: str, tokens: list[str]) -> bool:
        """Whether a sentence tells of holding two keys together, one of them this one, when
        the panel has that two-key hold ("press and hold SPIN and STEAM for 3 seconds: CL
        appears; hold them again to switch it off"): its on/off is the hold's, not the key's."""
        if len(tokens) != 1 or not re.search(r"\b(?:hold|held)", text, re.IGNORECASE):
            return False
        for info in self.infos:
            if len(info.controls) > 1 and tokens[0] in info.controls:
                names = [self.labels[c].text for c in info.controls if c in self.labels]
                if len(names) == len(info.controls) and all(n and n in text for n in names):
                    return True
        return False

    def _initial_from_values(self, ev: Evidence, tokens: list[str]) -> None:
        if isinstance(ev.initial, tuple) and ev.values:  # "(starts at 55°)" of 40° › 55° › COLD
            figure = f"{ev.initial[0]:g}"
            listed = [v for v in ev.values if re.fullmatch(rf"{re.escape(figure)}\s*\W{{0,2}}", v)]
            if len(listed) == 1 and not all(re.match(r"\d", v) for v in ev.values):
                ev.initial = listed[0]
        if ev.initial is not None or not ev.values:
            return
        for i in self.context(tokens):
            for v in ev.values:  # "600 (start setting) → 800 → 400": the value marked so
                if marked_start(v, self.manual.units[i].text):
                    ev.initial, ev.initial_at = v, i
                    return
        for i in self.context(tokens):
            m = re.search(
                r"\b(?:(?-i:(?!STARTS?\b))starts?|default|factory|initially|normally|delivered"
                r"|on delivery|out of the box|as supplied|unpack(?:ed|ing)?)\b"
                r"(.*)",  # (the word, not the key: "▶ START")
                self.manual.units[i].text,
                re.I,
            )
            if m:  # ("… starts in HOT. c) Press ⏻ again to switch off.": its own sentence)
                said = re.split(r"[.;!?]\s", m.group(1))[0]
                text = self.manual.units[i].text
                opened = text.rfind("(", 0, m.start())
                inner = said.split(")")[0]
                if opened > text.rfind(")", 0, m.start()) and not _names_any(ev.values, inner):
                    # "PULSE - pulses with the music (factory setting) RAINBOW - …": the
                    # bracket marks what its clause named before it, not what follows
                    said = re.split(r"[.;!?]\s", text[:opened])[-1]
                for v in ev.values:
                    if re.search(rf"(?<!\w){re.escape(v)}(?!\w)", said, re.I):  # ("55°)")
                        ev.initial, ev.initial_at = v, i
                        return
        for i in self.context(tokens):
            for v in ev.values:  # "(2.0 lb is preselected)", "Medium is selected by default."
                if re.search(
                    rf"(?<![\w.]){re.escape(v)}\s+{_SAID_PRESELECTED}",
                    self.manual.units[i].text,
                    re.I,
                ):
                    ev.initial, ev.initial_at = v, i
                    return


# said after a value that the appliance comes set to it: "2.0 lb is preselected", "MEDIUM is
# set at the factory", "Normal is selected by default"
_SAID_PRESELECTED = (
    r"(?:is|comes)\s+(?:pre-?selected|pre-?set|(?:selected|set)\s+(?:by\s+default|at\s+the\s+"
    r"factory|on\s+delivery)|the\s+(?:default|factory\s+setting))\b"
)


# a value's own bracket saying it is where the setting starts: "(start setting)", "(default)",
# "(factory setting)"
_MARKED_START = r"\(\s*(?:start(?:ing)?|default|factory|initial)(?:\s+(?:setting|value))?\s*\)"


def _names_any(values: list[str], text: str) -> bool:
    """Whether the text names one of the values ("(from the factory d15, …)")."""
    return any(re.search(rf"(?<!\w){re.escape(v)}(?!\w)", text, re.I) for v in values)


def marked_start(value: str, text: str) -> bool:
    """Whether the text marks the value as where the setting starts ("600 (start setting)",
    "60 % (factory)")."""
    if "(" not in text:
        return False  # (most texts: no pattern to build for them)
    unit = r"(?:\s*(?:%|°\s?[CF]?|[a-zA-Z]{1,3}\b))?"
    return bool(re.search(rf"(?<![\w.]){re.escape(value)}{unit}\s*{_MARKED_START}", text))


def _next_row_named(row: Unit, nxt: Unit) -> bool:
    """A later row of the same table (a specification table's) whose lead cell names a thing of
    its own: its figures are that thing's, not those of the control the row above names. A row
    with an empty lead cell goes on the row above, and stays in its context."""
    return bool(
        row.cells
        and nxt.cells
        and nxt.header == row.header
        and row.header
        and nxt.cells[0].strip()
        and nxt.cells[0].strip() != row.cells[0].strip()
    )
