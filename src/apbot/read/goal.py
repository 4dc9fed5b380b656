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

import math
from collections.abc import Iterable
from dataclasses import dataclass, field
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
from apbot.model.values import format_hms, parse_quantity, preview, unit_of
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
    timing: str = "duration"  # for time-like variables: duration, delay, clock
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


def _words(text: str) -> list[str]:
    return [t.text for t in tokenize(text.replace("_", " ")) if t.text.isalpha()]


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
            elif concept("delay") in info.vocab or concept("finish") in info.vocab:
                info.timing = "delay"
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
        if info.role == "switch" and (name in hiding or name == "power") and name == "power":
            info.role = "power"
        elif info.role == "switch" and name in hiding and concept("power") in info.vocab:
            info.role = "power"
    for feature, _index, step in _steps_of(model):
        labels = " ".join(_control_labels(model, step.actions)).casefold()
        if not any(word in _words(labels) for word in _START_LABELS):
            continue
        targets = [step.variable] if step.variable else []
        targets += list(step.set)
        for target in targets:
            info = infos.get(target or "")
            if info is not None and isinstance(info.var, DiscreteVariable) and info.role != "power":
                if stem(target or "") in _OPERATION_NAMES or info.role == "switch":
                    info.role = "running"
    for name, info in infos.items():
        if info.role in ("switch", "setting") and isinstance(info.var, DiscreteVariable):
            if stem(name) in _OPERATION_NAMES:
                info.role = "running"


def _start_values(model: ApplianceModel, infos: dict[str, VarInfo]) -> dict[str | None, tuple[str, Any]]:
    """What START sets the running variable to: by the variable whose feature ends with it
    (a timer programme ends in "timer" rather than "cooking"), and in general (key None)."""
    found: dict[str | None, tuple[str, Any]] = {}
    running = [n for n, i in infos.items() if i.role == "running"]
    for feature, steps in model.features.items():
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


def _phrases(model: ApplianceModel, infos: dict[str, VarInfo]) -> list[tuple[str, Any, tuple[str, ...], float]]:
    """Word sequences that name one value of one variable."""
    phrases: list[tuple[str, Any, tuple[str, ...], float]] = []
    for name, info in infos.items():
        if not isinstance(info.var, DiscreteVariable) or info.role in ("power", "running"):
            continue
        if info.role == "switch":
            continue
        show = info.var.show if isinstance(info.var.show, dict) else {}
        for value in info.values:
            text = str(value)
            if text.casefold() in _ON_WORDS + _OFF_WORDS + ("none", "----", "--"):
                continue
            forms = [text]
            if show.get(text) and "{" not in show[text]:
                forms.append(show[text])
            for form in forms:
                words = [w for w in _words(form)]
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
                    phrases.append(
                        (step.variable, effect.to, tuple(stem(w) for w in words), 0.95)
                    )
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


def parse_instruction(model: ApplianceModel, instruction: str) -> Goal:
    """The goal an instruction asks for, over ``model``'s variables, values canonical.

    Raises :class:`GoalParseError` when the instruction asks for a value the model lacks.

    >>> from apbot.examples import load_example
    >>> goal = parse_instruction(load_example("washing_machine"), "Wool at 30 degrees, no prewash")
    >>> sorted(goal.items())[:2]
    [('programme', 'wool'), ('temperature', '30')]
    """
    view = build(model)
    text = _Text.of(str(instruction))
    goal: Goal = {}
    claimed: set[int] = set()
    for match in _value_matches(view, text):
        if match.var in goal or any(k in claimed for k in range(match.start, match.end)):
            continue
        goal[match.var] = match.value
        claimed.update(range(match.start, match.end))
    mentions = find_mentions(text.tokens, skip=claimed)
    _assign_mentions(view, text, mentions, goal, claimed)
    _superlatives(view, text, goal, claimed)
    _switches(view, text, goal, claimed)
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
    for var, value, stems, weight in view.phrases:
        for i in range(n):
            end = _match_at(text, i, stems)
            if end is None:
                continue
            if _negated_before(text, i):
                continue
            exact = all(text.stems[k] in stems for k in range(i, end) if text.word(k) not in _CONNECTORS)
            score = len(stems) * weight * (1.0 if exact else 0.9)
            score += 0.5 * _near_vocab(view.infos[var], text, i, end, reach=2)
            matches.append(_Match(var, value, i, end, score))
    matches.sort(key=lambda m: (-m.score, m.start))
    return matches


def _match_at(text: _Text, i: int, stems: tuple[str, ...]) -> int | None:
    """End of the phrase ``stems`` matched from token i (connectors may sit between words)."""
    k = i
    for index, target in enumerate(stems):
        if index:
            while text.word(k) in _CONNECTORS and k < len(text.tokens):
                k += 1
        if k >= len(text.tokens) or not similar(text.stems[k], target):
            return None
        k += 1
    return k


def _near_vocab(info: VarInfo, text: _Text, start: int, end: int, reach: int = 6) -> float:
    """How strongly the words around a span name the variable (nearer counts more)."""
    score = 0.0
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
            weight = info.vocab.get(text.concepts[k], 0.0)
            if weight:
                score = max(score, factor * weight / distance)
            k += direction
    return score


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
            score += _cue_bonus(info, text, mention)
            options.append((score, -info.order, mi, name, value))
    options.sort(key=lambda o: (-o[0], -o[1]))
    used: set[int] = set()
    for score, _order, mi, name, value in options:
        if mi in used or name in goal:
            continue
        mention = mentions[mi]
        if score <= 0 and mention.kind == "number" and not _only_home(view, mention, goal):
            continue
        goal[name] = value
        used.add(mi)
        claimed.update(range(mention.start, mention.end))
    for mi, mention in enumerate(mentions):
        if mi not in used:
            _unplaced(view, text, mention, goal)


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
    if mention.kind == "clock":
        bonus += 0.5 if info.timing in ("clock", "delay") else 0.0
    if mention.dimension and mention.dimension == info.dimension:
        bonus += 0.3
    return bonus


def _fit(view: Model, info: VarInfo, mention: Mention, goal: Goal) -> Any:
    """The canonical value a mention gives this variable, or None when it does not fit."""
    domain = _domain_values(view, info, goal)
    var = info.var
    if isinstance(var, TimeVariable):
        if mention.kind == "duration" and info.timing != "clock":
            seconds = round(mention.value)
        elif mention.kind == "clock" and info.timing != "duration":
            seconds = round(mention.value)
            if format_hms(seconds) not in domain and seconds >= 13 * 3600 and not mention.meridiem:
                seconds -= 12 * 3600
            elif format_hms(seconds) not in domain and seconds >= 13 * 3600:
                seconds -= 12 * 3600
        else:
            return None
        value = format_hms(seconds)
        return value if value in domain else None
    if isinstance(var, NumericVariable):
        number = _number_for(info, var.unit, mention)
        if number is None:
            return None
        return _in_numeric(number, domain)
    # discrete
    if info.dimension is None and mention.kind not in ("number", "quantity"):
        return _show_quantity(info, mention)
    number = _number_for(info, "", mention) if info.dimension is None else None
    if info.dimension is not None:
        number = _number_for(info, _base_unit(info.dimension), mention)
    if number is None:
        return _show_quantity(info, mention)
    for value in domain:
        q = parse_quantity(str(value))
        if q is not None and abs(q[0] - number) < 1e-6:
            return value
    return _show_quantity(info, mention)


def _base_unit(dimension: str) -> str:
    return {"temperature": "°C", "ratio": "%", "speed": "rpm"}.get(dimension, "")


def _show_quantity(info: VarInfo, mention: Mention) -> Any:
    """A discrete value whose display text holds the mentioned quantity ("POT 600mL")."""
    show = info.var.show if isinstance(info.var.show, dict) else {}
    if mention.kind != "quantity" or not show:
        return None
    for value, text in show.items():
        for word in tokenize(text):
            pass
        for m in find_mentions(tokenize(text)):
            if m.kind == "quantity" and m.dimension == mention.dimension:
                if abs(m.value - mention.value) < 1e-6:
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
            return mention.value  # "350 degrees" on a Fahrenheit dial
        if target[0] != mention.dimension:
            return None
        return mention.value / target[1]
    return None


def _in_numeric(number: float, domain: list[Any]) -> Any:
    for value in domain:
        if abs(float(value) - number) < 1e-6:
            return value
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
    if mention.kind in ("number", "clock"):
        return
    kinds = []
    for name, info in view.infos.items():
        if info.role != "setting":
            continue
        if mention.kind == "duration" and (
            isinstance(info.var, TimeVariable) or info.dimension == "time"
        ):
            kinds.append(name)
        elif mention.kind == "fahrenheit" and info.dimension == "temperature":
            kinds.append(name)
        elif mention.kind == "quantity" and info.dimension == mention.dimension:
            kinds.append(name)
    if not kinds or any(name in goal for name in kinds):
        return
    near = max(kinds, key=lambda n: _near_vocab(view.infos[n], text, mention.start, mention.end))
    offered = preview(_domain_values(view, view.infos[near], goal), quote=False)
    raise GoalParseError(
        text.span(mention.start, mention.end),
        f"no setting of this model takes it; {near} can be {offered}",
    )


def _superlatives(view: Model, text: _Text, goal: Goal, claimed: set[int]) -> None:
    """"the lowest temperature", "full power", "a dark crust" on an ordered numeric setting."""
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
            if word in scale:
                scale_index = (scale.index(word), len(scale))
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
        values = _domain_values(view, view.infos[name], goal)
        if not values:
            continue
        if end is not None:
            goal[name] = values[end]
        elif scale_index is not None:
            goal[name] = values[scale_index[0]]
        claimed.add(k)


def _ordered(info: VarInfo) -> bool:
    return isinstance(info.var, NumericVariable | TimeVariable) or (
        isinstance(info.var, DiscreteVariable) and _numeric_values(info.values)
    )


def _switches(view: Model, text: _Text, goal: Goal, claimed: set[int]) -> None:
    """An on/off setting named in the instruction: on, unless its words are negated."""
    for name, info in view.infos.items():
        if info.role != "switch" or name in goal:
            continue
        best: tuple[float, int] | None = None
        for k in range(len(text.tokens)):
            if k in claimed or text.word(k) in STOP_WORDS:
                continue
            weight = info.vocab.get(text.concepts[k], 0.0)
            if weight <= 0 or _generic(text.concepts[k]):
                continue
            weight = 1.0 if text.stems[k] in _own_stems(info) else 0.6 * weight
            if best is None or weight > best[0]:
                best = (weight, k)
        if best is None or best[0] < 0.6:
            continue
        k = best[1]
        positive = not _negative_around(text, k)
        assert info.on is not None and info.off is not None
        goal[name] = info.on if positive else info.off
        claimed.add(k)


_GENERIC = frozenset(
    concept(w) for w in ("program", "time", "temperature", "level", "power", "size", "water")
)


def _generic(key: str) -> bool:
    return key in _GENERIC


def _own_stems(info: VarInfo) -> set[str]:
    words = _words(info.name) + (_words(info.var.label) if info.var.label else [])
    return {stem(w) for w in words if w not in STOP_WORDS}


def _negative_around(text: _Text, k: int) -> bool:
    for d in range(1, 4):
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


_START_WORDS = frozenset({"start", "begin", "started", "starting", "begins", "kick", "launch"})
_NOW_WORDS = ("right away", "straight away", "immediately", "start now", "it now", "now")
_ACTION_VERBS = frozenset(
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
        "run",
        "keep",
        "dehydrate",
        "broil",
        "toast",
        "bring",
        "make",
        "give",
    )
)


def _power_and_running(view: Model, text: _Text, goal: Goal) -> None:
    power = [n for n, i in view.infos.items() if i.role == "power"]
    for name in power:
        if _says_power_on(view, text):
            info = view.infos[name]
            goal[name] = info.on
    running = [n for n, i in view.infos.items() if i.role == "running"]
    if not running:
        return
    start = _says_start(view, text)
    if start is None:
        return
    key = next((v for v in goal if v in view.start_values), None)
    target = view.start_values.get(key) or view.start_values.get(None)
    if target is None:
        return
    name, value = target
    if start:
        goal[name] = value
    else:
        info = view.infos[name]
        goal[name] = info.off or build_domain(info.var).values[build_domain(info.var).initial]


def _says_power_on(view: Model, text: _Text) -> bool:
    for k, token in enumerate(text.tokens):
        if token.text not in ("turn", "switch", "power", "switched", "turned"):
            continue
        words = [text.word(k + d) for d in range(1, 5)]
        # "switch on" followed by a setting's name is that setting, not the power
        for d, word in enumerate(words):
            if word in ("on", "up"):
                between = words[:d]
                if all(concept(w) in view.appliance_words or w in ("the", "it") for w in between):
                    after = text.word(k + d + 2)
                    after_concept = concept(after) if after else ""
                    named = [
                        i
                        for i in view.infos.values()
                        if i.role != "power" and after_concept in i.vocab
                    ]
                    if between or not named or after in _CLAUSE_ENDS or after == ",":
                        if not between and named:
                            break
                        return True
                break
            if concept(word) not in view.appliance_words and word not in ("the", "it"):
                break
    return False


def _says_start(view: Model, text: _Text) -> bool | None:
    """True for "start it", False for "don't start", None when the instruction says neither."""
    joined = " ".join(t.text for t in text.tokens)
    negative = False
    positive = False
    for k, token in enumerate(text.tokens):
        word = token.text
        starts = word in _START_WORDS or (
            word in ("get", "set") and any(
                text.word(k + d) in ("going", "started", "cooking", "heating", "running")
                for d in range(1, 5)
            )
        ) or (word == "go" and text.word(k + 1) in ("ahead", ".", "!", ""))
        if word == "press" and text.word(k + 1) == "start":
            starts = True
        if not starts:
            continue
        before = [text.word(k - d) for d in range(1, 4)]
        if any(b in ("don't", "dont", "not", "without", "never") for b in before) or (
            text.word(k + 1) == "yet" or text.word(k - 1) == "but" and text.word(k + 1) == "not"
        ):
            negative = True
        else:
            positive = True
    if " not started" in joined or "but not start" in joined:
        negative = True
    if negative:
        return False
    if positive or any(f" {w} " in f" {joined} " for w in _NOW_WORDS[:3]):
        return True
    # "now" closing a clause, or an instruction that opens with a doing verb
    for k, token in enumerate(text.tokens):
        if token.text == "now" and text.word(k - 1) != "from" and text.word(k + 1) != "on":
            return True
    for k in _clause_starts(text):
        k2 = k + 1 if text.word(k) in ("just", "please", "then", "now") else k
        if text.stems[k2] in _ACTION_VERBS if k2 < len(text.stems) else False:
            return True
    return None


def _clause_starts(text: _Text) -> list[int]:
    starts = [0]
    for k, token in enumerate(text.tokens):
        if token.text in (".", ";", "!", "?") and k + 1 < len(text.tokens):
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


def _unused(*_: object) -> None:
    return None


_ = (math, _unused)
