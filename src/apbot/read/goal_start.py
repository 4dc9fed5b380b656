"""Starting: the running part of a goal said with verbs — "start it", "don't start it yet", and a
goal setting whose procedure ends by starting the appliance (a TIME DEFROST entry). Power said
with verbs ("switch it on") is goal_power_said's."""

from __future__ import annotations

from itertools import pairwise
from typing import Any

from apbot.model.domain import build_domain
from apbot.model.schema import DiscreteVariable, GoTo
from apbot.read.goal_held import (
    KEEPING,
    START_WORDS,
    held_back,
    left_off_for_now,
    said_later,
    someone_else,
    users_own,
)
from apbot.read.goal_kept_off import says_kept_off
from apbot.read.goal_power_said import (
    a_switch_state,
    says_power_off,
    says_power_on,
    setting_names,
    setting_words,
)
from apbot.read.goal_roles import doing_name
from apbot.read.goal_switch_values import started_switches
from apbot.read.goal_text import (
    CLAUSE_ENDS,
    FILLERS,
    STRONG_VERBS,
    VERB_FAMILIES,
    WEAK_VERBS,
    Text,
    clause_starts,
    new_act,
    phrase_here,
)
from apbot.read.goal_view import Goal, Model, step_effects
from apbot.read.goal_vocab import concept, stem
from apbot.read.number_tokens import tokenize

_DENIALS = frozenset({"don't", "dont", "not", "without", "never"})


_HELD_STATES = frozenset({"stopped", "paused", "idle", "unstarted"})


_NOW_PHRASES = ("right away", "straight away", "immediately")


def power_and_running(view: Model, text: Text, goal: Goal, counting: bool = False) -> None:
    """Power on when asked; the running variable on (or off) when the instruction says so, a
    goal setting's procedure starts it, or a delay counts down from now (``counting``)."""
    for name, info in view.infos.items():
        if info.role == "power" and name not in goal and says_power_on(view, text, goal):
            goal[name] = info.on
        elif (
            info.role == "power"
            and name not in goal
            and (says_power_off(view, text) or says_kept_off(view, text))
        ):
            goal[name] = info.off
            return  # switched off: nothing is started
    running = [n for n, i in view.infos.items() if i.role == "running"]
    if not running:
        # no running state of its own: the appliance works while it is on ("start cooling")
        power = [n for n, i in view.infos.items() if i.role == "power" and n not in goal]
        starts = _named_starts(view, text) | started_switches(view, text)  # not the click's
        said = _says_start(text, None, starts, verbs=False)
        if power and (said or _running_now(view, text, goal)):
            goal[power[0]] = view.infos[power[0]].on
        return
    if any(n in goal for n in running):
        return
    family = next((VERB_FAMILIES[stem(n)] for n in running if stem(n) in VERB_FAMILIES), None)
    doing = [n for n in running if doing_name(n)]
    if family is None and doing:
        family = frozenset({stem(doing[0])})  # PRINTING is started by "print", no other verb
    start = _says_start(
        text,
        family,
        _named_starts(view, text),
        settings=setting_words(view),
        names=setting_names(view),
        compounds=_name_pairs(view),
    )
    if start is None and doing:
        start = _own_verb(text, doing[0])  # "… and print.", "don't print yet"
    if start is None and _running_now(view, text, goal):
        start = True  # "with a one-minute countdown running.": asked to be under way
    started_by = _procedure_start(view, goal)
    if start is None and started_by is not None:
        start = True  # the procedure for a goal setting ends by starting (TIME DEFROST)
    delayed = any(view.infos[n].timing == "delay" for n in goal)
    if start is None and (counting or delayed) and _timer_mode(view, goal):
        return  # a countdown armed by choosing the TIMER mode: it starts by itself
    if start is None and counting and not doing:
        start = True  # "ready in 15 hours": only a started countdown ends then (by START,
        # not the key of a doing: "hold off the watering for two days" waters nothing now)
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


def _own_verb(text: Text, name: str) -> bool | None:
    """The verb of a doing ("print" for PRINTING) denied ("don't print yet": False) or opening
    a clause ("… and print.", "carbonate it now": True); None when it is not said so."""
    own = stem(name)
    if any(s == own and text.word(k - 1) in _DENIALS for k, s in enumerate(text.stems)):
        return False
    opens = clause_starts(text, loose=True)
    return True if any(k < len(text.stems) and text.stems[k] == own for k in opens) else None


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


def _running_now(view: Model, text: Text, goal: Goal) -> bool:
    """ "…, locked, and running": the appliance asked to be running (not "running low", nor
    "with the circulation running": a switch's state)."""
    return any(
        token.text == "running"
        and (text.word(k + 1) in CLAUSE_ENDS | {"", ","} or _said_running_at(view, text, k))
        and not any(text.word(k - d) in _DENIALS for d in range(1, 4))
        and not a_switch_state(view, text, goal, k)
        for k, token in enumerate(text.tokens)
    )


def _said_running_at(view: Model, text: Text, k: int) -> bool:
    """ "Drill running at six thousand", "the mill running at fineness 3": the appliance's own
    noun, then "running at" its setting, is the appliance asked to run (not "the fan running
    at high", a part's state)."""
    return text.word(k + 1) == "at" and concept(text.word(k - 1)) in view.appliance_words


_SET_GOING = frozenset({"going", "started", "cooking", "heating", "running"})
_GOING = frozenset(
    {"going", "started", "cooking", "heating", "running", "brewing", "washing", "blending"}
    | {"pouring", "dispensing", "working", "baking", "drying"}
)


def _named_starts(view: Model, text: Text) -> set[int]:
    """Positions of "start" that belong to a setting's name ("the delay start", "start time")."""
    named = set()
    for k, token in enumerate(text.tokens):
        if token.text not in START_WORDS:
            continue
        for info in view.infos.values():
            label = info.var.label or ""
            own = {stem(t.text) for t in tokenize(f"{info.name.replace('_', ' ')} {label}")}
            if stem("start") in own and phrase_here(text, k, own - {stem("start")}):
                named.add(k)
    return named


_AFTER_MOTION = CLAUSE_ENDS | {"", ",", "and", "now", "again", "freely", "until", "till"}


def _set_in_motion(text: Text, k: int, family: frozenset[str] | None) -> bool:
    """A causative that sets the appliance or its load working: "get it moving", "get the
    belt turning" (GET, then IT or THE and a noun, then a verb in -ing that ends the clause),
    "let it run", "let the water run freely" (LET, then the same, then RUN or the running
    state's own verb)."""
    j = k + 2 if text.word(k + 1) in ("it", "them") else k + 3
    if j == k + 3 and text.word(k + 1) != "the":
        return False
    verb = text.word(j)
    if text.word(j + 1) not in _AFTER_MOTION or not verb.isalpha():
        return False
    if j == k + 3 and text.word(j + 1) in ("until", "till"):
        return False  # "let the water run until it runs clear": a tap rinsing, not the appliance
    if text.word(k) == "get":
        return verb.endswith("ing") and len(verb) > 5
    return verb == "run" or (family is not None and stem(verb) in family)


def _says_start(
    text: Text,
    family: frozenset[str] | None = None,
    named: set[int] | frozenset[int] = frozenset(),
    verbs: bool = True,
    settings: frozenset[str] = frozenset(),
    names: frozenset[str] = frozenset(),
    compounds: frozenset[tuple[str, str]] = frozenset(),
) -> bool | None:
    """True for "start it", False for "don't start", None when the instruction says neither.
    ``verbs``: an instruction that opens with a doing verb ("Bake a cake") says start too —
    not a setting's own word a bare number follows ("Granulated sugar, heat 7", "melt 42"):
    that names the setting and its value."""
    joined = " " + " ".join(t.text for t in text.tokens) + " "
    negative = False
    positive = False
    for k, token in enumerate(text.tokens):
        word = token.text
        starts = word in START_WORDS and k not in named
        if word in ("get", "set") and any(
            text.word(k + d) in (_GOING if word == "get" else _SET_GOING)
            for d in range(2 if word == "set" else 1, 7)
        ):
            starts = True  # "get it going", "set the rice cooking" (not "set heating at 21")
        if word in ("get", "let") and _set_in_motion(text, k, family):
            starts = True  # "get it moving", "let the water run": the appliance set working
        if word == "go" and text.word(k + 1) in ("ahead", ".", "!", ""):
            starts = True
        if word == "run" and text.word(k + 1) == "it" and k in clause_starts(text):
            starts = True  # "Run it in dry mode"
        on_to_run = word == "run" and text.word(k - 1) == "to" and text.word(k - 2) == "on"
        set_running = word == "running" and text.word(k - 1) == "it"
        if on_to_run or (set_running and text.word(k - 2) in ("set", "get", "leave", "keep")):
            starts = True  # "switch it on to run", "set it running", "leave it running"
        if word in _HELD_STATES and any(text.word(k - d) in KEEPING | {"stay"} for d in (1, 2, 3)):
            negative = True  # "leave it stopped for now", "keep it paused"
        if left_off_for_now(text, k):
            negative = True  # "leave it off for now"
        if not starts:
            continue
        if said_later(text, k):
            continue  # "start by itself in six hours": a timer, not now
        if users_own(text, k):
            negative = True  # "wait for me to start": not now
            continue
        if someone_else(text, k):
            continue  # "so the kids can't start it"
        if text.word(k - 1) in ("delayed", "delay", "timed", "auto"):
            continue  # "arm the delayed start": the timer's name
        before = []
        for d in range(1, 4):
            if text.word(k - d) in CLAUSE_ENDS or new_act(text, k - d):
                break  # "without preheating and get it started": the start is a new order
            before.append(text.word(k - d))
        denied = any(b in _DENIALS for b in before)
        if denied or "yet" in (text.word(k + 1), text.word(k + 2)):
            negative = True
        else:
            positive = True
    if " not started " in joined or " but not start" in joined or held_back(text, family):
        negative = True
    if " not now " in joined:  # "at midnight, not now"
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
        said_time = text.word(k - 1)[:1].isdigit() or text.word(k - 1) in ("am", "pm", "oclock")
        if (
            token.text == "now"
            and text.word(k - 1) not in ("from", "for")
            and text.word(k + 1) != "on"
            and not said_time  # "it's 9:50 now": the time of day, to set the clock by
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
        if _named_with_a_number(names, text, k2):
            continue  # "heat 7": a setting named with its value, not a doing
        if _plural_form(text.word(k2)):
            continue  # "Fries at 175 degrees": a plural noun, never an order's bare verb
        # (a verb that ends the text is still a doing: "Speed 3, then blend")
        after = text.stems[k2 + 1] if k2 + 1 < len(text.stems) else ""
        if verb != stem("run") and (text.word(k2 + 1) == "-" or after in _KIND_NOUNS):
            continue  # "Clean mode at pressure 8", "Warm-holding on": a name, not a doing
        after_verb = text.stems[k2 + 1] if k2 + 1 < len(text.stems) else ""
        if verb in _NOUNS_TOO and (text.word(k2 + 1) == ":" or (verb, after_verb) in compounds):
            continue  # "Stitch length 3" of STITCH LENGTH, "Stitch: zigzag": a name, no order
        if verb in STRONG_VERBS:
            return True
        if verb == stem("get") and _made_ready(text, k2):
            continue  # "Get a 300 ml mug of water ready": set up, not started
        if verb in WEAK_VERBS and (k == 0 or text.word(k - 1) in (".", ";", "!")):
            if verb == stem("give") and any(
                text.concepts[j] in settings for j in range(k2 + 1, min(k2 + 9, len(text.tokens)))
            ):
                continue  # "Give the … dry cycle 90 minutes": a setting is given a value
            return True
        if verb in WEAK_VERBS and text.word(k2 + 1) == "me":
            return True  # "... and make me an espresso"
    return None


_KIND_NOUNS = frozenset(
    stem(w) for w in ("mode", "programme", "program", "setting", "cycle", "menu", "function")
)


def _name_pairs(view: Model) -> frozenset[tuple[str, str]]:
    """Each two words that stand together in a setting's name or label (STITCH LENGTH)."""
    pairs = set()
    for info in view.infos.values():
        for said in (info.name.replace("_", " "), info.var.label or ""):
            stems = [stem(t.text) for t in tokenize(said.casefold())]
            pairs |= set(pairwise(stems))
    return frozenset(pairs)


_NOUNS_TOO = frozenset(
    stem(w) for w in ("play", "stitch", "sew", "embroider", "sharpen", "laminate")
)
"""Orders of the work that are as often the first word of a setting's name: "Stitch length
3", "Play mode: shuffle" set a setting and start nothing."""


def _made_ready(text: Text, k: int) -> bool:
    """ "Get a mug of hot water ready", "get it ready for …": "ready" closes the object of
    GET in its clause — the appliance is to be prepared, not set going."""
    for j in range(k + 1, min(k + 12, len(text.tokens))):
        if text.word(j) in CLAUSE_ENDS or text.word(j) in (",", ";"):
            return False
        if text.word(j) == "ready":
            return True
    return False


def _plural_form(word: str) -> bool:
    """A word ending in -s as plural nouns do (FRIES, "chips"): an order opens with the bare
    verb ("Fry", "Bake"), so such a word opening a clause is a thing named, not a doing."""
    return len(word) > 3 and word.endswith("s") and not word.endswith(("ss", "us", "is"))


def _named_with_a_number(names: frozenset[str], text: Text, k: int) -> bool:
    """The word at k is a setting's own name and a bare number follows it, ending the clause
    ("heat 7,", "melt 42,"): not "defrost 750 g" (an amount to work on)."""
    number = text.word(k + 1).replace(".", "", 1)
    return (
        text.concepts[k] in names
        and number.isdigit()
        and text.word(k + 2) in CLAUSE_ENDS | {"", ",", "and"}
    )
