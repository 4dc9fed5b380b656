"""A function key that chooses which setting a shared adjuster changes.

Panels often give one pair of + / − keys (or one dial) two settings and a key to switch
between them: "TEMP/TIME — switches the + and − keys between the cooking time and the
temperature", "Press TEMP/TIME to switch between temperature and time, then use + / −". Read
key by key, the switching key looks like a toggle of its own and the pair like one amount; the
user's temperature then has no way to be set. This rule reads the sentence and gives the pair
both settings: alone it sets the one it sets by default, and after the key the other one, until
the key is pressed again (the feature ``[key, pair → first, key, pair → second]``, as the model
format writes such a switch).
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.clock_format import twelve_hour_clock
from apbot.read.labels import words
from apbot.read.roles_common import label_of, stepped_noun, token_of, turns
from apbot.read.shapes import Evidence
from apbot.read.text import Unit

# the settings a shared adjuster may switch between, as the manual names them → (name, label)
_NOUNS: dict[str, tuple[str, str]] = {
    "cooking time": ("time", "TIME"),
    "cook time": ("time", "TIME"),
    "time": ("time", "TIME"),
    "timer": ("timer", "TIMER"),
    "temperature": ("temperature", "TEMP"),
    "temp": ("temperature", "TEMP"),
    "weight": ("weight", "WEIGHT"),
    "power level": ("power", "POWER"),
    "power": ("power", "POWER"),
    "hours": ("hour", "HOUR"),
    "hour": ("hour", "HOUR"),
    "minutes": ("minute", "MIN"),
    "minute": ("minute", "MIN"),
    "speed": ("speed", "SPEED"),
    "humidity": ("humidity", "HUMIDITY"),
    "level": ("level", "LEVEL"),
}
_NOUN = "|".join(sorted((re.escape(n) for n in _NOUNS), key=len, reverse=True))
# "switches the + and − keys of the zone between the cooking time and the temperature",
# "to switch between temperature and time", "toggles between hours and minutes"
_DOING = r"(?:[a-z]+ing\s+)?"  # "the grilling time", "the baking temperature"
_BETWEEN_RE = re.compile(
    rf"\b(?:switch|toggle|alternate|change|swap)(?:es|s)?\b[^.;]{{0,60}}?\bbetween\s+(?:the\s+)?"
    rf"{_DOING}(?P<a>{_NOUN})\b(?:\s+setting)?\s+(?:and|or)\s+(?:the\s+)?{_DOING}"
    rf"(?P<b>{_NOUN})\b",
    re.IGNORECASE,
)
_HANDED_RE = re.compile(
    rf"\b(?:adjust|change|set|control|go(?:es)?\s+back\s+to|return)\w*\s+(?:to\s+)?(?:the\s+)?"
    rf"(?:zone'?s?\s+)?{_DOING}(?P<n>{_NOUN})\b",
    re.IGNORECASE,
)
_AGAIN_RE = re.compile(r"\b(?:again|once more)\b", re.IGNORECASE)
# the sentence must name the adjuster itself as what is switched: a sign standing alone as a
# key ("+ and −", "+/-", "the − key"; not "auto-mode", "1-2"), the arrows, the up/down keys,
# a dial, or "they" setting something; "counts down" or "on the display" name no pair
_SIGN = r"(?<![\w+−–-])[+−–-](?![\w−–-])"
_PAIR_WORDS_RE = re.compile(
    rf"{_SIGN}\s*(?:/|and|or|&)\s*{_SIGN}|{_SIGN}\s*(?:keys?|buttons?)\b|\bthe\s+{_SIGN}|[▲▼]"
    r"|\b(?:up|down)\s*(?:/|and|or|&)\s*(?:up|down)\b"
    r"|\b(?:up|down|plus|minus|arrow|adjust(?:ing)?|stepping)\s+(?:keys?|buttons?|arrows?)\b"
    r"|\barrows?\b|\b(?:dial|knob|wheel)\b"
    r"|\bthey\s+(?:now\s+|then\s+)?(?:adjust|change|set|step|control|raise)\w*",
    re.IGNORECASE,
)


def assign_shared(
    b: Builder, keys: list[ActionInfo], pairs: dict[str, dict[str, list[str]]]
) -> set[str]:
    """Give each key whose sentence says it switches a stepping pair between two settings a
    feature that sets both; returns the actions used (the keys and their pairs)."""
    used: set[str] = set()
    for key in keys:
        if key.skill != "press" or key.name in used or key.controls[0] not in b.labels:
            continue
        said = _switch_sentence(b, key)
        if said is None:
            continue
        nouns, at, ordered = said
        base = _pair_of(key, pairs, used)
        if base is None:
            continue
        up, down = pairs[base]["up"], pairs[base]["down"]
        first, second = nouns if ordered else _order(b, key, nouns, up + down)
        suffix = _suffix(key, base)
        made: list[str] = []
        for noun in (first, second):
            name, label = _NOUNS[noun]
            var = b.add_number(
                f"{name}_{suffix}" if suffix else name,
                f"{label} {suffix}" if suffix else label,
                Evidence(ranges=[]),
                cyclic=False,
            )
            made.append(var)
        effect = {**{a: "next" for a in up}, **{a: "prev" for a in down}}
        b.feature(
            f"{key.token}_{made[0]}",
            [
                {"actions": [key.name]},
                {"actions": up + down, "variable": made[0], "effect": effect},
                {"actions": [key.name]},
                {"actions": up + down, "variable": made[1], "effect": dict(effect)},
            ],
        )
        b.feature(
            f"set_{made[1]}",
            [{"actions": up + down, "variable": made[1], "effect": dict(effect)}],
        )
        b.note(
            f"features.{key.token}_{made[0]}",
            f"{label_of(b, key.controls[0])} switches the stepping keys between "
            f"{made[1]} (alone) and {made[0]}",
            at,
        )
        used |= {key.name, *up, *down}
        del pairs[base]
    return used


def _switch_sentence(b: Builder, key: ActionInfo) -> tuple[tuple[str, str], int, bool] | None:
    """The two settings the key's own sentence says it switches the adjuster between, and
    whether the sentence tells their order (the one after the press first)."""
    units = b.manual.units
    for i in b.labels[key.controls[0]].mentions:
        text = units[i].text
        m = _BETWEEN_RE.search(text)
        if m is not None and _PAIR_WORDS_RE.search(text):
            a, c = m.group("a").lower(), m.group("b").lower()
            if _NOUNS[a][0] != _NOUNS[c][0]:
                return (a, c), i, False
        # "lets the + and − keys adjust the temperature; press once more and they adjust the
        # time again": the press hands the pair one setting, the next press the other
        if _PAIR_WORDS_RE.search(text) and _AGAIN_RE.search(text):
            found = [n.group("n").lower() for n in _HANDED_RE.finditer(text)]
            named = [n for n in found if _NOUNS[n][0] != _NOUNS[found[0]][0]]
            if found and named:
                return (found[0], named[0]), i, True
    return None


def _pair_of(key: ActionInfo, pairs: dict[str, dict[str, list[str]]], used: set[str]) -> str | None:
    """The stepping pair the key switches: the one sharing its zone number ("TEMP/TIME 1" and
    "+ 1"), else the one shared pair."""
    whole = [b for b, p in pairs.items() if p["up"] and p["down"] and not set(p["up"]) & used]
    digits = re.search(r"(\d+)$", key.token)
    if digits:
        mine = [b for b in whole if b and re.search(rf"(?<!\d){digits.group(1)}$", b)]
        if len(mine) == 1:
            return mine[0]
    return "" if "" in whole else None


def _suffix(key: ActionInfo, base: str) -> str:
    """The zone number both names share ("1" for TEMP/TIME 1 with + 1), or nothing."""
    m = re.search(r"(\d+)$", base) if base else None
    return m.group(1) if m else ""


def _order(b: Builder, key: ActionInfo, nouns: tuple[str, str], pair: list[str]) -> tuple[str, str]:
    """(the setting the key's press gives the pair, the one the pair sets alone). The pair's
    own sentences name its default ("+ and − change the cooking time"); without them the key's
    printed name gives the order (TEMP/TIME: temperature first), else the sentence's."""
    a, c = nouns
    own = stepped_noun(b, [token_of(b, n) for n in pair], None)
    if own:
        for x, y in ((a, c), (c, a)):
            if _NOUNS[y][0] == _NOUNS.get(own, (own, ""))[0]:
                return x, y
    label = label_of(b, key.controls[0]).lower()
    spots = {n: label.find(_NOUNS[n][1].lower()) for n in nouns}
    if all(p >= 0 for p in spots.values()) and spots[a] != spots[c]:
        return (a, c) if spots[a] < spots[c] else (c, a)
    named = set(words(label))
    return (c, a) if _NOUNS[c][0] in named or _NOUNS[c][1].lower() in named else (a, c)


# "After PRESET has been pressed, turning the SELECT dial changes the time": the turn verb
# must take the dial itself ("the display will turn off", "the turntable" name no dial)
_AFTER_RE = (
    r"\b(?:after|once|when)\b(?P<keys>[^.;]{{1,60}}?)\b(?:has|have|is|are)\s+(?:been\s+)?"
    r"(?:pressed|touched|pushed|selected)\b[^.;]{{0,40}}?\b(?:turn(?:s|ing)?|rotat(?:e|es|ing))"
    r"\s+(?!off\b|on\b)(?:the\s+)?(?:\w+\s+)?(?:{dial})\b"
)
_PRESS_RE = r"\b(?:press|touch|push)\w*\s+(?:the\s+)?(?:{keys})\b"


def dial_after_keys(b: Builder, dial: str, keys: list[ActionInfo]) -> bool:
    """A dial that picks a list of its own and also sets what a key hands it: its legend says
    so ("After PRESET or COOK TIME has been pressed, turning the dial changes the time"), or
    a step that presses a key is followed by one that turns the dial ("2. Press COOK TIME." …
    "3. Turn the SELECT dial to adjust the time")."""
    labels = [re.escape(label_of(b, k.controls[0])) for k in keys if k.controls[0] in b.labels]
    if not labels:
        return False
    named = re.compile(rf"\b(?:{'|'.join(labels)})\b", re.IGNORECASE)
    noun = re.escape(dial.split("_")[0])
    own = {noun, re.escape(label_of(b, dial))} if dial in b.labels else {noun}
    after = re.compile(_AFTER_RE.format(dial="|".join(sorted(own))), re.IGNORECASE)
    units = b.manual.units
    for u in units:
        m = after.search(u.text)
        if m and named.search(m.group("keys")):
            return True
    pressed = re.compile(_PRESS_RE.format(keys="|".join(labels)), re.IGNORECASE)
    turned = re.compile(
        rf"^\W*(?:\d+[.)]\s*)?turn\w*\s+the\s+(?:\w+\s+)?{noun}\b[^.]*\b(?:to\s+)?"
        rf"(?:adjust|set|change|choose)\w*\s+the\s+(?:\w+\s+)?(?:time|temperature|timer|weight"
        rf"|hours?|minutes?|level|power|delay|preset)\b",
        re.IGNORECASE,
    )
    return any(
        pressed.search(units[i].text) and any(turned.search(units[j].text) for j in (i + 1, i + 2))
        for i in range(len(units) - 2)
    )


_PAIR_PRESS_RE = re.compile(
    r"\b(?:press|touch|push|use)\w*\s+(?:the\s+)?(?:[+−–▲▼]|-(?!\w)|up\b|down\b|plus\b|minus\b"
    r"|arrow)",
    re.IGNORECASE,
)
# the step for the hour names the hour ("to set the hour", "until the correct hour is shown")
# before any minutes; the step for the minutes names them
_HOUR_RE = re.compile(r"^(?:(?!\bminutes?\b).)*\bhours?\b", re.IGNORECASE | re.DOTALL)
_MINUTE_RE = re.compile(r"\bminutes?\b", re.IGNORECASE)


def clock_steps(
    b: Builder,
    keys: list[ActionInfo],
    dials: dict[str, list[ActionInfo]],
    pairs: dict[str, dict[str, list[str]]],
) -> list[tuple[ActionInfo, list[str], list[str], int]]:
    """A clock set as hour then minute with one key and one dial, told as numbered steps
    ("1. Press CLOCK. 2. Turn TIME to set the hour. 3. Press CLOCK. 4. Turn TIME to set the
    minutes."; or "Press + or − to set the hour" with the one stepping pair): (key, the dial's
    clockwise and anticlockwise turns or the pair's up and down keys, the unit) for each. The
    key takes no other role; the feature is added by :func:`add_clock_steps` once the dial has
    its own setting (turned alone it keeps it)."""
    found: list[tuple[ActionInfo, list[str], list[str], int]] = []
    units = b.manual.units
    for key in keys:
        if key.skill != "press" or key.controls[0] not in b.labels:
            continue
        if "clock" not in words(key.controls[0].replace("_", " ")):
            continue
        pressed = re.compile(
            _PRESS_RE.format(keys=re.escape(label_of(b, key.controls[0]))), re.IGNORECASE
        )
        adjusters: list[tuple[list[str], list[str], re.Pattern[str]]] = []
        for token, moves in dials.items():
            cw, ccw = turns(moves)
            if cw and ccw and token in b.labels:
                label = re.escape(label_of(b, token))
                adjusters.append(
                    (cw, ccw, re.compile(rf"\b(?:turn|rotat)\w*\s+(?:the\s+)?{label}\b", re.I))
                )
        shared = pairs.get("")
        if shared and shared["up"] and shared["down"]:
            adjusters.append((shared["up"], shared["down"], _PAIR_PRESS_RE))
        for up, down, adjusted in adjusters:
            at = _hour_then_minute(units, pressed, adjusted)
            if at is not None:
                found.append((key, up, down, at))
                break
    return found


def add_clock_steps(b: Builder, found: list[tuple[ActionInfo, list[str], list[str], int]]) -> None:
    """The features :func:`clock_steps` found: the key, the dial on the hour, the key again,
    the dial on the minutes (each a number that rolls round)."""
    for key, cw, ccw, at in found:
        twelve = twelve_hour_clock(b.manual.units)
        name = key.controls[0].removesuffix("_button")
        hour = b.unique(f"{name}_hour", b.variables)
        b.variables[hour] = {
            "type": "numeric",
            "ranges": [[1, 12, 1]] if twelve else [[0, 23, 1]],
            "wrap": True,
            "label": "HOUR",
        }
        minute = b.unique(f"{name}_minute", b.variables)
        b.variables[minute] = {"type": "numeric", "ranges": [[0, 59, 1]], "wrap": True,
                               "label": "MIN"}  # fmt: skip
        effect = {**{a: "next" for a in cw}, **{a: "prev" for a in ccw}}
        b.feature(
            f"set_{name}",
            [
                {"actions": [key.name]},
                {"actions": cw + ccw, "variable": hour, "effect": effect},
                {"actions": [key.name]},
                {"actions": cw + ccw, "variable": minute, "effect": dict(effect)},
            ],
        )
        lab = label_of(b, key.controls[0])
        b.note(f"features.set_{name}", f"{lab}, the hour, {lab} again, the minutes", at)


def _hour_then_minute(
    units: list[Unit], pressed: re.Pattern[str], adjusted: re.Pattern[str]
) -> int | None:
    """Where the steps press the key, move the adjuster for the hour, press the key again and
    move it for the minutes (each within three units of the last: a step may run on)."""

    def after(k: int, test: re.Pattern[str], what: re.Pattern[str] | None) -> int | None:
        return next(
            (
                j
                for j in range(k + 1, min(k + 4, len(units)))
                if test.search(units[j].text) and (what is None or what.search(units[j].text))
            ),
            None,
        )

    for i, u in enumerate(units):
        if not pressed.search(u.text):
            continue
        h = after(i, adjusted, _HOUR_RE)
        again = None if h is None else after(h, pressed, None)
        if again is not None and after(again, adjusted, _MINUTE_RE) is not None:
            return i
    return None
