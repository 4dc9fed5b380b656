"""Word sequences that name one value of one setting, for the goal parser's view of a model.

A value is named by its own words, its display code, a letter size's word, a general synonym,
a distinctive word of a many-word name, or the label of a key that goes straight to it ("GREEN
TEA" sets 80 °C). Kept apart from :mod:`apbot.read.goal_view`, which gathers each setting's
words and role and calls :func:`value_phrases` once per model.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from apbot.model.schema import ApplianceModel, DiscreteVariable, GoTo
from apbot.read.goal_roles import control_labels, step_effects, steps_of
from apbot.read.goal_values import OFF_WORDS, ON_WORDS, name_words, parse_quantity, phrase_words
from apbot.read.goal_vocab import LETTER_WORDS, STOP_WORDS, SYNONYMS, concept, stem

if TYPE_CHECKING:
    from apbot.read.goal_view import VarInfo

MAX_PHRASE_VALUES = 2_000
"""Values of one discrete variable matched as phrases; a longer list is matched by numbers only."""


PARTIAL = 0.6
"""Weight of a value named by one of its words alone ("the eco programme" for eco 40-60, "the
sleep programme" for AUTO SLEEP); such a match needs the setting's own word beside it."""


def _first_words(name: str, info: VarInfo) -> list[tuple[str, Any, tuple[str, ...], float]]:
    """Each word of a many-word value that no other value of the setting uses: people name a
    programme by its distinctive word, first or not (AUTO SLEEP, AUTO RELAX: "sleep", "relax")."""
    firsts: dict[str, list[Any]] = {}
    used: dict[str, int] = {}
    for value in info.values:
        words = [stem(w) for w in phrase_words(str(value))]
        for word in words:
            used[word] = used.get(word, 0) + 1
        for word in words if len(words) > 1 else []:
            if word.isalpha() and len(word) >= 3:
                firsts.setdefault(word, []).append(value)
    return [
        (name, values[0], (word,), PARTIAL)
        for word, values in firsts.items()
        if len(values) == 1 and used[word] == 1 and word not in STOP_WORDS
    ]


# words of a scale's ends, whose superlatives the parser reads as ends of any setting
_SCALE_WORDS = frozenset({"high", "low", "hi", "lo", "max", "min", "top", "long", "short"})

# unit symbols a value's name joins to another word (V AC, A DC), as people spell them out
_UNIT_SYMBOLS = {"v": "volt", "a": "amp", "w": "watt"}

# a display's sign for a time that runs without end, and the words people say it with
_ENDLESS_SIGNS = frozenset({"∞"})
_ENDLESS_WORDS = ("continuous", "continuously", "nonstop", "endless", "endlessly", "indefinitely")

# words of pace that stand for a level of speed ("run it slow": LOW), never of heat
_PACE_WORDS = frozenset({"slow", "fast"})


def value_phrases(
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
        shared = _shown_label(show)
        for value in info.values:
            text = str(value)
            if text.casefold() in ON_WORDS + OFF_WORDS + ("none", "----", "--"):
                continue
            if text in _ENDLESS_SIGNS:  # TIME 30 … 180 ∞: "run it nonstop", "continuously"
                phrases += [(name, value, (stem(w),), 0.9) for w in _ENDLESS_WORDS]
            forms = [text]
            shown = show.get(text)
            # a code spelled as a switch's word ("On" for ALWAYS ON) names no value in a request
            if shown and "{" not in shown and shown.casefold() not in ON_WORDS + OFF_WORDS:
                forms.append(shown)
            for form in forms:
                words = [w for w in phrase_words(form) if w != "and"]  # read as a connector
                if form is not text and shared:
                    words = [w for w in words if w not in shared]  # "WATER ■■■": no HIGH's word
                    if not any(c.isalpha() for w in words for c in w):
                        continue  # "SLP 15": its number is read as a quantity, not a name
                if parse_quantity(form) is not None:
                    continue  # a number or a quantity ("3.0 oz"): read as a quantity
                if not words:
                    continue
                bare = len(words) == 1 and words[0].casefold() in ("a", "i")
                if form is not text and bare:
                    if _lettered(text, info.values) and name_words(name):
                        # PROGRAM A shown "P-A": "program a", never the article alone
                        named = (stem(name_words(name)[-1].casefold()), stem(words[0]))
                        phrases.append((name, value, named, 1.0))
                    continue  # "µA" read as "a": a display code left a bare article names nothing
                if len(words) == 1 and words[0] in LETTER_WORDS:
                    for alias in LETTER_WORDS[words[0]]:
                        phrases.append((name, value, (stem(alias),), 0.9))
                    continue
                phrases.append((name, value, tuple(stem(w) for w in words), 1.0))
                spelled = [_UNIT_SYMBOLS.get(w.casefold(), w) for w in words]
                if len(words) > 1 and spelled != words:  # V AC: "the 60-volt AC range"
                    phrases.append((name, value, tuple(stem(w) for w in spelled), 0.9))
                ends = (str(info.values[0]), str(info.values[-1]))
                scale = words[0] in _SCALE_WORDS  # "the highest humidity": read as an end
                if len(words) == 1 and text in ends and len(info.values) >= 3 and not scale:
                    for most in superlatives(words[0]):  # "the slowest speed": SLOW of three
                        phrases.append((name, value, (stem(most),), 0.9))
                for synonym in SYNONYMS.get(words[0], ()) if len(words) == 1 else ():
                    if synonym in _PACE_WORDS and concept("temperature") in info.vocab:
                        continue  # "steam the fish slowly": a pace, no LOW heat
                    phrases.append((name, value, (stem(synonym),), 0.8))
        phrases += _first_words(name, info)
    # keys that go straight to one value ("GREEN TEA" sets 80 °C)
    for _feature, _index, step in steps_of(model):
        if not step.variable or step.variable not in infos:
            continue
        info = infos[step.variable]
        if info.role in ("power", "running"):
            continue
        stepping = {
            label.casefold()
            for action, effect in step_effects(step)
            if not isinstance(effect, GoTo)
            for label in control_labels(model, [action])
        }  # PRESSURE pressed steps the pressure, held goes to 1: its label names the setting
        for action, effect in step_effects(step):
            if not isinstance(effect, GoTo):
                continue
            if info.role == "switch" and str(effect.to) == str(info.off):
                continue  # SCHEDULE held cancels the schedule: saying its name asks for it on
            for label in control_labels(model, [action]):
                words = name_words(label)
                if label.casefold() in stepping:
                    continue
                if words and not any(w in STOP_WORDS for w in words):
                    phrases.append((step.variable, effect.to, tuple(stem(w) for w in words), 0.95))
    return phrases


def _shown_label(show: dict[Any, Any]) -> set[str]:
    """Words every value's display text shares ("WATER ■□□", "WATER ■■□", "WATER ■■■"): the
    setting's own label beside its level, which names no one value of it."""
    texts = [str(t) for t in show.values() if t and "{" not in str(t)]
    if len(texts) < 2:
        return set()
    shared = set(phrase_words(texts[0]))
    for text in texts[1:]:
        shared &= set(phrase_words(text))
    return shared


def superlatives(word: str) -> list[str]:
    """The superlative forms an adjective may take ("slow" → slowest, "big" → biggest,
    "gentle" → gentlest, "dry" → driest); none for a word of under three letters or one
    already ending in "-est"."""
    w = word.casefold()
    if len(w) < 3 or not w.isalpha() or w.endswith("est"):
        return []
    if w.endswith("e"):
        return [f"{w}st"]
    if w.endswith("y"):
        return [f"{w[:-1]}iest"]
    forms = [f"{w}est"]
    if len(w) <= 4 and w[-1] not in "aeiouwxy" and w[-2] in "aeiou" and w[-3] not in "aeiou":
        forms.append(f"{w}{w[-1]}est")  # big → biggest, hot → hottest
    return forms


def _lettered(text: str, values: list[Any]) -> bool:
    """The value is a letter of a lettered list (PROGRAM A, B, C shown "P-A"): the letter names
    it, unlike a unit's symbol (µA, A among V and Ω) left as a bare article."""
    letters = [str(v) for v in values if len(str(v)) == 1 and str(v).isalpha()]
    return text in letters and any(parse_quantity(v) is None for v in letters if v != text)
