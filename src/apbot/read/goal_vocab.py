"""Words: a light stemmer and the general vocabulary of appliance instructions.

Nothing here names an appliance, a task or a model: these are the words people use for
settings on any panel ("lock the keys" for a child lock, "firmer" for a harder texture), so
that the goal parser can match an instruction against a model's own names and labels.
"""

from __future__ import annotations

import re
from difflib import SequenceMatcher
from functools import lru_cache

_SPELLING = (
    (re.compile(r"is(e|es|ed|ing|ation)$"), r"iz\1"),
    (re.compile(r"ys(e|es|ed|ing)$"), r"yz\1"),
    (re.compile(r"(?<=\w{3})our$"), "or"),  # colour, flavour (not hour, four, pour)
    (re.compile(r"(?<=\w{3})ours$"), "ors"),
    (re.compile(r"tre$"), "ter"),
    (re.compile(r"tres$"), "ters"),
    (re.compile(r"^programme"), "program"),
)


_IRREGULAR = {"feet": "foot", "teeth": "tooth", "children": "child", "men": "man"}


_CAMEL = re.compile(r"(?<=[a-z])(?=[A-Z][a-z])")


def split_camel(text: str) -> str:
    """ "ExtraDry" and "varioSpeed" are two words each: a brand's run-together option names.

    >>> split_camel("varioSpeed with ExtraDry, not PIZZA or McVitie")
    'vario Speed with Extra Dry, not PIZZA or Mc Vitie'
    """
    return _CAMEL.sub(" ", text)


@lru_cache(maxsize=8192)
def stem(word: str) -> str:
    """A crude stem so that "drying", "dried" and "dry", or "sterilising" and "sterilize",
    compare equal. Both sides of every comparison go through it, so consistency matters more
    than linguistics.

    >>> stem("drying") == stem("dry") == stem("dried"), stem("baking") == stem("bake")
    (True, True)
    """
    w = word.casefold()
    if w.isdigit():
        return w  # a number is no word: "1000" is not "100" with a doubled letter
    if w.endswith("'s"):
        w = w[:-2]  # the clock's hour
    w = _IRREGULAR.get(w, w)  # "feet" for a FOOT zone
    for pattern, replacement in _SPELLING:
        w = pattern.sub(replacement, w)
    if len(w) <= 3:
        return w
    if w.endswith("ly") and len(w) > 5:
        w = w[:-2]
    if (w.endswith("ies") and len(w) > 4) or (w.endswith("ied") and len(w) > 4):
        w = w[:-3] + "y"
    elif w.endswith("ing") and len(w) > 5:
        w = w[:-3]
    elif (w.endswith("ed") and len(w) > 4) or (w.endswith("es") and len(w) > 4 and w[-3] in "sxz"):
        w = w[:-2]
    elif w.endswith("s") and not w.endswith("ss") and len(w) > 3:
        w = w[:-1]
    if len(w) > 3 and w[-1] == w[-2] and w[-1] not in "aeiouls":
        w = w[:-1]  # spinning -> spinn -> spin
    if len(w) > 3 and w.endswith("e"):
        w = w[:-1]
    return w


DETERMINERS = frozenset({"the", "a", "an", "its", "my", "our", "their", "your", "this", "that"})
"""Words that open a noun phrase: what follows them is a thing named ("the heater", "on the
low setting"), not a quality said of one ("a bit warmer")."""

_DOUBLED = "bdgmnpt"  # consonants a short word doubles before "-er": dim, dimmer


def doer_forms(word: str) -> list[str]:
    """The other half of a word and the name of what does it, which people swap when they
    name a setting: a HEAT setting is "the heater", a DIMMER is "dim it". A setting's name
    word in one form is said in the other (a word of five letters or fewer ending in "-er",
    TIMER, WATER, POWER, is no doer of a shorter word; nor is a word in "-e" made one).

    >>> doer_forms("heat"), doer_forms("dimmer"), doer_forms("timer")
    (['heater'], ['dim'], [])

    A form made by adding "-er" is also a comparative ("warmer", "quicker"): it names the
    setting only where it stands as a noun (:func:`said_as_doer`).
    """
    w = word.casefold()
    if not w.isalpha() or len(w) < 3:
        return []
    if w.endswith("er"):
        if len(w) <= 5:
            return []
        base = w[:-2]
        if base[-1] == base[-2] and base[-1] in _DOUBLED:
            base = base[:-1]
        return [base]
    if w.endswith("ity") and len(w) > 6:
        return [f"{w[:-3]}ifier"]  # HUMIDITY is set on "the humidifier", PURITY by "the purifier"
    if w.endswith("e"):
        return []  # TIME is no TIMER, FREEZE no FREEZER: a word in "-e" names a thing of its own
    return [f"{w}er"]


def similar(a: str, b: str) -> bool:
    """Two stems close enough to be one word misspelt or inflected ("steriliser", "sterilize")."""
    if a == b:
        return True
    if min(len(a), len(b)) < 5 or a[0] != b[0]:
        return False
    if (a.endswith("at") and b == f"{a}ion") or (b.endswith("at") and a == f"{b}ion"):
        return True  # the verb says its noun in -ation: "vibrate" for VIBRATION, "rotate"
    return SequenceMatcher(None, a, b).ratio() >= 0.85


def cut_short(short: str, word: str) -> bool:
    """``short`` is ``word`` cut short as a panel prints it: the word's start, of three
    letters or more, and either most of the word ("TABS" for tablets, "BUZZ" for buzzer) or
    cut where a syllable ends, on a consonant before a vowel ("OSC" for oscillation, "REGEN"
    for regeneration): "temptation" is no TEMP, "settings" no SET (a short word that merely
    starts alike, "temple", is still taken: most of it is the name; but not an adjective's
    ending after three letters: "fancy" is no FAN, "ionic" no ION)."""
    if len(short) < 3 or len(word) <= len(short) or not word.startswith(short):
        return False
    if len(short) == 3 and len(word) <= 5 and word.endswith(("y", "ic")):
        return False  # an adjective of its own after a three-letter name: "fancy", "ionic"
    if len(word) <= len(short) + 4:
        return True
    return short[-1] not in _VOWELS and word[len(short)] in _VOWELS


_VOWELS = frozenset("aeiou")


# Words that mean the same setting on many panels: each group maps to its first word's stem.
_GROUPS: tuple[tuple[str, ...], ...] = (
    ("program", "programme", "prog", "prg", "course", "cycle", "menu", "function", "func", "mode"),
    ("temperature", "temp", "degree", "degrees", "heat"),
    ("lock", "child", "childlock", "lockout", "keylock", "keys", "buttons", "controls", "panel"),
    ("delay", "delayed", "preset", "later", "wait", "countdown", "reserve", "reservation"),
    ("finish", "end", "ready", "done", "finished"),
    ("timer", "timers"),
    ("time", "duration", "times"),
    ("light", "lamp", "torch"),
    (
        "buzzer",
        "beep",
        "beeps",
        "beeper",
        "sound",
        "signal",
        "mute",
        "silence",
        "quiet",
        "alarm",
        "alert",
    ),
    ("dry", "drying", "dryer"),
    ("sterilize", "steam", "sterilise", "sanitize", "uv"),
    ("humidity", "rh", "humid", "humidistat"),
    ("fan", "airflow", "air", "blower", "convection", "circulation", "ventilation"),
    ("power", "watt", "watts", "wattage", "kw", "kilowatt", "output"),
    ("level", "setting", "mark", "intensity", "strength"),
    ("size", "loaf", "portion", "amount", "weight"),
    ("crust", "colour", "color", "browning"),
    ("spin", "spinning"),
    ("rinse", "rinses", "rinsing"),
    ("water", "litre", "litres", "liter", "liters", "fill"),
    ("warm", "warming", "keep"),
    ("clock", "clocks", "day"),
    ("texture", "firmness", "thickness", "consistency"),
    ("volume", "vol"),
    ("awake", "wake", "woken", "wakeup"),
    ("auto", "automatic", "automatically"),
    ("swing", "sweep", "oscillate", "oscillation", "oscillating"),
    ("rotate", "rotation", "rotisserie", "spit"),
    ("width", "wide", "widen", "narrow"),
    ("length", "long", "lengthen"),
    ("work", "effort", "efforts"),  # an interval timer's work and rest phases, as trainers
    ("rest", "recover", "recovering"),  # say them ("one-minute efforts, 30 s to recover")
    ("period", "quarter", "quarters", "inning", "innings"),  # a game's parts, as played
)
_CANON: dict[str, str] = {}
for _group in _GROUPS:
    for _word in _group:
        _CANON.setdefault(stem(_word), stem(_group[0]))


def concept(word: str) -> str:
    """The group a word belongs to (its own stem if none): "keys" and "lock" are one concept."""
    s = stem(word)
    return _CANON.get(s, s)


# Words that say a setting is wanted off, or not wanted ("no prewash", "skip the shake").
NEGATIONS = frozenset(
    {
        "no",
        "not",
        "without",
        "skip",
        "skipping",
        "don't",
        "dont",
        "never",
        "disable",
        "disabled",
        "off",
        "mute",
        "silence",
        "silent",
        "cancel",
        "stop",
        "none",
        "free",
        "nor",
        "release",
    }
)
# Stems of verbs of handling a setting: negated, they leave it as it is ("without touching the
# timer", "don't change the delay"), where "no delay", "without using the delay" want none.
HANDLING = frozenset(
    stem(w) for w in ("touch", "change", "alter", "adjust", "modify", "tweak", "fiddle", "mess")
)
# Words that carry no meaning for matching a variable by name.
STOP_WORDS = frozenset(
    {
        "the",
        "a",
        "an",
        "of",
        "and",
        "to",
        "for",
        "in",
        "on",
        "off",
        "at",
        "by",
        "with",
        "it",
        "set",
        "press",
        "button",
        "pad",
        "key",
        "touch",
        "select",
        "adjust",
        "up",
        "down",
        "start",
        "stop",
        "value",
        "enter",
        "entry",
        "confirm",
        "toggle",
        "hold",
        "plus",
        "minus",
        "cancel",
        "pause",
        "choose",
        "go",
        "feature",
    }
)
# Scales of adjectives: a numeric variable with a few values (a crust 1-3) maps them in order.
SCALES: tuple[tuple[str, ...], ...] = (
    ("light", "medium", "dark"),
    ("low", "medium", "high"),
    ("small", "medium", "large"),
    ("soft", "medium", "firm"),
)
# Superlatives: which end of a domain.
LOWEST = frozenset(
    {
        "lowest",
        "minimum",
        "min",
        "least",
        "shortest",
        "smallest",
        "quietest",
        "lightest",
        "palest",
        "coolest",
        "coldest",
        "weakest",
        "slowest",
        "gentlest",
        "softest",
        "dimmest",
        "faintest",
        "mildest",
        "subtlest",
        "slightest",
        "tiniest",
        "narrowest",
        "thinnest",
    }
)
HIGHEST = frozenset(
    {
        "highest",
        "maximum",
        "max",
        "most",
        "longest",
        "biggest",
        "largest",
        "hottest",
        "darkest",
        "strongest",
        "fastest",
        "full",
        "top",
        "warmest",
        "driest",
        "heaviest",
        "hardest",
        "firmest",
        "loudest",
        "widest",
        "broadest",
    }
)
# Letters that stand for sizes or levels on a display.
LETTER_WORDS = {
    "s": ("small",),
    "m": ("medium",),
    "l": ("large", "big"),
    "xl": ("extra",),
    "lo": ("low",),
    "hi": ("high",),
    "med": ("medium",),
}
# Adjectives that mean a value word ("firmer" for harder, "pale" for light).
SYNONYMS: dict[str, tuple[str, ...]] = {
    "harder": ("firmer", "firm", "hard"),
    "softer": ("soft", "soften"),
    "soft": ("quiet", "quieter"),  # a sound's soft level is its quiet one
    "light": ("pale", "lighter"),
    "dark": ("darker", "deep"),
    "low": ("lo", "quiet", "gentle", "quietest", "slow"),
    "high": ("hi", "full", "fast", "strong", "loud", "louder", "loudest"),
    "mid": ("medium", "middle", "moderate"),
    "lower": ("bottom",),
    "upper": ("top",),
    "bright": ("full", "brightest"),
    "large": ("big", "bigger", "largest", "biggest"),
    "small": ("little", "smaller", "smallest"),
    "continuous": ("nonstop", "non", "continuously"),
    "cont": ("continuous", "continuously", "nonstop"),
    "co": ("continuous", "continuously", "nonstop"),
    "auto": ("automatic",),
    "sterilize": ("steam", "sterilizing", "sterilization"),
    "dry": ("dehumidify", "dehumidifying", "dehumidification"),
    "free": ("freely", "flow"),
    "more": ("extra", "longer", "stronger"),
    "less": ("shorter", "lighter", "weaker"),
    "poultry": ("chicken", "turkey", "duck"),
    "meat": ("beef", "pork", "lamb", "mince", "steak"),
    "fish": ("salmon", "cod", "seafood", "prawns", "shrimp"),
    "vegetables": ("veg", "veggies", "vegetable"),
    "store": ("storage", "stored"),
    "eco": ("economy", "economical", "saving"),
    "storage": ("store", "storing"),
    "purify": ("clean", "cleaning", "purifying", "purification", "purifier"),
    "cool": ("chill", "chilled", "chilling", "cold"),
    "holiday": ("vacation", "away", "absence"),
    "fan": ("circulate", "ventilate"),  # the nouns name an AIR switch too (the group)
    "vacation": ("holiday", "away", "absence"),
    "economy": ("eco", "economical", "saving"),
    "repair": ("recovery", "recover", "recondition", "revive"),
    "refresh": ("freshen", "refreshing"),
    "female": ("woman", "lady", "girl"),  # a profile's sex said of the person
    "male": ("man", "gentleman", "boy"),
    # a reach said as a length ("the long sensor range", "read the chip from further away")
    "closed": ("shut",),  # a door, a lid, a valve shut is closed
    "far": ("long", "longer", "longest", "further", "farther", "furthest", "farthest"),
    "near": ("short", "shorter", "shortest", "close", "closer", "closest", "nearest"),
    # plain words for values panels print in their trade's word or initials
    "violet": ("purple",),
    "solar": ("sun", "sunshine", "sunlight"),
    "lunar": ("moon", "moonlight"),
    "ot": ("overtime",),  # a game's period past the last
    "reverse": ("backwards", "backward", "astern"),  # a direction said as the way it goes
    "bloom": ("flowering", "flower", "flowers", "blossom"),
    "tuner": ("radio",),
    "phono": ("turntable", "vinyl"),
    "bt": ("bluetooth",),
    "scissors": ("shears",),
    "thick": ("coarse",),
    "rear": ("posterior",),
}
# Counts written as adverbs ("rinse twice").
TIMES_WORDS = {"once": 1, "twice": 2, "thrice": 3}

SPAN_STARTS = frozenset({"on", "start", "begin", "sunrise", "dawn", "open", "wake", "morning"})
"""A time-of-day setting's words that name when something begins (ON TIME, SUNRISE)."""
SPAN_ENDS = frozenset({"off", "end", "stop", "sunset", "dusk", "close", "finish", "night"})
"""… and when it ends (OFF TIME, SUNSET)."""


def said_as_doer(word: str, before: str, after: str, states: tuple[str, ...]) -> bool:
    """Whether a doer form made by adding "-er" stands as the thing's name — after a
    determiner or before its state ("the heater", "heater off") — rather than as a comparative
    ("a bit warmer than usual", "make it quicker"). Forms made by taking "-er" off ("dim" for a
    DIMMER) are verbs and adjectives already, and always count."""
    if not word.endswith("er"):
        return True
    return before in DETERMINERS or after in states
