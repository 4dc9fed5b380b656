"""The display learner: repair the belief's display rules from text it could not read.

A reader of a manual copies display texts wrong — ``P{value}`` for what the panel prints as
``PL7``, "TEMP" for "TEMPERATURE". The belief can then read none of that setting's screens:
each is *unknown* text. Walking the setting shows several of them; what they share is the
template's own text and what varies is the value (:func:`apbot.agent.infer.infer_template`).
The learnt template becomes a data edit of the model (``label`` or ``show``), accepted only if
the repaired belief reads back every text it was learnt from.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import Any

from apbot.agent.infer import Dark, Unread, infer_template
from apbot.agent.reader import DisplayReader
from apbot.agent.repair import RepairError, set_display
from apbot.agent.session import Session, loose
from apbot.model.display import display_value
from apbot.model.schema import DiscreteVariable

_LAMP_GAP = re.compile(r"\s{2,}")


class DisplayLearner:
    """Learn how the display prints a setting from texts that showed it."""

    def __init__(self, session: Session) -> None:
        self.session = session

    def learn(self, name: str, texts: Sequence[str], believed: Any = None) -> bool:
        """Repair ``name``'s display rules so that these texts read as its values (once per
        setting; ``believed``: the value a single text is believed to show); True when the
        belief changed."""
        session = self.session
        model = session.belief.model
        spec = model.variables[name]
        if isinstance(spec.show, dict) or not spec.visible:
            return False  # a map of words per value: one wrong word is learnt by the walk
        mains = [self._main(text) for text in dict.fromkeys(texts) if text.strip()]
        template = infer_template(
            mains,
            lambda value: display_value(spec, value),
            lambda text: loose(spec, text),
            words=isinstance(spec, DiscreteVariable),
            known=believed,
        )
        if template is None or not session.budget.once("template", f"{name}:{template}"):
            return False
        try:
            new = set_display(model, name, template)
        except RepairError as exc:
            session.episode.log("repair", f"could not repair how {name} is shown: {exc}")
            return False
        reader = DisplayReader(new)
        if any(
            not any(h.screen.variable == name for h in reader.read(text).hypotheses)
            for text in mains
        ):
            return False
        session.adopt(new, f"{name} is shown as {template!r}", session.belief.pointer())
        return True

    def learn_word(self, name: str, trace: Sequence[Any]) -> bool:
        """A setting printed as one word per value (a lamp ``DRY+``, a screen ``ECO``) with one
        value's word copied wrong: a walk that read every other value, and one text it could
        not, which differs from what the belief prints for the missing value by that word
        alone. The word the display printed becomes the value's ``show`` entry (once per
        setting); True when the belief changed."""
        session = self.session
        model = session.belief.model
        spec = model.variables[name]
        if not isinstance(spec, DiscreteVariable) or not isinstance(spec.show, dict):
            return False
        texts = {v.text for v in trace if isinstance(v, Unread)}
        read = {v for v in trace if not isinstance(v, Unread | Dark)}
        missing = [v for v in session.domain_values(name) if v not in read]
        if len(texts) != 1 or len(missing) != 1 or len(read) < 1:
            return False
        text, value = texts.pop(), missing[0]
        before = session.belief.state
        if not session.belief.set_value(name, value):
            return False
        predicted = session.belief.expected().text
        session.belief.state = before
        shown, believed = _parts(text), _parts(predicted)
        new_words = shown - believed
        old_words = believed - shown
        old = spec.show.get(str(value), "")
        words = {w.casefold() for w in spec.show.values() if w}
        if len(new_words) != 1 or old_words - {old.casefold()} or new_words & words:
            return False
        word = next(p for p in text.split() if p.casefold() in new_words)
        if not session.budget.once("template", f"{name}:{value}:{word}"):
            return False
        try:
            new = set_display(model, name, {**spec.show, str(value): word})
        except RepairError as exc:
            session.episode.log("repair", f"could not repair how {name} is shown: {exc}")
            return False
        hypotheses = DisplayReader(new).read(text, {**session.belief.values(), name: value})
        if not any(h.value(name) == value for h in hypotheses.hypotheses):
            return False
        session.adopt(new, f"{name} {value!r} is shown as {word!r}", session.belief.pointer())
        return True

    def read(self, name: str, text: str) -> Any:
        """``name``'s value in ``text`` under the (repaired) belief, or None."""
        context = self.session.belief.values()
        for hypothesis in self.session.perceiver.reader.read(text, context).hypotheses:
            if hypothesis.screen.variable == name:
                found = {**hypothesis.outside, **hypothesis.values}
                if name in found:
                    return found[name]
        return None

    def _main(self, text: str) -> str:
        """The main display: the text without the lamps the belief knows at its end."""
        lamps = self.session.perceiver.reader.lamp_texts()
        parts = _LAMP_GAP.split(text.strip())
        while len(parts) > 1 and parts[-1].casefold() in lamps:
            parts.pop()
        return parts[0]  # a lamp the belief does not know is no part of a template either


def _parts(text: str) -> set[str]:
    """The words of a display, case-folded (the main text and each lamp)."""
    return {part.casefold() for part in text.split() if part}
