"""On/off settings: "no prewash", "lock the keys", "mute", a switch named by its lamp's word, and
a switch a goal setting's own procedure turns on (READY AT turns the finish timer on). Settings
said to be none or off by a negation or a verb ("no delay", "skip the rinse") are ``goal_offs``'."""

from __future__ import annotations

from apbot.read.goal_let import kept_on, never_let
from apbot.read.goal_shortened import compound_of_name
from apbot.read.goal_switch_words import (
    another_switchs_phrase,
    qualified_by_anothers,
    state_said_after,
    tail_of_anothers,
    whole_name_switched,
)
from apbot.read.goal_text import (
    CLAUSE_ENDS,
    VERB_FAMILIES,
    Text,
    negated_before,
    negative_around,
    phrase_here,
    verb_positions,
)
from apbot.read.goal_values import (
    OFF_WORDS,
    ON_WORDS,
    generic,
    kind_noun,
    name_words,
)
from apbot.read.goal_view import (
    Goal,
    Model,
    VarInfo,
    doer_stems,
    its_own_word,
    own_concepts,
    own_stems,
)
from apbot.read.goal_vocab import (
    NEGATIONS,
    STOP_WORDS,
    SYNONYMS,
    concept,
    cut_short,
    said_as_doer,
    stem,
)


def switches(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int] | None = None
) -> None:
    """An on/off setting named in the instruction: on, unless its words are negated."""
    verbs = verb_positions(text)
    # "start pouring" names the operation under way, not a SLOW POUR switch that shares its verb
    operating = {
        v
        for n, i in view.infos.items()
        if i.role == "running"
        for v in VERB_FAMILIES.get(stem(n), ())
    }
    for name, info in view.infos.items():
        if info.role != "switch" or name in goal:
            continue
        own = own_stems(info)
        doers = doer_stems(info)  # "dim it" for a DIMMER: names it, makes it no longer name
        # COOK TIME (on/off) beside a COOK TIME given a value: its own words named that one;
        # only another word of it (the SOUND its legend says it switches) names the switch
        shadowed = any(own == own_stems(view.infos[other]) for other in goal)
        best: tuple[float, int] | None = None
        left = False  # "leave the auto switched off": as it is, not a setting asked for
        for k in range(len(text.tokens)):
            if k in claimed or text.word(k) in STOP_WORDS:
                continue
            key = text.concepts[k]
            if text.stems[k] == stem("unlock") and stem("lock") in own:
                key = concept("lock")  # "unlock the keys": the lock, off
            weight = info.vocab.get(key, 0.0)
            cut = _abbreviated(view, goal, text.stems[k], own)
            if weight <= 0 and cut:
                key, weight = text.stems[k], 1.0  # "tablets" for a TABS key
            if weight <= 0 and compound_of_name(view, info, text.word(k)):
                key, weight = next(iter(own)), 1.0  # "the headlight on" for a LIGHT switch
            if weight <= 0:
                warmth = _kept_warmth(text, k, own)
                if warmth:  # "keep it chilled" for AFTER COOL
                    key, weight = concept(warmth), 1.0
            if weight <= 0 and _mode_synonym(text, k, own):
                key, weight = next(iter(own)), 1.0  # "holiday mode" for a VACATION switch
            if weight <= 0 or (
                generic(key)
                and not _general_own(view, info, text, k)
                and not whole_name_switched(view, info, text, k)  # "the output on"
            ):
                continue  # "heating on" names a HEAT switch; "hold off the watering" no switch
            if text.stems[k] not in own and _in_a_named_phrase(view, info, text, k):
                continue  # "movie sound mode": SOUND MODE's words, not a MUTE's synonym
            if _switching_verb(view, text, k):
                continue  # "Switch the iron on": the verb, not an AUTO SWITCH-OFF's own word
            if _anothers_name(view, goal, info, text.stems[k]):
                continue  # "eco" names the ECO switch, not HOLIDAY that wears ECO's label
            if _part_after(text, k, info.vocab):
                continue  # "clean the ventilation slots": a part of the body, not the switch
            if another_switchs_phrase(view, info, text, k) or tail_of_anothers(view, info, text, k):
                continue  # "super freeze": SUPER FREEZE, not SUPER COOL that shares SUPER
            if qualified_by_anothers(view, info, text, k):
                continue  # "the hazard lights": HAZARD's, no LIGHTS
            if _in_anothers_name(view, goal, info, text, k, where, claimed):
                continue  # "the light timer to 3.5 minutes": LIGHT TIME's word, no LIGHT switch
            mine = text.stems[k] in own or key in own_concepts(info)
            if shadowed and mine and not state_said_after(text, k):
                continue  # but "the alert off" beside ALERT 20-45: the ALERT hold, its state said
            locks = key == concept("lock") or concept("lock") in own_concepts(info)
            if locks and not _locking(text, k):
                continue  # "wake the panel", "hot water": not the (hot-water) lock
            if text.stems[k] in doers - own and not said_as_doer(
                text.word(k), text.word(k - 1), text.word(k + 1), ON_WORDS + OFF_WORDS
            ):
                continue  # "a bit warmer than usual": a comparative, no KEEP WARM switch
            if (
                text.stems[k] in doers
                or key in own_concepts(info)
                or key == concept("lock")
                or cut
                or _lamp_word(view, info, text.word(k))
            ):
                weight = 1.0
                # "Warm the water" is not KEEP WARM; "UV light" is not the night light
                doubtful = len(own) > 1 and (
                    k in verbs or (k - 1) in claimed or text.stems[k] in operating
                )
                if doubtful and not (phrase_here(text, k, own) or _kept(text, k, own)):
                    continue
            elif negative_around(text, k):
                weight = 0.5  # a feature's word only says "without" ("no finish time")
            elif _state_after(text, k, info.vocab) and key not in view.appliance_words:
                weight = 0.5  # "the recirculation pump on": its legend's thing, its state said
            else:
                continue
            if any(text.word(k - d) in ("leave", "leaving") for d in range(1, 4)):
                left = True
            shared = len(own) > 1 and _names_a_setting(view, goal, text.stems[k])
            if shared and not phrase_here(text, k, own - {text.stems[k]}):
                continue  # "medium mist": the MIST level, not the WARM MIST switch
            if best is None or weight > best[0]:
                best = (weight, k)
        if best is None or left:
            continue
        k = best[1]
        last = k  # the switch's name may run over several words ("automatic keep-warm")
        while last + 1 < len(text.tokens) and (
            text.stems[last + 1] in own
            or text.concepts[last + 1] in own_concepts(info)
            or (
                text.word(last + 1) == "-"
                and text.stems[min(last + 2, len(text.tokens) - 1)] in own
            )
        ):
            last += 1
        positive = not (negative_around(text, k) or negative_around(text, last))
        if text.word(k) in _SILENCING and text.stems[k] in own:
            positive = not _denied_before(text, k)  # "mute it" turns a MUTE switch on
        if any(never_let(text, p) for p in range(max(0, k - 3), last + 1) if text.stems[p] in own):
            positive = False  # "never let it go into the dim mode": AUTO DIM off
        elif kept_on(text, k, last):
            positive = True  # "don't let the light go out": the light stays on
        assert info.on is not None and info.off is not None
        goal[name] = info.on if positive else info.off
        if where is not None:
            where[name] = k
        claimed.add(k)


_SILENCING = frozenset({"mute", "silence"})
_DENIALS = frozenset({"don't", "dont", "not", "never", "no", "without"})


def _in_a_named_phrase(view: Model, info: VarInfo, text: Text, k: int) -> bool:
    """The word at ``k`` is one of another variable's own name words, said with another of
    them beside it ("sound mode" of SOUND MODE): that name, not a synonym of this switch."""
    for other in view.infos.values():
        words = own_stems(other)
        named = other is not info and text.stems[k] in words and len(words) > 1
        if named and phrase_here(text, k, words - {text.stems[k]}):
            return True
    return False


def _denied_before(text: Text, k: int) -> bool:
    """ "don't mute it": a denial in the three words before ``k``, in its clause."""
    for d in range(1, 4):
        word = text.word(k - d)
        if word in CLAUSE_ENDS or word == ",":
            return False
        if word in _DENIALS:
            return True
    return False


def _lamp_word(view: Model, info: VarInfo, word: str) -> bool:
    """The one word the display lights while the switch is on (PUMP for a RECIRC key's
    recirculation): what the user sees it called, so "the pump on" names it — when it is no
    general word (AUTO, ON) and no other setting's own word or value."""
    show = info.var.show if isinstance(info.var.show, dict) else {}
    lit = str(show.get(str(info.on), "")).strip().casefold()
    if not lit.isalpha() or len(lit) < 3 or word.casefold() not in (lit, f"{lit}s"):
        return False  # the word as lit, a noun: "nearly boiling" is no BOIL lamp
    said = stem(lit)
    if generic(concept(said)) or lit in ON_WORDS + OFF_WORDS or lit == "auto":
        return False
    return not any(
        other is not info
        and (said in own_stems(other) or any(stem(str(v).casefold()) == said for v in other.values))
        for other in view.infos.values()
    )


# openings and parts of the body a switch's word may name ("fan vents", "ventilation slots")
_PARTS = frozenset(
    {"slot", "slots", "opening", "openings", "vent", "vents", "grille", "grilles", "hole"}
    | {"holes", "outlet", "outlets", "inlet", "inlets", "duct", "ducts", "louvre", "louvres"}
    | {"louver", "louvers", "intake", "intakes"}
)


def _part_after(text: Text, k: int, vocab: dict[str, float]) -> bool:
    """The switch's words at ``k`` (and the ones right after it) name a part: a word of
    openings or covers follows them ("the ventilation slots", "air circulation vents")."""
    j = k + 1
    while j < len(text.tokens) and vocab.get(text.concepts[j], 0.0) > 0:
        j += 1
    return j < len(text.tokens) and text.word(j) in _PARTS


def _state_after(text: Text, k: int, vocab: dict[str, float]) -> bool:
    """The switch's words at ``k`` (and the ones right after it) are followed by the state
    asked for, which ends the phrase: "the recirculation pump on, …", "with the pump running."
    ("kernels on the butter programme" is no state); a state negated is not asked for ("never
    with the pump running", "no need for the pump on")."""
    if negated_before(text, k, reach=5):
        return False
    j = k + 1
    while j < len(text.tokens) and vocab.get(text.concepts[j], 0.0) > 0:
        j += 1
    ends = CLAUSE_ENDS | {"", ",", "and", "then"}
    if text.word(j) in ("on", "running") and text.word(j + 1) in ends:
        return True
    # "switch on the daily timer", "enable the timer": the state asked just before the thing
    said = False
    for i in range(k - 1, max(-1, k - 4), -1):
        word = text.word(i)
        if word in _ENABLING or (word == "on" and text.word(i - 1) in ("switch", "turn", "put")):
            said = True
            break
        if word in CLAUSE_ENDS or word in (",", "and", "off") or word in NEGATIONS:
            break
    return said and text.word(j) in ends | {"too", "as", "now"}


_ENABLING = frozenset({"enable", "activate"})


_MODE_NOUNS = frozenset(stem(w) for w in ("mode", "setting", "programme", "function"))


def _general_own(view: Model, info: VarInfo, text: Text, k: int) -> bool:
    return its_own_word(view, info, text.stems[k]) and not negative_around(text, k)


def _mode_synonym(text: Text, k: int, own: set[str]) -> bool:
    """A word of the same meaning as a one-word switch's name, said as a mode ("holiday mode"
    for VACATION, "energy-saving mode" for ECO): a mode's value that the panel has as a switch
    of its own."""
    if len(own) != 1 or k + 1 >= len(text.tokens) or text.stems[k + 1] not in _MODE_NOUNS:
        return False
    name = next(iter(own))
    return any(
        stem(w) == text.stems[k] for n, ws in SYNONYMS.items() if stem(n) == name for w in ws
    )


def _anothers_name(view: Model, goal: Goal, info: VarInfo, word: str) -> bool:
    """The word is only on this switch's label, and it is another switch's own name: the
    other key's second function (HOLIDAY behind a held ECO) does not take ECO's word."""
    if word in {stem(w) for w in name_words(info.name)}:
        return False
    return any(
        other is not info
        and other.role == "switch"
        and name not in goal
        and word in {stem(w) for w in name_words(other.name)}
        for name, other in view.infos.items()
    )


def _in_anothers_name(
    view: Model,
    goal: Goal,
    info: VarInfo,
    text: Text,
    k: int,
    where: dict[str, int] | None,
    claimed: set[int] | frozenset[int] = frozenset(),
) -> bool:
    """The switch's word at ``k`` is said in the name of another setting the goal gives a
    value: beside a word of that setting's own that is none of the switch's ("the bin alarm
    at 100 %"), or as that setting's word right before its value, no state said ("the light
    timer to 3.5 minutes", "light timeout 1.5 min"): that setting's name, not the switch."""
    if text.word(k + 1) in ON_WORDS + OFF_WORDS:
        return False  # "the light on for 2 minutes": the switch, its state said
    for name, other in view.infos.items():
        if other is info or name not in goal or other.role != "setting":
            continue
        # a word of the other's before the switch's makes one name ("the bin alarm"); one
        # after it only when the switch's word is the other's too: "prewash spin 1200" said
        # without a comma lists PREWASH beside the SPIN's value, it names no prewash spin
        shared_word = other.vocab.get(text.concepts[k], 0.0) > 0
        at = (where or {}).get(name)
        for j in (k - 1, k + 1) if shared_word else (k - 1,):
            if not 0 <= j < len(text.tokens) or text.word(j) in STOP_WORDS or j in claimed:
                continue  # "600 rpm ECO": the last word of a value, no name
            if j < k and at is not None and at < j:
                continue  # "extra heavy soil steam": SOIL's name closes its value, said before
            key = text.concepts[j]
            if generic(key) or kind_noun(key) or info.vocab.get(key, 0.0) > 0:
                continue  # "night mode", "eco mode": a kind of setting, said of the switch
            if text.stems[j] in own_stems(other):
                return True
        if info.vocab.get(text.concepts[k + 1] if k + 1 < len(text.tokens) else "", 0.0) > 0:
            continue  # "daily drying at 7 pm": the switch's own name said whole
        head = text.word(k + 1)  # the noun the switch's word qualifies: "light timer"
        compound = head.isalpha() and head not in STOP_WORDS | CLAUSE_ENDS
        compound = compound and text.stems[k + 1] not in _MODE_NOUNS  # "night mode": the switch
        named = other.vocab.get(text.concepts[k], 0.0) > 0
        if compound and named and at is not None and k < at <= k + 5:
            if any(text.word(x) in ON_WORDS + OFF_WORDS for x in range(k + 2, at - 1)):
                continue  # "the glow light on for 5 minutes": the switch, its state said
            return True
    return False


def _names_a_setting(view: Model, goal: Goal, word: str) -> bool:
    """The word is an own word of a setting of several values that the goal already has
    (MIST of the mist level, given "mist 2")."""
    return any(
        info.role == "setting" and name in goal and word in own_stems(info)
        for name, info in view.infos.items()
    )


_LOCK_WORDS = frozenset(
    {"lock", "locked", "locks", "locking", "unlock", "unlocked", "childlock", "lockout", "keylock"}
    | {"release", "released", "childproof", "proof"}
)


def _locking(text: Text, k: int) -> bool:
    """A word of the lock's group ("the panel", "the keys") means the lock only beside a word
    of locking ("lock the panel", "child-lock the controls", "keys locked")."""
    window = range(max(0, k - 4), min(len(text.tokens), k + 4))
    return any(text.word(j) in _LOCK_WORDS or "lock" in text.word(j) for j in window)


def _abbreviated(view: Model, goal: Goal, word: str, own: set[str]) -> bool:
    """The switch's one-word name is a short form of the word ("TABS" for tablets, "OSC"
    for oscillation). A name cut at a syllable of a much longer word ("REGEN" of
    regeneration) yields to a setting the goal has that wears the same name."""
    if len(own) != 1:
        return False
    short = next(iter(own))
    if not cut_short(short, word):
        return False
    return len(word) <= len(short) + 4 or not _worn_by_setting(view, goal, own)


def _worn_by_setting(view: Model, goal: Goal, own: set[str]) -> bool:
    """A setting the goal already has wears the switch's name among its own words (REGEN
    TIME beside REGEN): the longer word the user said ("move the regeneration to 1 am")
    named that setting, not the switch."""
    return any(
        info.role == "setting" and name in goal and own < own_stems(info)
        for name, info in view.infos.items()
    )


def _kept(text: Text, k: int, own: set[str]) -> bool:
    """ "keep it hot", "keep the water warm", "keep it cold": KEEP WARM (KEEP COOL) said with
    words in between, or with a word of the same warmth."""
    rest = own - {stem("keep")}
    if text.stems[k] != stem("keep") or not rest:
        return False
    said = rest | {s for word in rest for s in _WARMTH.get(word, ())}
    return any(text.stems[j] in said for j in range(k + 1, min(k + 4, len(text.tokens))))


def _kept_warmth(text: Text, k: int, own: set[str]) -> str:
    """ "keep it chilled", "keep them cold": a word of the warmth of one of the switch's own
    words (AFTER COOL), said after "keep"; that own word, or ""."""
    if not any(text.stems[j] == stem("keep") for j in range(max(0, k - 3), k)):
        return ""
    return next((word for word in own if text.stems[k] in _WARMTH.get(word, ())), "")


_WARMTH = {
    stem("warm"): frozenset({stem("hot")}),
    stem("cool"): frozenset(stem(w) for w in ("cold", "chilled", "chill", "frozen")),
    stem("cold"): frozenset(stem(w) for w in ("cool", "chilled", "chill", "frozen")),
}


_SWITCHING = frozenset(stem(w) for w in ("switch", "turn"))


def _switching_verb(view: Model, text: Text, k: int) -> bool:
    """Token ``k`` is the verb of switching something on or off ("switch the iron on", "turn it
    off", "switch off the light"), not a word of a switch's name (AUTO SWITCH-OFF)."""
    if text.stems[k] not in _SWITCHING:
        return False
    j = k + 1
    while text.word(j) in ("it", "the") or concept(text.word(j)) in view.appliance_words:
        j += 1
    return text.word(j) in ("on", "off", "up")
