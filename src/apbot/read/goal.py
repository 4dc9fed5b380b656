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

import re
from dataclasses import dataclass
from typing import Any

from apbot.model.domain import ValueProblem, normalise
from apbot.model.schema import (
    ApplianceModel,
    DiscreteVariable,
    NumericVariable,
    TimeVariable,
)
from apbot.model.values import closest_matches, format_hms, preview, unit_of
from apbot.read.goal_start import (
    boil,
    entry_switches,
    no_values,
    power_and_running,
    switches,
    zero_settings,
)
from apbot.read.goal_text import (
    CLAUSE_ENDS,
    CONNECTORS,
    NUMBER_WORDS,
    Text,
    near_vocab,
    negated_before,
    phrase_here,
    turned_off_after,
    verb_positions,
)
from apbot.read.goal_twins import find_twins, place_twins
from apbot.read.goal_view import (
    PARTIAL,
    Goal,
    Model,
    VarInfo,
    domain_values,
    generic,
    magnitude,
    model_view,
    numeric_values,
    own_stems,
    parse_quantity,
    quantity_dimensions,
    unit_text,
)
from apbot.read.goal_vocab import (
    HIGHEST,
    LOWEST,
    SCALES,
    STOP_WORDS,
    SYNONYMS,
    concept,
    similar,
    stem,
)
from apbot.read.numbers import COUNT_NOUNS, Mention, find_mentions, tokenize


class GoalParseError(ValueError):
    """The instruction asks for something the model cannot do.

    ``words`` quotes the instruction's words at fault; ``reason`` says why (no such value, out
    of range, and what the model offers instead).
    """

    def __init__(self, words: str, reason: str) -> None:
        self.words = words
        self.reason = reason
        self.setting: str | None = None  # the setting it would go to, when there is one
        self.asked: Any = None  # the value as said, in that setting's terms
        super().__init__(f"{words!r}: {reason}")


MAX_INSTRUCTION = 5_000
"""Characters of one instruction; a longer text is not something a user said to an appliance."""


@dataclass
class _Match:
    var: str
    value: Any
    start: int
    end: int
    score: float


def parse_instruction(
    model: ApplianceModel,
    instruction: str,
    manual: str = "",
    outside: list[str] | None = None,
) -> Goal:
    """The goal an instruction asks for, over ``model``'s variables, values canonical.

    ``manual``, when given, names the values the panel shows only as codes ("2" is the French
    loaf; :mod:`apbot.read.goal_manual`). Raises :class:`GoalParseError` when the instruction
    asks for a value the model lacks — unless ``outside`` is given: then a quantity the model
    has no value for is still given to the setting of its kind the words name, as said (a
    belief read from a manual may lack the value the appliance has, and the closed loop looks
    for it), and the reason it would have been refused is appended to ``outside``.

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
    view = model_view(model, manual or "")
    text = Text.of(_joined_compounds(view, str(instruction)))
    goal: Goal = {}
    claimed: set[int] = set()
    where: dict[str, int] = {}  # the token each setting was read from
    for match in _value_matches(view, text):
        if match.var in goal or any(k in claimed for k in range(match.start, match.end)):
            continue
        goal[match.var] = match.value
        where[match.var] = match.start
        claimed.update(range(match.start, match.end))
    _restated_codes(view, text, goal, claimed)
    _pronoun_ones(text, claimed)
    mentions = _distinct(find_mentions(text.tokens, skip=claimed))
    counting = _assign_mentions(view, text, mentions, goal, claimed, where, outside)
    _superlatives(view, text, goal, claimed, where)
    zero_settings(view, text, goal, claimed, where)
    no_values(view, text, goal, claimed)
    switches(view, text, goal, claimed, where)
    place_twins(view, text, goal, where)
    entry_switches(view, goal)
    boil(view, text, goal)
    power_and_running(view, text, goal, counting)
    try:
        _unknown_values(view, text, goal, claimed)
    except GoalParseError as exc:
        if outside is None:
            raise
        outside.append(str(exc))
    return _checked(view, goal, outside)


_KIND_WORDS = frozenset(
    stem(w) for w in ("programme", "program", "mode", "cycle", "menu", "course", "function")
)


def _unknown_values(view: Model, text: Text, goal: Goal, claimed: set[int]) -> None:
    """ "the turbo programme" on a model without TURBO: a value name the model lacks is an
    error, not a silent omission. Only the word right before a programme-kind word counts,
    and only when no value of that kind was found."""
    for k in range(1, len(text.tokens)):
        if text.stems[k] not in _KIND_WORDS or k - 1 in claimed:
            continue
        word = text.word(k - 1)
        if not word.isalpha() or word in STOP_WORDS or word in _ORDINARY:
            continue
        key = text.concepts[k]
        kinds = [
            info
            for info in view.infos.values()
            if isinstance(info.var, DiscreteVariable)
            and info.role == "setting"
            and info.vocab.get(key, 0.0) >= 0.8
        ]
        if not kinds or any(info.name in goal for info in kinds):
            continue
        here = text.stems[k - 1]
        if any(
            text.concepts[k - 1] in info.vocab
            or any(
                len(key) >= 3 and (here.startswith(key) or key.startswith(here))
                for key in info.vocab
            )
            for info in view.infos.values()
        ):
            continue  # "temperature mode", "automatic programme": a setting's own word
        info = kinds[0]
        names = [str(v) for v in info.values]
        close = closest_matches(word, names, limit=1)
        hint = f"; did you mean {close[0]!r}?" if close else ""
        raise GoalParseError(
            text.span(k - 1, k + 1),
            f"{info.name} has no {word!r}; it can be {preview(names, quote=False)}{hint}",
        )


_ORDINARY = frozenset(
    {
        "this",
        "that",
        "my",
        "your",
        "its",
        "their",
        "same",
        "usual",
        "whole",
        "full",
        "any",
        "normal",
        "standard",
        "default",
        "next",
        "other",
        "another",
        "each",
        "every",
        "one",
        "first",
        "second",
        "last",
        "right",
        "correct",
        "wrong",
        "entire",
        "complete",
        "new",
    }
)


def _value_matches(view: Model, text: Text) -> list[_Match]:
    matches: list[_Match] = []
    n = len(text.tokens)
    verbs = verb_positions(text)
    itself = {stem(w) for w in re.findall(r"[a-z]+", _appliance_name(view))}
    running = {stem(n) for n, info in view.infos.items() if info.role == "running"}
    for var, value, stems, weight in view.phrases:
        info = view.infos[var]
        for i in range(n):
            found = _match_at(text, i, stems)
            if found is None:
                continue
            end, quality = found
            if negated_before(text, i) or turned_off_after(text, end):
                continue
            if text.word(i - 1) in ("stay", "stays", "remain", "remains"):
                continue  # "so the bottles stay dry": a state of the load, not the DRY cycle
            if quality < 1.0 and text.stems[end - 1] in itself and i not in verbs:
                continue  # "turn on the air fryer": the appliance, not its AIR FRY programme
            if text.word(end) == "-" and text.word(end + 1) in ("off", "on"):
                continue  # "auto-off" names a timer, not the AUTO mode
            own = near_vocab(info, text, i, end, reach=2)
            opening = i == 0 or text.word(i - 1) in (".", ";", "!")
            if weight <= PARTIAL and not (own or (opening and text.word(end) in ("with", ","))):
                continue  # a first word alone names a value only beside "programme"
                # (or opening the sentence: "Auto with ExtraDry")
            if _names_other(view, var, text, i, end):
                continue  # "power level 8" is not the POWER mode
            if len(stems) == 1 and _names_switch(view, var, text, i):
                continue  # "switch the light on" is the LIGHT, not a light crust
            if len(stems) == 1 and _qualifies_other(view, var, text, end):
                continue  # "manual speed 3": the speed, in its manual kind
            if len(stems) == 1 and text.stems[i] in running and not own:
                continue  # "Brew six cups", "get it brewing": the operation, not a BREW mode
            if len(stems) == 1 and _names_setting(view, var, text, i):
                continue  # "low fan", "fan on quiet": the FAN setting, not the FAN mode
            score = len(stems) * weight * quality + 0.5 * own
            if i in verbs and len(stems) == 1:
                score *= 0.5  # "bake a French loaf": the verb is weaker than the noun
            matches.append(_Match(var, value, i, end, score))
    matches.sort(key=lambda m: (-m.score, m.start))
    return _prefer_heads(matches)


def _names_switch(view: Model, var: str, text: Text, i: int) -> bool:
    """The word at i is an on/off setting's own name, and nothing of ``var`` stands next to it."""
    if near_vocab(view.infos[var], text, i, i + 1, reach=2):
        return False
    for name, info in view.infos.items():
        own = own_stems(info)
        if name == var or info.role != "switch" or text.stems[i] not in own:
            continue
        said = text.word(i + 1) in ("on", "off") and text.word(i + 2) not in ("a", "an", "the")
        if said or phrase_here(text, i, own - {text.stems[i]}):
            return True  # "switch the light on" (not "AUTO on a half load")
    return False


def _qualifies_other(view: Model, var: str, text: Text, end: int) -> bool:
    """The value word stands right before another setting's own name, which a number or a
    superlative then sets ("manual speed 3", "the highest manual speed")."""
    if end >= len(text.tokens):
        return False
    others = [
        info
        for name, info in view.infos.items()
        if name != var and info.role == "setting" and text.stems[end] in own_stems(info)
    ]
    if not others:
        return False
    following = text.word(end + 1)
    before = text.word(end - 2)
    return following[:1].isdigit() or following in NUMBER_WORDS or before in LOWEST | HIGHEST


def _appliance_name(view: Model) -> str:
    appliance = view.model.appliance
    return f"{appliance.name} {appliance.category.replace('_', ' ')}".casefold()


def _names_setting(view: Model, var: str, text: Text, i: int) -> bool:
    """The word at i is another setting's own name and one of that setting's values stands
    right beside it ("low fan", "fan on quiet", "high fan")."""
    if near_vocab(view.infos[var], text, i, i + 1, reach=1):
        return False  # "fan mode": the mode's own word is next to it
    for name, info in view.infos.items():
        if name == var or info.role != "setting" or text.stems[i] not in own_stems(info):
            continue
        values = {stem(str(v)) for v in info.values if str(v).isalpha()}
        after = i + 2 if text.word(i + 1) in ("on", "at", "to") else i + 1
        after += 1 if text.word(after) in ("the", "a") else 0
        for j in (i - 1, i + 1, after):
            if 0 <= j < len(text.tokens) and text.stems[j] in values:
                return True  # "low fan", "fan on quiet", "the fan to the quiet speed"
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


def _names_other(view: Model, var: str, text: Text, i: int, end: int) -> bool:
    """The words i..end name another variable, and a number or more of that variable's words
    follow ("power level 8" sets the level, not the POWER mode)."""
    keys = [text.concepts[k] for k in range(i, end) if text.word(k) not in CONNECTORS]
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
    if (following[:1].isdigit() or following in NUMBER_WORDS) and text.word(
        k + 1
    ) not in COUNT_NOUNS:
        return True
    key = text.concepts[k] if k < len(text.concepts) else ""
    return any(info.vocab.get(key, 0.0) for info in others)


def _match_at(text: Text, i: int, stems: tuple[str, ...]) -> tuple[int, float] | None:
    """End and quality of the phrase ``stems`` matched from token i (connectors may sit
    between words; a synonym or a longer word that starts like the value counts less)."""
    k = i
    quality = 1.0
    for index, target in enumerate(stems):
        if index:
            while text.word(k) in CONNECTORS and k < len(text.tokens):
                k += 1
            if index == 1 and stems[0] in _SPLIT_VERBS and len(stems) == 2:
                # "keep the chili warm": KEEP WARM around its object
                gap = next(
                    (j for j in range(k, min(k + 4, len(text.tokens))) if text.stems[j] == target),
                    None,
                )
                k = gap if gap is not None else k
        if k >= len(text.tokens):
            return None
        here = text.stems[k]
        if here == target:
            pass
        elif text.word(k).endswith("ly") and len(text.word(k)) > 5:
            return None  # "automatically" says how, it does not name AUTO
        elif similar(here, target):
            quality = min(quality, 0.9)
        elif here in _SYNONYM_STEMS.get(target, ()):
            quality = min(quality, 0.8)
        elif (
            len(target) >= 4
            and here.startswith(target)
            and (len(here) <= len(target) + 4 or len(target) >= 5 or len(stems) > 1)
            and text.word(k) not in LOWEST | HIGHEST
        ):
            quality = min(quality, 0.8)  # "storage" for STORE, "convection bake" for CONV BAKE
        elif len(stems) == 1 and len(target) >= 5 and here.endswith(target):
            quality = min(quality, 0.7)  # "multigrain" for GRAINS
        elif len(target) >= 3 and here == target + "er":
            quality = min(quality, 0.8)  # "the air fryer" for AIR FRY
        elif len(stems) > 1 and len(here) >= 3 and target.startswith(here):
            quality = min(quality, 0.7)  # "frozen veg" for frozen vegetables
        else:
            return None
        k += 1
    return k, quality


_SPLIT_VERBS = frozenset({stem("keep")})


_SYNONYM_STEMS: dict[str, frozenset[str]] = {
    stem(word): frozenset(stem(w) for w in others) for word, others in SYNONYMS.items()
}


_HYPHEN_PAIR = re.compile(r"\b([A-Za-z]{2,})-([A-Za-z]{2,})\b")


def _joined_compounds(view: Model, instruction: str) -> str:
    """ "pre-infusion" for a PREINFUSION key: a hyphenated word the model writes as one."""
    words = {w for info in view.infos.values() for w in own_stems(info)}
    words |= {s for _var, _value, stems, _weight in view.phrases for s in stems}

    def join(match: re.Match[str]) -> str:
        whole = match[1] + match[2]
        return whole if stem(whole) in words else match[0]

    text = _HALF_POWER.sub("50% power", _HYPHEN_PAIR.sub(join, instruction))
    return _fractions(text)


_UNIT_WORDS = r"(litres?|liters?|kilos?|kg|pounds?|lbs?|cups?|hours?|minutes?)"
_HALF_A = re.compile(rf"\bhalf an? {_UNIT_WORDS}\b", re.IGNORECASE)
_A_AND_A_HALF = re.compile(rf"\ban? {_UNIT_WORDS} and a half\b", re.IGNORECASE)
_AND_PART = re.compile(
    rf"\b(\d+|[a-z]+) and (a half|a quarter|three[- ]quarters?) {_UNIT_WORDS}\b", re.IGNORECASE
)
_FRACTIONS = {"a half": 0.5, "a quarter": 0.25}


def _fractions(text: str) -> str:
    """ "half a litre", "a kilo and a half", "three and three-quarter hours" as decimals."""
    from apbot.model.values import NUMBER_WORDS as WORDS

    text = _HALF_A.sub(lambda m: f"0.5 {m[1]}", text)
    text = _A_AND_A_HALF.sub(
        lambda m: m[0] if m[1].lower().startswith(("hour", "minute")) else f"1.5 {m[1]}", text
    )

    def part(m: re.Match[str]) -> str:
        whole = float(m[1]) if m[1].isdigit() else WORDS.get(m[1].lower())
        if whole is None:
            return m[0]
        fraction = _FRACTIONS.get(m[2].lower(), 0.75)
        return f"{whole + fraction:g} {m[3]}"

    return _AND_PART.sub(part, text)


_HALF_POWER = re.compile(r"\bhalf[- ]power\b", re.IGNORECASE)


def _pronoun_ones(text: Text, claimed: set[int]) -> None:
    """ "on the rear one", "the big one": "one" after "the" and a word is a pronoun."""
    for k, token in enumerate(text.tokens):
        ends = CLAUSE_ENDS | {",", "and", "with", "at", "on", "to", ""}
        if token.text == "one" and text.word(k - 2) == "the" and text.word(k + 1) in ends:
            claimed.add(k)


def _restated_codes(view: Model, text: Text, goal: Goal, claimed: set[int]) -> None:
    """ "yogurt (menu 12)": the number beside the setting's word restates the value already
    read by name (its code); it is not another setting."""
    for k, token in enumerate(text.tokens):
        if k in claimed or not token.text.isdigit() or k == 0:
            continue
        key = text.concepts[k - 1]
        for name, value in goal.items():
            if view.infos[name].vocab.get(key, 0.0) < 0.8:
                continue
            code = _CODE.fullmatch(str(value)) or re.fullmatch(r"(\d+)", str(value))
            if code is not None and int(code[1]) == int(token.text):
                claimed.add(k)


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
    view: Model,
    text: Text,
    mentions: list[Mention],
    goal: Goal,
    claimed: set[int],
    where: dict[str, int],
    outside: list[str] | None = None,
) -> bool:
    """Give each quantity to the open setting it fits best. True when a delay was set relative
    to now ("ready in 15 hours", "3 hours from now"): a countdown that must be started."""
    counting = False
    options: list[tuple[float, int, int, str, Any]] = []
    for mi, mention in enumerate(mentions):
        for name, info in view.infos.items():
            if name in goal or info.role in ("power", "running", "switch"):
                continue
            value = _fit(view, info, mention, goal)
            if value is None:
                continue
            score = near_vocab(info, text, mention.start, mention.end)
            if info.timing in ("clock", "finish") and not near_vocab(
                info, text, mention.start, mention.end, reach=12
            ):
                named = info.timing == "clock" and concept("clock") in text.concepts
                if not (named and mention.kind == "clock"):
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
        where[name] = mention.start
        used.add(mi)
        claimed.update(range(mention.start, mention.end))
        if view.infos[name].timing == "delay" and _relative(text, mention):
            counting = True
    for mi, mention in enumerate(mentions):
        if mi not in used and mention.kind == "clock" and _clock_parts(view, text, mention, goal):
            used.add(mi)
    for mi, mention in enumerate(mentions):
        if mi not in used:
            try:
                _unplaced(view, text, mention, goal)
            except GoalParseError as exc:
                if outside is None or exc.setting is None:
                    raise
                goal[exc.setting] = exc.asked  # as said: the appliance may have it
                where[exc.setting] = mention.start
                outside.append(str(exc))
    return counting


def _clock_parts(view: Model, text: Text, mention: Mention, goal: Goal) -> bool:
    """A time of day kept as two settings, an hour and a minute (a clock, an auto-start time):
    set both from one time, on the pair the words around it name."""
    pairs: dict[str, dict[str, VarInfo]] = {}
    for info in view.infos.values():
        if info.role != "setting" or info.name in goal:
            continue
        words = [w for w in info.name.casefold().split("_") if w]
        part = next((p for p, names in _PARTS.items() if names & set(words)), None)
        if part is None:
            continue
        rest = "_".join(w for w in words if w not in _PARTS[part])
        pairs.setdefault(rest, {})[part] = info
    options = []
    for parts in pairs.values():
        if len(parts) != 2:
            continue
        score = sum(near_vocab(i, text, mention.start, mention.end) for i in parts.values())
        clock = stem("clock") in own_stems(parts["hour"])
        if clock and score <= 0 and concept("clock") in text.concepts:
            score = 0.1  # "The clock is off — set it to 13:15"
        if clock and score <= 0:
            continue  # a time of day sets the clock only when the clock is named
        options.append((score, not clock, parts))
    if not options:
        return False
    parts = max(options, key=lambda o: (o[0], o[1]))[2]
    hour, minute = divmod(int(mention.value) // 60, 60)
    values = {}
    for part, number in (("hour", hour), ("minute", minute)):
        domain = domain_values(view, parts[part], goal)
        if part == "hour" and not _has_number(domain, number) and number > 12:
            number -= 12
        found = next((v for v in domain if _as_int(v) == number), None)
        if found is None:
            return False
        values[parts[part].name] = found
    goal.update(values)
    return True


_PARTS = {"hour": {"hour", "hours", "hr", "h"}, "minute": {"minute", "minutes", "min", "m"}}


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


def _relative(text: Text, mention: Mention) -> bool:
    """A duration counted from now: "in 8 hours", "5 h from now", "starting in 2 hours"."""
    before = text.word(mention.start - 1)
    after = " ".join(text.word(mention.end + d) for d in range(2))
    return before in ("in", "within") or after == "from now"


def _cue_bonus(info: VarInfo, text: Text, mention: Mention) -> float:
    """Relative times prefer delays, "for" a duration, clock times clocks; units fit units."""
    before = text.word(mention.start - 1)
    before2 = text.word(mention.start - 2)
    bonus = 0.0
    if mention.kind == "duration":
        relative = _relative(text, mention) or before2 in ("delay", "delayed", "wait")
        relative = relative or before in ("delay", "delayed", "wait")
        if info.timing == "delay":
            bonus += 0.9 if relative else -0.3
        elif relative:
            bonus -= 0.3
    if mention.dimension and mention.dimension == info.dimension:
        bonus += 0.3
    main = {"time", "cook", "cooking", "duration"} & set(info.name.split("_"))
    if mention.kind == "duration" and info.timing == "duration" and main:
        bonus += 0.1  # a duration no word claims goes to the cooking time, not QUICK MIN's
    if mention.kind == "duration" and info.turns is not None:
        said = _turning(text, mention.start)
        if said is not None:
            bonus += 1.0 if said == info.turns else -1.0
    return bonus


_TURN_VERBS = frozenset(
    {"switch", "turn", "come", "switching", "turning", "coming", "comes", "switches", "turns"}
)


def _turning(text: Text, start: int) -> str | None:
    """ "switch off after 2 hours", "an off-timer of 10 hours", "come on in 7.5 hours": which
    way the appliance turns when the duration ends (None when the words do not say)."""
    for k in range(start - 1, max(-1, start - 7), -1):
        word = text.word(k)
        if word in CLAUSE_ENDS or word == ",":
            break
        if word == "off":
            return "off"
        if word == "on" and text.word(k - 1) in _TURN_VERBS | {"itself", "it"}:
            return "on"
    return None


def _fit(view: Model, info: VarInfo, mention: Mention, goal: Goal) -> Any:
    """The canonical value a mention gives this variable, or None when it does not fit."""
    counted = mention.kind == "number" and mention.unit
    if counted and concept(mention.unit) not in info.vocab and not _COUNTING & set(info.vocab):
        return None  # "two slices" counts slices: only a quantity setting takes it
    domain = domain_values(view, info, goal)
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
        unit = unit_text(var)
        number = _number_for(info, unit, mention)
        if number is None:
            return _percent_of_level(info, mention, domain)
        fahrenheit_dial = unit.casefold() in ("°f", "f")
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
    return (
        _coded(domain, mention)
        or _show_quantity(info, mention)
        or _named_quantity(view, info, mention, domain)
    )


_CODE = re.compile(r"[A-Za-z]{1,2}[- ]?(\d+)")


def _coded(domain: list[Any], mention: Mention) -> Any:
    """ "programme 5" for a value written P5, "menu 6" for A-6: a short prefix and the number."""
    if mention.kind != "number" or mention.value != int(mention.value):
        return None
    found = [v for v in domain if (m := _CODE.fullmatch(str(v))) and int(m[1]) == mention.value]
    return found[0] if len(found) == 1 else None


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


_COUNTING = frozenset(
    concept(w) for w in ("quantity", "qty", "count", "number", "servings", "pieces", "portions")
)


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


def _named_quantity(view: Model, info: VarInfo, mention: Mention, domain: list[Any]) -> Any:
    """A coded value the manual gives as this quantity ("60 %" for knob mark 2)."""
    for value, text in view.named_quantities.get(info.name, []):
        for m in find_mentions(tokenize(text)):
            same = m.dimension == mention.dimension and m.kind == mention.kind
            if same and abs(m.value - mention.value) < 1e-6 and value in domain:
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


def _clock_for_a_delay(view: Model, text: Text, mention: Mention, goal: Goal) -> None:
    """ "finish by 7 am" where the model only counts hours from now: say so, do not guess."""
    for info in view.infos.values():
        if info.role != "setting" or info.timing != "delay" or info.name in goal:
            continue
        if near_vocab(info, text, mention.start, mention.end) >= 0.5:
            raise GoalParseError(
                text.span(mention.start, mention.end),
                f"{info.name} is a time from now, not a time of day; give it as 'in N hours'",
            )


def _unplaced(view: Model, text: Text, mention: Mention, goal: Goal) -> None:
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
    if not kinds and mention.kind == "clock":
        _clock_for_a_delay(view, text, mention, goal)
    if not kinds:
        return
    closeness = {n: near_vocab(view.infos[n], text, mention.start, mention.end) for n in kinds}
    near = max(kinds, key=lambda n: closeness[n])
    if mention.kind == "clock" and closeness[near] < 0.5:
        return  # a time of day said in passing ("a 3 a.m. feed")
    if any(name in goal for name in kinds) and (near in goal or closeness[near] < 0.5):
        return  # another setting of its kind was given; this may be a remark
    info = view.infos[near]
    values = domain_values(view, info, goal)
    parent = info.var.depends_on
    if not values and parent:
        reason = f"{near} does not apply when {parent} is {goal.get(parent)!r}"
    else:
        where = f" when {parent} is {goal[parent]!r}" if parent and parent in goal else ""
        reason = f"no setting of this model takes it; {near} can be {preview(values, quote=False)}"
        reason += where
    error = GoalParseError(text.span(mention.start, mention.end), reason)
    error.setting, error.asked = near, _as_said(info, mention)
    if error.asked is None:
        error.setting = None
    raise error


def _as_said(info: VarInfo, mention: Mention) -> Any:
    """The quantity as the user said it, in the setting's own terms (None: no such terms)."""
    var = info.var
    if isinstance(var, TimeVariable) and mention.kind in ("duration", "clock"):
        return format_hms(round(mention.value))
    if isinstance(var, NumericVariable):
        number = _number_for(info, unit_text(var), mention)
        if number is not None:
            return int(number) if float(number).is_integer() else round(number, 3)
    return None


def _superlatives(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int]
) -> None:
    """ "the lowest temperature", "full power", "a dark crust" on an ordered numeric setting."""
    marks = {m for twins in find_twins(view.model) for m in twins.marks.values()}
    for k, token in enumerate(text.tokens):
        word = token.text
        if k in claimed or word in marks:
            continue  # "the top zone" on an oven with a top and a bottom
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
        if end is not None and _names_set(view, text, k, goal):
            continue  # "the lowest humidity setting, 40%": said of a setting already read
        best: tuple[float, str] | None = None
        for name, info in view.infos.items():
            if name in goal or info.role != "setting" or not _ordered(info):
                continue
            values = domain_values(view, info, goal)
            if scale_index is not None and end is None and len(values) != scale_index[1]:
                continue
            score = near_vocab(info, text, k, k + 1, reach=4)
            if score > 0 and (best is None or score > best[0]):
                best = (score, name)
        if best is None:
            continue
        name = best[1]
        values = _ordered_values(domain_values(view, view.infos[name], goal))
        if not values:
            continue
        if end == 0 and len(values) > 2 and _is_off_level(view.infos[name], values[0]):
            goal[name] = values[1]  # "the lowest level": the lowest one that works, not off
        elif end is not None:
            goal[name] = values[end]
        elif scale_index is not None:
            goal[name] = values[scale_index[0]]
        where[name] = k
        claimed.add(k)


def _names_set(view: Model, text: Text, k: int, goal: Goal) -> bool:
    """The word after the superlative names (not generically) a setting the goal already has."""
    for j in (k + 1, k + 2):
        key = text.concepts[j] if j < len(text.concepts) else ""
        if key and not generic(key) and any(view.infos[n].vocab.get(key, 0.0) >= 0.8 for n in goal):
            return True
    return False


def _is_off_level(info: VarInfo, lowest: Any) -> bool:
    """A power or level setting whose lowest value, 0, is off rather than a level."""
    return (
        isinstance(info.var, NumericVariable)
        and info.dimension in (None, "power")
        and bool({concept("power"), concept("level")} & set(info.vocab))
        and magnitude(lowest) == 0
    )


def _ordered(info: VarInfo) -> bool:
    return isinstance(info.var, NumericVariable | TimeVariable) or (
        isinstance(info.var, DiscreteVariable)
        and (
            numeric_values(info.values)
            or bool(quantity_dimensions(info.values))
            or len(_scaled(info.values)) >= 2
        )
    )


def _scaled(values: list[Any]) -> list[Any]:
    """Values that are words of one scale ("low", "medium", "high"), in the scale's order."""
    for scale in SCALES:
        found = [v for v in values if str(v).casefold() in scale]
        if len(found) >= 2:
            return sorted(found, key=lambda v: scale.index(str(v).casefold()))
    return []


def _ordered_values(values: list[Any]) -> list[Any]:
    """Values in order of size: numbers and times as they are; of a discrete list, the ones
    that are quantities ("100 W" < "450 W"), by size, or the words of a scale (low < high)."""
    if all(isinstance(v, int | float) for v in values) or all(
        str(v).count(":") == 2 for v in values
    ):
        return values
    sized = [(q[0], v) for v in values if (q := parse_quantity(str(v))) is not None]
    if len(sized) < 2 and _scaled(values):
        return _scaled(values)
    return [v for _size, v in sorted(sized, key=lambda pair: pair[0])]


def _checked(view: Model, goal: Goal, outside: list[str] | None = None) -> Goal:
    """Normalise every value against its variable (the programme's case for a setting); with
    ``outside``, a value the variable lacks is kept as said and noted."""
    out: Goal = {}
    for name, value in goal.items():
        info = view.infos[name]
        try:
            out[name] = normalise(info.var, value)
        except ValueProblem as exc:
            problem = GoalParseError(str(value), f"not a value of {name}: {exc}")
            if outside is None:
                raise problem from None
            out[name] = value
            if not any(f" {name} can be" in note for note in outside):
                outside.append(str(problem))
    return out
