"""Superlatives of a kind: "as hot as it goes", "on its warmest setting", "as long as it
allows" — which kind of quantity the word measures, whether the comparison is closed by the
appliance's own limit, and the one open setting of that kind (goal_scales picks the end)."""

from __future__ import annotations

from apbot.model.schema import TimeVariable
from apbot.read.goal_full_percent import strength_at_end
from apbot.read.goal_ladders import numbered_levels, ordered, worded_levels
from apbot.read.goal_text import CLAUSE_ENDS, Text
from apbot.read.goal_values import generic
from apbot.read.goal_view import Goal, Model, VarInfo, domain_values, own_concepts
from apbot.read.goal_vocab import concept

_MORE = frozenset({"much", "many", "high", "hot", "long", "strong", "fast", "big", "loud", "warm"})
_LESS = frozenset(
    {"little", "few", "low", "cool", "short", "weak", "slow", "small", "quiet", "cold"}
) | frozenset({"gentle", "soft", "mild"})
_MORE |= {"bright"}  # "the backlight as bright as possible"
_LESS |= {"dim"}  # "as dim as it goes"
_KIND_OF_WORD = {
    **dict.fromkeys(("hottest", "warmest", "coldest", "coolest"), "temperature"),
    **dict.fromkeys(("hot", "warm", "cold", "cool"), "temperature"),
    **dict.fromkeys(("longest", "shortest", "long", "short"), "time"),
    **dict.fromkeys(("strongest", "weakest", "gentlest", "softest", "mildest"), "level"),
    **dict.fromkeys(("strong", "weak", "gentle", "soft", "mild"), "level"),
    **dict.fromkeys(("fastest", "slowest"), "speed"),  # "as fast as possible": in a hurry
    **dict.fromkeys(("loudest", "quietest", "loud", "quiet"), "volume"),
}
"""The kind a superlative's own word measures; "level": a strength, counted in numbered
levels (an intensity 1-5, a massage OFF/1/2/3), whatever the setting is called; "speed": the
levels of a setting named for its speed (a SOFT START 1-2 is not how fast it runs); "volume":
the one setting named VOLUME ("as quiet as it goes")."""
_AS_AS_KINDS = frozenset(w for w, kind in _KIND_OF_WORD.items() if not w.endswith("est"))
_FULL = frozenset({"full", "maximum", "max", "top", "minimum", "min"})
_STRENGTHS = frozenset({"power", "strength"})
"""An end said of the appliance's strength ("at full power", "minimum strength") grades the
one setting counted in levels when no setting is named by those words."""


def strength_said(text: Text, k: int) -> bool:
    """ "full power", "minimum strength": an end of the appliance's strength, whatever setting
    counts it (the word "power" may also name an on/off switch; it is no level of its own)."""
    return (text.word(k) in _FULL and text.word(k + 1) in _STRENGTHS) or strength_at_end(text, k)


def kind_of(text: Text, k: int) -> str | None:
    """The kind of quantity a superlative's own word measures ("the hottest" a temperature,
    "as long as it allows" a duration), whatever setting it is said of."""
    word = text.word(k)
    if strength_said(text, k):
        return "level"  # "at full power" on a brush whose strength is an INTENSITY 1-8
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


# words that make a superlative said of a setting ("the warmest SETTING", "the lowest LEVEL")
_OF_SETTING = frozenset(
    concept(w)
    for w in ("setting", "settings", "level", "temperature", "heat", "one", "position", "mode")
)


def of_a_setting(info: VarInfo, text: Text, k: int) -> bool:
    """A superlative of a kind ("warmest", "as long as it allows") is said of the setting when
    its own words or "setting"/"level" follow it, when "as ... as" closes it with the
    appliance's limit, or at "its hottest"; "the coldest night", "warmest in the afternoon" are
    the weather's."""
    if text.word(k - 1) == "as":
        return True  # _kind_of has checked the limit that closes it
    if strength_said(text, k):
        return True  # "at full power": the strength the setting's levels count
    if _its_limit(text, k + 1) or _ends_its_clause(text, k):
        return True  # "the hottest it goes", "the lullabies at the loudest;"
    j = k + 2 if text.word(k + 1) in ("possible", "available", "allowed") else k + 1
    key = text.concepts[j] if j < len(text.concepts) else ""  # "the longest possible soak"
    if key in _OF_SETTING or (key and info.vocab.get(key, 0.0) > 0):
        return True
    if key and key in _KIND_NOUNS.get(kind_of(text, k) or "", ()):
        return True  # "the longest time the timer allows": the kind's own noun
    after = text.word(k + 1)
    return text.word(k - 1) == "its" and (after in CLAUSE_ENDS or after in (",", ""))


_KIND_NOUNS = {
    "time": frozenset(concept(w) for w in ("time", "duration")),
    "temperature": frozenset(concept(w) for w in ("temperature",)),
}
"""The noun a superlative's kind is: "the longest time" grades the one open duration."""

_CLOSERS = frozenset({",", "-", "and", "then", "but", "please", ""}) | CLAUSE_ENDS


def _ends_its_clause(text: Text, k: int) -> bool:
    """ "the lullabies at the loudest", "bake on the hottest, then …": a superlative after
    "at / on / to the" that ends its clause has nothing else to grade than a setting (the
    weather's "the coldest night" goes on to its noun)."""
    return (
        text.word(k - 1) in ("the", "its")
        and text.word(k - 2) in ("at", "on", "to")
        and text.word(k + 1) in _CLOSERS
    )


def of_another_kind(info: VarInfo, kind: str) -> bool:
    """A setting whose measure is known and is no temperature, for a superlative of heat: "the
    hottest" is no end of a time (AUTO OFF 30-90 min). ("the shortest" grades a cutting
    height as well as a time: only heat is this plain.)"""
    if kind != "temperature":
        return False
    measure = "time" if isinstance(info.var, TimeVariable) else info.dimension
    return measure is not None and measure not in ("temperature", "fahrenheit")


def named_specifically(info: VarInfo, text: Text, k: int) -> bool:
    """A word of the setting's own stands near the superlative, not only "setting" or "level"
    ("the warmest setting" names no LEVEL; "the hottest temperature" names TEMP)."""
    for j in range(max(0, k - 4), min(len(text.tokens), k + 5)):
        key = text.concepts[j]
        if j != k and info.vocab.get(key, 0.0) > 0 and not generic(key):
            return True
    return False


def only_of_kind(view: Model, goal: Goal, kind: str) -> tuple[float, str] | None:
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
            or (kind == "volume" and _own_volume(info))
        )
    ]
    return (0.0, found[0]) if len(found) == 1 else None


_SIGNALS = frozenset(
    concept(w) for w in ("beep", "key", "button", "touch", "alarm", "buzzer", "signal", "tone")
)


def _own_volume(info: VarInfo) -> bool:
    """A VOLUME of what the appliance plays, not of its signals: "as quiet as it goes" on an
    air purifier asks for a quiet fan, never for softer beeps (BEEP VOLUME, KEY VOLUME)."""
    own = own_concepts(info)
    return concept("volume") in own and not own & _SIGNALS


def names_another(view: Model, name: str, text: Text, k: int) -> bool:
    """ "the gentlest cycle", "the strongest programme": the word after the superlative names
    another setting (a choice of programmes), so no numbered level is meant."""
    key = text.concepts[k + 1] if k + 1 < len(text.concepts) else ""
    return bool(key) and any(
        key in own_concepts(info) for other, info in view.infos.items() if other != name
    )


_AMOUNTS = frozenset({"much", "many", "little", "few"})


def as_as(text: Text, k: int) -> tuple[int, int] | None:
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
