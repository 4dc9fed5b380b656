"""Quantities to settings: each mention goes to the open setting whose type, unit and words fit
best; a quantity no setting of its kind takes is refused (or kept as said, for a read belief)."""

from __future__ import annotations

import re
from typing import Any

from apbot.model.schema import NumericVariable, TimeVariable
from apbot.model.values import format_hms, preview
from apbot.read.goal_error import GoalParseError
from apbot.read.goal_fit import fit, number_for
from apbot.read.goal_own_names import held_at
from apbot.read.goal_text import CLAUSE_ENDS, Text, near_vocab, repeat_for_a_length, said_before
from apbot.read.goal_ties import own_key_depth
from apbot.read.goal_unitless import unitless_duration, unitless_named
from apbot.read.goal_values import name_words, unit_text, zone_case
from apbot.read.goal_view import Goal, Model, VarInfo, domain_values, own_concepts, own_stems
from apbot.read.goal_vocab import SPAN_ENDS, SPAN_STARTS, concept, stem
from apbot.read.numbers import Mention


def assign_mentions(
    view: Model,
    text: Text,
    mentions: list[Mention],
    goal: Goal,
    claimed: set[int],
    where: dict[str, int],
    outside: list[str] | None = None,
) -> bool:
    """Give each quantity to the open setting it fits best. True when a delay was set relative
    to now ("ready in 15 hours", "3 hours from now") or a time to finish at ("ready at 7:30"):
    a countdown that must be started."""
    counting = False
    options: list[tuple[float, int, str, Any]] = []
    for mi, mention in enumerate(mentions):
        for name, info in view.infos.items():
            if name in goal or info.role in ("power", "running", "switch"):
                continue
            value = fit(view, info, mention, goal)
            if value is None:
                continue
            score = near_vocab(info, text, mention.start, mention.end)
            if score <= 0 and _a_state(info, text, mention):
                continue  # "the tank is 50 % full": a percentage said of something else
            if held_at(info, text, mention):
                continue  # "hold at 70 for 30 minutes": 70 is held, the HOLD is 30 minutes
            if score < 0.5 and repeat_for_a_length(text, mention, info):
                continue  # "cleaning every two hours": how often, not how long something lasts
            by = info.timing == "finish" and mention.kind == "clock" and mention.lead == "by"
            if info.timing in ("clock", "finish") and not near_vocab(
                info, text, mention.start, mention.end, reach=12
            ):
                named = info.timing == "clock" and (
                    concept("clock") in text.concepts or _time_named(text, mention)
                )
                if not ((named or by) and mention.kind == "clock"):
                    continue  # a time of day sets the clock only when the clock is named
            if info.timing == "at" and not _its_time_of_day(view, info, text, mention):
                continue
            score += _cue_bonus(info, text, mention) + (0.5 if by else 0.0)
            score += _scheduled_bonus(view, info, text, mention)
            score += _after_its_case(info, text, mention, goal)
            score += _named_right_before(info, text, mention)
            options.append((score, mi, name, value))
    # equals: a setting with a key of its own first, then the order the belief describes them
    # in (a read belief's is the manual's: the main setting before a probe's target)
    options.sort(key=lambda o: (-o[0], own_key_depth(view.model, o[2]), view.infos[o[2]].order))
    used: set[int] = set()
    # a bare number waits for the others: "eight cups … at setting four" leaves it one home
    waited = [o for o in options if o[0] <= 0 and mentions[o[1]].kind == "number"]
    for score, mi, name, value in options + waited:
        if mi in used or name in goal:
            continue
        mention = mentions[mi]
        article = text.word(mention.start) in ("a", "an", "couple", "single") and (
            text.word(mention.start + 1) not in ("hundred", "thousand")  # "a hundred" counts
        )
        lone = not article and _only_home(view, mention, goal)
        if score <= 0 and mention.kind == "number" and not lone:
            continue
        goal[name] = value
        where[name] = mention.start
        used.add(mi)
        claimed.update(range(mention.start, mention.end))
        if view.infos[name].timing == "delay" and _relative(text, mention):
            counting = True
        if view.infos[name].timing == "finish" and mention.kind == "clock":
            counting = True  # "ready at 7:30": only a started countdown ends then
    for mi, mention in enumerate(mentions):
        if mi not in used and mention.kind == "clock" and _clock_parts(view, text, mention, goal):
            used.add(mi)
    for mi, mention in enumerate(mentions):
        if mi not in used:
            unitless = unitless_named(view, text, mention, goal) or unitless_duration(
                view, text, mention, goal
            )
            if unitless is not None:  # "fridge at 3 degrees", FRIDGE read without its unit
                where[unitless] = mention.start
                used.add(mi)
                claimed.update(range(mention.start, mention.end))
                continue
            try:
                _unplaced(view, text, mention, goal)
            except GoalParseError as exc:
                if outside is None or exc.setting is None:
                    raise
                goal[exc.setting] = exc.asked  # as said: the appliance may have it
                where[exc.setting] = mention.start
                outside.append(str(exc))
    return counting


_COPULAS = frozenset({"is", "are", "was", "were", "'s", "it's", "stands", "reads", "shows"})


def _a_state(info: VarInfo, text: Text, mention: Mention) -> bool:
    """A percentage its clause states of something ("my battery is at 25 %", "the tank is 50 %
    full") rather than asks of the appliance: no level without a unit of its own takes it when
    none of its words stand near."""
    if mention.dimension != "ratio" or info.dimension is not None:
        return False
    for i in range(mention.start - 1, -1, -1):
        word = text.word(i)
        if word in CLAUSE_ENDS or word in (",", "-", "and", "but", "then"):
            return False
        if word in _COPULAS:
            return True
    return False


def _after_its_case(info: VarInfo, text: Text, mention: Mention, goal: Goal) -> float:
    """ "the body zone at 6", "feet on 4": a bare number said right after a value of the
    setting this one depends on (each zone keeps its own level) is that setting's."""
    case = zone_case(info.var)
    if mention.kind != "number" or not case or case not in goal:
        return 0.0
    return 1.0 if said_before(text, mention.start, stem(str(goal[case]))) else 0.0


def _named_right_before(info: VarInfo, text: Text, mention: Mention) -> float:
    """ "head at twenty", "fan to 3": a setting's own name, then "at" / "to", then the
    quantity binds the two more tightly than any name standing after the quantity ("legs up
    to forty degrees, head at twenty": the forty is not the head's)."""
    if text.word(mention.start - 1) not in ("at", "to") or mention.start < 2:
        return 0.0
    return 0.5 if text.concepts[mention.start - 2] in own_concepts(info) else 0.0


def _time_named(text: Text, mention: Mention) -> bool:
    """ "set the time to 9:05 pm", "the correct time is 7:15": the time of day, i.e. the clock."""
    for j in range(mention.start - 1, max(-1, mention.start - 4), -1):
        if text.word(j) == "time":
            return text.word(j - 1) in ("the", "correct", "right", "current", "exact")
        if text.word(j) not in ("to", "is", "as", "at", "now", ":"):
            return False
    return False


def _its_time_of_day(view: Model, info: VarInfo, text: Text, mention: Mention) -> bool:
    """A time of day goes to a day-dial setting (a start time, a feeding time) its words name,
    or to the model's only setting that is a time of day ("mow at 7 in the morning")."""
    if near_vocab(info, text, mention.start, mention.end, reach=12):
        return True
    days = [i for i in view.infos.values() if i.timing in ("at", "clock", "finish")]
    if mention.kind != "clock" or days == [info]:
        return mention.kind == "clock" and days == [info]
    if _said_now(text, mention):
        return False  # "it's 7:40 pm right now": the clock's time
    if _switched_then(view, info, text, mention):
        return True  # "the lights on at 7:30", "off at 10 pm", "starting at 6"
    return [i for i in days if i.timing != "clock"] == [info]  # beside a clock: "water at 7 pm"


def _scheduled_bonus(view: Model, info: VarInfo, text: Text, mention: Mention) -> float:
    """Beside a schedule (ON TIME, START TIME), the time it is now ("it's 7:40 pm") is the
    clock's, and a time said after the schedule's word ("on at 7", "starting at 6") its own."""
    if mention.kind != "clock" or not any(i.timing == "at" for i in view.infos.values()):
        return 0.0
    if info.timing == "clock":
        return 0.5 if _said_now(text, mention) else 0.0
    if info.timing == "at":
        return 0.5 if _switched_then(view, info, text, mention) else 0.0
    return 0.0


def _switched_then(view: Model, info: VarInfo, text: Text, mention: Mention) -> bool:
    """The time follows the schedule's word and "at"/"from" ("the lamp on at 7", "starting at
    6"), said of the appliance — not of another setting ("the soak on at 8 am")."""
    if mention.lead not in ("at", "from"):
        return False
    if stem(text.word(mention.start - 2)) not in _switch_stems(info):
        return False
    thing = text.concepts[mention.start - 3] if mention.start >= 3 else ""
    return not any(
        other is not info and other.vocab.get(thing, 0.0) >= 0.8 for other in view.infos.values()
    )


def _switch_stems(info: VarInfo) -> set[str]:
    """The words ON TIME, OFF TIME, START TIME are named for, as stems."""
    words = name_words(f"{info.name} {info.var.label or ''}".casefold())
    return {stem(w) for w in words if w in SPAN_STARTS | SPAN_ENDS}


def _said_now(text: Text, mention: Mention) -> bool:
    """ "it's 6:05", "the time is 7:15", "7:40 right now": the time it is, not one to act at."""
    before = text.word(mention.start - 1)
    after = [text.word(mention.end + d) for d in range(3)]
    said = after[: next((d for d, w in enumerate(after) if w in CLAUSE_ENDS or w == ","), 3)]
    return before in ("it's", "is", "its") or "now" in said  # not "on at 7 pm; now …"


def _clock_parts(view: Model, text: Text, mention: Mention, goal: Goal) -> bool:
    """A time of day kept as two settings, an hour and a minute (a clock, an auto-start time):
    set both from one time, on the pair the words around it name."""
    pairs: dict[str, dict[str, VarInfo]] = {}
    for info in view.infos.values():
        if info.role != "setting" or info.name in goal:
            continue
        words = [w for w in info.name.casefold().split("_") if w]
        part = next((p for p, names in _PARTS.items() if names & set(words)), None)
        if part is None:
            continue
        rest = "_".join(w for w in words if w not in _PARTS[part])
        pairs.setdefault(rest, {})[part] = info
    options = []
    for parts in pairs.values():
        if len(parts) != 2:
            continue
        score = sum(near_vocab(i, text, mention.start, mention.end) for i in parts.values())
        clock = stem("clock") in own_stems(parts["hour"])
        if clock and score <= 0 and concept("clock") in text.concepts:
            score = 0.1  # "The clock is off — set it to 13:15"
        if clock and score <= 0:
            continue  # a time of day sets the clock only when the clock is named
        options.append((score, not clock, parts))
    if not options:
        return False
    parts = max(options, key=lambda o: (o[0], o[1]))[2]
    hour, minute = divmod(int(mention.value) // 60, 60)
    values = {}
    for part, number in (("hour", hour), ("minute", minute)):
        domain = domain_values(view, parts[part], goal)
        if part == "hour" and not _has_number(domain, number) and number > 12:
            number -= 12
        found = next((v for v in domain if _as_int(v) == number), None)
        if found is None and part == "hour":
            found = twelve_hour_value(domain, hour)
        if found is None:
            return False
        values[parts[part].name] = found
    goal.update(values)
    return True


_PARTS = {"hour": {"hour", "hours", "hr", "h"}, "minute": {"minute", "minutes", "min", "m"}}


_TWELVE_HOUR = re.compile(r"^\s*(\d{1,2})\s*([ap])\.?\s*m\.?\s*$", re.IGNORECASE)


def twelve_hour_value(domain: list[Any], hour: int) -> Any:
    """The value of an hour setting written on a 12-hour clock ("7 AM", "12 PM") that is the
    day's ``hour`` (0-23); None when the values are not so written."""
    want = (hour % 12 or 12, "a" if hour < 12 else "p")
    for value in domain:
        found = _TWELVE_HOUR.match(str(value))
        if found and (int(found.group(1)), found.group(2).casefold()) == want:
            return value
    return None


def _as_int(value: Any) -> int | None:
    try:
        number = float(value)
    except (TypeError, ValueError):
        return None
    return int(number) if number == int(number) else None


def _has_number(domain: list[Any], number: int) -> bool:
    return any(_as_int(v) == number for v in domain)


def _only_home(view: Model, mention: Mention, goal: Goal) -> bool:
    """A bare number that fits exactly one open variable goes there."""
    homes = [
        n
        for n, i in view.infos.items()
        if n not in goal and i.role == "setting" and fit(view, i, mention, goal) is not None
    ]
    return len(homes) == 1


def _relative(text: Text, mention: Mention) -> bool:
    """A duration counted from now: "in 8 hours", "5 h from now", "starting in 2 hours"."""
    before = text.word(mention.start - 1)
    after = " ".join(text.word(mention.end + d) for d in range(2))
    return before in ("in", "within") or after == "from now"


def _cue_bonus(info: VarInfo, text: Text, mention: Mention) -> float:
    """Relative times prefer delays, "for" a duration, clock times clocks; units fit units."""
    before = text.word(mention.start - 1)
    before2 = text.word(mention.start - 2)
    bonus = 0.0
    if mention.kind == "duration":
        relative = _relative(text, mention) or before2 in ("delay", "delayed", "wait")
        relative = relative or before in ("delay", "delayed", "wait")
        if info.timing == "delay":
            bonus += 0.9 if relative else -0.3
        elif relative:
            bonus -= 0.3
    if mention.dimension and mention.dimension == info.dimension:
        bonus += 0.3
    main = {"time", "cook", "cooking", "duration"} & set(info.name.split("_"))
    if mention.kind == "duration" and info.timing == "duration" and main:
        bonus += 0.1  # a duration no word claims goes to the cooking time, not QUICK MIN's
    if mention.kind == "duration" and info.turns is not None:
        said = _turning(text, mention.start)
        if said is not None:
            bonus += 1.0 if said == info.turns else -1.0
    return bonus


_TURN_VERBS = frozenset(
    {"switch", "turn", "come", "switching", "turning", "coming", "comes", "switches", "turns"}
)


def _turning(text: Text, start: int) -> str | None:
    """ "switch off after 2 hours", "an off-timer of 10 hours", "come on in 7.5 hours": which
    way the appliance turns when the duration ends (None when the words do not say)."""
    for k in range(start - 1, max(-1, start - 7), -1):
        word = text.word(k)
        if word in CLAUSE_ENDS or word == ",":
            break
        if word == "off":
            return "off"
        if word == "on" and text.word(k - 1) in _TURN_VERBS | {"itself", "it"}:
            return "on"
    return None


def _clock_for_a_delay(view: Model, text: Text, mention: Mention, goal: Goal) -> None:
    """ "finish by 7 am" where the model only counts hours from now: say so, do not guess."""
    for info in view.infos.values():
        if info.role != "setting" or info.timing != "delay" or info.name in goal:
            continue
        if near_vocab(info, text, mention.start, mention.end) >= 0.5:
            raise GoalParseError(
                text.span(mention.start, mention.end),
                f"{info.name} is a time from now, not a time of day; give it as 'in N hours'",
            )


def _unplaced(view: Model, text: Text, mention: Mention, goal: Goal) -> None:
    """A quantity with a unit that only open variables of its kind could take, none of which
    has the value: the model cannot do what was asked."""
    if mention.kind == "number":
        return
    kinds = []
    for name, info in view.infos.items():
        if info.role != "setting":
            continue
        timed = isinstance(info.var, TimeVariable) or info.dimension == "time"
        if (
            (mention.kind == "clock" and info.timing in ("clock", "finish"))
            or (mention.kind == "duration" and timed)
            or (mention.kind == "fahrenheit" and info.dimension == "temperature")
            or (mention.kind == "quantity" and info.dimension == mention.dimension)
        ):
            kinds.append(name)
    if not kinds and mention.kind == "clock":
        _clock_for_a_delay(view, text, mention, goal)
    if not kinds:
        return
    closeness = {n: near_vocab(view.infos[n], text, mention.start, mention.end) for n in kinds}
    near = max(kinds, key=lambda n: closeness[n])
    if mention.kind == "clock" and closeness[near] < 0.5:
        return  # a time of day said in passing ("a 3 a.m. feed")
    if any(name in goal for name in kinds) and (near in goal or closeness[near] < 0.5):
        return  # another setting of its kind was given; this may be a remark
    if mention.kind == "duration":  # a time of day (the clock, when something starts) lasts not
        kinds = [n for n in kinds if view.infos[n].timing not in ("clock", "at")]
        if not kinds:
            return
        near = max(kinds, key=lambda n: closeness[n])
    if closeness[near] < 0.5 and repeat_for_a_length(text, mention, view.infos[near]):
        return  # how often something comes round, said of none of these settings
    info = view.infos[near]
    values = domain_values(view, info, goal)
    parent = info.var.depends_on
    if not values and parent:
        reason = f"{near} does not apply when {parent} is {goal.get(parent)!r}"
    else:
        where = f" when {parent} is {goal[parent]!r}" if parent and parent in goal else ""
        reason = f"no setting of this model takes it; {near} can be {preview(values, quote=False)}"
        reason += where
    error = GoalParseError(text.span(mention.start, mention.end), reason)
    error.setting, error.asked = near, _as_said(info, mention)
    if error.asked is None:
        error.setting = None
    raise error


def _as_said(info: VarInfo, mention: Mention) -> Any:
    """The quantity as the user said it, in the setting's own terms (None: no such terms)."""
    var = info.var
    if isinstance(var, TimeVariable) and mention.kind in ("duration", "clock"):
        return format_hms(round(mention.value))
    if isinstance(var, NumericVariable):
        number = number_for(info, unit_text(var), mention)
        if number is not None:
            return int(number) if float(number).is_integer() else round(number, 3)
    return None
