"""An on/off lamp the belief prints other than the panel, learnt from the press meant to switch it.

A manual's words for a lamp fall short of the panel in two common ways. The lamp is a word with
a qualifier that changes with the state ("LOCK RED" / "LOCK GREEN" where the manual says the
lock icon turns green): the belief lights "LOCK" and reads both as lit. Or the word the reader
took as the sign of the state is not the one the panel shows (a descaling "CAL" as the sign of
running) while the panel prints another ("POURING 400 ml" in place of the temperature). A
third: the belief has no lamp at all (a warm mist shown "MIST on" on its own screen) and the
panel lights one (``WARM``) beside whatever it showed. Each
way the press that was to switch the setting changed the display by one word the belief does
not read, and the belief saw no change: that word is the setting's new state.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.agent.reader import DisplayReader
from apbot.agent.repair import RepairError, add_indicator, set_display
from apbot.agent.session import UNREADABLE, Executed, Session
from apbot.agent.value_words import names_value
from apbot.model.display import lamp_for
from apbot.model.domain import all_values
from apbot.model.schema import ApplianceModel, DiscreteVariable


def relit(session: Session, done: Executed) -> bool:
    """Learn how the display shows ``done``'s on/off lamp setting from the press that was to
    switch it and showed it unswitched (or dark): True when the belief changed."""
    name = done.variable
    if done.refused or name is None or name not in done.surprises or done.state_before is None:
        return False
    model = session.belief.model
    spec = model.variables.get(name)
    if not isinstance(spec, DiscreteVariable) or not spec.visible:
        return False
    domain = tuple(session.domain_values(name))
    old = session.belief.compiled.assignment(done.state_before)[name]
    predicted, observed = done.surprises[name]
    unread = observed is UNREADABLE  # the belief's own screen for it, with other words
    if len(domain) != 2 or predicted == old or not (unread or observed in (old, None)):
        return False
    before, after = done.text_before, done.feedback.text
    if not before.strip() or not after.strip() or before == after:
        return False
    known = printed_words(model)
    kind = "relit"
    show = None if unread else qualified(lamp_for(spec, name, old, domain), before, after, known)
    if show is not None and not lamp_for(spec, name, predicted, domain):
        lit, unlit = show
        mapping = {str(old): lit, str(predicted): unlit}
    elif (
        not unread
        and not lamp_for(spec, name, old, domain)
        and (word := new_sign(lamp_for(spec, name, predicted, domain), before, after, known))
    ):
        mapping = {str(predicted): word, str(old): ""}
    elif (
        name not in model.display.indicators
        and (
            # (its own label lit alone is a lamp too: "WARM" for the keep-warm the belief prints
            # "WARM on" on its own screen; not its own screen showing a value, "WARM off")
            word := new_word(before, after, known - _own_words(spec, name))
        )
        and (
            word.casefold() not in _own_words(spec, name)
            or (observed != old and not _labels_a_value(word, after, spec, domain))
        )
    ):
        # the belief shows it on its own screen only ("MIST on"); the panel lights a word
        mapping, kind = {str(predicted): word, str(old): ""}, "lit"
    else:
        return False
    if kind == "lit" and not (
        done.start_shown(name)
        or names_value(spec, name, mapping[str(predicted)], predicted, domain)
    ):
        # nothing says which value lights a word (a sign of running does: the manual's lamp),
        # and the press moved from the belief's guess of the start: the word may show the
        # other value (a boost that starts on, lit STD when switched off)
        return False
    if not session.budget.once("template", f"{kind}:{name}"):
        return False
    try:
        new = set_display(model, name, mapping)
        if kind == "lit":  # a lamp now, on every screen
            new = add_indicator(new, name)
    except RepairError as exc:
        session.episode.log("repair", f"could not repair how {name} is shown: {exc}")
        return False
    if not _reads(new, name, after, predicted, session.belief.values()):
        return False
    shown = ", ".join(f"{v!r} as {t!r}" for v, t in mapping.items() if t)
    session.adopt(new, f"{name} is shown {shown}", session.belief.pointer())
    session.belief.set_value(name, predicted)
    session.reread()
    return True


def qualified(lamp: str, before: str, after: str, known: set[str]) -> tuple[str, str] | None:
    """The lamp with the word beside it before and after the press (``LOCK RED``, ``LOCK
    GREEN``), when that word alone changed: one word of letters the belief does not know on
    each side of the press, following the lamp (or, if none follows, before it).

    >>> qualified("LOCK", "55°C  LOCK RED", "LOCK GREEN", set())
    ('LOCK RED', 'LOCK GREEN')
    >>> qualified("LOCK", "55°C  LOCK", "LOCK GREEN", set()) is None
    True
    """
    if not lamp:
        return None
    word = r"([^\W\d_]+)"
    for pattern, join in (
        (rf"(?<!\w){re.escape(lamp)}\s+{word}(?!\w)", lambda w: f"{lamp} {w}"),
        (rf"(?<!\w){word}\s+{re.escape(lamp)}(?!\w)", lambda w: f"{w} {lamp}"),
    ):
        was = {w for w in re.findall(pattern, before, re.IGNORECASE)}
        now = {w for w in re.findall(pattern, after, re.IGNORECASE)}
        if len(was) != 1 or len(now) != 1:
            continue
        old, new = was.pop(), now.pop()
        if old.casefold() == new.casefold() or {old.casefold(), new.casefold()} & known:
            return None
        return join(old), join(new)
    return None


def new_sign(lamp: str, before: str, after: str, known: set[str]) -> str | None:
    """The one word of letters the press brought to the display (``POURING``), when the lamp
    the belief lights for the new state is nowhere on it: a word it did not show before and
    the belief does not know.

    >>> new_sign("CAL", "45°C 400 ml", "POURING 400 ml", set())
    'POURING'
    >>> new_sign("CAL", "45°C 400 ml", "CAL 400 ml", set()) is None
    True
    """
    if not lamp or re.search(rf"(?<!\w){re.escape(lamp)}(?!\w)", after, re.IGNORECASE):
        return None
    return new_word(before, after, known)


def new_word(before: str, after: str, known: set[str]) -> str | None:
    """The one word of letters the press brought to the display that it did not show before
    and the belief does not know (``WARM`` lit beside ``MANUAL MIST 3``).

    >>> new_word("MIST 3  MANUAL", "WARM  MANUAL  MIST 3", {"mist", "manual"})
    'WARM'
    """
    was = {w.casefold() for w in before.split()}
    new = [w for w in after.split() if w.isalpha() and w.casefold() not in was | known]
    return new[0] if len(new) == 1 else None


def _own_words(spec: Any, name: str) -> set[str]:
    """The words of a setting's own label (case-folded)."""
    return {w.casefold() for w in spec.display_label(name).split() if w.isalpha()}


def _labels_a_value(label: str, text: str, spec: Any, domain: tuple[Any, ...]) -> bool:
    """Whether ``label`` in ``text`` is followed by a value (``LAMP off``, ``LAMP 0``): the
    setting's own screen, not its label lit alone as a lamp. A figure counts only in the same
    field (one space); a value word of the setting, or on/off, anywhere after it.

    >>> _labels_a_value("LAMP", "LAMP 0", None, ("off", "on"))
    True
    >>> _labels_a_value("LAMP", "LAMP  160°C", None, ("off", "on"))
    False
    """
    words = {str(v).casefold() for v in domain} | {"on", "off"}
    shows = getattr(spec, "show", None)
    for shown in shows.values() if isinstance(shows, dict) else [shows or ""]:
        words |= {w.casefold() for w in str(shown).split() if w.isalpha()}
    words.discard(label.casefold())
    for m in re.finditer(rf"(?<!\w){re.escape(label)}(\s+)(\S+)", text, re.IGNORECASE):
        gap, follow = m.group(1), m.group(2)
        if follow.strip(".,:;").casefold() in words or (gap == " " and follow[0].isdigit()):
            return True
    return False


def printed_words(model: ApplianceModel) -> set[str]:
    """Every word the belief prints: labels, units, the values of its lists of choices (a
    programme's ``rotisserie`` is no sign of a lamp), each value's ``show`` text, guard
    messages and the home screen (case-folded)."""
    words: set[str] = set()
    for name, spec in model.variables.items():
        texts = [spec.display_label(name), getattr(spec, "unit", None) or ""]
        if isinstance(spec.show, dict):
            texts += list(spec.show.values())
        elif spec.show:
            texts.append(spec.show)
        if isinstance(spec, DiscreteVariable):
            texts += [str(v) for v in all_values(spec)]
        for text in texts:
            words |= {w.casefold() for w in text.split() if w.isalpha()}
    for guard in model.guards:
        words |= {w.casefold() for w in (guard.display or "").split() if w.isalpha()}
    # the home screen's own words: a key that brought it back (a START that confirmed the
    # entry typed last) lit no new sign
    words |= {w.casefold() for w in (model.display.idle or "").split() if w.isalpha()}
    return words


def _reads(model: ApplianceModel, name: str, text: str, value: Any, context: Any) -> bool:
    """Whether ``model`` reads ``text`` as ``name`` = ``value``."""
    reading = DisplayReader(model).read(text, {**context, name: value})
    return any(h.value(name) == value for h in reading.hypotheses)
