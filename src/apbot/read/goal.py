"""The offline goal parser: a user's instruction to a partial assignment over a model's variables.

It reads only the *belief* model — variable names, labels, values, units, show texts, and the
labels of the controls that set them — and the instruction. It never invents a setting the
instruction does not mention, and an instruction the model cannot satisfy (a value outside a
domain, a named value the model lacks) raises :class:`GoalParseError` naming the words and why.

How it works, in order:

1. *value names*: every discrete value (and every labelled key that sets one value, such as a
   GREEN TEA key) is matched as a phrase against the instruction's stemmed words;
2. *quantities*: durations, clock times and numbers with units (``apbot.read.numbers``) are
   given to the variable whose type, unit and domain fit, and whose names are nearest in the
   text; a relative time ("ready in 8 hours") prefers a delay, a clock time a clock;
3. *superlatives and scales*: "the lowest", "full power", "a dark crust" on a numeric setting;
4. *switches*: an on/off setting named in the text is on unless negated ("no prewash");
5. *power and start*: "switch it on" sets the power variable; "start it", "get it going" or an
   instruction that opens with a cooking verb sets the running variable to what the model's
   START key sets (in the programme that was asked for); "don't start" sets it off.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

from apbot.model.domain import AnyVariable, ValueProblem, all_values, build_domain, normalise
from apbot.model.schema import (
    ApplianceModel,
    DiscreteVariable,
    GoTo,
    NumericVariable,
    Step,
    TimeVariable,
)
from apbot.model.values import format_hms, preview, unit_of
from apbot.model.values import parse_quantity as _parse_quantity
from apbot.read.goal_vocab import (
    HIGHEST,
    LETTER_WORDS,
    LOWEST,
    NEGATIONS,
    SCALES,
    STOP_WORDS,
    SYNONYMS,
    concept,
    similar,
    stem,
)
from apbot.read.numbers import Mention, Token, find_mentions, tokenize

Goal = dict[str, Any]


class GoalParseError(ValueError):
    """The instruction asks for something the model cannot do.

    ``words`` quotes the instruction's words at fault; ``reason`` says why (no such value, out
    of range, and what the model offers instead).
    """

    def __init__(self, words: str, reason: str) -> None:
        self.words = words
        self.reason = reason
        super().__init__(f"{words!r}: {reason}")


# --- what the parser knows about each variable ---------------------------------------------------

_ON_WORDS = ("on", "yes", "enabled", "true")
_OFF_WORDS = ("off", "no", "disabled", "false")
_OPERATION_NAMES = frozenset(
    stem(w)
    for w in (
        "running",
        "run",
        "heating",
        "cooking",
        "dispensing",
        "pouring",
        "status",
        "state",
        "operation",
        "washing",
        "brewing",
        "working",
    )
)
_START_LABELS = ("start", "run", "go", "begin", "dispense", "pour")


@dataclass
class VarInfo:
    """One variable as the parser sees it: words that name it and its role."""

    name: str
    var: AnyVariable
    vocab: dict[str, float] = field(default_factory=dict)
    role: str = "setting"  # setting, switch, power, running
    on: str | None = None
    off: str | None = None
    timing: str = "duration"  # for time-like variables: duration, delay, finish (at), clock
    dimension: str | None = None
    order: int = 0

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


@lru_cache(maxsize=65536)
def parse_quantity(text: str) -> tuple[float, str | None, float] | None:
    """:func:`apbot.model.values.parse_quantity`, remembered: value lists are read per mention."""
    return _parse_quantity(text)


MAX_INSTRUCTION = 5_000
"""Characters of one instruction; a longer text is not something a user said to an appliance."""
MAX_PHRASE_VALUES = 2_000
"""Values of one discrete variable matched as phrases; a longer list is matched by numbers only."""


def _words(text: str) -> list[str]:
    return [t.text for t in tokenize(text.replace("_", " ")) if t.text.isalpha()]


def _phrase_words(text: str) -> list[str]:
    """Words and numbers of a value's name ("quick 20", "eco 40-60", "A-6")."""
    return [t.text for t in tokenize(text.replace("_", " ")) if t.text.isalnum()]


def _steps_of(model: ApplianceModel) -> Iterable[tuple[str, int, Step]]:
    for feature, steps in model.features.items():
        for index, step in enumerate(steps):
            yield feature, index, step


def _control_labels(model: ApplianceModel, actions: Iterable[str]) -> list[str]:
    labels: list[str] = []
    controls = {c.id: c for c in model.controls}
    for action_id in actions:
        action = model.actions.get(action_id)
        if action is None:
            continue
        for cid in [action.control] if action.control else list(action.controls or []):
            control = controls.get(cid or "")
            if control is not None and control.label:
                labels.append(control.label)
    return labels


def _step_effects(step: Step) -> list[tuple[str, Any]]:
    """(action, effect) pairs of a step."""
    if isinstance(step.effect, dict):
        return list(step.effect.items())
    return [(a, step.effect) for a in step.actions]


def _add_vocab(info: VarInfo, text: str, weight: float) -> None:
    for word in _words(text):
        if word in STOP_WORDS or len(word) < 2:
            continue
        key = concept(word)
        info.vocab[key] = max(info.vocab.get(key, 0.0), weight)


def _is_on_off(values: list[Any]) -> tuple[str, str] | None:
    lowered = [str(v).casefold() for v in values]
    if len(values) != 2:
        return None
    on = next((values[i] for i, v in enumerate(lowered) if v in _ON_WORDS), None)
    off = next((values[i] for i, v in enumerate(lowered) if v in _OFF_WORDS), None)
    if on is None or off is None:
        return None
    return str(on), str(off)


def build(model: ApplianceModel) -> Model:
    """Gather each variable's words and role from the model."""
    infos: dict[str, VarInfo] = {}
    for order, (name, var) in enumerate(model.variables.items()):
        info = VarInfo(name, var, order=order)
        _add_vocab(info, name, 1.0)
        if var.label:
            _add_vocab(info, var.label, 1.0)
        if isinstance(var.show, str):
            _add_vocab(info, var.show.split("{")[0], 0.7)
        elif isinstance(var.show, dict):
            for value, text in var.show.items():
                if "{" not in text and str(value).casefold() not in _OFF_WORDS:
                    _add_vocab(info, text, 0.7)
        if isinstance(var, NumericVariable):
            info.dimension = (unit_of(var.unit) or (None, 0))[0] if var.unit else None
        if isinstance(var, DiscreteVariable):
            switch = _is_on_off(info.values)
            if switch:
                info.role, info.on, info.off = "switch", switch[0], switch[1]
            if _numeric_values(info.values):
                info.dimension = _dimension_by_name(info)
            for dimension in _quantity_dimensions(info.values):
                _add_vocab(info, _DIMENSION_WORDS.get(dimension, ""), 0.6)  # "450 W": power
        infos[name] = info
    # features and control labels name the variables they adjust
    for feature, index, step in _steps_of(model):
        if step.variable and step.variable in infos:
            info = infos[step.variable]
            _add_vocab(info, feature, 0.6)
            steps = model.features[feature]
            entry = [a for s in steps[:index] for a in s.actions]
            own = [
                a
                for a, effect in _step_effects(step)
                if not isinstance(effect, GoTo) and len(model.actions.get(a, _NoAction).__dict__)
            ]
            if info.role == "switch":
                continue  # a switch's key is often shared (hold TIMER to lock)
            for label in _control_labels(model, entry + own):
                if not any(w in _START_LABELS for w in _words(label)):
                    _add_vocab(info, label, 0.8)
    _mark_power_and_running(model, infos)
    for info in infos.values():
        if isinstance(info.var, TimeVariable) or (
            isinstance(info.var, NumericVariable) and info.dimension == "time"
        ):
            if "clock" in info.vocab:
                info.timing = "clock"
            elif concept("delay") in info.vocab:
                info.timing = "delay"
            elif concept("finish") in info.vocab:
                # a time of day to finish at ("READY AT") or a wait ("READY IN", "END 3h")
                at = isinstance(info.var, TimeVariable) and not (
                    {"in", "after"} & set(_words(f"{info.name} {info.var.label or ''}"))
                )
                info.timing = "finish" if at else "delay"
    phrases = _phrases(model, infos)
    start_values = _start_values(model, infos)
    appliance = {concept(w) for w in _words(model.appliance.name + " " + model.appliance.category)}
    appliance |= {
        concept(w)
        for w in (
            "it",
            "machine",
            "appliance",
            "unit",
            "device",
            "washer",
            "cooker",
            "fryer",
            "oven",
            "kettle",
            "maker",
            "dehumidifier",
            "steriliser",
            "sterilizer",
            "hob",
            "everything",
        )
    }
    return Model(model, infos, phrases, start_values, frozenset(appliance))


class _NoAction:
    pass


def _numeric_values(values: list[Any]) -> bool:
    numeric = [v for v in values if parse_quantity(str(v)) is not None]
    return len(numeric) >= max(1, len(values) - 2)


_DIMENSION_WORDS = {"power": "power", "temperature": "temperature", "mass": "weight"}


def _quantity_dimensions(values: list[Any]) -> set[str]:
    """Dimensions that at least two values are quantities of ("100 W", "450 W")."""
    counts: dict[str, int] = {}
    for value in values:
        q = parse_quantity(str(value))
        if q is not None and q[1] is not None:
            counts[q[1]] = counts.get(q[1], 0) + 1
    return {d for d, c in counts.items() if c >= 2}


def _dimension_by_name(info: VarInfo) -> str | None:
    if concept("temperature") in info.vocab:
        return "temperature"
    if concept("humidity") in info.vocab:
        return "ratio"
    if concept("spin") in info.vocab:
        return "speed"
    return None


def _mark_power_and_running(model: ApplianceModel, infos: dict[str, VarInfo]) -> None:
    """The power switch hides the panel (or is called power); the running variable is what a
    START key sets, or is named for an operation (heating, dispensing, status)."""
    hiding = {name for guard in model.guards if guard.hide for name in guard.when}
    for name, info in infos.items():
        dark = name in hiding and concept("lock") not in info.vocab  # a panel that goes dark
        named = name in ("power", "on_off", "power_switch") or dark
        if info.role == "switch" and named:
            info.role = "power"
    for _feature, _index, step in _steps_of(model):
        pressed = [a for a in step.actions if model.actions[a].skill == "press"]
        labels = " ".join(_control_labels(model, pressed)).casefold()
        if not any(word in _words(labels) for word in _START_LABELS):
            continue
        goes = any(isinstance(effect, GoTo) for _a, effect in _step_effects(step))
        targets = [step.variable] if step.variable and goes else []
        targets += list(step.set)
        for target in targets:
            found = infos.get(target or "")
            if (
                found is not None
                and isinstance(found.var, DiscreteVariable)
                and found.role != "power"
                and (stem(target or "") in _OPERATION_NAMES or found.role == "switch")
            ):
                found.role = "running"
    for name, info in infos.items():
        operation = stem(name) in _OPERATION_NAMES
        if (
            operation
            and info.role in ("switch", "setting")
            and isinstance(info.var, DiscreteVariable)
        ):
            info.role = "running"


def _start_values(
    model: ApplianceModel, infos: dict[str, VarInfo]
) -> dict[str | None, tuple[str, Any]]:
    """What START sets the running variable to: by the variable whose feature ends with it
    (a timer programme ends in "timer" rather than "cooking"), and in general (key None)."""
    found: dict[str | None, tuple[str, Any]] = {}
    running = [n for n, i in infos.items() if i.role == "running"]
    for _feature, steps in model.features.items():
        adjusted = [s.variable for s in steps if s.variable and s.variable not in running]
        for step in steps:
            for action, effect in _step_effects(step):
                if not isinstance(effect, GoTo) or step.variable not in running:
                    continue
                labels = " ".join(_control_labels(model, [action])).casefold()
                if not any(word in _words(labels) for word in _START_LABELS):
                    continue
                value = (step.variable, effect.to)
                if len(steps) == 1 or not adjusted:
                    found.setdefault(None, value)
                for var in adjusted:
                    found.setdefault(var, value)
    for name in running:
        info = infos[name]
        on = info.on or next(
            (v for v in info.values if v != build_domain(info.var).values[0]), None
        )
        if on is not None:
            found.setdefault(None, (name, on))
    return found


def _phrases(
    model: ApplianceModel, infos: dict[str, VarInfo]
) -> list[tuple[str, Any, tuple[str, ...], float]]:
    """Word sequences that name one value of one variable."""
    phrases: list[tuple[str, Any, tuple[str, ...], float]] = []
    for name, info in infos.items():
        if not isinstance(info.var, DiscreteVariable) or info.role in ("power", "running"):
            continue
        if info.role == "switch":
            continue
        show = info.var.show if isinstance(info.var.show, dict) else {}
        if len(info.values) > MAX_PHRASE_VALUES:
            continue
        for value in info.values:
            text = str(value)
            if text.casefold() in _ON_WORDS + _OFF_WORDS + ("none", "----", "--"):
                continue
            forms = [text]
            if show.get(text) and "{" not in show[text]:
                forms.append(show[text])
            for form in forms:
                words = _phrase_words(form)
                if all(w.replace(".", "").isdigit() for w in words):
                    continue  # a number: read as a quantity
                if not words:
                    continue
                if len(words) == 1 and words[0] in LETTER_WORDS:
                    for alias in LETTER_WORDS[words[0]]:
                        phrases.append((name, value, (stem(alias),), 0.9))
                    continue
                phrases.append((name, value, tuple(stem(w) for w in words), 1.0))
                for synonym in SYNONYMS.get(words[0], ()) if len(words) == 1 else ():
                    phrases.append((name, value, (stem(synonym),), 0.8))
    # keys that go straight to one value ("GREEN TEA" sets 80 °C)
    for _feature, _index, step in _steps_of(model):
        if not step.variable or step.variable not in infos:
            continue
        info = infos[step.variable]
        if info.role in ("power", "running"):
            continue
        for action, effect in _step_effects(step):
            if not isinstance(effect, GoTo):
                continue
            for label in _control_labels(model, [action]):
                words = _words(label)
                if words and not any(w in STOP_WORDS for w in words):
                    phrases.append((step.variable, effect.to, tuple(stem(w) for w in words), 0.95))
    return phrases


# --- parsing -------------------------------------------------------------------------------------

_CONNECTORS = frozenset({"and", "+", "-", "/", "&", ",", "then", "with", "n"})
_CLAUSE_ENDS = frozenset({".", ";", "!", "?", "(", ")"})


@dataclass
class _Text:
    tokens: list[Token]
    stems: list[str]
    concepts: list[str]

    @classmethod
    def of(cls, text: str) -> _Text:
        tokens = tokenize(text)
        return cls(tokens, [stem(t.text) for t in tokens], [concept(t.text) for t in tokens])

    def word(self, k: int) -> str:
        return self.tokens[k].text if 0 <= k < len(self.tokens) else ""

    def span(self, start: int, end: int) -> str:
        return " ".join(t.text for t in self.tokens[start:end])


@dataclass
class _Match:
    var: str
    value: Any
    start: int
    end: int
    score: float


_VIEWS: dict[int, tuple[ApplianceModel, Model]] = {}


def _view(model: ApplianceModel) -> Model:
    """:func:`build`, remembered for the last few models (an agent parses many sentences)."""
    hit = _VIEWS.get(id(model))
    if hit is not None and hit[0] is model:
        return hit[1]
    view = build(model)
    if len(_VIEWS) >= 32:
        _VIEWS.pop(next(iter(_VIEWS)))
    _VIEWS[id(model)] = (model, view)
    return view


def parse_instruction(model: ApplianceModel, instruction: str) -> Goal:
    """The goal an instruction asks for, over ``model``'s variables, values canonical.

    Raises :class:`GoalParseError` when the instruction asks for a value the model lacks.

    >>> from apbot.examples import load_example
    >>> goal = parse_instruction(load_example("washing_machine"), "Wool at 30 degrees, no prewash")
    >>> sorted(goal.items())[:2]
    [('programme', 'wool'), ('temperature', '30')]
    """
    if len(str(instruction)) > MAX_INSTRUCTION:
        raise GoalParseError(
            str(instruction)[:40] + "…",
            f"the instruction has {len(str(instruction)):,} characters; at most "
            f"{MAX_INSTRUCTION:,} are read",
        )
    view = _view(model)
    text = _Text.of(str(instruction))
    goal: Goal = {}
    claimed: set[int] = set()
    for match in _value_matches(view, text):
        if match.var in goal or any(k in claimed for k in range(match.start, match.end)):
            continue
        goal[match.var] = match.value
        claimed.update(range(match.start, match.end))
    mentions = _distinct(find_mentions(text.tokens, skip=claimed))
    _assign_mentions(view, text, mentions, goal, claimed)
    _superlatives(view, text, goal, claimed)
    _zero_settings(view, text, goal, claimed)
    _switches(view, text, goal, claimed)
    _entry_switches(view, goal)
    _boil(view, text, goal)
    _power_and_running(view, text, goal)
    return _checked(view, goal)


def _negated_before(text: _Text, start: int, reach: int = 3) -> bool:
    for k in range(start - 1, max(-1, start - reach - 1), -1):
        word = text.word(k)
        if word in _CLAUSE_ENDS or word == ",":
            return False
        if word in NEGATIONS and word not in ("off", "stop", "free"):
            return True
    return False


def _value_matches(view: Model, text: _Text) -> list[_Match]:
    matches: list[_Match] = []
    n = len(text.tokens)
    verbs = _verb_positions(text)
    for var, value, stems, weight in view.phrases:
        info = view.infos[var]
        for i in range(n):
            found = _match_at(text, i, stems)
            if found is None:
                continue
            end, quality = found
            if _negated_before(text, i):
                continue
            if text.word(end) == "-" and text.word(end + 1) in ("off", "on"):
                continue  # "auto-off" names a timer, not the AUTO mode
            own = _near_vocab(info, text, i, end, reach=2)
            if _names_other(view, var, text, i, end):
                continue  # "power level 8" is not the POWER mode
            if len(stems) == 1 and _names_switch(view, var, text, i):
                continue  # "switch the light on" is the LIGHT, not a light crust
            score = len(stems) * weight * quality + 0.5 * own
            if i in verbs and len(stems) == 1:
                score *= 0.5  # "bake a French loaf": the verb is weaker than the noun
            matches.append(_Match(var, value, i, end, score))
    matches.sort(key=lambda m: (-m.score, m.start))
    return _prefer_heads(matches)


def _names_switch(view: Model, var: str, text: _Text, i: int) -> bool:
    """The word at i is an on/off setting's own name, and nothing of ``var`` stands next to it."""
    if _near_vocab(view.infos[var], text, i, i + 1, reach=2):
        return False
    for name, info in view.infos.items():
        own = _own_stems(info)
        if name == var or info.role != "switch" or text.stems[i] not in own:
            continue
        if text.word(i + 1) in ("on", "off") or _phrase_here(text, i, own - {text.stems[i]}):
            return True
    return False


def _prefer_heads(matches: list[_Match]) -> list[_Match]:
    """Of two values of one variable side by side ("UV storage"), the second — the head noun —
    is meant, unless it matched much worse."""
    best: dict[str, _Match] = {}
    for match in matches:
        best.setdefault(match.var, match)
    for var, first in best.items():
        for other in matches:
            if other.var == var and other.start == first.end and other.score >= first.score - 0.3:
                other.score = first.score + 0.01
    matches.sort(key=lambda m: (-m.score, m.start))
    return matches


def _names_other(view: Model, var: str, text: _Text, i: int, end: int) -> bool:
    """The words i..end name another variable, and a number or more of that variable's words
    follow ("power level 8" sets the level, not the POWER mode)."""
    keys = [text.concepts[k] for k in range(i, end) if text.word(k) not in _CONNECTORS]
    others = [
        info
        for name, info in view.infos.items()
        if name != var and all(info.vocab.get(key, 0.0) >= 0.8 for key in keys)
    ]
    if not others:
        return False
    shared = {key for info in others for key in info.vocab}
    for k in (i - 1, end):
        key = text.concepts[k] if 0 <= k < len(text.concepts) else ""
        if key in view.infos[var].vocab and key not in shared:
            return False  # "temperature mode": the mode's own word is next to it
    k = end + 1 if text.word(end) == "(" else end
    following = text.word(k)
    if following[:1].isdigit() or following in _NUMBER_WORDS:
        return True
    key = text.concepts[k] if k < len(text.concepts) else ""
    return any(info.vocab.get(key, 0.0) for info in others)


_NUMBER_WORDS = frozenset(
    {
        "one",
        "two",
        "three",
        "four",
        "five",
        "six",
        "seven",
        "eight",
        "nine",
        "ten",
        "eleven",
        "twelve",
        "twenty",
        "thirty",
        "forty",
        "fifty",
        "sixty",
        "seventy",
        "eighty",
        "ninety",
        "hundred",
    }
)


def _verb_positions(text: _Text) -> set[int]:
    """Tokens that open a clause with a verb of doing ("Bake a cake", "then steam it")."""
    positions = set()
    for k in _clause_starts(text, loose=True):
        k2 = k + 1 if text.word(k) in _FILLERS else k
        if k2 < len(text.stems) and text.stems[k2] in _ACTION_VERBS:
            positions.add(k2)
    return positions


_FILLERS = ("just", "please", "then", "now", "also", "first")


def _match_at(text: _Text, i: int, stems: tuple[str, ...]) -> tuple[int, float] | None:
    """End and quality of the phrase ``stems`` matched from token i (connectors may sit
    between words; a synonym or a longer word that starts like the value counts less)."""
    k = i
    quality = 1.0
    for index, target in enumerate(stems):
        if index:
            while text.word(k) in _CONNECTORS and k < len(text.tokens):
                k += 1
        if k >= len(text.tokens):
            return None
        here = text.stems[k]
        if here == target:
            pass
        elif similar(here, target):
            quality = min(quality, 0.9)
        elif here in _SYNONYM_STEMS.get(target, ()):
            quality = min(quality, 0.8)
        elif (
            len(target) >= 4
            and here.startswith(target)
            and (len(here) <= len(target) + 4 or len(target) >= 5)
            and text.word(k) not in LOWEST | HIGHEST
        ):
            quality = min(quality, 0.8)  # "storage" for STORE, "combination" for COMBI
        elif len(stems) > 1 and len(here) >= 3 and target.startswith(here):
            quality = min(quality, 0.7)  # "frozen veg" for frozen vegetables
        else:
            return None
        k += 1
    return k, quality


_SYNONYM_STEMS: dict[str, frozenset[str]] = {
    stem(word): frozenset(stem(w) for w in others) for word, others in SYNONYMS.items()
}


def _near_vocab(info: VarInfo, text: _Text, start: int, end: int, reach: int = 8) -> float:
    """How strongly the words around a span name the variable: each of its words found
    counts once, nearer counts more, and a comma in between halves it."""
    found: dict[str, float] = {}
    for direction, first in ((-1, start - 1), (1, end)):
        k = first
        factor = 1.0
        for distance in range(1, reach + 1):
            if not 0 <= k < len(text.tokens):
                break
            word = text.word(k)
            if word in _CLAUSE_ENDS:
                break
            if word == ",":
                factor *= 0.4
            key = text.concepts[k]
            weight = info.vocab.get(key, 0.0)
            if weight:
                found[key] = max(found.get(key, 0.0), factor * weight / distance)
            k += direction
    return sum(found.values())


def _distinct(mentions: list[Mention]) -> list[Mention]:
    """Drop a quantity that repeats the one just before it ("at 9 pm (21:00)", "a day, 24 h")."""
    kept: list[Mention] = []
    for mention in mentions:
        last = kept[-1] if kept else None
        if (
            last is not None
            and last.kind == mention.kind
            and abs(last.value - mention.value) < 1e-6
            and mention.start - last.end <= 3
        ):
            continue
        kept.append(mention)
    return kept


def _assign_mentions(
    view: Model, text: _Text, mentions: list[Mention], goal: Goal, claimed: set[int]
) -> None:
    options: list[tuple[float, int, int, str, Any]] = []
    for mi, mention in enumerate(mentions):
        for name, info in view.infos.items():
            if name in goal or info.role in ("power", "running", "switch"):
                continue
            value = _fit(view, info, mention, goal)
            if value is None:
                continue
            score = _near_vocab(info, text, mention.start, mention.end)
            if info.timing in ("clock", "finish") and not _near_vocab(
                info, text, mention.start, mention.end, reach=12
            ):
                continue  # a time of day sets the clock only when the clock is named
            score += _cue_bonus(info, text, mention)
            options.append((score, -info.order, mi, name, value))
    options.sort(key=lambda o: (-o[0], -o[1]))
    used: set[int] = set()
    for score, _order, mi, name, value in options:
        if mi in used or name in goal:
            continue
        mention = mentions[mi]
        article = text.word(mention.start) in ("a", "an", "couple", "single")
        lone = not article and _only_home(view, mention, goal)
        if score <= 0 and mention.kind == "number" and not lone:
            continue
        goal[name] = value
        used.add(mi)
        claimed.update(range(mention.start, mention.end))
    for mi, mention in enumerate(mentions):
        if mi not in used and mention.kind == "clock" and _clock_parts(view, mention, goal):
            used.add(mi)
    for mi, mention in enumerate(mentions):
        if mi not in used:
            _unplaced(view, text, mention, goal)


def _clock_parts(view: Model, mention: Mention, goal: Goal) -> bool:
    """A clock kept as two settings, its hour and its minute: set both from one time."""
    parts: dict[str, VarInfo] = {}
    for info in view.infos.values():
        own = _own_stems(info)
        if info.role != "setting" or stem("clock") not in own or info.name in goal:
            continue
        if own & {stem("hour"), stem("hours"), "hr", "h"}:
            parts["hour"] = info
        elif own & {stem("minute"), stem("minutes"), "min", "m"}:
            parts["minute"] = info
    if len(parts) != 2:
        return False
    hour, minute = divmod(int(mention.value) // 60, 60)
    values = {}
    for part, number in (("hour", hour), ("minute", minute)):
        domain = _domain_values(view, parts[part], goal)
        if part == "hour" and not _has_number(domain, number) and number > 12:
            number -= 12
        found = next((v for v in domain if _as_int(v) == number), None)
        if found is None:
            return False
        values[parts[part].name] = found
    goal.update(values)
    return True


def _as_int(value: Any) -> int | None:
    try:
        number = float(value)
    except (TypeError, ValueError):
        return None
    return int(number) if number == int(number) else None


def _has_number(domain: list[Any], number: int) -> bool:
    return any(_as_int(v) == number for v in domain)


def _only_home(view: Model, mention: Mention, goal: Goal) -> bool:
    """A bare number that fits exactly one open variable goes there."""
    homes = [
        n
        for n, i in view.infos.items()
        if n not in goal and i.role == "setting" and _fit(view, i, mention, goal) is not None
    ]
    return len(homes) == 1


def _cue_bonus(info: VarInfo, text: _Text, mention: Mention) -> float:
    """Relative times prefer delays, "for" a duration, clock times clocks; units fit units."""
    before = text.word(mention.start - 1)
    before2 = text.word(mention.start - 2)
    after = " ".join(text.word(mention.end + d) for d in range(2))
    bonus = 0.0
    if mention.kind == "duration":
        relative = (
            before in ("in", "within")
            or after in ("from now",)
            or before2 in ("start", "begin", "starting", "delay", "delayed", "wait")
            or before in ("delay", "delayed", "wait")
        )
        if info.timing == "delay":
            bonus += 0.9 if relative else -0.3
        elif relative:
            bonus -= 0.3
    if mention.dimension and mention.dimension == info.dimension:
        bonus += 0.3
    return bonus


def _fit(view: Model, info: VarInfo, mention: Mention, goal: Goal) -> Any:
    """The canonical value a mention gives this variable, or None when it does not fit."""
    domain = _domain_values(view, info, goal)
    var = info.var
    if isinstance(var, TimeVariable):
        if mention.kind == "duration" and info.timing not in ("clock", "finish"):
            seconds = round(mention.value)
        elif mention.kind == "clock" and info.timing in ("duration", "delay"):
            if not mention.colon or mention.meridiem or mention.lead not in ("for", "to", "of"):
                return None
            hours, minutes = divmod(round(mention.value) // 60, 60)
            # "for 1:30": minutes and seconds on a mm:ss display, else hours and minutes
            seconds = hours * 60 + minutes if var.format == "mm:ss" else round(mention.value)
        elif mention.kind == "clock":
            seconds = round(mention.value)
            if format_hms(seconds) not in domain and seconds >= 13 * 3600:
                # a 12-hour clock: 19:00 is 7:00
                seconds -= 12 * 3600
        else:
            return None
        value = format_hms(seconds)
        return value if value in domain else None
    if isinstance(var, NumericVariable):
        number = _number_for(info, var.unit, mention)
        if number is None:
            return _percent_of_level(info, mention, domain)
        fahrenheit_dial = var.unit.casefold() in ("°f", "f")
        converted = (mention.kind == "fahrenheit" and not fahrenheit_dial) or (
            fahrenheit_dial and mention.unit in ("°c", "c", "celsius")
        )
        tolerance = (_F_TOLERANCE * (1.8 if fahrenheit_dial else 1.0)) if converted else 1e-6
        return _in_numeric(number, domain, tolerance=tolerance)
    # discrete values that are numbers ("60", "1000") or quantities ("1.75 oz", "450 W")
    measured = _measure(mention)
    if measured is None:
        return None
    amount, dimension = measured
    for value in domain:
        q = parse_quantity(str(value))
        if q is None:
            continue
        if q[1] is not None:
            if q[1] == dimension and abs(q[0] - amount) < 1e-6 * max(1.0, abs(amount)):
                return value
        elif dimension is None or dimension == info.dimension:
            if abs(q[0] - amount) < 1e-6:
                return value
        elif (
            dimension == "fahrenheit"
            and info.dimension == "temperature"
            and abs(q[0] - (amount - 32) * 5 / 9) < 0.6
        ):
            return value
    return _show_quantity(info, mention)


def _percent_of_level(info: VarInfo, mention: Mention, domain: list[Any]) -> Any:
    """ "50% power" on a power level of 1-10 is level 5."""
    if mention.dimension != "ratio" or not domain or info.dimension is not None:
        return None
    if not ({concept("power"), concept("level")} & set(info.vocab)):
        return None
    top = max(float(v) for v in domain)
    if top not in (10, 100):
        return None
    return _in_numeric(mention.value * top / 100, domain)


def _measure(mention: Mention) -> tuple[float, str | None] | None:
    if mention.kind == "number":
        return mention.value, None
    if mention.kind in ("quantity", "fahrenheit"):
        return mention.value, mention.dimension
    if mention.kind == "duration":
        return mention.value, "time"
    return None


def _base_unit(dimension: str) -> str:
    return {"temperature": "°C", "ratio": "%", "speed": "rpm"}.get(dimension, "")


def _show_quantity(info: VarInfo, mention: Mention) -> Any:
    """A discrete value whose display text holds the mentioned quantity ("POT 600mL")."""
    show = info.var.show if isinstance(info.var.show, dict) else {}
    if mention.kind != "quantity" or not show:
        return None
    for value, text in show.items():
        for m in find_mentions(tokenize(text)):
            same = m.kind == "quantity" and m.dimension == mention.dimension
            if same and abs(m.value - mention.value) < 1e-6:
                return value
    return None


def _number_for(info: VarInfo, unit: str, mention: Mention) -> float | None:
    """The mention as a number in ``unit`` (None when the dimensions differ)."""
    target = unit_of(unit) if unit else None
    if mention.kind == "number":
        return mention.value
    if mention.kind == "duration":
        if target is None or target[0] != "time":
            return None
        return mention.value / target[1]
    if mention.kind == "fahrenheit":
        if unit.casefold() in ("°f", "f"):
            return mention.value
        if target is not None and target[0] == "temperature":
            return round((mention.value - 32) * 5 / 9, 6)
        return None
    if mention.kind == "quantity":
        if target is None:
            if unit:
                return None
            return mention.value if mention.dimension in (None, info.dimension) else None
        if unit.casefold() in ("°f", "f") and mention.dimension == "temperature":
            if mention.unit in ("°c", "c", "celsius"):
                return round(mention.value * 9 / 5 + 32, 6)  # "180 °C" on a Fahrenheit dial
            return mention.value  # "350 degrees" on a Fahrenheit dial
        if target[0] != mention.dimension:
            return None
        return mention.value / target[1]
    return None


_F_TOLERANCE = 5.0
"""°C a Fahrenheit figure may miss a Celsius dial by: 350 °F is 176.7 °C, printed as 180 °C."""


def _in_numeric(number: float, domain: list[Any], tolerance: float = 1e-6) -> Any:
    """The domain value equal to ``number`` (or nearest within ``tolerance``)."""
    best = min(domain, key=lambda v: abs(float(v) - number), default=None)
    if best is not None and abs(float(best) - number) <= tolerance:
        return best
    return None


def _domain_values(view: Model, info: VarInfo, goal: Goal) -> list[Any]:
    var = info.var
    if var.depends_on and var.depends_on in goal and var.cases:
        case = var.cases.get(str(goal[var.depends_on]))
        if case is None:
            return []
        return list(build_domain(var, case).values)
    return list(info.values)


def _unplaced(view: Model, text: _Text, mention: Mention, goal: Goal) -> None:
    """A quantity with a unit that only open variables of its kind could take, none of which
    has the value: the model cannot do what was asked."""
    if mention.kind == "number":
        return
    kinds = []
    for name, info in view.infos.items():
        if info.role != "setting":
            continue
        timed = isinstance(info.var, TimeVariable) or info.dimension == "time"
        if (
            (mention.kind == "clock" and info.timing in ("clock", "finish"))
            or (mention.kind == "duration" and timed)
            or (mention.kind == "fahrenheit" and info.dimension == "temperature")
            or (mention.kind == "quantity" and info.dimension == mention.dimension)
        ):
            kinds.append(name)
    if not kinds:
        return
    closeness = {n: _near_vocab(view.infos[n], text, mention.start, mention.end) for n in kinds}
    near = max(kinds, key=lambda n: closeness[n])
    if mention.kind == "clock" and closeness[near] < 0.5:
        return  # a time of day said in passing ("a 3 a.m. feed")
    if any(name in goal for name in kinds) and (near in goal or closeness[near] < 0.5):
        return  # another setting of its kind was given; this may be a remark
    info = view.infos[near]
    values = _domain_values(view, info, goal)
    parent = info.var.depends_on
    if not values and parent:
        reason = f"{near} does not apply when {parent} is {goal.get(parent)!r}"
    else:
        where = f" when {parent} is {goal[parent]!r}" if parent and parent in goal else ""
        reason = f"no setting of this model takes it; {near} can be {preview(values, quote=False)}"
        reason += where
    raise GoalParseError(text.span(mention.start, mention.end), reason)


def _superlatives(view: Model, text: _Text, goal: Goal, claimed: set[int]) -> None:
    """ "the lowest temperature", "full power", "a dark crust" on an ordered numeric setting."""
    for k, token in enumerate(text.tokens):
        word = token.text
        if k in claimed:
            continue
        end = None
        if word in LOWEST:
            end = 0
        elif word in HIGHEST:
            end = -1
        scale_index = None
        for scale in SCALES:
            said = "medium" if word in ("middle", "mid", "med") else word
            if said in scale:
                scale_index = (scale.index(said), len(scale))
        if end is None and scale_index is None:
            continue
        best: tuple[float, str] | None = None
        for name, info in view.infos.items():
            if name in goal or info.role != "setting" or not _ordered(info):
                continue
            values = _domain_values(view, info, goal)
            if scale_index is not None and end is None and len(values) != scale_index[1]:
                continue
            score = _near_vocab(info, text, k, k + 1, reach=4)
            if score > 0 and (best is None or score > best[0]):
                best = (score, name)
        if best is None:
            continue
        name = best[1]
        values = _ordered_values(_domain_values(view, view.infos[name], goal))
        if not values:
            continue
        if end is not None:
            goal[name] = values[end]
        elif scale_index is not None:
            goal[name] = values[scale_index[0]]
        claimed.add(k)


def _ordered(info: VarInfo) -> bool:
    return isinstance(info.var, NumericVariable | TimeVariable) or (
        isinstance(info.var, DiscreteVariable)
        and (_numeric_values(info.values) or bool(_quantity_dimensions(info.values)))
    )


def _ordered_values(values: list[Any]) -> list[Any]:
    """Values in order of size: numbers and times as they are; of a discrete list, the ones
    that are quantities ("100 W" < "450 W"), by size."""
    if all(isinstance(v, int | float) for v in values) or all(
        str(v).count(":") == 2 for v in values
    ):
        return values
    sized = [(q[0], v) for v in values if (q := parse_quantity(str(v))) is not None]
    return [v for _size, v in sorted(sized, key=lambda pair: pair[0])]


def _switches(view: Model, text: _Text, goal: Goal, claimed: set[int]) -> None:
    """An on/off setting named in the instruction: on, unless its words are negated."""
    verbs = _verb_positions(text)
    for name, info in view.infos.items():
        if info.role != "switch" or name in goal:
            continue
        own = _own_stems(info)
        best: tuple[float, int] | None = None
        for k in range(len(text.tokens)):
            if k in claimed or text.word(k) in STOP_WORDS:
                continue
            key = text.concepts[k]
            weight = info.vocab.get(key, 0.0)
            if weight <= 0 or _generic(key):
                continue
            if text.stems[k] in own or key in _own_concepts(info):
                weight = 1.0
                # "Warm the water" is not KEEP WARM; "UV light" is not the night light
                doubtful = len(own) > 1 and (k in verbs or (k - 1) in claimed)
                if doubtful and not _phrase_here(text, k, own):
                    continue
            elif _negative_around(text, k):
                weight = 0.5  # a feature's word only says "without" ("no finish time")
            else:
                continue
            if best is None or weight > best[0]:
                best = (weight, k)
        if best is None:
            continue
        k = best[1]
        positive = not _negative_around(text, k)
        assert info.on is not None and info.off is not None
        goal[name] = info.on if positive else info.off
        claimed.add(k)


def _phrase_here(text: _Text, k: int, own: set[str]) -> bool:
    """Another of the switch's own words stands next to token k ("keep warm", "night light")."""
    return any(text.stems[j] in own for j in (k - 1, k + 1) if 0 <= j < len(text.tokens))


def _entry_switches(view: Model, goal: Goal) -> None:
    """A setting entered through a switch ("READY AT" turns the finish timer on, then sets the
    time) implies that switch on, unless the instruction already said otherwise."""
    for _feature, steps in view.model.features.items():
        for index, step in enumerate(steps):
            if step.variable not in goal:
                continue
            for earlier in steps[:index]:
                target = earlier.variable
                info = view.infos.get(target or "")
                if info is None or info.role != "switch" or target in goal:
                    continue
                effects = [effect for _a, effect in _step_effects(earlier)]
                if all(effect == "toggle" for effect in effects) and effects:
                    goal[info.name] = info.on


def _zero_settings(view: Model, text: _Text, goal: Goal, claimed: set[int]) -> None:
    """ "no delay", "no final spin", "skip the rinse": a numeric setting that can be 0 is 0."""
    for k, token in enumerate(text.tokens):
        if token.text not in NEGATIONS or token.text in ("off", "free", "stop", "cancel"):
            continue
        for d in range(1, 4):
            j = k + d
            if j >= len(text.tokens) or text.word(j) in _CLAUSE_ENDS or text.word(j) == ",":
                break
            key = text.concepts[j]
            homes = [
                info
                for info in view.infos.values()
                if info.name not in goal
                and info.role == "setting"
                and not isinstance(info.var, DiscreteVariable)
                and (text.stems[j] in _own_stems(info) or key in _own_concepts(info))
                and _starts_at_zero(info)
            ]
            if len(homes) == 1:
                values = _domain_values(view, homes[0], goal)
                zero = next((v for v in values if _magnitude(v) == 0), None)
                if zero is not None:
                    goal[homes[0].name] = zero
                    claimed.add(j)
                break


def _own_concepts(info: VarInfo) -> set[str]:
    return {concept(w) for w in _own_stems(info)}


def _starts_at_zero(info: VarInfo) -> bool:
    """A setting whose "none" is 0: any number, or a duration that starts empty (not a clock)."""
    if isinstance(info.var, NumericVariable):
        return True
    if isinstance(info.var, TimeVariable) and info.timing not in ("clock", "finish"):
        domain = build_domain(info.var) if not info.var.depends_on else None
        return domain is None or _magnitude(domain.values[domain.initial]) == 0
    return False


def _magnitude(value: Any) -> float | None:
    if isinstance(value, int | float):
        return float(value)
    text = str(value)
    if text.count(":") == 2:
        h, m, sec = (int(x) for x in text.split(":"))
        return float(h * 3600 + m * 60 + sec)
    return None


def _boil(view: Model, text: _Text, goal: Goal) -> None:
    """ "bring it to the boil": 100 °C on a water temperature setting that offers it."""
    if not any(s == stem("boil") for s in text.stems):
        return
    for info in view.infos.values():
        if info.name in goal or not isinstance(info.var, NumericVariable):
            continue
        if info.dimension == "temperature" and info.var.unit.casefold() in ("°c", "c"):
            values = _domain_values(view, info, goal)
            if 100 in values and max(values) == 100:
                goal[info.name] = 100


_GENERIC = frozenset(
    concept(w) for w in ("program", "time", "temperature", "level", "power", "size", "water")
)


def _generic(key: str) -> bool:
    return key in _GENERIC


def _own_stems(info: VarInfo) -> set[str]:
    words = _words(info.name) + (_words(info.var.label) if info.var.label else [])
    return {stem(w) for w in words if w not in STOP_WORDS}


def _negative_around(text: _Text, k: int) -> bool:
    for d in range(1, 6):
        word = text.word(k - d)
        if word in _CLAUSE_ENDS or word == ",":
            break
        if word in NEGATIONS and word not in ("free",):
            return True
        if word in ("on", "with", "enable", "add"):
            break
    if text.word(k) in ("mute", "silence", "unlock"):
        return True
    for d in range(1, 4):
        word = text.word(k + d)
        if word in _CLAUSE_ENDS or word == ",":
            break
        if word in ("off", "disabled"):
            return True
        if word == "on":
            return False
    return False


_DENIALS = frozenset({"don't", "dont", "not", "without", "never"})
_START_WORDS = frozenset({"start", "begin", "started", "starting", "begins", "kick", "launch"})
_NOW_PHRASES = ("right away", "straight away", "immediately")
_STRONG_VERBS = frozenset(
    stem(w)
    for w in (
        "cook",
        "heat",
        "warm",
        "boil",
        "bake",
        "fry",
        "roast",
        "steam",
        "simmer",
        "sear",
        "melt",
        "brew",
        "reheat",
        "wash",
        "dispense",
        "pour",
        "thaw",
        "defrost",
        "soften",
        "pop",
        "dehydrate",
        "broil",
        "toast",
        "run",
        "microwave",
        "grill",
        "knead",
    )
)
_WEAK_VERBS = frozenset(stem(w) for w in ("keep", "bring", "make", "give", "fill"))
# A running variable named for one operation is started only by that operation's verbs.
_VERB_FAMILIES: dict[str, frozenset[str]] = {
    stem("heating"): frozenset(stem(w) for w in ("heat", "warm", "boil", "bring", "keep")),
    stem("dispensing"): frozenset(stem(w) for w in ("dispense", "pour", "fill")),
    stem("pouring"): frozenset(stem(w) for w in ("dispense", "pour", "fill")),
}
_ACTION_VERBS = _STRONG_VERBS | _WEAK_VERBS


def _power_and_running(view: Model, text: _Text, goal: Goal) -> None:
    for name, info in view.infos.items():
        if info.role == "power" and name not in goal and _says_power_on(view, text):
            goal[name] = info.on
    running = [n for n, i in view.infos.items() if i.role == "running"]
    if not running or any(n in goal for n in running):
        return
    family = next((_VERB_FAMILIES[stem(n)] for n in running if stem(n) in _VERB_FAMILIES), None)
    start = _says_start(text, family)
    started_by = _procedure_start(view, goal)
    if start is None and started_by is not None:
        start = True  # the procedure for a goal setting ends by starting (TIME DEFROST)
    if start is None:
        return
    key = next((v for v in goal if v in view.start_values), None)
    target = started_by or view.start_values.get(key) or view.start_values.get(None)
    if target is None:
        return
    name, value = target
    info = view.infos[name]
    if start:
        goal[name] = value
    else:
        domain = build_domain(info.var)
        goal[name] = info.off or domain.values[domain.initial]


def _procedure_start(view: Model, goal: Goal) -> tuple[str, Any] | None:
    """(running variable, value) when a goal setting's own procedure ends with a step that
    sets the running variable — the model says that entering it starts the appliance."""
    for _feature, steps in view.model.features.items():
        for index, step in enumerate(steps):
            if step.variable not in goal:
                continue
            for later in steps[index + 1 :]:
                info = view.infos.get(later.variable or "")
                if info is None or info.role != "running":
                    continue
                for _action, effect in _step_effects(later):
                    if isinstance(effect, GoTo):
                        return info.name, effect.to
    return None


def _says_power_on(view: Model, text: _Text) -> bool:
    """ "turn the machine on", "switch on, ...", "power the bread maker up"."""
    n = len(text.tokens)
    for k, token in enumerate(text.tokens):
        if token.text not in ("turn", "switch", "power", "switched", "turned"):
            continue
        j = k + 1
        while j < n and (concept(text.word(j)) in view.appliance_words or text.word(j) == "the"):
            j += 1
        if text.word(j) not in ("on", "up"):
            continue
        if j > k + 1:
            return True  # "turn it on", "power the bread maker up"
        m = j + 1
        while m < n and (concept(text.word(m)) in view.appliance_words or text.word(m) == "the"):
            m += 1
        if m >= n or text.word(m) in _CLAUSE_ENDS | {",", "and", "then"}:
            return True  # "switch on, ...", "switch on the cooker and ..."
    return False


def _says_start(text: _Text, family: frozenset[str] | None = None) -> bool | None:
    """True for "start it", False for "don't start", None when the instruction says neither."""
    joined = " " + " ".join(t.text for t in text.tokens) + " "
    negative = False
    positive = False
    for k, token in enumerate(text.tokens):
        word = token.text
        starts = word in _START_WORDS
        if word in ("get", "set") and any(
            text.word(k + d) in ("going", "started", "cooking", "heating", "running")
            for d in range(1, 7)
        ):
            starts = True
        if word == "go" and text.word(k + 1) in ("ahead", ".", "!", ""):
            starts = True
        if not starts:
            continue
        before = []
        for d in range(1, 4):
            if text.word(k - d) in _CLAUSE_ENDS:
                break
            before.append(text.word(k - d))
        denied = any(b in _DENIALS for b in before)
        if denied or "yet" in (text.word(k + 1), text.word(k + 2)):
            negative = True
        else:
            positive = True
    if " not started " in joined or " but not start" in joined:
        negative = True
    for k, token in enumerate(text.tokens):  # "don't heat it yet"
        if token.text in _DENIALS and token.text != "without" and k + 1 < len(text.stems):
            verb = text.stems[k + 1]
            if verb in _STRONG_VERBS and (family is None or verb in family):
                negative = True
    if negative:
        return False
    if positive or any(f" {w} " in joined for w in _NOW_PHRASES):
        return True
    for k, token in enumerate(text.tokens):
        if token.text == "now" and text.word(k - 1) != "from" and text.word(k + 1) != "on":
            return True
    for k in _clause_starts(text, loose=True):
        k2 = k + 1 if text.word(k) in _FILLERS else k
        if k2 >= len(text.stems):
            continue
        verb = text.stems[k2]
        if family is not None and verb not in family:
            continue
        if verb in _STRONG_VERBS:
            return True
        if verb in _WEAK_VERBS and (k == 0 or text.word(k - 1) in (".", ";", "!")):
            return True
    return None


def _clause_starts(text: _Text, loose: bool = False) -> list[int]:
    """Where sentences begin (and, when ``loose``, clauses after ", and", "then")."""
    ends = {".", ";", "!", "?"} | ({",", "and", "then"} if loose else set())
    starts = [0]
    for k, token in enumerate(text.tokens):
        if token.text in ends and k + 1 < len(text.tokens):
            starts.append(k + 1)
    return starts


def _checked(view: Model, goal: Goal) -> Goal:
    """Normalise every value against its variable (the programme's case for a setting)."""
    out: Goal = {}
    for name, value in goal.items():
        info = view.infos[name]
        try:
            out[name] = normalise(info.var, value)
        except ValueProblem as exc:
            raise GoalParseError(str(value), f"not a value of {name}: {exc}") from None
    return out
