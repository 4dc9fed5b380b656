"""A control's values written away from its own sentences: a row of lamps named after it, the
panel's one knob and the row drawn after it, a lettered legend row, a list led by the setting's
name, a list tied to its word anywhere, the values printed beside its name ("FAN HI/LO"). Apart
from evidence.py (what the sentences about a control say) because each searches the whole
manual, and only when the control's own context gave no better list.
"""

from __future__ import annotations

import re

from apbot.read.evidence_checks import lettered_row
from apbot.read.evidence_lists import ListReader
from apbot.read.labels import words
from apbot.read.shapes import LAMP_LIST_RE, Evidence, _aside, _keyish
from apbot.read.value_lists import anchored_lists, bare_list


class ElsewhereReader(ListReader):
    """Values of a control found by its name or its key anywhere in the manual."""

    def _values_elsewhere(
        self,
        tokens: list[str],
        own_words: set[str],
        others: set[str],
        own: set[str],
        best: list[str] | None,
        best_prio: float,
        ev: Evidence,
    ) -> tuple[list[str] | None, float]:
        """The best list so far, replaced by one found elsewhere of a higher priority (each
        search runs only while what was read is worth less than what it would find); sets
        ``ev.values_at`` to where the list is."""
        units = self.manual.units
        if best_prio < 2.0 and own_words:  # "Mode lamps (left to right): NORMAL CONT. FAN"
            for i, unit in enumerate(units):
                lamps = LAMP_LIST_RE.match(unit.text)
                lamp_words = (
                    {w[:4] for w in words(lamps.group(0)) if len(w) >= 4} if lamps else set()
                )
                if lamps and lamp_words & {w[:4] for w in own_words if len(w) >= 4}:
                    # ("Keep-warm temperature lamps:" for TEMP SELECT: temp ~ temperature)
                    rest = unit.text[lamps.end() :]
                    for after in units[i + 1 : i + 8]:  # "CONT." ended a "sentence" mid-line
                        if after.line != unit.line:
                            break
                        rest += "   " + after.text
                    found = bare_list(rest)
                    if found:
                        best, best_prio, ev.values_at = found, 2.0, i
                        break
        alone = [t for t in tokens if t in ("knob", "dial")]
        if best_prio < 2.6 and alone and sum(t.endswith(alone[0]) for t in self.labels) == 1:
            # the panel's one knob: "The knob has seven positions." and the row drawn after it
            the = re.compile(rf"\bthe {alone[0]}\b", re.I)
            for i, unit in enumerate(units):
                if the.search(unit.text) and not _aside(units, i):
                    counted = [c for c in self._lists(i, True, tokens) if c[1] == 2.6]
                    if counted and self.labels[alone[0]].line is not None:
                        best, best_prio, ev.values_at = counted[0][0], 2.6, i
                        break
        if best_prio < 2.4:  # "B | Temperature key" and "B:  90   60   40   30   COLD"
            key_words = {w for t in tokens for w in words(t.replace("_", " "))}
            key_words |= {w for t in tokens if t in self.labels for w in words(self.labels[t].text)}
            lettered = lettered_row(units, key_words)
            if lettered:
                best, best_prio, ev.values_at = lettered[0], 2.4, lettered[1]
        if best_prio < 1.85:  # "Drying-time settings available: 10 · 20 · 30 · 60 min."
            for i, unit in enumerate(units):
                before = units[i - 1] if i and units[i - 1].line == unit.line else None
                led = None if _aside(units, i) else self._led_list(unit, tokens, before)
                if led and not _keyish(led, others, own):
                    best, best_prio, ev.values_at = led, 1.85, i
                    break
        if best_prio < 1.8:  # lists tied to the setting's own word anywhere in the manual
            for t in tokens:
                for w in [x for x in words(t.replace("_", " ")) if len(x) >= 4][:1]:
                    for i, unit in enumerate(units):
                        anchored = [] if _aside(units, i) else anchored_lists(unit.text, w)
                        if anchored and _keyish(anchored[0], others, own):
                            continue
                        if anchored and best_prio < 1.8:
                            best, best_prio, ev.values_at = anchored[0], 1.8, i
        for t in tokens:
            label = self.labels[t].text if t in self.labels else ""
            if not label or best_prio >= 2.5 or not re.search(r"[A-Z]", label):
                continue
            printed = re.fullmatch(r"([A-Z][A-Z ]*?)\s+([A-Z0-9]{1,6}(?:/[A-Z0-9]{1,6})+)", label)
            if printed and t in self.labels and self.labels[t].line is not None:
                # the key's printed name carries its values: "FAN HI/LO"
                best, best_prio = printed.group(2).split("/"), 2.5
                ev.values_at = self.labels[t].mentions[0] if self.labels[t].mentions else None
                continue
            pattern = re.compile(
                rf"\b{re.escape(label)}\s+([A-Z0-9]{{1,6}}(?:/[A-Z0-9]{{1,6}})+)\b"
            )
            for i, unit in enumerate(units):
                m = pattern.search(unit.text)
                if m and m.group(1).lower() in others:
                    continue  # "TIME START/PAUSE" on a panel drawing: the next key's name
                if m:  # "FAN HI/LO": the panel prints the values next to the name
                    best, best_prio, ev.values_at = m.group(1).split("/"), 2.5, i
                    break
        return best, best_prio
