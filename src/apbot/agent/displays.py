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
from typing import Any, get_args

from apbot.agent.infer import Dark, Unread, infer_template
from apbot.agent.quantities import loose
from apbot.agent.reader import DisplayReader
from apbot.agent.repair import RepairError, drop_indicator, set_display
from apbot.agent.session import Executed, Session
from apbot.agent.value_words import names_value
from apbot.model.display import OFF_WORDS, can_show, display_value, lamp_for
from apbot.model.domain import AnyVariable
from apbot.model.schema import (
    ApplianceModel,
    DiscreteVariable,
    NumericVariable,
    TimeStyle,
    TimeVariable,
)

_LAMP_GAP = re.compile(r"\s{2,}")


class DisplayLearner:
    """Learn how the display prints a setting from texts that showed it."""

    def __init__(self, session: Session) -> None:
        self.session = session
        # per setting, the displays read with its lamp unlit where the belief predicted it lit
        self._unlit: dict[str, set[str]] = {}

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
        variants: list[tuple[AnyVariable, str | None, bool]] = [(spec, None, False)]
        if isinstance(spec, TimeVariable):
            # the reader may print a time in the wrong style ("0:30" for a panel's "30 min")
            variants += [
                (spec.model_copy(update={"format": s}), s, False)
                for s in get_args(TimeStyle)
                if s != spec.format
            ]
        if isinstance(spec, NumericVariable) and spec.unit:
            # the manual names a unit ("45 %") the panel does not print ("45")
            variants.append((spec.model_copy(update={"unit": None}), None, True))
        # texts whose varying part is a whole value of the setting's domain first ("1/2+0.7"
        # and "1/2+0.3" show 1/2+0.7 and 1/2+0.3, not a template "1/2+0.{value}" of words 7, 3)
        found: tuple[str, str | None, bool] | None = _whole_values(
            spec, mains, session.domain_values(name)
        )
        # then a text that holds the believed value, in any style; a bare value only then
        found = found or next(
            (
                (template, style, unitless)
                for bare in (False, True)
                for variant, style, unitless in variants
                if (template := self._template(variant, mains, believed, bare)) is not None
            ),
            None,
        )
        if found is None:
            return False
        template, style, unitless = found
        key = f"{name}:{template}:{style}" if style else f"{name}:{template}"
        try:
            new: ApplianceModel | None = set_display(
                model, name, template, style, drop_unit=unitless
            )
        except RepairError as exc:
            new, problem = None, exc
        if new is not None and _no_value_shown(new, name, mains):
            # the panel's own words for its values, which the walk pairs with them
            # (``apbot.agent.renamed``), not new values; asked again after more texts
            return False
        if not session.budget.once("template", key):
            return False
        if new is None:
            session.episode.log("repair", f"could not repair how {name} is shown: {problem}")
            return False
        reader = DisplayReader(new)
        if any(
            not any(h.screen.variable == name for h in reader.read(text).hypotheses)
            for text in mains
        ):
            return False
        how = f"{template!r} ({style})" if style else repr(template)
        how += " (no unit)" if unitless else ""
        session.adopt(new, f"{name} is shown as {how}", session.belief.pointer())
        return True

    @staticmethod
    def _template(
        spec: AnyVariable, mains: list[str], believed: Any, bare: bool = True
    ) -> str | None:
        return infer_template(
            mains,
            lambda value: display_value(spec, value),
            lambda text: loose(spec, text),
            words=isinstance(spec, DiscreteVariable),
            known=believed,
            bare=bare,
        )

    def learn_word(
        self, name: str, trace: Sequence[Any], believed: Any = None, start_read: bool = False
    ) -> bool:
        """A setting printed as one word per value (a lamp ``DRY+``, a screen ``ECO``) with one
        value's word copied wrong: a walk that read every other value, and one text it could
        not, which differs from what the belief prints for the missing value by that word
        alone. The word the display printed becomes the value's ``show`` entry (once per
        setting); True when the belief changed. An on/off setting the belief prints as
        "LABEL value" learns the one word its lamp lights (:meth:`_lamp_word`); ``believed``:
        the value the walk's first press was to give, which is known only if the value that
        press moved from was read (``start_read``) — else the word must name it itself."""
        session = self.session
        model = session.belief.model
        spec = model.variables[name]
        if not isinstance(spec, DiscreteVariable):
            return False
        texts = {v.text for v in trace if isinstance(v, Unread)}
        read = {v for v in trace if not isinstance(v, Unread | Dark)}
        missing = [v for v in session.domain_values(name) if v not in read]
        dark = any(isinstance(v, Dark) for v in trace)
        if spec.show is None and len(texts) == 1 and not read and dark:
            # the word and a dark display in turn: the word is the value the walk's first
            # press was to give (``believed``), the dark display the other
            domain = session.domain_values(name)
            others = [v for v in domain if v != believed]
            word = next(iter(texts))
            if not start_read and not names_value(spec, name, word, believed, domain):
                return False  # from a guessed start the press may have given the other value
            if len(others) == 1 and len(others) < len(domain):
                return self._lamp_word(name, texts.pop(), believed, others[0])
        if len(texts) != 1 or len(missing) != 1 or len(read) < 1:
            return False
        text, value = texts.pop(), missing[0]
        if spec.show is None:
            return self._lamp_word(name, text, value, read.pop())
        if isinstance(spec.show, str):
            return self._combined_word(name, text, value, read)
        if not isinstance(spec.show, dict):
            return False
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
        if old and old.casefold() in self._printed():
            return False  # the panel has printed the belief's word: it was not copied wrong
        word = next(p for p in text.split() if p.casefold() in new_words)
        return self._show_word(name, value, word, {**spec.show, str(value): word}, text)

    def _printed(self) -> set[str]:
        """The words the display printed so far in this episode."""
        trace = self.session.episode.trace
        return {w for e in trace if e.kind == "action" and e.display for w in _parts(e.display)}

    def _combined_word(self, name: str, text: str, value: Any, read: set[Any]) -> bool:
        """A choice printed as its value alone, whose walk read every value but one, shown as
        the words of the others together (``UPPER LOWER`` for both plates, ``A B C`` for all
        zones): those words are that value's (once, if read back)."""
        session = self.session
        spec = session.belief.model.variables[name]
        if spec.show is None or str(spec.show).strip() != "{value}":
            return False
        words = text.split()
        printed = {display_value(spec, v).casefold() for v in read}
        if len(words) < 2 or not all(w.casefold() in printed for w in words):
            return False
        show = {str(v): display_value(spec, v) for v in session.domain_values(name)}
        show[str(value)] = " ".join(words)
        return self._show_word(name, value, show[str(value)], show, text)

    def _lamp_word(self, name: str, text: str, value: Any, other: Any) -> bool:
        """An on/off setting the belief prints as "LABEL value", whose walk read one value
        (a display without it) and showed the other as one short word it cannot read
        (``LIGHT``, ``ROT``): the panel lights that word for that value and prints nothing for
        the other. Only for two values and a word of letters (no number: that is a value of
        some setting), and only if the repaired belief reads the word back (once)."""
        session = self.session
        words = text.split()
        if len(session.domain_values(name)) != 2 or not 1 <= len(words) <= 2:
            return False
        if not all(w.isalpha() for w in words):
            return False
        word = " ".join(words)
        return self._show_word(name, value, word, {str(value): word, str(other): ""}, text)

    def _show_word(self, name: str, value: Any, word: str, show: dict[str, str], text: str) -> bool:
        """Adopt ``show`` as how ``name`` is printed, if it is new (once per word) and the
        repaired belief reads ``text`` back as ``value``."""
        session = self.session
        if not session.budget.once("template", f"{name}:{value}:{word}"):
            return False
        try:
            new = set_display(session.belief.model, name, show)
        except RepairError as exc:
            session.episode.log("repair", f"could not repair how {name} is shown: {exc}")
            return False
        hypotheses = DisplayReader(new).read(text, {**session.belief.values(), name: value})
        if not any(h.value(name) == value for h in hypotheses.hypotheses):
            return False
        session.adopt(new, f"{name} {value!r} is shown as {word!r}", session.belief.pointer())
        return True

    def no_lamp(self, done: Executed) -> bool:
        """A setting the belief shows as a lamp on every screen, predicted lit with a value
        it has, read unlit from displays that do not show the lamp's text while other screens
        are up: the display shows the setting on its own screen only (a reader that took
        "POWER 1000 W" for a lamp). One unlit reading is as well a key that failed to light a
        real lamp, so the lamp goes only after it was unlit on two different displays, and
        only if the repaired belief still has a screen that shows the setting. The setting's
        value is then the belief's alone until a screen shows it. An on/off setting whose lamp
        is only its label ("ECO") reads "off" where unlit: read so while another setting's
        screen is up, it is doubted the same way. True when the belief changed, or at the
        first unlit display (plan again and look once more)."""
        session = self.session
        seen = done.seen
        model = session.belief.model
        if seen is None or seen.unknown or seen.blank or not seen.screens:
            return False
        for name, (predicted, observed) in done.surprises.items():
            if name not in model.display.indicators or predicted is None:
                continue
            spec = model.variables[name]
            domain = tuple(session.domain_values(name))
            if observed is not None and (
                spec.show is not None or lamp_for(spec, name, observed, domain)
            ):
                # an unlit on/off lamp reads "off": doubted only where the lamp is the label
                # the belief guessed lit, not a word the manual prints for it ("LOCK")
                continue
            lamp = lamp_for(spec, name, predicted, domain)
            if lamp and str(observed).casefold() in OFF_WORDS and _spelt(lamp, observed, seen.text):
                # "SOUND OFF": the lamp's word lit beside the off value — spelt out on a
                # screen of its own, not a lamp whose absence elsewhere says "off"
                if self._spelt_out(name, observed):
                    return True
                continue
            if not lamp or lamp.casefold() in seen.text.casefold() or seen.showing(name):
                continue
            unlit = self._unlit.setdefault(name, set())
            first = not unlit
            # a lamp that is only the label: two unlit readings, even of one display, suffice
            guessed = observed is not None
            unlit.add(seen.text.strip().casefold() + (f"#{len(unlit)}" if guessed else ""))
            if first:
                # one unlit display: the key may have failed to light a real lamp. Plan again
                # (once per setting) and see the lamp on the next display before repairing
                session.episode.log("repair", f"{name}'s lamp unlit: to be seen again")
                return True
            if len(unlit) < 2:
                continue
            try:
                new = drop_indicator(model, name)
            except RepairError:
                continue
            if not can_show(new, name) or not _has_screen(new, name):
                continue  # without the lamp nothing would show it: keep what the panel said
            if not session.budget.once("template", f"lamp:{name}"):
                continue
            session.adopt(new, f"{name} has no lamp: shown on its own screen only", None)
            session.belief.set_value(name, predicted)
            # never read on its own screen yet: a claim must see it there first
            session.stale.add(name)
            session.unread.add(name)
            return True
        return False

    def _spelt_out(self, name: str, observed: Any) -> bool:
        """Drop ``name``'s lamp where a screen of its own still shows it (once); True when
        the belief changed."""
        session = self.session
        try:
            new = drop_indicator(session.belief.model, name)
        except RepairError:
            return False
        if not can_show(new, name) or not _has_screen(new, name):
            return False
        if not session.budget.once("template", f"lamp:{name}"):
            return False
        session.adopt(new, f"{name} is spelt out on its own screen, not a lamp", None)
        session.belief.set_value(name, observed)
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

    def main(self, text: str) -> str:
        """The main display of ``text`` (without the lamps the belief knows at its end)."""
        return self._main(text)

    def _main(self, text: str) -> str:
        """The main display: the text without the lamps the belief knows at its end."""
        lamps = self.session.perceiver.reader.lamp_texts()
        parts = _LAMP_GAP.split(text.strip())
        while len(parts) > 1 and parts[-1].casefold() in lamps:
            parts.pop()
        return parts[0]  # a lamp the belief does not know is no part of a template either


def _no_value_shown(model: ApplianceModel, name: str, mains: Sequence[str]) -> bool:
    """Whether several texts of a choice, read through ``model``'s new template, show none of
    its values: every word they put in the value's place is one the setting lacks."""
    if not isinstance(model.variables[name], DiscreteVariable) or len(mains) < 2:
        return False
    reader = DisplayReader(model)
    return not any(
        name in h.values
        for text in mains
        for h in reader.read(text).hypotheses
        if h.screen.variable == name
    )


def _parts(text: str) -> set[str]:
    """The words of a display, case-folded (the main text and each lamp)."""
    return {part.casefold() for part in text.split() if part}


def _has_screen(model: ApplianceModel, name: str) -> bool:
    """Whether a feature step of ``model`` adjusts ``name``: its own screen comes up while it
    does (a key acting from anywhere brings up no screen)."""
    return any(step.variable == name for steps in model.features.values() for step in steps)


def _spelt(lamp: str, value: Any, text: str) -> bool:
    """Whether the display spells the lamp's words out with the value's own word after them.

    >>> _spelt("SOUND", "off", "SOUND OFF"), _spelt("READY AT", "off", "READY AT --:--")
    (True, False)
    """
    words = rf"{re.escape(lamp)}\s+{re.escape(str(value))}"
    return re.search(rf"(?<!\w){words}(?!\w)", text, re.I) is not None


def _whole_values(
    spec: AnyVariable, mains: list[str], domain: list[Any]
) -> tuple[str, None, bool] | None:
    """The template under which every text shows a whole value of a word setting's domain
    (None: no such template, or not a word setting)."""
    if not isinstance(spec, DiscreteVariable) or len(mains) < 2 or not domain:
        return None
    known = {str(v).lower(): v for v in domain}

    def parse(text: str) -> Any:
        value = loose(spec, text)
        return None if value is None else known.get(str(value).lower())

    template = infer_template(
        mains, lambda value: display_value(spec, value), parse, words=True, backtrack=True
    )
    return None if template is None else (template, None, False)
