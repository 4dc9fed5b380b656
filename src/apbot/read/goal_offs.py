"""Settings said to be off, none or at their top: "no delay", "without any steam", "turn off the
automatic watering", "let it switch itself off", "bring it to the boil" — the words name no
value, the negation or the verb does (split from ``goal_switches``, which names switches)."""

from __future__ import annotations

import re
from typing import Any

from apbot.model.domain import build_domain
from apbot.model.schema import DiscreteVariable, NumericVariable, TimeVariable
from apbot.read.goal_let import never_let
from apbot.read.goal_text import (
    CLAUSE_ENDS,
    Text,
)
from apbot.read.goal_values import (
    OFF_WORDS,
    generic,
    magnitude,
    unit_text,
)
from apbot.read.goal_view import (
    Goal,
    Model,
    VarInfo,
    doer_stems,
    domain_values,
    its_own_word,
    own_concepts,
    own_stems,
)
from apbot.read.goal_vocab import HANDLING, NEGATIONS, STOP_WORDS, concept, stem

_SELF_OFF_VERBS = frozenset(stem(w) for w in ("switch", "shut", "turn", "power", "cut"))
_PREVENTED = frozenset({"stop", "prevent", "keep", "don't", "dont", "not", "never", "doesn't"})
_PREVENTED |= frozenset({"won't", "disable", "no", "without"})


def self_switching_off(view: Model, text: Text, goal: Goal, claimed: set[int]) -> None:
    """ "stop it from shutting itself off", "let it switch itself off": the automatic
    switch-off (a switch named AUTO OFF), off when the words prevent it, else on."""
    found = [
        info
        for info in view.infos.values()
        if info.role == "switch"
        and info.name not in goal
        and concept("auto") in info.vocab
        and {"off", "stop", "shutoff", "shutdown"}
        & set(info.name.casefold().replace("-", "_").split("_"))
    ]
    if len(found) != 1:
        return
    info = found[0]
    for k, token in enumerate(text.tokens):
        if k in claimed:
            continue
        alone = token.text == "own" and [text.word(k - 2), text.word(k - 1)] == ["on", "its"]
        if alone:
            k -= 2  # "powering down on its own": as "itself"
        elif token.text != "itself":
            k = _off_when_done(text, k)
            if k < 0:
                continue
        by = 1 if text.word(k - 1) == "by" else 0  # "turn off by itself"
        verb = any(text.stems[j] in _SELF_OFF_VERBS for j in (k - 1 - by, k - 2 - by))
        off = "off" in (text.word(k + 1), text.word(k - 1 - by)) or (
            text.word(k - 1 - by) == "down" and text.stems[k - 2 - by] == stem("power")
        )  # "keep it from powering down on its own"
        if not (verb and off):
            continue
        prevented = False
        for d in range(2, 8):
            word = text.word(k - d)
            if word in CLAUSE_ENDS or word == ",":
                break
            if word == "without" and not _gerund(text, (k - 1 - by, k - 2 - by)):
                continue  # "bake without the lid and let it turn itself off"
            prevented = prevented or word in _PREVENTED
        assert info.on is not None and info.off is not None
        goal[info.name] = info.off if prevented else info.on
        claimed.add(k)
        return


def _gerund(text: Text, at: tuple[int, ...]) -> bool:
    """ "without the meter turning itself off": the switching-off verb is what "without" leaves
    out (a gerund); "without the lid and let it turn itself off" leaves out a lid."""
    return any(
        j >= 0 and text.stems[j] in _SELF_OFF_VERBS and text.word(j).endswith("ing") for j in at
    )


_DONE = frozenset({"done", "finished", "ready", "over", "through"})


def _off_when_done(text: Text, k: int) -> int:
    """ "let it turn off afterwards", "switch off when it's done", "shut off at the end": an
    "off" at ``k`` followed by words of finishing reads like "switches itself off". The
    index one past the "off" (where "itself" would stand), or -1."""
    if text.word(k) != "off":
        return -1
    after = [text.word(k + d) for d in range(1, 5)]
    at_end = after[:2] == ["at", "the"] and after[2] in ("end", "finish")
    ends = after[0] in ("afterwards", "afterward") or at_end
    done = after[0] in ("when", "once") and any(w in _DONE for w in after[1:])
    return k + 1 if ends or done else -1


def zero_settings(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int] | None = None
) -> None:
    """ "no delay", "no final spin", "skip the rinse": a numeric setting that can be 0 is 0 —
    not "without touching the timer", "don't change the delay" (left as they are)."""
    for k, token in enumerate(text.tokens):
        if token.text not in NEGATIONS or token.text in ("off", "free", "stop", "cancel"):
            continue
        for d in range(1, 4):
            j = k + d
            if j >= len(text.tokens) or text.word(j) in CLAUSE_ENDS or text.word(j) == ",":
                break
            if text.stems[j] in HANDLING:
                break  # "without touching the timer": left as it is, not none
            home = _zero_home(view, text, goal, j)
            if home is not None:
                _set_zero(view, goal, claimed, where, j, home)
                break


def _zero_home(view: Model, text: Text, goal: Goal, j: int) -> VarInfo | None:
    """The one numeric setting not yet in the goal that the word at ``j`` names and whose
    "none" is 0."""
    key = text.concepts[j]
    homes = [
        info
        for info in view.infos.values()
        if info.name not in goal
        and info.role == "setting"
        and (not isinstance(info.var, DiscreteVariable) or _bare_zero(info) is not None)
        and (text.stems[j] in own_stems(info) or key in own_concepts(info))
        and (_starts_at_zero(info) or _bare_zero(info) is not None)
    ]
    return homes[0] if len(homes) == 1 else None


def _set_zero(
    view: Model,
    goal: Goal,
    claimed: set[int],
    where: dict[str, int] | None,
    j: int,
    home: VarInfo | None,
) -> None:
    if home is None:
        return
    values = domain_values(view, home, goal)
    zero = next((v for v in values if magnitude(v) == 0), _bare_zero(home))
    if zero is None and home.timing in ("delay", "finish") and values:
        zero = min(values, key=lambda v: magnitude(v) or 0.0)  # the soonest end
    if zero is not None:
        goal[home.name] = zero
        if where is not None:
            where[home.name] = j
        claimed.add(j)


_SWITCHING = frozenset({"turn", "switch", "turned", "switched", "set", "put"})


def switched_off_numbers(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int] | None = None
) -> None:
    """ "auto-lock off", "turn off the automatic locking", "the auto-relock disabled": a
    numeric setting whose lowest value 0 is its "none", switched off is 0 — only where "off"
    is no word of its own name (AUTO OFF keeps its minutes) and no number is said for it; said
    with the state after it, only a setting named for what it does automatically (AUTO …):
    "the timer off" may mean the timer left as it is."""
    for k, token in enumerate(text.tokens):
        if token.text in ("disabled", "off") and k > 0 and k - 1 not in claimed:
            home = _zero_home(view, text, goal, k - 1)
            automatic = home is not None and concept("auto") in own_concepts(home)
            if home is not None and automatic and stem("off") not in own_stems(home):
                _set_zero(view, goal, claimed, where, k - 1, home)
                continue
        after = token.text == "off" and text.word(k - 1) in _SWITCHING
        if after or token.text == "disable":
            j = k + 1
            while text.word(j) in ("the", "its", "my", "that"):
                j += 1
            if j < len(text.tokens) and j not in claimed:
                home = _zero_home(view, text, goal, j)
                if home is not None and stem("off") not in own_stems(home):
                    _set_zero(view, goal, claimed, where, j, home)


def off_levels(view: Model, text: Text, goal: Goal, claimed: set[int]) -> None:
    """ "no steam at all", "without any steam", "the mist off": a setting of several levels
    whose first is OFF (off, eco, normal, turbo) named with a negation is off — not a level."""
    for info in view.infos.values():
        if info.name in goal or info.role != "setting":
            continue
        if not isinstance(info.var, DiscreteVariable):
            continue
        values = domain_values(view, info, goal)
        offs = [v for v in values if str(v).casefold() in OFF_WORDS]
        if len(offs) != 1 or len(info.values) < 3:
            continue
        own = doer_stems(info)
        mine = own_concepts(info)
        others = {s for i in view.infos.values() if i is not info for s in own_stems(i)} - own
        for k in range(len(text.tokens)):
            if k in claimed or text.word(k) in STOP_WORDS:
                continue
            if not (text.stems[k] in own or text.concepts[k] in mine):
                continue
            if generic(text.concepts[k]) and not its_own_word(view, info, text.stems[k]):
                continue  # "the water off": WATER TEMP, where no other setting says "water"
            if any(text.stems[j] in others for j in (k - 1, k + 1) if 0 <= j < len(text.stems)):
                continue  # "the vertical steam off": a word of another setting's name
            if _said_off(text, k):
                goal[info.name] = offs[0]
                claimed.add(k)
                break


_LEVEL_FILLERS = frozenset({"the", "any", "a", "its", "more"})


def _said_off(text: Text, k: int) -> bool:
    """The level named at ``k`` is said to be none: "no mist", "without any mist", "turn off the
    mist", "the mist off" — not any negation near it ("don't touch the mist" keeps it as is)."""
    j = k - 1
    while j >= 0 and text.word(j) in _LEVEL_FILLERS:
        j -= 1
    if text.word(j) in ("no", "without", "zero"):
        return True
    if _turned_off(text, j) or (text.word(j).isalpha() and _turned_off(text, _before(text, j))):
        return True  # "turn off the mist", "turn off the automatic watering"
    if never_let(text, k):
        return True  # "never let it go to sleep": the SLEEP after a while, off
    for d in range(1, 4):
        word = text.word(k + d)
        if word in CLAUSE_ENDS or word in (",", "on", ""):
            return False
        if word in ("off", "disabled"):
            return True
    return False


_OFF_VERBS = frozenset({"turn", "switch", "shut", "turning", "switching"})


def _turned_off(text: Text, j: int) -> bool:
    """ "turn off" / "switch off" ends at ``j``."""
    return text.word(j) == "off" and text.word(j - 1) in _OFF_VERBS


def _before(text: Text, j: int) -> int:
    """The word before ``j`` and the fillers before it ("the", "any")."""
    j -= 1
    while j >= 0 and text.word(j) in _LEVEL_FILLERS:
        j -= 1
    return j


def switched_off_values(view: Model, text: Text, goal: Goal, where: dict[str, int]) -> None:
    """ "turn off automatic watering" where AUTO / OFF is the schedule: a value said right
    after "turn off" names what is switched off — its setting goes to its one OFF value."""
    for name, value in list(goal.items()):
        info = view.infos[name]
        k = where.get(name)
        if k is None or info.role != "setting" or not isinstance(info.var, DiscreteVariable):
            continue
        offs = [v for v in domain_values(view, info, goal) if str(v).casefold() in OFF_WORDS]
        if len(offs) == 1 and value != offs[0] and _turned_off(text, _before(text, k)):
            goal[name] = offs[0]


def no_values(view: Model, text: Text, goal: Goal, claimed: set[int]) -> None:
    """ "without spinning" where the spin setting has a "no spin" value: that value."""
    for k, token in enumerate(text.tokens):
        if token.text not in ("no", "without", "skip") or k + 1 >= len(text.tokens):
            continue
        j = k + 1
        while text.word(j) in ("the", "any", "a", "using", "use"):
            j += 1  # "without using any preset"
        if j in claimed or j >= len(text.tokens):
            continue
        for info in view.infos.values():
            limit = text.word(j) == "time" and text.word(j + 1) in ("limit", "limits")
            named = text.stems[j] in own_stems(info)
            if info.name in goal or info.role != "setting" or not (named or limit):
                continue
            values = domain_values(view, info, goal)
            if not named:  # "no time limit": the one setting that can run without end
                values = [v for v in values if str(v).casefold() in _ENDLESS]
            for value in values:
                words = [stem(w) for w in str(value).casefold().split()]
                if len(words) == 2 and words[0] in ("no", "without") and words[1] == text.stems[j]:
                    goal[info.name] = value
                    claimed.add(j)
            plain = [v for v in values if str(v).casefold() in _PLAIN]
            plain = plain or [v for v in values if str(v).casefold() in _ENDLESS]
            if info.name not in goal and len(plain) == 1 and isinstance(info.var, DiscreteVariable):
                goal[info.name] = plain[0]  # "without any preset": the MANUAL (no preset) one
                claimed.add(j)


_PLAIN = frozenset({"manual", "none", "normal"})
_ENDLESS = frozenset({"continuous", "cont", "unlimited", "nonstop", "∞", "endless"})
"""A timer's value that runs without end: "no timer", "no time limit" ask for it."""


def _bare_zero(info: VarInfo) -> Any:
    """The "0" of a list of bare numbers (DELAY 0 / 15 / 30 / 45 / 60 min): its none."""
    if not isinstance(info.var, DiscreteVariable) or len(info.values) < 2:
        return None
    if not all(re.fullmatch(r"\d+(?:\.\d+)?", str(v)) for v in info.values):
        return None
    return next((v for v in info.values if float(v) == 0), None)


def _starts_at_zero(info: VarInfo) -> bool:
    """A setting whose "none" is 0: any number, or a duration that starts empty (not a clock)."""
    if isinstance(info.var, NumericVariable):
        return True
    if isinstance(info.var, TimeVariable) and info.timing not in ("clock", "finish", "at"):
        domain = build_domain(info.var) if not info.var.depends_on else None
        return domain is None or magnitude(domain.values[domain.initial]) == 0
    return False


def boil(view: Model, text: Text, goal: Goal) -> None:
    """ "bring it to the boil": 100 °C on a water temperature setting that offers it."""
    if not any(s == stem("boil") for s in text.stems):
        return
    for info in view.infos.values():
        if info.name in goal or not isinstance(info.var, NumericVariable):
            continue
        if info.dimension == "temperature" and unit_text(info.var).casefold() in ("°c", "c"):
            values = domain_values(view, info, goal)
            if 100 in values and max(values) == 100:
                goal[info.name] = 100
