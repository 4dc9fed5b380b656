"""What the goal parser knows about a model: each variable's words, role and timing.

Built once per model from its own names only — variable names and labels, show texts, feature
names, the labels of the keys that adjust a variable, and which key starts the appliance — and
remembered, since an agent parses many sentences against one belief.
"""

from __future__ import annotations

import itertools
import re
from dataclasses import dataclass, field
from typing import Any

from apbot.model.domain import AnyVariable, all_values, build_domain
from apbot.model.schema import (
    ApplianceModel,
    DiscreteVariable,
    GoTo,
    NumericVariable,
    Step,
)
from apbot.read.goal_aliases import bracket_aliases
from apbot.read.goal_appliance_words import appliance_said, appliance_words
from apbot.read.goal_code_words import code_words
from apbot.read.goal_expanded_labels import add_expanded_labels
from apbot.read.goal_legends import add_kind_nouns, add_setting_words, legend_words
from apbot.read.goal_manual import coded_names
from apbot.read.goal_own_names import TIMED_STOPS, add_nouns, add_timed_stops
from apbot.read.goal_phrases import value_phrases
from apbot.read.goal_roles import (
    START_LABELS,
    control_labels,
    mark_power_and_running,
    start_values_of,
    step_effects,
    steps_of,
)
from apbot.read.goal_timings import mark_timings
from apbot.read.goal_values import (
    OFF_WORDS,
    ON_WORDS,
    kind_noun,
    name_words,
    numeric_values,
    on_off_pair,
    parse_quantity,
    phrase_words,
    quantity_dimensions,
    unit_kind,
    unit_text,
    unit_words,
)
from apbot.read.goal_vocab import (
    STOP_WORDS,
    concept,
    doer_forms,
    stem,
)
from apbot.read.range_codes import code_past_top

Goal = dict[str, Any]


@dataclass
class VarInfo:
    """One variable as the parser sees it: words that name it and its role."""

    name: str
    var: AnyVariable
    vocab: dict[str, float] = field(default_factory=dict)
    doers: set[str] = field(default_factory=set)  # stems of its name words' doer forms
    role: str = "setting"  # setting, switch, power, running
    on: str | None = None
    off: str | None = None
    # for time-like variables: duration, delay, finish (at), clock, or "at": a time of day
    # something happens at (a start time, a feeding time) on a model without a clock
    timing: str = "duration"
    dimension: str | None = None
    order: int = 0
    turns: str | None = None  # a timer that switches the appliance "on" or "off" at its end

    @property
    def values(self) -> list[Any]:
        return all_values(self.var)


@dataclass
class Model:
    """The parser's view of a model, built once."""

    model: ApplianceModel
    infos: dict[str, VarInfo]
    phrases: list[tuple[str, Any, tuple[str, ...], float]]  # var, value, stems, weight
    start_values: dict[str | None, tuple[str, Any]]  # feature var (None: plain START) -> value
    appliance_words: frozenset[str]
    named_quantities: dict[str, list[tuple[Any, str]]] = field(default_factory=dict)
    # var -> (value, "60 %"): a coded value the manual gives as a quantity (knob mark 2: 60 %)
    top_codes: dict[str, Any] = field(default_factory=dict)
    # var -> the code the manual puts one step past its highest number (P after 9)
    manual_words: frozenset[str] = frozenset()
    # the manual's words: a three-letter panel code is named only by a word it uses ("slow")
    manual_lines: tuple[str, ...] = ()
    # the manual's lines, casefolded: where it prints a setting's name beside a value


_OWN_NOUNS = frozenset({"key"})
"""Stop words (said of any key) that are a setting's whole name: a karaoke's musical KEY."""


def _add_vocab(info: VarInfo, text: str, weight: float) -> None:
    for word in name_words(text):
        if word in STOP_WORDS or len(word) < 2:
            continue
        key = concept(word)
        info.vocab[key] = max(info.vocab.get(key, 0.0), weight)


def _add_doers(info: VarInfo, text: str, appliance: set[str]) -> None:
    """ "the heater" for HEAT, "dim" for DIMMER: a name word's doer form names it less surely
    (never a word of the appliance's own name: "cook" is no COOKER)."""
    for word in name_words(text):
        if word not in STOP_WORDS:
            for form in doer_forms(word):
                if stem(form) not in appliance:
                    info.doers.add(stem(form))
                    _add_vocab(info, form, 0.6)


def _sound_is_volume(infos: dict[str, VarInfo]) -> None:
    """ "turn the sound down to 3": the one VOLUME setting is the sound, where nothing else of
    the model is named for sound (no BEEP switch, no ALARM TONE)."""
    sound = concept("sound")
    volumes = [i for i in infos.values() if stem("volume") in i.vocab and i.role == "setting"]
    if len(volumes) == 1 and not any(sound in i.vocab for i in infos.values()):
        volumes[0].vocab[sound] = 0.8


def build(model: ApplianceModel, manual: str = "") -> Model:
    """Gather each variable's words and role from the model (and the names the manual gives
    to coded values, when it is given)."""
    infos: dict[str, VarInfo] = {}
    appliance = {stem(w) for w in name_words(appliance_said(model))}
    for order, (name, var) in enumerate(model.variables.items()):
        info = VarInfo(name, var, order=order)
        _add_vocab(info, name, 1.0)
        if var.label:
            _add_vocab(info, var.label, 1.0)
        if not info.vocab and set(name_words(name.casefold())) <= _OWN_NOUNS:
            info.vocab[concept(name)] = 0.8  # a setting named KEY (a song's pitch): its word
        _add_doers(info, f"{name} {var.label or ''}", appliance)
        add_nouns(info, f"{name} {var.label or ''}")
        add_timed_stops(info, f"{name} {var.label or ''}")
        if isinstance(var.show, str):
            _add_vocab(info, var.show.split("{")[0], 0.7)
            _add_vocab(info, var.show.rsplit("}", 1)[-1], 0.7)  # "{value}pt": "8 pt" names it
        elif isinstance(var.show, dict):
            for value, text in var.show.items():
                if (
                    "{" not in text
                    and str(value).casefold() not in OFF_WORDS
                    and (text.casefold() not in ON_WORDS + OFF_WORDS)
                ):
                    _add_vocab(info, text, 0.7)
        if isinstance(var, NumericVariable):
            var = info.var = _counted_by_name(name, var)
            unit = unit_text(var)
            info.dimension = (unit_kind(unit) or (None, 0))[0] if unit else None
            if not unit:  # a reader may miss the unit: SPIN 0-1400 still takes "1000 rpm"
                info.dimension = _dimension_by_name(info)
            _add_vocab(info, unit_words(unit), 0.6)  # "twelve volts" names the setting in V
        if isinstance(var, DiscreteVariable):
            switch = on_off_pair(info.values)
            if switch:
                info.role, info.on, info.off = "switch", switch[0], switch[1]
            if numeric_values(info.values):
                info.dimension = _dimension_by_name(info)
                shown = _shown_unit(var)  # "{value} s": a chart of times in seconds
                if shown:
                    info.dimension = (unit_kind(shown) or (info.dimension, 0))[0]
            for dimension in sorted(quantity_dimensions(info.values)):
                _add_vocab(info, _DIMENSION_WORDS.get(dimension, ""), 0.6)  # "450 W": power
        infos[name] = info
    # features and control labels name the variables they adjust
    for feature, index, step in steps_of(model):
        if step.variable and step.variable in infos:
            info = infos[step.variable]
            steps: list[Step] = model.features.get(feature, [])
            if steps:  # not a key that acts from anywhere
                _add_vocab(info, feature, 0.6)
            entry = [a for s in steps[:index] for a in s.actions]
            own = [
                a
                for a, effect in step_effects(step)
                if not isinstance(effect, GoTo) and a in model.actions
            ]
            if info.role == "switch":
                continue  # a switch's key is often shared (hold TIMER to lock)
            for label in control_labels(model, entry + own):
                if not any(w in START_LABELS for w in name_words(label)):
                    _add_vocab(info, label, 0.8)
    mark_power_and_running(model, infos)
    _sound_is_volume(infos)
    mark_timings(infos)
    phrases = value_phrases(model, infos)
    start_values = start_values_of(model, infos)
    appliance = appliance_words(model, manual, infos, phrases)
    keys: dict[str, list[str]] = {}
    set_keys: dict[str, list[str]] = {}  # the settings' keys, for what their legends call them
    for _feature, _index, step in steps_of(model):
        if step.variable in infos and infos[step.variable].role in ("switch", "setting"):
            kind = keys if infos[step.variable].role == "switch" else set_keys
            kind.setdefault(step.variable, []).extend(control_labels(model, step.actions))
    legends = legend_words(model, manual, keys)
    shared = {w for a, b in itertools.combinations(legends.values(), 2) for w in a & b}
    taken = {key for info in infos.values() for key in info.vocab}
    for name, words in legends.items():
        for word in words - shared:
            key = concept(word)
            if word not in STOP_WORDS and key not in taken:
                infos[name].vocab[key] = 0.5  # a word only this key's legend in the manual has
    add_setting_words(infos, manual, set_keys)
    add_kind_nouns(infos, manual)
    add_expanded_labels(infos, manual, {**keys, **set_keys})
    named: dict[str, list[tuple[Any, str]]] = {}
    coded_list = coded_names(model, manual)
    shared_words = _words_all_names_share(coded_list)
    for coded, value, label in coded_list:
        if parse_quantity(label) is not None:
            named.setdefault(coded, []).append((value, label))
            continue
        names = [w for w in phrase_words(label) if w != "and"]
        names = [w for w in names if w not in shared_words.get(coded, ())] or names
        if names and not all(w in STOP_WORDS for w in names):
            phrases.append((coded, value, tuple(stem(w) for w in names), 0.95))
    settings = tuple(f"{n} {i.var.label}".replace("_", " ") for n, i in infos.items())
    aliases = bracket_aliases(_forms(infos), manual, settings, frozenset(appliance))
    phrases += [(n, v, stems, 0.9) for n, v, stems in aliases]
    phrases += code_words(infos, manual)  # REV for "reverse", the manual's line pairing them
    tops = {
        name: code
        for name, info in infos.items()
        if isinstance(info.var, DiscreteVariable)
        and (code := code_past_top(manual, list(info.values))) is not None
    }
    manual_words = frozenset(re.findall(r"[a-z]+", manual.casefold()))
    return Model(
        model,
        infos,
        phrases,
        start_values,
        frozenset(appliance),
        named,
        tops,
        manual_words,
        tuple(manual.casefold().splitlines()),
    )


def _words_all_names_share(coded: list[tuple[str, Any, str]]) -> dict[str, set[str]]:
    """setting -> the words every name the manual gives its codes shares ("Cross-cut head",
    "Micro-cut head"): the kind of thing the setting picks, no name of one value — the user
    says "micro-cut". Only for settings with two or more different names, none with a
    figure ("300 W + grill": what is left would be a quantity)."""
    labels: dict[str, set[str]] = {}
    for name, _value, label in coded:
        if parse_quantity(label) is None:
            labels.setdefault(name, set()).add(label)
    out: dict[str, set[str]] = {}
    for name, said in labels.items():
        if len(said) >= 2 and not any(c.isdigit() for label in said for c in label):
            words = [set(phrase_words(label)) for label in said]
            out[name] = set.intersection(*words)
    return out


def _forms(infos: dict[str, VarInfo]) -> dict[str, dict[Any, list[str]]]:
    """setting -> value -> how it is written (its name, its display text), for the manual's
    bracketed names of it."""
    out: dict[str, dict[Any, list[str]]] = {}
    for name, info in infos.items():
        if info.role != "setting" or not isinstance(info.var, DiscreteVariable):
            continue
        show = info.var.show if isinstance(info.var.show, dict) else {}
        out[name] = {
            value: [str(value)] + ([str(show[str(value)])] if show.get(str(value)) else [])
            for value in info.values
            if str(value).casefold() not in ON_WORDS + OFF_WORDS
        }
    return out


# a count named for its unit: DAYS 1-14 counts days ("every 5 days", "for two weeks")
_NAMED_UNITS = {"days": "d", "weeks": "wk"}


def _counted_by_name(name: str, var: NumericVariable) -> NumericVariable:
    """A unitless count whose name ends in a plural unit of days (DAYS, INTERVAL DAYS) counts in
    it: a reader or a panel leaves that unit out, the name says it. Plural only: a DAY setting is
    as often a day of the week."""
    if unit_text(var):
        return var
    for text in (var.label or "", name):
        words = name_words(text.casefold())
        if words and words[-1] in _NAMED_UNITS:
            return var.model_copy(update={"unit": _NAMED_UNITS[words[-1]]})
    return var


_DIMENSION_WORDS = {"power": "power", "temperature": "temperature", "mass": "weight"}


def _shown_unit(var: DiscreteVariable) -> str:
    """The unit a list of numbers prints after each of them ("{value} s"), or ""."""
    show = var.show if isinstance(var.show, str) else ""
    rest = show.strip()[len("{value}") :].strip() if show.strip().startswith("{value}") else ""
    return rest if rest and "{" not in rest else ""


def _dimension_by_name(info: VarInfo) -> str | None:
    if concept("temperature") in info.vocab:
        return "temperature"
    if concept("humidity") in info.vocab:
        return "ratio"
    if concept("spin") in info.vocab:
        return "speed"
    if concept("speed") in info.vocab and _turns_a_minute(info):
        return "speed"  # SPEED 33 / 45 / 78: turns a minute ("a 45 rpm single"), not levels 1-3
    return None


def _turns_a_minute(info: VarInfo) -> bool:
    """Every value is a bare number and some reach 10 or more: a rate, not a level number."""
    numbers = [parse_quantity(str(v)) for v in all_values(info.var)]
    bare = [q[0] for q in numbers if q is not None and q[1] is None]
    return len(bare) == len(numbers) > 1 and max(bare) >= 10


_VIEWS: dict[tuple[int, int], tuple[ApplianceModel, str, Model]] = {}


def model_view(model: ApplianceModel, manual: str = "") -> Model:
    """:func:`build`, remembered for the last few models (an agent parses many sentences)."""
    key = (id(model), hash(manual))
    hit = _VIEWS.get(key)
    if hit is not None and hit[0] is model and hit[1] == manual:
        return hit[2]
    view = build(model, manual)
    if len(_VIEWS) >= 32:
        _VIEWS.pop(next(iter(_VIEWS)))
    _VIEWS[key] = (model, manual, view)
    return view


def domain_values(view: Model, info: VarInfo, goal: Goal) -> list[Any]:
    var = info.var
    if var.depends_on and var.depends_on in goal and var.cases:
        case = var.cases.get(str(goal[var.depends_on]))
        if case is None:
            return []
        return list(build_domain(var, case).values)
    return list(info.values)


def own_concepts(info: VarInfo) -> set[str]:
    return {concept(w) for w in own_stems(info)}


def own_stems(info: VarInfo) -> set[str]:
    words = name_words(info.name) + (name_words(info.var.label) if info.var.label else [])
    own = {stem(w) for w in words if w not in STOP_WORDS}
    return own or {stem(w) for w in words if w in TIMED_STOPS and concept(w) in info.vocab}


def doer_stems(info: VarInfo) -> set[str]:
    """The setting's own stems and their doer forms' ("heater" for HEAT, "dim" for DIMMER):
    what names a switch or a setting said off."""
    return own_stems(info) | info.doers


def its_own_word(view: Model, info: VarInfo, word: str) -> bool:
    """A word of the setting's own name that no other setting's name has: it names that one
    setting even when it is as general a word as "heat" or "water" (a HEAT switch beside a
    TEMPERATURE, a WATER level beside a SEAT level) — unless it only says what kind of setting
    is meant (a LOAF switch is not named by "a 750 g loaf")."""
    if kind_noun(concept(word)):
        return False  # "the loaf", "the mode": what kind of setting, never one setting's name
    return word in own_stems(info) and not any(
        other is not info and word in {stem(w) for w in name_words(other.name)}
        for other in view.infos.values()
    )  # a label another variable only wears (a held key's second function) does not count
