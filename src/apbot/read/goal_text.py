"""An instruction as the goal parser reads it: tokens with stems and concepts, clauses, and
how strongly the words around a span name a variable."""

from __future__ import annotations

import re
from dataclasses import dataclass

from apbot.read.goal_view import VarInfo
from apbot.read.goal_vocab import (
    NEGATIONS,
    concept,
    split_camel,
    stem,
)
from apbot.read.number_tokens import Token, tokenize
from apbot.read.numbers import Mention

CONNECTORS = frozenset({"and", "+", "-", "/", "&", ",", "then", "with", "n"})


CLAUSE_ENDS = frozenset({".", ";", "!", "?", "(", ")"})


# words that name a measure only beside a number ("a 3 mm long stitch"); alone they describe
# the task ("sew a long seam"), not a setting
_MEASURE_WORDS = frozenset({"long"})


def _measured(tokens: list[Token], k: int) -> bool:
    """A number stands just before the word at k (with its unit: "3 mm long") or right after."""
    near = [tokens[j].text for j in (k - 2, k - 1, k + 1) if 0 <= j < len(tokens)]
    return any(re.fullmatch(r"\d+(?:[.,]\d+)?", w) or w in NUMBER_WORDS for w in near)


@dataclass
class Text:
    tokens: list[Token]
    stems: list[str]
    concepts: list[str]

    @classmethod
    def of(cls, text: str) -> Text:
        tokens = tokenize(split_camel(unhyphen(text)))
        concepts = [concept(t.text) for t in tokens]
        for k, t in enumerate(tokens):
            if t.text in _MEASURE_WORDS and not _measured(tokens, k):
                concepts[k] = stem(t.text)  # "a long seam": no length asked for
        return cls(tokens, [stem(t.text) for t in tokens], concepts)

    def word(self, k: int) -> str:
        return self.tokens[k].text if 0 <= k < len(self.tokens) else ""

    def span(self, start: int, end: int) -> str:
        return " ".join(t.text for t in self.tokens[start:end])


def negated_before(text: Text, start: int, reach: int = 3) -> bool:
    for k in range(start - 1, max(-1, start - reach - 1), -1):
        word = text.word(k)
        if word in CLAUSE_ENDS or word == ",":
            return False
        if word in NEGATIONS and word not in ("off", "stop", "free"):
            return True
        if word == "of" and text.word(k - 1) == "instead":
            return True  # "switch off at the end instead of keeping warm"
        if word == "off" and text.word(k - 1) == "hold":
            return True  # "hold off on keep warm": not that
    return False


def turned_off_after(text: Text, end: int) -> bool:
    """ "keep-warm turned off", "the buzzer off": the words before ``end`` name a switch that
    is being turned off, not a value being chosen."""
    k = end
    if text.word(k) in ("turned", "switched", "set", "is", "left"):
        k += 1
    return text.word(k) in ("off", "disabled")


_HYPHENED = re.compile(
    r"\b(a|an|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve)-and-(a|an)-"
    r"(half|quarter)(?:-(hours?|minutes?))?\b",
    re.IGNORECASE,
)


def unhyphen(text: str) -> str:
    """ "a one-and-a-half-hour timer" reads as "one and a half hour".

    >>> unhyphen("a one-and-a-half-hour timer")
    'a one and a half hour timer'
    """
    return _HYPHENED.sub(lambda m: f"{m[1]} and {m[2]} {m[3]}" + (f" {m[4]}" if m[4] else ""), text)


NUMBER_WORDS = frozenset(
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


def verb_positions(text: Text) -> set[int]:
    """Tokens that open a clause with a verb of doing ("Bake a cake", "then steam it")."""
    positions = set()
    for k in clause_starts(text, loose=True):
        k2 = k + 1 if text.word(k) in FILLERS else k
        if k2 < len(text.stems) and text.stems[k2] in _ACTION_VERBS:
            positions.add(k2)
    return positions


FILLERS = ("just", "please", "then", "now", "also", "first")


def near_vocab(
    info: VarInfo, text: Text, start: int, end: int, reach: int = 8, acts: bool = False
) -> float:
    """How strongly the words around a span name the variable: each of its words found
    counts once, nearer counts more, and a comma in between halves it. With ``acts``, an
    "and" that opens a new act ("… on medium warmth and leave the seat …") ends the search:
    the setting named in the next act is not the one this value is said of."""
    found: dict[str, float] = {}
    for direction, first in ((-1, start - 1), (1, end)):
        k = first
        factor = 1.0
        for distance in range(1, reach + 1):
            if not 0 <= k < len(text.tokens):
                break
            word = text.word(k)
            if word in CLAUSE_ENDS:
                break
            if acts and word == "and" and text.word(k + 1) in _AND_VERBS:
                break
            if word == ",":
                factor *= 0.4
            key = text.concepts[k]
            weight = info.vocab.get(key, 0.0)
            if weight:
                found[key] = max(found.get(key, 0.0), factor * weight / distance)
            k += direction
    return sum(found.values())


def phrase_here(text: Text, k: int, own: set[str]) -> bool:
    """Another of the switch's own words stands next to token k ("keep warm", "night light")."""
    return any(text.stems[j] in own for j in (k - 1, k + 1) if 0 <= j < len(text.tokens))


_LONG_REACH = frozenset({"without", "no", "don't", "dont"})


_AND_VERBS = frozenset(
    {"lock", "set", "turn", "switch", "put", "make", "give", "use", "keep", "start", "add"}
    | {"select", "choose", "pick", "enable", "activate", "engage", "leave", "have", "let"}
)


ACT_VERBS = _AND_VERBS | {"start", "get", "go", "run"}


def new_act(text: Text, j: int) -> bool:
    """An "and" or "then" at ``j`` joins a new order ("… without preheating and get it
    started", "… then lock the keys"): what came before it, a negation too, ends there. Said
    or typed without commas, the joining word is all that marks the end of the clause."""
    return text.word(j) in ("and", "then") and text.word(j + 1) in ACT_VERBS


def negative_around(text: Text, k: int) -> bool:
    if (
        text.word(k + 1) == "on"
        and (text.word(k + 2) in CLAUSE_ENDS | {",", "and", ""} or text.word(k + 2) in ACT_VERBS)
        and not any(text.word(k - d) in ("don't", "dont", "not", "never") for d in range(1, 4))
    ):
        return False  # "with no spin at all and ECO on"
    for d in range(1, 8):
        word = text.word(k - d)
        if word in CLAUSE_ENDS or word == ",":
            break
        if new_act(text, k - d):
            break  # "turn off after an hour and lock the keys": a new act, not negated
        if word in NEGATIONS and word not in ("free",) and (d < 6 or word in _LONG_REACH):
            return True  # "without the fruit-and-nut beep"
        if word == "of" and text.word(k - d - 1) == "instead":
            return True  # "switch off instead of keeping warm"
        if word == "off" and text.word(k - d - 1) == "hold":
            return True  # "hold off the keep warm": not that
        if word == "on" and text.word(k - d - 1) == "off" and text.word(k - d - 2) == "hold":
            return True  # "hold off on keep warm"
        if word in ("on", "with", "enable", "add"):
            break
    if text.word(k) in ("mute", "silence", "unlock"):
        return True
    for d in range(1, 5):
        word = text.word(k + d)
        if word in CLAUSE_ENDS or word == ",":
            break
        if word == "off" and text.word(k + d - 1) == "-":
            continue  # "the auto-off", "the shut-off": a noun, not the switch said off
        if word in ("off", "disabled", "silenced", "muted"):
            return True
        if word == "on":
            return False
    return False


STRONG_VERBS = frozenset(
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
        "blend",
        "crush",
        "whip",
        "chop",
        "grind",
        "mill",
        "drill",
        "cure",
        "pump",
        "inflate",
        "grate",
        "shred",
        "puree",
        "pulse",
        "clean",
        "sterilise",
        "sterilize",
        "dehumidify",
        # the work of players, needles, blades and rollers said as an order (not "mow",
        # "seal", "floss": as often a schedule, a mode, a kind of sugar)
        "play",
        "stitch",
        "sew",
        "embroider",
        "sharpen",
        "laminate",
    )
)


WEAK_VERBS = frozenset(stem(w) for w in ("keep", "bring", "make", "give", "fill", "get", "hold"))


# A running variable named for one operation is started only by that operation's verbs.
VERB_FAMILIES: dict[str, frozenset[str]] = {
    stem("heating"): frozenset(stem(w) for w in ("heat", "warm", "boil", "bring")),
    stem("dispensing"): frozenset(stem(w) for w in ("dispense", "pour", "fill")),
    stem("pouring"): frozenset(stem(w) for w in ("dispense", "pour", "fill")),
    stem("dispense"): frozenset(stem(w) for w in ("dispense", "pour", "fill")),
    stem("pour"): frozenset(stem(w) for w in ("dispense", "pour", "fill")),
}


_ACTION_VERBS = STRONG_VERBS | WEAK_VERBS


def clause_starts(text: Text, loose: bool = False) -> list[int]:
    """Where sentences begin (and, when ``loose``, clauses after ", and", "then")."""
    ends = {".", ";", "!", "?"} | ({",", "and", "then"} if loose else set())
    starts = [0]
    for k, token in enumerate(text.tokens):
        if token.text in ends and k + 1 < len(text.tokens):
            starts.append(k + 1)
    return starts


def said_before(text: Text, k: int, word: str, reach: int = 4) -> bool:
    """The stemmed ``word`` stands within ``reach`` tokens before ``k``, in the same stretch of
    text (no comma or sentence end between): "the body zone at 6", "the foot section on max"."""
    for j in range(k - 1, max(-1, k - reach - 1), -1):
        if text.word(j) in CLAUSE_ENDS or text.word(j) == ",":
            return False
        if text.stems[j] == word:
            return True
    return False


_LENGTH_WORDS = frozenset({"length", "duration", "long", "hours", "minutes", "time"})


def repeat_for_a_length(text: Text, mention: Mention, info: VarInfo) -> bool:
    """A duration said as how often something comes round ("every two hours", "each 6 h") beside
    a setting named for how long something lasts (a LENGTH, a DURATION, SLEEP HOURS, RUN TIME): not
    what it asks, unless the setting's own words stand right there (an interval setting may take
    it)."""
    if mention.kind != "duration" or text.word(mention.start - 1) not in ("every", "each"):
        return False
    return bool(set(info.name.split("_")) & _LENGTH_WORDS)
