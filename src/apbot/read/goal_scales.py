"""Superlatives and scales: "the lowest temperature", "full power", "a dark crust" on an
ordered setting."""

from __future__ import annotations

import re
from typing import Any

from apbot.model.schema import DiscreteVariable, TimeVariable
from apbot.read.goal_degree_stems import superlative_stem_setting
from apbot.read.goal_ladders import (
    is_off_level,
    ladder,
    levels,
    numbered_levels,
    ordered,
    ordered_values,
    worded_levels,
)
from apbot.read.goal_text import CLAUSE_ENDS, Text, near_vocab, said_before
from apbot.read.goal_twins import find_twins
from apbot.read.goal_unit_cases import unit_selector
from apbot.read.goal_values import (
    generic,
    zone_case,
)
from apbot.read.goal_view import Goal, Model, VarInfo, domain_values, own_concepts
from apbot.read.goal_vocab import HIGHEST, LOWEST, SCALES, concept, stem


def superlatives(
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
        reach = 4
        compared = _as_as(text, k)
        if end is None and compared is not None:
            end, reach = compared
        if end is None and _own_superlative(view, goal, word) is not None:
            end = -1  # "the thickest setting" on THICK ▲ / ▼, "the brightest" for BRIGHTNESS
        if end is None and _superlative_before_name(view, text, k, goal):
            end, reach = -1, 1  # "the brightest backlight": the most of the setting named
        if end is None and word in _SPANS and _degree_before_name(view, text, k, goal):
            end, reach = _SPANS[word], 2  # "the wide pitch range": the widest of its spans
        if end is None and _little_of(view, text, k, goal):
            end, reach = 0, 2  # "with just a little water": the least of it that works
        scale_index = None
        for scale in SCALES:
            said = "medium" if word in ("middle", "mid", "med") else word
            if said in scale:
                scale_index = (scale.index(said), len(scale))
        if end is None and scale_index is None:
            continue
        if _denied(text, k):
            continue  # "not the hottest water": no end of the scale is asked for
        if end is not None and k + 1 in claimed:
            continue  # "full boost": said of the value read from the next word, no end
        if end is not None and _restates(text, k):
            continue  # "at the maximum of 75 °C": the quantity says it, for its own setting
        if end is not None and _names_set(view, text, k, goal):
            continue  # "the lowest humidity setting, 40%": said of a setting already read
        best: tuple[float, str] | None = None
        for name, info in view.infos.items():
            if name in goal or info.role != "setting" or not ordered(info):
                continue
            if info.timing == "clock":
                continue  # "the hottest day": the time of day now is no scale to pick an end of
            values = domain_values(view, info, goal)
            if scale_index is not None and end is None and len(levels(values)) != scale_index[1]:
                continue  # "a medium massage" of OFF, 1, 2, 3: medium of the three levels
            score = near_vocab(info, text, k, k + 1, reach=reach) or _after_its_case(
                info, text, k, goal
            )
            if ladder(info.values) and not _beside(info, text, k, reach):
                continue  # named levels are a weak order: only "the most steam" says it
            if score > 0 and _made_of_its_word(info, word):
                score += 0.5  # "the widest pulse": PULSE WIDTH, not PULSE RATE
            if score > 0 and (best is None or score > best[0]):
                best = (score, name)
        own = _own_superlative(view, goal, word)
        if own is not None and best is None:
            best = (0.0, own)
        if best is None and end is not None:
            stemmed = superlative_stem_setting(text, k, _open_ordered(view, goal))
            best = (0.0, stemmed) if stemmed else None
        kind = _kind_of(text, k) if end is not None else None
        if kind and (best is None or not _named_specifically(view.infos[best[1]], text, k)):
            only = _only_of_kind(view, goal, kind)
            if (
                only is not None
                and _of_a_setting(view.infos[only[1]], text, k)
                and (kind not in ("level", "speed") or not _names_another(view, only[1], text, k))
            ):
                best = only
        if best is None:
            continue
        name = best[1]
        values = ordered_values(_scale_domain(view, view.infos[name], goal))
        if not values:
            continue
        top = view.top_codes.get(name)
        if end == -1 and top is not None and top not in values:
            values = [*values, top]  # "full": the hob's P, one step past 9
        off_first = (len(values) > 2 and is_off_level(view.infos[name], values[0])) or (
            len(values) > 1 and bool(ladder(values))
        )
        if end == 0 and off_first:
            goal[name] = values[1]  # "the lowest level": the lowest one that works, not off
        elif end is not None:
            goal[name] = values[end]
        elif scale_index is not None:
            goal[name] = levels(values)[scale_index[0]]
        where[name] = k
        claimed.add(k)


def _open_ordered(view: Model, goal: Goal) -> dict[str, dict[str, float]]:
    return {
        name: info.vocab
        for name, info in view.infos.items()
        if name not in goal and info.role == "setting" and ordered(info)
    }


def _made_of_its_word(info: VarInfo, word: str) -> bool:
    """The superlative is made of a word of the setting's own ("widest" of WIDTH)."""
    if not word.endswith("est") or len(word) < 6:
        return False
    base = word[:-3]
    return bool({concept(base), concept(base + "e")} & own_concepts(info))


def _own_superlative(view: Model, goal: Goal, word: str) -> str | None:
    """The one open ordered setting a superlative is made of the setting's own word for
    ("thickest" of a THICK ▲ / ▼ thickness, "brightest" of BRIGHTNESS): the most of it."""
    if not word.endswith("est") or word in LOWEST or word in HIGHEST or len(word) < 6:
        return None
    base = word[:-3]
    if len(base) > 3 and base[-1] == base[-2]:
        base = base[:-1]  # "hottest": hot
    bases = {base, base[:-1] + "y" if base.endswith("i") else base}  # "heaviest": heavy
    found = [
        name
        for name, info in view.infos.items()
        if name not in goal
        and info.role == "setting"
        and ordered(info)
        and any(w in bases or w in {f"{b}ness" for b in bases} for w in _own_words(info))
    ]
    return found[0] if len(found) == 1 else None


def _superlative_before_name(view: Model, text: Text, k: int, goal: Goal) -> bool:
    """A superlative adjective ("brightest", "deepest"; seven letters or more, so no "best",
    "rest") right before an open ordered setting's own name asks for the most of it: an
    adjective of degree before the thing it grades. The least is said with LOWEST's words."""
    word = text.word(k)
    if len(word) < 7 or not word.endswith("est") or not word.isalpha() or word in LOWEST:
        return False
    after = text.concepts[k + 1] if k + 1 < len(text.tokens) else ""
    return any(
        name not in goal
        and info.role == "setting"
        and ordered(info)
        and after in own_concepts(info)
        for name, info in view.infos.items()
    )


_SPANS = {"wide": -1, "broad": -1, "narrow": 0}
"""How wide a span is, said plainly of a setting that is a span (a pitch RANGE of ±8 / ±16)."""


def _degree_before_name(view: Model, text: Text, k: int, goal: Goal) -> bool:
    """The adjective stands right before (or one word before) an open ordered setting's own
    name: "the wide range", "a narrow pitch range" grade that setting."""
    after = {text.concepts[j] for j in (k + 1, k + 2) if j < len(text.tokens)}
    return any(
        name not in goal
        and info.role == "setting"
        and ordered(info)
        and bool(after & own_concepts(info))
        for name, info in view.infos.items()
    )


def _little_of(view: Model, text: Text, k: int, goal: Goal) -> bool:
    """ "a little water", "a bit of steam": an amount said as small, right before an open
    ordered setting's own name, is its least level (the lowest that works, not OFF)."""
    word, after = text.word(k), k + 1
    if word == "bit" and text.word(after) == "of":
        after += 1
    if word not in ("little", "bit") or text.word(k - 1) != "a" or after >= len(text.tokens):
        return False
    return any(
        name not in goal
        and info.role == "setting"
        and ordered(info)
        and text.concepts[after] in own_concepts(info)
        for name, info in view.infos.items()
    )


def _own_words(info: VarInfo) -> set[str]:
    """The setting's name's and label's words, and its keys' labels' (THICK ▲)."""
    words = set(re.findall(r"[a-z]+", f"{info.name} {info.var.label or ''}".casefold()))
    return words | {w for w, weight in info.vocab.items() if weight >= 0.8}


def _scale_domain(view: Model, info: VarInfo, goal: Goal) -> list[Any]:
    """The values an end of the scale is taken from: those of the case the goal puts the
    setting's mode in, or else of the case the panel starts in ("as hot as it goes" on a
    spa showing °C is 48 °C, not the 118 of its °F case). Only for a selector of units: the
    cases of another mode are what the user may pick ("as hot as it will go" past a safety
    stop)."""
    var = info.var
    parent = var.depends_on
    if parent and parent not in goal and var.cases and unit_selector(view, parent):
        mode = view.infos[parent].var
        start = getattr(mode, "initial", None)
        if start is None and isinstance(mode, DiscreteVariable) and mode.values:
            start = mode.values[0]
        case = var.cases.get(str(start))
        if case is not None:
            return domain_values(view, info, {**goal, parent: start})
    return domain_values(view, info, goal)


_MORE = frozenset({"much", "many", "high", "hot", "long", "strong", "fast", "big", "loud", "warm"})
_LESS = frozenset(
    {"little", "few", "low", "cool", "short", "weak", "slow", "small", "quiet", "cold"}
) | frozenset({"gentle", "soft", "mild"})
_KIND_OF_WORD = {
    **dict.fromkeys(("hottest", "warmest", "coldest", "coolest"), "temperature"),
    **dict.fromkeys(("hot", "warm", "cold", "cool"), "temperature"),
    **dict.fromkeys(("longest", "shortest", "long", "short"), "time"),
    **dict.fromkeys(("strongest", "weakest", "gentlest", "softest", "mildest"), "level"),
    **dict.fromkeys(("strong", "weak", "gentle", "soft", "mild"), "level"),
    **dict.fromkeys(("fastest", "slowest"), "speed"),  # "as fast as possible": in a hurry
}
"""The kind a superlative's own word measures; "level": a strength, counted in numbered
levels (an intensity 1-5, a massage OFF/1/2/3), whatever the setting is called; "speed": the
levels of a setting named for its speed (a SOFT START 1-2 is not how fast it runs)."""
_AS_AS_KINDS = frozenset(w for w, kind in _KIND_OF_WORD.items() if not w.endswith("est"))


def _kind_of(text: Text, k: int) -> str | None:
    """The kind of quantity a superlative's own word measures ("the hottest" a temperature,
    "as long as it allows" a duration), whatever setting it is said of."""
    word = text.word(k)
    if word in _AS_AS_KINDS:
        if text.word(k - 1) != "as" or text.word(k + 1) != "as":
            return None  # "a long wash", "hot water": no end of a scale
        if not _its_limit(text, k + 2):
            return None  # "as long as I'm away" is a while, not the appliance's limit
    return _KIND_OF_WORD.get(word)


_ITS_LIMIT = frozenset({"possible", "allowed", "permitted"})
# what the appliance itself may do at its limit: "as long as it allows", "as cool as it will go"
_LIMIT_VERBS = frozenset(
    {"will", "'ll", "can", "could", "may", "would", "allows", "allow", "lets", "let", "permits"}
) | frozenset({"goes", "go", "gets", "get", "does", "do", "is"})
# what may follow the limit in its clause: "as cool as it will go FOR the cuttings"
_AFTER_LIMIT = frozenset({"for", "with", "to", "on", "please", "and", "then", "but", "in", "at"})


def _its_limit(text: Text, j: int) -> bool:
    """ "as long as it allows", "as possible": the comparison is closed by the appliance's own
    limit, not by the user's wish ("as warm as you like") nor by the weather ("as cold as it
    gets out there"): after "it"/"they" only a verb of what it can do, up to the clause end."""
    if text.word(j) in _ITS_LIMIT:
        return True
    if text.word(j) not in ("it", "they"):
        return False
    seen = False
    for i in range(j + 1, len(text.tokens)):
        word = text.word(i)
        if word in CLAUSE_ENDS or word in (",", "-") or (seen and word in _AFTER_LIMIT):
            return seen
        if word not in _LIMIT_VERBS:
            return False
        seen = True
    return seen


_DENIALS = frozenset({"not", "never", "don't", "dont", "no", "nothing"})


def _denied(text: Text, k: int) -> bool:
    """ "not the hottest water", "never the longest": a superlative its clause denies."""
    for i in range(k - 1, max(-1, k - 4), -1):
        word = text.word(i)
        if word in CLAUSE_ENDS or word == ",":
            return False
        if word in _DENIALS or word.endswith("n't"):
            return True
    return False


# words that make a superlative said of a setting ("the warmest SETTING", "the lowest LEVEL")
_OF_SETTING = frozenset(
    concept(w)
    for w in ("setting", "settings", "level", "temperature", "heat", "one", "position", "mode")
)


def _of_a_setting(info: VarInfo, text: Text, k: int) -> bool:
    """A superlative of a kind ("warmest", "as long as it allows") is said of the setting when
    its own words or "setting"/"level" follow it, when "as ... as" closes it with the
    appliance's limit, or at "its hottest"; "the coldest night", "warmest in the afternoon" are
    the weather's."""
    if text.word(k - 1) == "as":
        return True  # _kind_of has checked the limit that closes it
    j = k + 2 if text.word(k + 1) in ("possible", "available", "allowed") else k + 1
    key = text.concepts[j] if j < len(text.concepts) else ""  # "the longest possible soak"
    if key in _OF_SETTING or (key and info.vocab.get(key, 0.0) > 0):
        return True
    after = text.word(k + 1)
    return text.word(k - 1) == "its" and (after in CLAUSE_ENDS or after in (",", ""))


def _named_specifically(info: VarInfo, text: Text, k: int) -> bool:
    """A word of the setting's own stands near the superlative, not only "setting" or "level"
    ("the warmest setting" names no LEVEL; "the hottest temperature" names TEMP)."""
    for j in range(max(0, k - 4), min(len(text.tokens), k + 5)):
        key = text.concepts[j]
        if j != k and info.vocab.get(key, 0.0) > 0 and not generic(key):
            return True
    return False


def _only_of_kind(view: Model, goal: Goal, kind: str) -> tuple[float, str] | None:
    """ "on its warmest setting", "poach them as long as it allows": a superlative of a
    temperature or a duration that names no setting is said of the one setting of that kind
    still open (none when two could be meant: a clock and a timer are not both durations)."""
    found = [
        name
        for name, info in view.infos.items()
        if name not in goal
        and info.role == "setting"
        and ordered(info)
        and domain_values(view, info, goal)
        and (
            info.dimension == kind
            or (kind == "temperature" and info.dimension == "fahrenheit")
            or (kind == "time" and isinstance(info.var, TimeVariable) and info.timing == "duration")
            or (kind == "level" and (numbered_levels(info) or worded_levels(info)))
            or (kind == "speed" and concept("speed") in own_concepts(info))
        )
    ]
    return (0.0, found[0]) if len(found) == 1 else None


def _names_another(view: Model, name: str, text: Text, k: int) -> bool:
    """ "the gentlest cycle", "the strongest programme": the word after the superlative names
    another setting (a choice of programmes), so no numbered level is meant."""
    key = text.concepts[k + 1] if k + 1 < len(text.concepts) else ""
    return bool(key) and any(
        key in own_concepts(info) for other, info in view.infos.items() if other != name
    )


_AMOUNTS = frozenset({"much", "many", "little", "few"})


def _as_as(text: Text, k: int) -> tuple[int, int] | None:
    """ "as much steam as it can give", "the fan as low as it goes": an end of the scale (-1
    the top, 0 the bottom) when a second "as" closes the comparison, and how far the setting's
    words may stand (between the two for "much": "as much as it allows" names nothing)."""
    word = text.word(k)
    if text.word(k - 1) != "as" or word not in _MORE | _LESS:
        return None
    for j in range(k + 1, min(k + 5, len(text.tokens))):
        if text.word(j) in CLAUSE_ENDS or text.word(j) == ",":
            return None
        if text.word(j) == "as":
            end = -1 if word in _MORE else 0
            return end, (j - k - 1 if word in _AMOUNTS else 2)
    return None


def at_its_limit(text: Text, k: int) -> bool:
    """ "as strong as it goes", "as hot as possible": the word at ``k`` is compared with the
    appliance's own limit, so it asks for an end of a scale, not for a value the word names
    (a heat's HIGH that "strong" stands for)."""
    if text.word(k - 1) != "as" or text.word(k) not in _MORE | _LESS:
        return False
    for j in range(k + 1, min(k + 5, len(text.tokens))):
        if text.word(j) in CLAUSE_ENDS or text.word(j) == ",":
            return False
        if text.word(j) == "as":
            return _its_limit(text, j + 1)
    return False


def _restates(text: Text, k: int) -> bool:
    """ "the maximum of 75 °C", "its lowest, 40 %": a number right after the superlative."""
    j = k + 1
    if text.word(j) in ("of", ",", ":", "-", "("):
        j += 1
    return text.word(j)[:1].isdigit()


def _beside(info: VarInfo, text: Text, k: int, reach: int) -> bool:
    """The setting's own word follows the superlative closely ("maximum steam", "as much
    steam as"), not a word of it somewhere around ("the full load, with steam")."""
    if text.word(k) in ("full", "top"):
        return False
    ahead = range(k + 1, min(k + 1 + min(reach, 2), len(text.tokens)))
    return any(info.vocab.get(text.concepts[j], 0.0) >= 0.8 for j in ahead)


def _names_set(view: Model, text: Text, k: int, goal: Goal) -> bool:
    """The word after the superlative names (not generically) a setting the goal already has."""
    pair = [text.concepts[j] for j in (k + 1, k + 2) if j < len(text.concepts)]
    if len(pair) == 2 and not any(generic(c) for c in pair):
        both = [n for n, i in view.infos.items() if all(i.vocab.get(c, 0.0) >= 0.8 for c in pair)]
        if both and not any(n in goal for n in both):
            return False  # "the narrow pitch range" beside a PITCH read: the PITCH RANGE's
    for j in (k + 1, k + 2):
        key = text.concepts[j] if j < len(text.concepts) else ""
        if key and not generic(key) and any(view.infos[n].vocab.get(key, 0.0) >= 0.8 for n in goal):
            return True
        if (
            key
            and not generic(key)
            and any(
                info.vocab.get(key, 0.0) >= 0.8 for n, info in view.infos.items() if n not in goal
            )
        ):
            return False  # "the lightest crust ready in 12 hours": CRUST's, said with no comma
    return False


def _after_its_case(info: VarInfo, text: Text, k: int, goal: Goal) -> float:
    """ "the foot zone on maximum": a superlative right after a value of the setting this one
    depends on (each zone keeps its own level) is said of this setting."""
    case = zone_case(info.var)
    if not case or case not in goal:
        return 0.0
    return 0.5 if said_before(text, k, stem(str(goal[case]))) else 0.0
