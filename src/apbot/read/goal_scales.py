"""Superlatives and scales: "the lowest temperature", "full power", "a dark crust" on an
ordered setting."""

from __future__ import annotations

import re
from typing import Any

from apbot.model.schema import DiscreteVariable
from apbot.read.goal_degree_stems import superlative_stem_setting
from apbot.read.goal_full_percent import percent_strength
from apbot.read.goal_keyed_ends import at_the_latest, keyed_end, keyed_offset
from apbot.read.goal_ladders import (
    is_off_level,
    ladder,
    levels,
    ordered,
    ordered_values,
)
from apbot.read.goal_marked_ends import of_another
from apbot.read.goal_scale_kinds import (
    as_as,
    kind_of,
    named_specifically,
    names_another,
    of_a_setting,
    of_another_kind,
    only_of_kind,
    strength_said,
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
        compared = as_as(text, k)
        if end is None and compared is not None:
            end, reach = compared
        keyed = None if word in LOWEST or word in HIGHEST else keyed_end(view, goal, word)
        if keyed is not None and (of_another(view, text, k, keyed[0]) or at_the_latest(text, k)):
            keyed = None  # "the coarsest amount": said of another setting, not the dial's end
        if end is None and keyed is not None:
            end, reach = keyed[1], 1  # "the finest": where the FINER key stops
        if end is None and _own_superlative(view, goal, word) is not None:
            end = -1  # "the thickest setting" on THICK ▲ / ▼, "the brightest" for BRIGHTNESS
        if end is None and _superlative_before_name(view, text, k, goal):
            end, reach = -1, 1  # "the brightest backlight": the most of the setting named
        if end is None and word in _SPANS and _degree_before_name(view, text, k, goal):
            end, reach = _SPANS[word], 2  # "the wide pitch range": the widest of its spans
        if end is None and _little_of(view, text, k, goal):
            end, reach = 0, 2  # "with just a little water": the least of it that works
        scale_index = None
        middle = word in ("middle", "mid")  # of any odd count of levels, not of three only
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
            count = len(levels(values))
            if middle and end is None and count % 2 and count >= 3:
                pass  # "the middle speed" of five: the third
            elif scale_index is not None and end is None and count != scale_index[1]:
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
        if keyed is not None:
            best = (0.0, keyed[0])  # the key names its setting: no other setting's words
        kind = kind_of(text, k) if end is not None and keyed is None else None
        clash = kind is not None and best is not None and of_another_kind(view.infos[best[1]], kind)
        if kind and (best is None or clash or not named_specifically(view.infos[best[1]], text, k)):
            only = only_of_kind(view, goal, kind)
            if only is None and kind == "level" and strength_said(text, k):
                only = percent_strength(view, goal)  # "at full power" on a BRIGHT 0-100 %
            if (
                only is not None
                and of_a_setting(view.infos[only[1]], text, k)
                and (
                    kind not in ("level", "speed")
                    or strength_said(text, k)
                    or not names_another(view, only[1], text, k)
                )
            ):
                best = only
            elif clash:
                best = None  # "the hottest setting" is no end of an AUTO OFF time
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
        back = keyed_offset(text, k) if keyed is not None or word in LOWEST | HIGHEST else 0
        first = 1 if end == 0 and off_first and keyed is None else 0
        if back and first + back < len(values):
            # "the second finest", "the second highest speed": steps back from that end
            goal[name] = values[first + back] if end == 0 else values[-1 - back]
        elif end == 0 and off_first:
            goal[name] = values[1]  # "the lowest level": the lowest one that works, not off
        elif end is not None:
            goal[name] = values[end]
        elif scale_index is not None:
            steps = levels(values)
            goal[name] = steps[len(steps) // 2] if middle else steps[scale_index[0]]
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
