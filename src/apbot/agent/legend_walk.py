"""Learn a setting's display signs from the manual's legend after a walk showed them.

A walk of a list or on/off setting's key that showed signs the belief cannot read (``♪``,
``✱``) or read as values the setting lacks (``AMBER``, ``N``) looks them up in the manual
(:mod:`apbot.agent.legend`) before any other learner guesses from the walk alone: the walk
cannot tell which sign is which value when the value it started from was the reader's guess,
and the other learners would make the signs new values. The signs become the values' ``show``
words — printed alone or after the setting's label (``HEAT AMBER``), as a lamp on every screen
or on the setting's own — in the first form that reads every text the walk showed back as the
value its sign names; a value left with no sign, when exactly one is and a text showed none,
is printed as nothing (a lamp gone), and a text with no sign is then taken as that value's.
Once per setting and set of signs: a walk that shows more signs later adds theirs.
"""

from __future__ import annotations

from typing import Any

from apbot.agent.infer import Dark, Unread
from apbot.agent.legend import legend, signs
from apbot.agent.reader import DisplayReader
from apbot.agent.readings import is_read
from apbot.agent.relit import printed_words
from apbot.agent.repair import RepairError, add_indicator, set_display
from apbot.agent.session import Session
from apbot.model.display import display_value
from apbot.model.schema import ApplianceModel, DiscreteVariable


def learn_legend(session: Session, name: str, walked: list[Any]) -> dict[str, Any] | None:
    """Adopt the signs the manual gives ``name``'s values, learnt from the walk ``walked``;
    the sign → value map when the belief changed (to read the walk again), else None."""
    model = session.belief.model
    spec = model.variables.get(name)
    manual = session.context.manual
    if not isinstance(spec, DiscreteVariable) or not spec.visible or not manual:
        return None
    domain = session.domain_values(name)
    texts = [v.text for v in walked if isinstance(v, Unread)]
    strange = sorted({str(v) for v in walked if _strange(v, domain)})
    if (not texts and not strange) or any(_spells(s, domain) for s in strange):
        return None  # a value's own word in a longer form ("continuous"): the walk renames it
    label = spec.display_label(name)
    known = printed_words(model) - {s.casefold() for s in strange}
    found = signs(texts, known) + [s for s in strange if not any(c.isdigit() for c in s)]
    own = [w for w in label.split() if w.isalpha()] or [name]
    mapping = legend(manual, sorted(set(found)), domain, own)
    if not mapping or any(s not in mapping for s in strange):
        return None
    show = {str(v): display_value(spec, v) for v in domain}
    if isinstance(spec.show, dict):
        show.update(spec.show)
    show.update({str(value): sign for sign, value in mapping.items()})
    bare = [str(v) for v in domain if v not in mapping.values()]
    signless = [t for t in texts if not any(s in t.split() for s in mapping)]
    out = (  # unless the value's own word is there: "HOT" where the sign is for cold
        len(bare) == 1
        and bool(signless)
        and not any(show[bare[0]].casefold() in t.casefold().split() for t in signless)
    )
    if out:
        show[bare[0]] = ""  # shown by no sign: the lamp is out
    if not session.budget.once("template", f"legend:{name}:{sorted(mapping)}"):
        return None
    shown = texts + _walk_texts(session, len(walked) + 1)
    expected = [(t, v) for t in shown for s, v in mapping.items() if s in t.split()]
    context = session.belief.values()
    # what the belief read already must still read so ("MODE normal" beside a new sign)
    kept = [(t, v) for t in shown if (v := _one_value(model, name, t, context)) is not None]
    expected += [(t, v) for t, v in kept if str(v) not in mapping]
    signed = {str(v) for v in mapping.values()}
    for new in _forms(model, name, show, label, shown, signed):
        if all(_reads(new, name, t, v, context) for t, v in expected) and all(
            _read(new, name, t, context) or (out and t in signless) for t in texts
        ):
            words = ", ".join(f"{v} as {s!r}" for s, v in mapping.items())
            session.adopt(new, f"{name} is shown {words} (the manual's legend)", None)
            return mapping
    return None


def read_sign(session: Session, name: str, text: str) -> Any:
    """``name``'s value in ``text`` wherever the display shows it (a lamp beside another
    setting's screen too), when every reading of the text agrees on one; else None."""
    reading = session.perceiver.reader.read(text, session.belief.values())
    found = {repr(v): v for h in reading.hypotheses if _shows(v := h.value(name))}
    return next(iter(found.values())) if len(found) == 1 else None


def _spells(word: str, domain: list[Any]) -> bool:
    """Whether ``word`` spells a value in full or in short ("continuous" for cont)."""
    folded = word.casefold()
    values = [str(v).casefold() for v in domain]
    if len(folded) < 3:
        return False  # a letter or two is a code ("W"), no spelling
    return any(len(v) >= 3 and (folded.startswith(v) or v.startswith(folded)) for v in values)


def _strange(value: Any, domain: list[Any]) -> bool:
    """A value read on the walk that the setting lacks (a word, not a figure)."""
    if isinstance(value, Dark | Unread) or value in domain:
        return False
    return isinstance(value, str) and len(value.split()) == 1  # one sign, not a screen's words


def _forms(
    model: ApplianceModel,
    name: str,
    show: dict[str, str],
    label: str,
    texts: list[str],
    signed: set[str],
) -> list[Any]:
    """The repaired beliefs to try, most likely first: as a lamp on every screen, then on the
    setting's own screen; each sign after the label where the texts print them so (``HEAT
    AMBER``), else alone first; a value with no sign keeps its word, or has the label too."""
    labelled = {v: f"{label} {w}" if v in signed else w for v, w in show.items()}
    every = {v: f"{label} {w}" if w else "" for v, w in show.items()}
    beside = any(
        f"{label} {w}".casefold() in t.casefold() for t in texts for w in show.values() if w
    )
    forms = []
    for lamp in (True, False):
        for words in (labelled, every, show) if beside else (show, labelled, every):
            try:
                new = set_display(model, name, words)
                forms.append(add_indicator(new, name) if lamp else new)
            except RepairError:
                continue
    return forms


def _walk_texts(session: Session, presses: int) -> list[str]:
    """What the display showed after the last ``presses`` presses (the walk's, and the one
    before it that brought the setting up)."""
    shown = [e.display for e in session.episode.trace if e.kind == "action" and e.display]
    return shown[-presses:]


def _one_value(model: ApplianceModel, name: str, text: str, context: Any) -> Any:
    """The one value of ``name`` ``model`` reads in ``text`` (None: none, or several)."""
    reading = DisplayReader(model).read(text, context)
    found = {repr(v): v for h in reading.hypotheses if _shows(v := h.value(name))}
    return next(iter(found.values())) if len(found) == 1 else None


def _read(model: ApplianceModel, name: str, text: str, context: Any) -> bool:
    """Whether ``model`` reads some value of ``name`` in ``text``."""
    reading = DisplayReader(model).read(text, context)
    return any(_shows(h.value(name)) for h in reading.hypotheses)


def _shows(value: Any) -> bool:
    """Whether a reading found a value (not ``--``, and not the screen leaving it out: a
    sentinel taken for a value became one of the setting's values on a walk)."""
    return is_read(value) and value is not None


def _reads(model: ApplianceModel, name: str, text: str, value: Any, context: Any) -> bool:
    reading = DisplayReader(model).read(text, {**context, name: value})
    return any(h.value(name) == value for h in reading.hypotheses)
