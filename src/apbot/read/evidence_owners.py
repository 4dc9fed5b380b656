"""Which words of the manual are about a control and which about another key: a sentence's span
from the key's label to the next key's, a list led by another key's noun, a heading compounding
two keys' words, a model-comparison table's own column. Kept apart from the list finders of
evidence_lists.py, which ask these questions."""

from __future__ import annotations

import re

from apbot.read.evidence_tables import TableReader
from apbot.read.labels import words
from apbot.read.model_columns import own_column
from apbot.read.text import Unit

_LEVELS_RE = re.compile(r"(?:levels?|settings?|modes?|options?|stages?|steps?)")  # of a setting


class OwnWords(TableReader):
    """The questions of whose words a text holds (a part of
    :class:`apbot.read.evidence_lists.ListReader`)."""

    def _other_head(self, token: str, tw: list[str], heading: str) -> bool:
        """A heading whose title names this key's word right before another key's name ("Bowl
        mode: slush, chill or off" beside BOWL and MODE): the compound's last noun says what it
        is about, here the other key's setting, so its section lends this key nothing."""
        title = words(heading.split(":")[0])
        # the key's word itself, then the other's: a compound ("Bowl mode"), where the second
        # noun is the head; an inflected word ("Delayed start") is no compound of the two keys
        at = [k for k, h in enumerate(title) if h in tw]
        others = {
            w
            for t, lab in self.labels.items()
            if t != token and lab.line is not None
            for w in words(lab.text)
            if len(w) >= 4 and w not in tw
        }
        return any(k + 1 < len(title) and title[k + 1] in others for k in at)

    def _about_another(self, text: str, tokens: list[str]) -> bool:
        """A sentence led by another key's noun ("Pouch sizes the laminator accepts:" near
        COLD): the list it introduces is about that, not this key's values. "Power levels
        available:" (near MODE, beside a POWER key) names levels, whichever key steps them."""
        lead = words(text)[:2]
        own = {w for t in tokens for w in words(t.replace("_", " "))}
        theirs = self._other_keys_words(tokens) - own
        if len(lead) > 1 and _LEVELS_RE.fullmatch(lead[1]):
            return False
        return bool(lead) and lead[0] in theirs

    def _own_model_row(self, unit: Unit) -> str:
        """A table row's text; in a table comparing the models of a range, only its first cell
        and this manual's own model's cell (a sister's cells name what this one lacks)."""
        if not unit.cells or len(unit.header) != len(unit.cells):
            return unit.text
        keys = [*self.labels, *(lab.text for lab in self.labels.values())]
        own = own_column(unit.header, self.manual.lines, self.manual.units, keys)
        return unit.text if own is None else f"{unit.cells[0]} | {unit.cells[own]}"

    def _names_setting(self, lead: list[str], tokens: list[str]) -> bool:
        """Whether words start by naming the control's setting (by its action word or its printed
        label; "Water levels" names WATER LEVEL)."""
        names = [words(t.replace("_", " ")) for t in tokens]
        names += [words(self.labels[t].text) for t in tokens if t in self.labels]
        return any(
            name
            and len(name) <= len(lead)
            and all(lw.startswith(nw) and len(nw) >= 3 for nw, lw in zip(name, lead, strict=False))
            for name in names
        )

    def _own_spans(self, text: str, tokens: list[str]) -> list[str]:
        """:meth:`_own_span` from each place the key's label stands in the sentence."""
        own = [self.labels[t].text for t in tokens if t in self.labels and self.labels[t].text]
        starts = sorted({m.start() for lab in own for m in re.finditer(re.escape(lab), text)})
        if len(starts) <= 1:
            return [self._own_span(text, tokens)]
        return [self._own_span(text[k:], tokens) for k in starts]

    def _own_span(self, text: str, tokens: list[str]) -> str:
        """The part of a sentence about the key: from its label to the next other key's label
        ("below TEMP. a row printed 20 30 40, and below SPIN a row printed 400 800")."""
        own = [self.labels[t].text for t in tokens if t in self.labels and self.labels[t].text]
        starts = [text.find(lab) for lab in own if lab and text.find(lab) >= 0]
        if not starts:
            return text
        start = min(starts)
        others = [
            lab.text
            for t, lab in self.labels.items()
            if t not in tokens
            and lab.text
            and lab.text not in own
            and not any(lab.text in o for o in own)
        ]
        end = len(text)
        for lab in others:
            k = text.find(lab, start + 1)
            if k > start:
                end = min(end, k)
        return text[start:end]

    def _arrows_of_another(self, text: str, tokens: list[str]) -> bool:
        """A run of arrows that another key's label leads, nearer than this key's ("COLOUR x2 ·
        TIMER x4 (30 → 45 → 60)"): the run is the steps of the key named right before it."""
        first = re.search(r"→|->|⇒", text)
        if not first:
            return False
        head = text[: first.start()]
        own = [self.labels[t].text for t in tokens if t in self.labels and self.labels[t].text]
        at_own = max((m.start() for lab in own for m in _label_at(lab, head)), default=-1)
        if at_own < 0:
            return False
        others = [
            lab.text
            for t, lab in self.labels.items()
            if t not in tokens and lab.text and lab.text not in own
        ]
        own_ends = [m.end() for lab in own for m in _label_at(lab, head) if m.start() == at_own]
        after = max(own_ends, default=at_own)
        return any(
            m.start() > at_own
            # "MENU 1 / MENU 2 button – …": labels joined by a slash or "or" share the run
            and not re.fullmatch(r"[\s/,&+]*(?:(?:and|or)\s*)?", head[after : m.start()])
            for lab in others
            for m in _label_at(lab, head)
        )


def _label_at(label: str, text: str) -> list[re.Match[str]]:
    """Where a key's printed label stands in a text as a word of its own, in the same case."""
    return list(re.finditer(rf"(?<!\w){re.escape(label)}(?!\w)", text))
