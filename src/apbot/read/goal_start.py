"""On/off settings, zeros, power and start: the parts of a goal said with verbs and negations.

"no prewash", "lock the keys", "no delay", "switch it on", "start it", "don't start it yet",
and a goal setting whose procedure ends by starting the appliance (a TIME DEFROST entry).
"""

from __future__ import annotations

from typing import Any

from apbot.model.domain import build_domain
from apbot.model.schema import (
    DiscreteVariable,
    GoTo,
    NumericVariable,
    TimeVariable,
)
from apbot.read.goal_text import (
    CLAUSE_ENDS,
    FILLERS,
    NUMBER_WORDS,
    STRONG_VERBS,
    VERB_FAMILIES,
    WEAK_VERBS,
    Text,
    clause_starts,
    negative_around,
    phrase_here,
    verb_positions,
)
from apbot.read.goal_view import (
    Goal,
    Model,
    VarInfo,
    domain_values,
    generic,
    magnitude,
    own_concepts,
    own_stems,
    step_effects,
    unit_text,
)
from apbot.read.goal_vocab import (
    NEGATIONS,
    STOP_WORDS,
    concept,
    stem,
)
from apbot.read.numbers import tokenize


def switches(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int] | None = None
) -> None:
    """An on/off setting named in the instruction: on, unless its words are negated."""
    verbs = verb_positions(text)
    for name, info in view.infos.items():
        if info.role != "switch" or name in goal:
            continue
        own = own_stems(info)
        if any(own == own_stems(view.infos[other]) for other in goal):
            continue  # COOK TIME (on/off) beside a COOK TIME given a value: the words named that
        best: tuple[float, int] | None = None
        left = False  # "leave the auto switched off": as it is, not a setting asked for
        for k in range(len(text.tokens)):
            if k in claimed or text.word(k) in STOP_WORDS:
                continue
            key = text.concepts[k]
            if text.stems[k] == stem("unlock") and stem("lock") in own:
                key = concept("lock")  # "unlock the keys": the lock, off
            weight = info.vocab.get(key, 0.0)
            if weight <= 0 and _abbreviated(text.stems[k], own):
                key, weight = text.stems[k], 1.0  # "tablets" for a TABS key
            if weight <= 0 or generic(key):
                continue
            locks = key == concept("lock") or concept("lock") in own_concepts(info)
            if locks and not _locking(text, k):
                continue  # "wake the panel", "hot water": not the (hot-water) lock
            if (
                text.stems[k] in own
                or key in own_concepts(info)
                or key == concept("lock")
                or _abbreviated(text.stems[k], own)
            ):
                weight = 1.0
                # "Warm the water" is not KEEP WARM; "UV light" is not the night light
                doubtful = len(own) > 1 and (k in verbs or (k - 1) in claimed)
                if doubtful and not (phrase_here(text, k, own) or _kept(text, k, own)):
                    continue
            elif negative_around(text, k):
                weight = 0.5  # a feature's word only says "without" ("no finish time")
            else:
                continue
            if any(text.word(k - d) in ("leave", "leaving") for d in range(1, 4)):
                left = True
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
        assert info.on is not None and info.off is not None
        goal[name] = info.on if positive else info.off
        if where is not None:
            where[name] = k
        claimed.add(k)


_LOCK_WORDS = frozenset(
    {"lock", "locked", "locks", "locking", "unlock", "unlocked", "childlock", "lockout", "keylock"}
    | {"release", "released"}
)


def _locking(text: Text, k: int) -> bool:
    """A word of the lock's group ("the panel", "the keys") means the lock only beside a word
    of locking ("lock the panel", "child-lock the controls", "keys locked")."""
    window = range(max(0, k - 4), min(len(text.tokens), k + 4))
    return any(text.word(j) in _LOCK_WORDS or "lock" in text.word(j) for j in window)


def _abbreviated(word: str, own: set[str]) -> bool:
    """The switch's one-word name is a short form of the word ("TABS" for tablets)."""
    return len(own) == 1 and any(
        len(short) >= 3 and word.startswith(short) and len(word) <= len(short) + 4 for short in own
    )


def _kept(text: Text, k: int, own: set[str]) -> bool:
    """ "keep it hot", "keep the water warm": KEEP WARM said with words in between."""
    if text.stems[k] != stem("keep") or stem("warm") not in own:
        return False
    return any(
        text.stems[j] in (stem("warm"), stem("hot"))
        for j in range(k + 1, min(k + 4, len(text.tokens)))
    )


def entry_switches(view: Model, goal: Goal) -> None:
    """A setting entered through a switch ("READY AT" turns the finish timer on, then sets the
    time) implies that switch on, unless the instruction already said otherwise."""
    for _feature, steps in view.model.features.items():
        for index, step in enumerate(steps):
            if step.variable not in goal:
                continue
            for earlier in steps[:index]:
                target = earlier.variable
                info = view.infos.get(target or "")
                if info is None or info.role != "switch" or target in goal:
                    continue
                effects = [effect for _a, effect in step_effects(earlier)]
                if all(effect == "toggle" for effect in effects) and effects:
                    goal[info.name] = info.on


def zero_settings(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int] | None = None
) -> None:
    """ "no delay", "no final spin", "skip the rinse": a numeric setting that can be 0 is 0."""
    for k, token in enumerate(text.tokens):
        if token.text not in NEGATIONS or token.text in ("off", "free", "stop", "cancel"):
            continue
        for d in range(1, 4):
            j = k + d
            if j >= len(text.tokens) or text.word(j) in CLAUSE_ENDS or text.word(j) == ",":
                break
            key = text.concepts[j]
            homes = [
                info
                for info in view.infos.values()
                if info.name not in goal
                and info.role == "setting"
                and not isinstance(info.var, DiscreteVariable)
                and (text.stems[j] in own_stems(info) or key in own_concepts(info))
                and _starts_at_zero(info)
            ]
            if len(homes) == 1:
                values = domain_values(view, homes[0], goal)
                zero = next((v for v in values if magnitude(v) == 0), None)
                if zero is None and homes[0].timing in ("delay", "finish") and values:
                    zero = min(values, key=lambda v: magnitude(v) or 0.0)  # the soonest end
                if zero is not None:
                    goal[homes[0].name] = zero
                    if where is not None:
                        where[homes[0].name] = j
                    claimed.add(j)
                break


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
            if info.name in goal or info.role != "setting" or text.stems[j] not in own_stems(info):
                continue
            values = domain_values(view, info, goal)
            for value in values:
                words = [stem(w) for w in str(value).casefold().split()]
                if len(words) == 2 and words[0] in ("no", "without") and words[1] == text.stems[j]:
                    goal[info.name] = value
                    claimed.add(j)
            plain = [v for v in values if str(v).casefold() in _PLAIN]
            if info.name not in goal and len(plain) == 1 and isinstance(info.var, DiscreteVariable):
                goal[info.name] = plain[0]  # "without any preset": the MANUAL (no preset) one
                claimed.add(j)


_PLAIN = frozenset({"manual", "none", "normal"})


def _starts_at_zero(info: VarInfo) -> bool:
    """A setting whose "none" is 0: any number, or a duration that starts empty (not a clock)."""
    if isinstance(info.var, NumericVariable):
        return True
    if isinstance(info.var, TimeVariable) and info.timing not in ("clock", "finish"):
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


_DENIALS = frozenset({"don't", "dont", "not", "without", "never"})


_START_WORDS = frozenset({"start", "begin", "started", "starting", "begins", "kick", "launch"})


_NOW_PHRASES = ("right away", "straight away", "immediately")


def power_and_running(view: Model, text: Text, goal: Goal, counting: bool = False) -> None:
    """Power on when asked; the running variable on (or off) when the instruction says so, a
    goal setting's procedure starts it, or a delay counts down from now (``counting``)."""
    for name, info in view.infos.items():
        if info.role == "power" and name not in goal and _says_power_on(view, text):
            goal[name] = info.on
    running = [n for n, i in view.infos.items() if i.role == "running"]
    if not running:
        # no running state of its own: the appliance works while it is on ("start cooling")
        power = [n for n, i in view.infos.items() if i.role == "power" and n not in goal]
        said = _says_start(text, None, _named_starts(view, text), verbs=False)
        if power and (said or _running_now(text)):
            goal[power[0]] = view.infos[power[0]].on
        return
    if any(n in goal for n in running):
        return
    family = next((VERB_FAMILIES[stem(n)] for n in running if stem(n) in VERB_FAMILIES), None)
    start = _says_start(text, family, _named_starts(view, text), settings=_setting_words(view))
    started_by = _procedure_start(view, goal)
    if start is None and started_by is not None:
        start = True  # the procedure for a goal setting ends by starting (TIME DEFROST)
    delayed = any(view.infos[n].timing == "delay" for n in goal)
    if start is None and (counting or delayed) and _timer_mode(view, goal):
        return  # a countdown armed by choosing the TIMER mode: it starts by itself
    if start is None and counting:
        start = True  # "ready in 15 hours": only a started countdown ends then
    if start is None:
        return
    key = next((v for v in goal if v in view.start_values), None)
    target = started_by or view.start_values.get(key) or view.start_values.get(None)
    if target is None:
        return
    name, value = target
    info = view.infos[name]
    if start:
        goal[name] = value
    else:
        if info.off is not None:
            goal[name] = info.off
        elif info.var.depends_on is None:  # its start value (a dependent one has no own)
            domain = build_domain(info.var)
            goal[name] = domain.values[domain.initial]


def _timer_mode(view: Model, goal: Goal) -> bool:
    """A mode setting with a TIMER (or DELAY) value arms a delayed start: set it, when the
    goal has not chosen that setting otherwise."""
    for info in view.infos.values():
        if info.role != "setting" or not isinstance(info.var, DiscreteVariable):
            continue
        armed = [v for v in info.values if concept(str(v)) in (concept("timer"), concept("delay"))]
        if len(armed) == 1 and goal.get(info.name) in (None, *armed):
            goal[info.name] = armed[0]
            return True
    return False


def _procedure_start(view: Model, goal: Goal) -> tuple[str, Any] | None:
    """(running variable, value) when a goal setting's own procedure ends with a step that
    sets the running variable — the model says that entering it starts the appliance."""
    for _feature, steps in view.model.features.items():
        for index, step in enumerate(steps):
            if step.variable not in goal:
                continue
            for later in steps[index + 1 :]:
                info = view.infos.get(later.variable or "")
                if info is None or info.role != "running":
                    continue
                for _action, effect in step_effects(later):
                    if isinstance(effect, GoTo):
                        return info.name, effect.to
    return None


def _says_power_on(view: Model, text: Text) -> bool:
    """ "turn the machine on", "switch on, ...", "power the bread maker up"."""
    n = len(text.tokens)
    switch_words = {s for i in view.infos.values() if i.role == "switch" for s in own_stems(i)}
    for k, token in enumerate(text.tokens):
        if token.text not in ("turn", "switch", "power", "switched", "turned"):
            continue
        if token.text in ("switched", "turned") and text.stems[k - 1] in switch_words:
            continue  # "Keep Fresh switched on": that switch, not the power
        j = k + 1
        while j < n and (concept(text.word(j)) in view.appliance_words or text.word(j) == "the"):
            j += 1
        if text.word(j) not in ("on", "up"):
            continue
        if j > k + 1:
            return True  # "turn it on", "power the bread maker up"
        m = j + 1
        while m < n and (concept(text.word(m)) in view.appliance_words or text.word(m) == "the"):
            m += 1
        if m >= n or text.word(m) in CLAUSE_ENDS | {",", "and", "then"} | _AFTER_ON:
            return True  # "switch on, ...", "switch on the cooker and ...", "switch on in fan"
        if _mode_word(view, text.stems[m]) and not any(
            i.role == "running" for i in view.infos.values()
        ):
            return True  # "switch on heating at 30 °C": on, in that mode
    for k in range(n):  # "wake the panel", "wake it up"
        if text.stems[k] == stem("wake") and (k == 0 or text.word(k - 1) in CLAUSE_ENDS | {","}):
            return True
    for k, token in enumerate(text.tokens):  # "with the machine left on", "leave it on"
        if token.text in ("leave", "left", "keep", "kept", "stay", "stays"):
            j = k + 1
            while j < n and (
                concept(text.word(j)) in view.appliance_words or text.word(j) == "the"
            ):
                j += 1
            before = concept(text.word(k - 1)) in view.appliance_words
            if (
                text.word(j) == "on"
                and (j > k + 1 or before)
                and text.word(j + 1) in (CLAUSE_ENDS | {",", "and", "then", ""})
            ):
                return True
    return False


def _setting_words(view: Model) -> frozenset[str]:
    """Concepts that name a setting outright (its own name or label; not generic words)."""
    return frozenset(
        key
        for info in view.infos.values()
        if info.role == "setting"
        for key, weight in info.vocab.items()
        if weight >= 0.8 and (not generic(key) or key == concept("program"))
    )


def _running_now(text: Text) -> bool:
    """ "…, locked, and running": the appliance asked to be running (not "running low")."""
    return any(
        token.text == "running"
        and text.word(k + 1) in CLAUSE_ENDS | {"", ","}
        and not any(text.word(k - d) in _DENIALS for d in range(1, 4))
        for k, token in enumerate(text.tokens)
    )


def _mode_word(view: Model, word: str) -> bool:
    """The word is a one-word value of a programme-like setting (HEAT, COOL, DRY)."""
    return any(
        stems == (word,)
        for var, _value, stems, weight in view.phrases
        if weight >= 1.0 and view.infos[var].role == "setting"
    )


_SET_GOING = frozenset({"going", "started", "cooking", "heating", "running"})
_GOING = frozenset(
    {"going", "started", "cooking", "heating", "running", "brewing", "washing", "blending"}
    | {"pouring", "dispensing", "working", "baking", "drying"}
)


def _later(text: Text, k: int) -> bool:
    """A start word followed in its clause by "in/after N ..." (a delayed start)."""
    for j in range(k + 1, min(k + 6, len(text.tokens))):
        word = text.word(j)
        if word in CLAUSE_ENDS or word == ",":
            return False
        following = text.word(j + 1)
        if following in ("a", "an"):
            following = text.word(j + 2)
        numeral = following[:1].isdigit() or following in NUMBER_WORDS | {"half", "quarter"}
        if word in ("in", "after") and numeral:
            return True
    return False


_NOT_ASKED = frozenset({"can't", "cannot", "couldn't", "won't", "i'll", "i", "we'll", "we"})


def _someone_else(text: Text, k: int) -> bool:
    """The start is said of someone else or of what may not happen ("so the kids can't start
    it", "I'll start it myself"): not a request to start."""
    for d in range(1, 4):
        word = text.word(k - d)
        if word in CLAUSE_ENDS or word == ",":
            return False
        if word in _NOT_ASKED or (word == "can" and text.word(k - d + 1) == "not"):
            return True
    return False


_AFTER_ON = frozenset({"in", "at", "to", "with", "for"})


def _named_starts(view: Model, text: Text) -> set[int]:
    """Positions of "start" that belong to a setting's name ("the delay start", "start time")."""
    named = set()
    for k, token in enumerate(text.tokens):
        if token.text not in _START_WORDS:
            continue
        for info in view.infos.values():
            label = info.var.label or ""
            own = {stem(t.text) for t in tokenize(f"{info.name.replace('_', ' ')} {label}")}
            if stem("start") in own and phrase_here(text, k, own - {stem("start")}):
                named.add(k)
    return named


def _says_start(
    text: Text,
    family: frozenset[str] | None = None,
    named: set[int] | frozenset[int] = frozenset(),
    verbs: bool = True,
    settings: frozenset[str] = frozenset(),
) -> bool | None:
    """True for "start it", False for "don't start", None when the instruction says neither.
    ``verbs``: an instruction that opens with a doing verb ("Bake a cake") says start too."""
    joined = " " + " ".join(t.text for t in text.tokens) + " "
    negative = False
    positive = False
    for k, token in enumerate(text.tokens):
        word = token.text
        starts = word in _START_WORDS and k not in named
        if word in ("get", "set") and any(
            text.word(k + d) in (_GOING if word == "get" else _SET_GOING)
            for d in range(2 if word == "set" else 1, 7)
        ):
            starts = True  # "get it going", "set the rice cooking" (not "set heating at 21")
        if word == "go" and text.word(k + 1) in ("ahead", ".", "!", ""):
            starts = True
        if word == "run" and text.word(k + 1) == "it" and k in clause_starts(text):
            starts = True  # "Run it in dry mode"
        if not starts:
            continue
        if _later(text, k):
            continue  # "start by itself in six hours": a timer, not now
        if _someone_else(text, k):
            continue  # "so the kids can't start it", "I'll start it myself"
        if text.word(k - 1) in ("delayed", "delay", "timed", "auto"):
            continue  # "arm the delayed start": the timer's name
        before = []
        for d in range(1, 4):
            if text.word(k - d) in CLAUSE_ENDS:
                break
            before.append(text.word(k - d))
        denied = any(b in _DENIALS for b in before)
        if denied or "yet" in (text.word(k + 1), text.word(k + 2)):
            negative = True
        else:
            positive = True
    if " not started " in joined or " but not start" in joined:
        negative = True
    for k, token in enumerate(text.tokens):  # "don't heat it yet"
        if token.text in _DENIALS and token.text != "without" and k + 1 < len(text.stems):
            verb = text.stems[k + 1]
            if verb in STRONG_VERBS and (family is None or verb in family):
                negative = True
    if negative:
        return False
    if positive or any(f" {w} " in joined for w in _NOW_PHRASES):
        return True
    for k, token in enumerate(text.tokens):
        if (
            token.text == "now"
            and text.word(k - 1) not in ("from", "for")
            and text.word(k + 1) != "on"
        ):
            return True
    if not verbs:
        return None
    for k in clause_starts(text, loose=True):
        k2 = k + 1 if text.word(k) in FILLERS else k
        if k2 >= len(text.stems):
            continue
        verb = text.stems[k2]
        if family is not None and verb not in family:
            continue
        if verb in STRONG_VERBS:
            return True
        if verb in WEAK_VERBS and (k == 0 or text.word(k - 1) in (".", ";", "!")):
            if verb == stem("give") and any(
                text.concepts[j] in settings for j in range(k2 + 1, min(k2 + 9, len(text.tokens)))
            ):
                continue  # "Give the … dry cycle 90 minutes": a setting is given a value
            return True
        if verb in WEAK_VERBS and text.word(k2 + 1) == "me":
            return True  # "... and make me an espresso"
    return None
