"""Value names in an instruction: each discrete value (or a key that sets one value) matched as a
phrase against the stemmed words, and the matches ordered; the words that say a match names
something else are in ``goal_name_context``."""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

from apbot.read.goal_adverbs import adverb_of_no_value
from apbot.read.goal_appliance_words import appliance_said
from apbot.read.goal_fit import CODE
from apbot.read.goal_name_context import (
    _by_itself,
    _compound_tail,
    _grades_named,
    _grades_other,
    _head_nouns,
    _heads,
    _names_other,
    _names_setting,
    _names_switch,
    _qualifies_other,
    _scale_head,
    _tail_of_other_name,
)
from apbot.read.goal_phrases import PARTIAL
from apbot.read.goal_scale_kinds import at_its_limit
from apbot.read.goal_shortened import (
    SYNONYM_STEMS,
    abbreviated_synonym,
    adverb_of,
    compound_head,
    cut_short_word,
    display_abbreviation,
    panel_code,
    raw_words,
    said_as_past_place,
    said_as_place,
)
from apbot.read.goal_text import (
    CLAUSE_ENDS,
    CONNECTORS,
    NUMBER_WORDS,
    Text,
    near_vocab,
    negated_before,
    turned_off_after,
    verb_positions,
)
from apbot.read.goal_ties import told_apart
from apbot.read.goal_view import Goal, Model, own_stems, phrase_words
from apbot.read.goal_vocab import HIGHEST, LOWEST, similar, stem


@dataclass
class _Match:
    var: str
    value: Any
    start: int
    end: int
    score: float
    near: float = 0.0  # between settings that share the words: the one named nearest wins


_MERIDIEMS = frozenset({"am", "pm", "a", "p", "m", "."})


def _after_a_number(text: Text, i: int) -> bool:
    """Whether the word before ``i`` is a number ("7 am", "seven p.m."): only then is a lone
    "am" / "p" half of a time said; "memory P" names a value P."""
    k = i - 1
    while k >= 0 and text.word(k) in _MERIDIEMS:  # the "m" of "7 a.m." looks past "a" and "."
        k -= 1
    before = text.word(k)
    return any(ch.isdigit() for ch in before) or before in NUMBER_WORDS


def value_matches(view: Model, text: Text) -> list[_Match]:
    matches: list[_Match] = []
    n = len(text.tokens)
    verbs = verb_positions(text)
    itself = {stem(w) for w in re.findall(r"[a-z]+", appliance_said(view.model))}
    heads = _head_nouns(view)
    works_on = itself - heads
    running = {stem(n) for n, info in view.infos.items() if info.role == "running"}
    doing = {  # "start frying" names the FRYING state under way, not a FRIES menu
        str(v).casefold()
        for info in view.infos.values()
        if info.role == "running"
        for v in info.values
        if str(v).casefold().endswith("ing") and len(str(v)) > 4
    }
    for var, value, stems, weight in view.phrases:
        info = view.infos[var]
        for i in range(n):
            found = _match_at(
                text, i, stems, panel_code(value), view.manual_words, raw_words(value, stems)
            )
            if found is None:
                continue
            end, quality = found
            if negated_before(text, i) or turned_off_after(text, end):
                continue
            if all(text.word(j) in _MERIDIEMS for j in range(i, end)) and _after_a_number(text, i):
                continue  # "7 am": half of a time said, not the first value listed "4:00 AM"
            if text.word(i) in ("up", "down") and text.word(i - 1) in _PARTICLE_VERBS:
                continue  # "set up the buttonhole", "warm up": a verb's particle, not UP
            if text.word(i) in _DEGREE_ADVERBS and end == i + 1:
                continue  # "fully to the left": how far, not the FULL (bright) level
            if said_as_past_place(text, i):
                continue  # "the bowl was in the freezer": where it stood, not the FREEZE mode
            if text.word(i - 1) in ("stay", "stays", "remain", "remains"):
                continue  # "so the bottles stay dry": a state of the load, not the DRY cycle
            if quality < 1.0 and text.stems[end - 1] in itself and i not in verbs:
                continue  # "turn on the air fryer": the appliance, not its AIR FRY programme
            if text.word(end) == "-" and text.word(end + 1) in ("off", "on"):
                continue  # "auto-off" names a timer, not the AUTO mode
            own = near_vocab(info, text, i, end, reach=2)
            opening = i == 0 or text.word(i - 1) in (".", ";", "!")
            if weight <= PARTIAL:
                rest = {stem(w) for w in phrase_words(str(value))} - set(stems)
                turned = end + 1 if text.stems[end : end + 1] and text.stems[end] in rest else end
                if not (own or (opening and text.word(end) in ("with", ","))):
                    if not _heads(text, turned, works_on, heads):
                        continue  # a first word alone names a value only beside "programme"
                        # (or opening the sentence: "Auto with ExtraDry"; or before what the
                        # appliance works on: "an AGM battery" on a battery charger)
                    end = turned  # "a relaxing auto massage": AUTO RELAX, its words turned round
            if _names_other(view, var, text, i, end):
                continue  # "power level 8" is not the POWER mode
            if len(stems) == 1 and _tail_of_other_name(view, var, text, i):
                continue  # "auto-close after 2 minutes": the AUTO CLOSE setting, not CLOSED
            if _by_itself(text, end):
                continue  # "close itself after one minute": what it does on its own, later
            if len(stems) == 1 and _names_switch(view, var, text, i):
                continue  # "switch the light on" is the LIGHT, not a light crust
            if len(stems) == 1 and _qualifies_other(view, var, text, end):
                continue  # "manual speed 3": the speed, in its manual kind
            if len(stems) == 1 and (text.stems[i] in running or text.word(i) in doing) and not own:
                continue  # "Brew six cups", "get it brewing": the operation, not a BREW mode
            if len(stems) == 1 and at_its_limit(text, i) and _grades_named(view, var, text, i):
                continue  # "the alarm as low as it goes": that setting's end, not a LOW
            if weight * quality < 1.0 and len(stems) == 1 and at_its_limit(text, i):
                continue  # "as strong as it goes": an end of a scale, not the HIGH it means
            if len(stems) == 1 and _grades_other(view, var, text, i):
                continue  # "full volume": the volume's end, not a HIGH of another setting
            if len(stems) == 1 and _names_setting(view, var, text, i):
                continue  # "low fan", "fan on quiet": the FAN setting, not the FAN mode
            score = len(stems) * weight * quality + 0.5 * own
            if i in verbs and len(stems) == 1:
                score *= 0.5  # "bake a French loaf": the verb is weaker than the noun
            if len(stems) == 1 and _scale_head(text, i, own_stems(info)):
                continue  # "medium-rare", "low-fat": a degree of something else
            if len(stems) == 1 and _compound_tail(text, i):
                score *= 0.5  # "air-dry", "sterilise-and-dry": the end of another word
            near = near_vocab(info, text, i, end, reach=6, acts=True)
            matches.append(_Match(var, value, i, end, score, near))
    matches.sort(key=_order)
    matches = told_apart(matches, _order, lambda m: m.var, lambda m: m.value, view)
    return _prefer_specific(_prefer_heads(matches), text, itself)


_DEGREE_ADVERBS = frozenset({"fully", "completely", "totally", "entirely"})
"""Adverbs of how far ("fully open", "fully to the left"), whose stem is a value's synonym."""


def _order(match: _Match) -> tuple[float, int, float]:
    """Best first; at one place, the setting whose own words stand nearest ("the water warmth
    on the low setting" is the WATER level's LOW, not the DRYER's)."""
    return (-match.score, match.start, -match.near)


def _prefer_specific(matches: list[_Match], text: Text, itself: set[str]) -> list[_Match]:
    """A value named like the appliance itself (YOGURT on a yogurt maker) is what everything
    it makes is called: "Greek yogurt", "soy yogurt on the vegan setting" name the other
    value of that setting said beside it."""
    best: dict[str, _Match] = {}
    for match in matches:
        best.setdefault(match.var, match)
    changed = False
    for var, first in best.items():
        if not all(text.stems[k] in itself for k in range(first.start, first.end)):
            continue
        other = next(
            (
                m
                for m in matches
                if m.var == var
                and m.value != first.value
                and not all(text.stems[k] in itself for k in range(m.start, m.end))
            ),
            None,
        )
        if other is not None:
            other.score = first.score + 0.01
            changed = True
    if changed:
        matches.sort(key=_order)
    return matches


_PARTICLE_VERBS = frozenset(
    {"set", "warm", "heat", "speed", "slow", "cool", "calm", "wind", "shut", "settle", "sit"}
)


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


def _match_at(
    text: Text,
    i: int,
    stems: tuple[str, ...],
    coded: bool = False,
    known: frozenset[str] = frozenset(),
    words: tuple[str, ...] = (),
) -> tuple[int, float] | None:
    """End and quality of the phrase ``stems`` matched from token i (connectors may sit
    between words; a synonym or a longer word that starts like the value counts less; a
    ``coded`` value, a three-letter panel code, also by the word it cuts short, one of the
    manual's ``known`` words when it is given: "hotel" is no HOT, "mango" no MAN)."""
    k = i
    quality = 1.0
    for index, target in enumerate(stems):
        if index:
            joined = text.word(k) in ("and", "or", "&", "+") or stems[index - 1] in ("and", "or")
            while text.word(k) in CONNECTORS and k < len(text.tokens):
                k += 1
            if joined and text.word(k) in ("the", "a", "an"):
                k += 1  # "the floor and the walls" for FLOOR AND WALLS: an article repeated
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
        if adverb_of_no_value(text, k):
            return None  # "done shortly" is no SHT (short), "I'll stop it manually" no MAN
        if here == target:
            pass
        elif len(stems) == 1 and adverb_of(text, k, target, coded, known):
            quality = min(quality, 0.8)  # "seal it gently" for GENTLE, "fire slowly" for SLO
        elif text.word(k).endswith("ly") and len(text.word(k)) > 5:
            return None  # "automatically" says how, it does not name AUTO
        elif similar(here, target):
            quality = min(quality, 0.9)
        elif here in SYNONYM_STEMS.get(target, ()):
            quality = min(quality, 0.8)
        elif len(stems) > 1 and len(target) >= 3 and abbreviated_synonym(target, here):
            quality = min(quality, 0.7)  # "steam-and-dry" for STER+DRY (sterilise: steam)
        elif (
            len(target) >= 4
            and here.startswith(target)
            and (len(here) <= len(target) + 4 or len(target) >= 5 or len(stems) > 1)
            and text.word(k) not in LOWEST | HIGHEST
        ):
            quality = min(quality, 0.8)  # "storage" for STORE, "convection bake" for CONV BAKE
        elif len(stems) == 1 and len(target) >= 5 and here.endswith(target):
            quality = min(quality, 0.7)  # "multigrain" for GRAINS
        elif words and cut_short_word(words[index], target, text.word(k)):
            quality = min(quality, 0.8)  # "buzzer" for BUZZ (whose stem is "buz")
        elif (
            len(stems) == 1
            and words
            and compound_head(words[0], text.word(k), known)
            and not said_as_place(text, k)
        ):
            quality = min(quality, 0.7)  # "teapot" for POT ("tea" a word of the manual)
        elif (
            index == len(stems) - 1
            and index > 0
            and len(target) == 1
            and target.isalpha()
            and len(here) >= 4
            and here.startswith(target)
        ):
            quality = min(quality, 0.8)  # "zero gravity" for ZERO G: a last word cut to its initial
        elif len(target) >= 3 and here == target + "er":
            quality = min(quality, 0.8)  # "the air fryer" for AIR FRY
        elif len(stems) > 1 and len(here) >= 3 and target.startswith(here):
            quality = min(quality, 0.7)  # "frozen veg" for frozen vegetables
        elif (
            coded
            and (not known or text.word(k) in known)
            and display_abbreviation(target, text.word(k))
        ):
            quality = min(quality, 0.7)  # "on slow" for SLO, "in green" for GRN
        else:
            return None
        k += 1
    return k, quality


_SPLIT_VERBS = frozenset({stem("keep")})


def pronoun_ones(text: Text, claimed: set[int]) -> None:
    """ "on the rear one", "the big one": "one" after "the" and a word is a pronoun."""
    for k, token in enumerate(text.tokens):
        ends = CLAUSE_ENDS | {",", "and", "with", "at", "on", "to", ""}
        if token.text == "one" and text.word(k - 2) == "the" and text.word(k + 1) in ends:
            claimed.add(k)


def restated_codes(view: Model, text: Text, goal: Goal, claimed: set[int]) -> None:
    """ "yogurt (menu 12)": the number beside the setting's word restates the value already
    read by name (its code); it is not another setting."""
    for k, token in enumerate(text.tokens):
        if k in claimed or not token.text.isdigit() or k == 0:
            continue
        key = text.concepts[k - 1]
        for name, value in goal.items():
            if view.infos[name].vocab.get(key, 0.0) < 0.8:
                continue
            code = CODE.fullmatch(str(value)) or re.fullmatch(r"(\d+)", str(value))
            if code is not None and int(code[1]) == int(token.text):
                claimed.add(k)
