"""Renamed values: a walk that follows the belief's order exactly, with some values printed
in words the belief does not use.

A manual names a setting's values one way and the panel prints them another: a switch the
manual calls "on"/"off" shows ``I``/``0``; a power scale read as 0..10 ends in ``P`` on the
display; a choice of "distance" shows as ``DIST``. Walking the setting then shows texts the
belief cannot read (or reads as values outside its domain), and a repair of the *domain* from
them would replace the manual's values by the display's words — which the goal, parsed
against the manual's values, no longer names ("keep_warm='on' is not a value the model
knows").

The walk itself says which word is which value when the rest of the belief is right: the
belief predicts, press by press from the value it expected after the walk's first press, the
value each press gives. When every shown value the belief can read is the one predicted and
the other texts pair one-to-one with the predicted values the display never showed as
themselves, those texts are those values' words (a text the belief reads as another
setting's screen is no such word, nor digits printed without the setting's label — another
setting's number, a clock — nor a text without the label where the walk read the setting's
other values with it). They become the values' ``show`` templates
(a data edit, kept only if the repaired belief reads every such text back as its value), and
the walk is read again in the belief's values, so nothing else is learnt wrong from it.

A panel that lights a setting beside the others (``M1  40 °C``, a lamp ``KEEP WARM`` after the
programme) and prints nothing for its "off" shows texts the belief reads as the other
settings' screens: what the walk's texts do not all share is the setting's own part
(:func:`own_parts`), and the part printed as nothing anchors the pairing at "off".
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import Any

from apbot.agent.infer import Dark, Unread
from apbot.agent.reader import DisplayReader
from apbot.agent.repair import RepairError, add_indicator, set_display
from apbot.agent.session import Executed, Session
from apbot.agent.setting_texts import GAP
from apbot.agent.value_words import names_value, spells_value
from apbot.model.display import OFF_WORDS, display_value, show_template
from apbot.model.schema import TEMPLATE_FIELD

_MAX_LISTED = 60  # a template per value for more values than this is no edit worth making


def predicted_walk(
    session: Session, name: str, last: Executed, keys: Sequence[str], seconds: float | None
) -> list[Any] | None:
    """The values of ``name`` the belief predicts: the one ``last`` was to give, then one after
    each of ``keys`` pressed from there (in ``last``'s step). None when it cannot say."""
    belief = session.belief
    if last.pointer is None or last.predicted is None:
        return None
    saved = belief.state
    try:
        belief.set_pointer(last.pointer)
        if not belief.set_value(name, last.predicted):
            return None
        values = [belief.value(name)]
        for key in keys:
            belief.advance(key, seconds)
            values.append(belief.value(name))
        return values
    finally:
        belief.state = saved


def pairing(
    shown: Sequence[Any], predicted: Sequence[Any], domain: Sequence[Any]
) -> dict[Any, Any] | None:
    """Shown token → believed value for the tokens the belief cannot read, when the walk is a
    renaming of the prediction: one-to-one, and every value read as itself where predicted.
    None otherwise (or when nothing is renamed).

    >>> pairing(["I", "0", "I"], ["on", "off", "on"], ["off", "on"])
    {'I': 'on', '0': 'off'}
    >>> pairing([9, "P", "P"], [9, 10, 10], list(range(11)))
    {'P': 10}
    >>> pairing([3, "P"], [2, 10], list(range(11))) is None  # 3 where 2 was due: not a renaming
    True
    """
    if len(shown) != len(predicted) or len(shown) < 2:
        return None
    known = set(map(repr, domain))
    forward: dict[Any, Any] = {}
    backward: dict[Any, Any] = {}
    for token, value in zip(shown, predicted, strict=True):
        if value is None or repr(value) not in known:
            return None
        if repr(token) in known and token != value:
            return None
        if forward.setdefault(token, value) != value or backward.setdefault(value, token) != token:
            return None
    renamed = {t: v for t, v in forward.items() if repr(t) not in known}
    return renamed or None


def rename_walk(
    session: Session,
    main: Any,
    name: str,
    last: Executed,
    walks: Sequence[tuple[list[Any], str]],
    seconds: float | None,
) -> dict[Any, Any] | None:
    """Learn the words of the values a walk printed otherwise (see the module); ``walks``: each
    walk with the key it pressed, the first opened by ``last``'s own display; ``main``: the
    main part of a display text. The tokens learnt (see :func:`translate`) when the belief
    changed, else None."""
    trace = [v for walk, _ in walks for v in walk]
    if not trace or any(isinstance(v, Dark) for v in trace):
        return None
    reader = session.perceiver.reader
    if any(isinstance(v, Unread) and reader.read(v.text).hypotheses for v in trace):
        # another setting's screen, not this one's in other words — unless the walk's texts
        # differ only by a part of their own (the others' parts stay put): that part is it
        return _rename_own(session, name, last, walks, seconds)
    spec = session.belief.model.variables[name]
    if not spec.visible:
        return None
    keys = [key for walk, key in walks for _ in walk[1:]]  # each walk opens with no press
    predicted = predicted_walk(session, name, last, keys, seconds)
    if predicted is None:
        return None
    # each later walk opens with the display the one before it ended on (not a press)
    shown: list[Any] = []
    for index, (walk, _) in enumerate(walks):
        shown += walk if index == 0 else walk[1:]
    tokens = [_token(v, main) for v in shown]
    domain = session.domain_values(name)
    pairs = pairing(tokens, predicted, domain)
    if pairs is None:
        return _rename_own(session, name, last, walks, seconds)
    if not any(repr(t) in set(map(repr, domain)) for t in tokens) and not any(
        _resembles(spec, name, t, v) for t, v in pairs.items()
    ):
        return None  # nothing read as itself, no word like its value: the order has no anchor
    texts = {token: _text(spec, name, value, token) for token, value in pairs.items()}
    label = str(spec.display_label(name)).casefold()[:3]
    if any(
        isinstance(token, tuple) and any(c.isdigit() for c in text) and label not in text.casefold()
        for token, text in texts.items()
    ):
        return None  # digits without the label: another setting's number (a clock), no word
    if any(re.search(r"\d\d", text) and label not in text.casefold() for text in texts.values()):
        return None  # "100°C" for keep-warm off: the temperature's number, no word for a value
    read = {
        repr(t): _text(spec, name, pairs.get(t, t), t) for t in tokens if not isinstance(t, tuple)
    }
    if any(label in text.casefold() for text in read.values()) and any(
        isinstance(token, tuple) and label not in text.casefold() for token, text in texts.items()
    ):
        return None  # its other values came with its label: a text without it is not its own
    others = {_text(spec, name, v, v).casefold() for v in domain if v not in pairs.values()}
    folded = [t.casefold() for t in texts.values()]
    if len(set(folded)) < len(folded) or others.intersection(folded):
        return None  # two values, one text: the display does not tell them apart
    if any(_number_for_number(spec, name, t, v) for t, v in pairs.items()):
        return None  # a number where another was due: the numbers read are wrong, not words
    if all(_said(t).casefold().startswith(str(v).casefold()) for t, v in pairs.items()):
        return None  # values spelt out ("lo" as "low"): the walk's domain learns them as such
    show = _templates(spec, name, domain, pairs)
    if show is None:
        return None
    key = ", ".join(f"{v}={_said(t)}" for t, v in pairs.items())
    if not session.budget.once("template", f"{name}:renamed:{key}"):
        return None
    try:
        new = set_display(session.belief.model, name, show)
    except RepairError as exc:
        session.episode.log("repair", f"could not repair how {name} is shown: {exc}")
        return None
    repaired = DisplayReader(new)
    context = session.belief.values()
    for token, value in pairs.items():
        text = _text(spec, name, value, token)
        reading = repaired.read(text, {**context, name: value})
        found = {repr(h.value(name)) for h in reading.hypotheses if h.screen.variable == name}
        if found != {repr(value)}:
            return None
    words = ", ".join(f"{v} as {_said(t)!r}" for t, v in pairs.items())
    session.adopt(new, f"{name} prints {words}", session.belief.pointer())
    return pairs


def translate(walk: Sequence[Any], pairs: dict[Any, Any], main: Any) -> list[Any]:
    """A walk read again in the belief's values, after :func:`rename_walk` learnt ``pairs``
    (an unread text by the whole of it where its own part was learnt)."""
    return [
        pairs.get(("whole", v.text), pairs.get(_token(v, main), v))
        if isinstance(v, Unread)
        else pairs.get(v, v)
        for v in walk
    ]


def by_own_parts(pairs: dict[Any, Any]) -> bool:
    """Whether :func:`rename_walk` learnt ``pairs`` from the walk's own parts
    (:func:`own_parts`): such a walk went round every value of the setting."""
    return any(isinstance(t, tuple) and t[0] == "whole" for t in pairs)


def own_parts(texts: Sequence[str]) -> dict[str, str] | None:
    """Each text's own part: its parts (as the display spaces them) that are not in every
    text — a setting walked on a display that also prints other settings, which stay put.
    None unless some text has no such part (the setting's value printed as nothing) and
    some text has one.

    >>> own_parts(["M1  40  °C", "M2  40  °C", "40  °C"])
    {'M1  40  °C': 'M1', 'M2  40  °C': 'M2', '40  °C': ''}
    >>> own_parts(["KEEP WARM  FORMULA", "FORMULA"])
    {'KEEP WARM  FORMULA': 'KEEP WARM', 'FORMULA': ''}
    >>> own_parts(["A  1", "B  2"]) is None  # every part changes: no part stays put
    True
    """
    split = {t: [p for p in GAP.split(t.strip()) if p] for t in dict.fromkeys(texts)}
    if len(split) < 2:
        return None
    common = set.intersection(*(set(parts) for parts in split.values()))
    own = {t: "  ".join(p for p in parts if p not in common) for t, parts in split.items()}
    if not common or all(own.values()) or not any(own.values()):
        return None
    return own


def _named(spec: Any, name: str, pairs: dict[Any, Any], domain: Sequence[Any]) -> bool:
    """Whether a word paired with a value names it: the value's own word among its words
    ("FLOW ON" for on), or the setting's name or label ("KEEP WARM" for keep-warm on)."""
    return any(
        part
        and (
            names_value(spec, name, part, value, domain)
            or any(spells_value(word, value) for word in part.split())
        )
        for part, value in pairs.items()
    )


def _names_other(part: str, value: Any, domain: Sequence[Any]) -> bool:
    """Whether a part says it shows another value of the setting than the one the walk
    paired it with (``M3`` or ``HI`` paired with low): the pairing rests on the belief's
    order of the values, which a part naming its own value cannot contradict.

    >>> _names_other("M3", "2", ["off", "1", "2", "3"]), _names_other("M2", "2", ["2", "3"])
    (True, False)
    >>> _names_other("HI", "low", ["off", "low", "high"])
    True
    """
    words = re.findall(r"[^\W\d_]+|\d+", part.casefold())

    def says(value: Any) -> bool:
        return any(w == str(value).casefold() or spells_value(w, value) for w in words)

    return not says(value) and any(says(other) for other in domain if repr(other) != repr(value))


def _rename_own(
    session: Session,
    name: str,
    last: Executed,
    walks: Sequence[tuple[list[Any], str]],
    seconds: float | None,
) -> dict[Any, Any] | None:
    """A walk of texts the belief cannot read as the setting, which differ only by a part of
    their own (:func:`own_parts`), printed as nothing for the setting's "off": those parts
    are its values' words, paired with the values the belief predicts press by press. Kept
    only where the walk went round (each part came back as the same value), the part printed
    as nothing is the one off value, no part reads as another setting, and the repaired
    belief reads every whole text back as its value. The pairs learnt, by whole text."""
    trace = [v for walk, _ in walks for v in walk]
    if not all(isinstance(v, Unread) for v in trace):
        return None
    spec = session.belief.model.variables[name]
    if not spec.visible:
        return None
    own = own_parts([v.text for v in trace])
    if own is None:
        return None
    keys = [key for walk, key in walks for _ in walk[1:]]
    predicted = predicted_walk(session, name, last, keys, seconds)
    if predicted is None:
        return None
    shown: list[str] = []
    for index, (walk, _) in enumerate(walks):
        shown += [v.text for v in (walk if index == 0 else walk[1:])]
    tokens = [own[text] for text in shown]
    if tokens[-1] not in tokens[:-1]:
        return None  # the walk never came round: no second sight of any part
    domain = session.domain_values(name)
    pairs = pairing(tokens, predicted, domain)
    if pairs is None or set(map(repr, pairs.values())) != set(map(repr, domain)):
        return None  # every value, each with its own part
    if str(pairs.get("", "")).casefold() not in OFF_WORDS:
        return None  # nothing printed is "off", or the walk has no anchor
    if any(_names_other(part, value, domain) for part, value in pairs.items()):
        return None  # the belief's order is not the panel's: ``M3`` paired with 2
    if len(domain) == 2 and not last.start_shown(name) and not _named(spec, name, pairs, domain):
        return None  # from a guessed start either value may be the word's: it must say which
    reader = session.perceiver.reader
    for part in pairs:
        if part and any(h.screen.variable != name for h in reader.read(part).hypotheses):
            return None  # another setting's screen: not this one's word
    if not session.budget.once("template", f"{name}:own:" + "|".join(map(str, pairs))):
        return None
    show = {str(value): part for part, value in pairs.items()}
    try:
        # always on the display beside the others, as a lamp is: its absence is "off"
        new = add_indicator(set_display(session.belief.model, name, show), name)
    except RepairError as exc:
        session.episode.log("repair", f"could not repair how {name} is shown: {exc}")
        return None
    repaired = DisplayReader(new)
    context = session.belief.values()
    for text in own:
        value = pairs[own[text]]
        reading = repaired.read(text, {**context, name: value})
        found = {repr(v) for v in reading.candidates(name)}
        # a part read as its value (a partial reading may also take it for the lamp unlit);
        # a text without one, as nothing else
        if repr(value) not in found or (not own[text] and found != {repr(value)}):
            session.episode.log("repair", f"own part: {text!r} reads {found} not {value!r}")
            return None
    words = ", ".join(f"{v} as {part or 'nothing'!r}" for part, v in pairs.items())
    session.adopt(new, f"{name} prints {words}", session.belief.pointer())
    session.reread()  # the display now, read with the words learnt: the setting is seen
    return {("whole", text): pairs[part] for text, part in own.items()}


def _resembles(spec: Any, name: str, token: Any, value: Any) -> bool:
    """The text names its value by itself: an abbreviation of it ("DIST" for distance), or
    the on / off marks of a switch ("I" / "0"), once the setting's label is taken out."""
    said = _said(token).casefold()
    label = str(spec.display_label(name)).casefold()
    said = said.replace(label, " ") if label else said
    return spells_value(said, value)


def _number_for_number(spec: Any, name: str, token: Any, value: Any) -> bool:
    """A number shown (bare, or beside the setting's label or unit) where the belief predicted
    another number: a range read wrong (30 … 90 read as 1 … 7), which the walk's range repair
    learns; as words for the values it would keep the wrong numbers the goal cannot name."""
    if _as_number(value) is None:
        return False
    said = _said(token).casefold()
    for part in (str(spec.display_label(name)), str(getattr(spec, "unit", "") or "")):
        if part:
            said = said.replace(part.casefold(), " ")
    return _as_number(said.strip()) is not None


def _as_number(value: Any) -> float | None:
    try:
        return float(str(value).replace(",", "."))
    except ValueError:
        return None


def _said(token: Any) -> str:
    return str(token[1]) if isinstance(token, tuple) else str(token)


def _token(value: Any, main: Any) -> Any:
    """A walk's entry as a key: an unread text by its main part, a value as itself."""
    if isinstance(value, Unread):
        return ("text", main(value.text))
    return value


def _templates(
    spec: Any, name: str, domain: Sequence[Any], pairs: dict[Any, Any]
) -> dict[str, str] | None:
    """``show`` with each renamed value's own template (the text shown, or the belief's
    template around the value as read), every other value printed as before."""
    show: dict[str, str] = {}
    if isinstance(spec.show, dict):
        show = dict(spec.show)
    elif spec.show is not None:
        if len(domain) > _MAX_LISTED:
            return None
        show = {str(v): show_template(spec, v) for v in domain}
    for token, value in pairs.items():
        show[str(value)] = _text(spec, name, value, token, template=True)
    return show


def _text(spec: Any, name: str, value: Any, token: Any, template: bool = False) -> str:
    """The text a renamed value showed (``token``): an unread text as it was, a value read
    outside the domain in the belief's template for ``value``, the label filled in unless a
    template is asked for."""
    if isinstance(token, tuple) and len(token) == 2 and token[0] == "text":
        return str(token[1])
    pattern = show_template(spec, value)
    shown = display_value(spec, token)

    def fill(match: Any) -> str:
        field = match.group(1)
        if field == "value":
            return shown
        if field == "label" and not template:
            return str(spec.display_label(name))
        return str(match.group(0))

    return TEMPLATE_FIELD.sub(fill, pattern)
