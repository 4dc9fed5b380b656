"""Action names → what each does physically (press, hold, turn, type a digit) and on which control.

The environment names its actions (``press_menu``, ``hold_minus_plus``, ``turn_dial_cw``,
``press_5``); the name is all the reader knows of the panel before it reads the manual. The verb
gives the skill, the rest names the control; a hold whose rest splits into the names of two other
controls is a two-key hold. Environments spell these many ways (``press_menu_button``,
``press_and_hold_lock_button``, ``turn_timer_dial_clockwise``, ``long_press_x_key``): the kind of
control said after its name is dropped, since the manual names the control without it.
"""

from __future__ import annotations

import functools
import re
from dataclasses import dataclass

from apbot.read.errors import ReaderError

IDENT = re.compile(r"^[a-z][a-z0-9_]*$")
PRESS_VERBS = ("press", "push", "touch", "tap", "slide", "flip", "switch", "toggle", "click")
HOLD_VERBS = ("hold", "long_press", "press_and_hold", "long")
TURN_VERBS = ("turn", "rotate", "twist", "spin")
CW_WORDS = ("cw", "clockwise", "right", "up", "forward", "next", "plus")
CCW_WORDS = ("ccw", "anticlockwise", "counterclockwise", "left", "down", "back", "minus")
# what kind of control it is, said after its name ("press_menu_button", "turn_timer_dial_cw"):
# the manual calls the control MENU or TIMER, so the kind is no part of its name (a "toggle"
# is a toggle switch: "power_toggle" is the power key)
KIND_WORDS = re.compile(r"_(?:buttons?|keys?|knobs?|dials?|switch(?:es)?|toggles?|btns?|pads?)$")
MAX_ACTIONS = 1000
# a key's kind alone, after a verb that is also a key's name ("turn_button": the TURN key, no dial)
_KEY_KIND = re.compile(r"(?:buttons?|keys?|btns?|pads?)")
# a number key however its name is spelled: the digit alone, or with the word for a key or a
# digit before or after it ("key_5", "digit_5", "number_5_button")
_DIGIT_KEY = re.compile(
    r"(?:(?:keys?|digit|number|num|numpad|buttons?|btn)_)?(\d)(?:_(?:keys?|buttons?|btn))?"
)


@dataclass(frozen=True)
class ActionInfo:
    """One action: its name, skill and the control tokens it uses (two for a two-key hold)."""

    name: str
    skill: str  # press, hold, turn_cw, turn_ccw
    controls: tuple[str, ...]
    digit: int | None = None

    @property
    def token(self) -> str:
        return "_".join(self.controls)


# how long a hold lasts, said at the end of its name ("hold_zone_3s", "zone_hold_3_sec"): the
# hold's length, not a part of the control's name
_DURATION = re.compile(r"_\d{1,2}_?(?:s|sec|secs|seconds?)$")


# a way only a turn goes, said last with no verb ("bright_cw", "cct_ccw", "dial_clockwise"):
# up / down / left / right also name keys, so they make no turn on their own
_TURN_WAY = re.compile(r".+_(?:cw|ccw|clockwise|(?:anti|counter)_?clockwise)$")


def _split_verb(name: str) -> tuple[str, str]:
    """(verb, the rest) of an action name, the verb said first ("press_zone") or last
    ("zone_press", "zone_hold_3s", "knob_turn_cw"): environments name actions either way."""
    core = _DURATION.sub("", name) or name
    if not any(core.startswith(v + "_") or core.endswith("_" + v) for v in HOLD_VERBS):
        core = name  # ("press_10s": the key printed 10s, no hold's length)
    for verb in (*HOLD_VERBS, *TURN_VERBS, *PRESS_VERBS):
        if core == verb:
            return verb, ""
        if core.startswith(verb + "_"):
            return verb, core[len(verb) + 1 :]
    for verb in (*HOLD_VERBS, *PRESS_VERBS):
        if core.endswith("_" + verb) and len(core) > len(verb) + 1:
            return verb, core[: -len(verb) - 1]
    ways = "|".join((*CW_WORDS, *CCW_WORDS))
    for verb in TURN_VERBS:
        turned = re.fullmatch(rf"(.+)_{verb}(?:_({ways}))?", core)
        if turned:
            return verb, "_".join(p for p in turned.groups() if p)
    if _TURN_WAY.search(core):  # "volume_cw", "dial_anticlockwise": only a turn goes that way
        return "turn", core
    return "", core


def parse_actions(names: list[str]) -> list[ActionInfo]:
    """Parse the environment's action names; raise :class:`ReaderError` on a malformed list."""
    if not names:
        raise ReaderError("no action names given: the reader needs the appliance's actions")
    if len(names) > MAX_ACTIONS:
        raise ReaderError(f"{len(names)} actions given; at most {MAX_ACTIONS} are accepted")
    seen: set[str] = set()
    for name in names:
        if not isinstance(name, str) or not IDENT.match(name):
            raise ReaderError(
                f"action name {name!r} is not lowercase_with_underscores (e.g. press_menu)"
            )
        if name in seen:
            raise ReaderError(f"action name {name!r} is given twice")
        seen.add(name)
    first: list[tuple[str, str, str]] = []
    for name in names:
        verb, rest = _split_verb(name)
        first.append((name, verb, _without_kind(rest, verb)))
    single = {rest for _, verb, rest in first if rest and verb not in HOLD_VERBS}
    single |= {_turn_base(rest) for _, verb, rest in first if verb in TURN_VERBS}
    single.discard("")
    # a key that is only ever held ("hold_learn") is a key too: "hold_learn_mode" holds it
    # with MODE
    held = {rest for _, verb, rest in first if rest and verb in HOLD_VERBS}
    turned = _compared_dials(first)
    out: list[ActionInfo] = []
    for name, verb, rest in first:
        info = turned.get(name) or action_info(name)
        if verb in HOLD_VERBS:  # a two-key hold names two of the other keys
            controls = _hold_controls(rest or name, single)
            if controls == (rest or name,) and rest not in single:
                pair = _hold_controls(rest, single | (held - {rest}))
                controls = pair if len(pair) == 2 else controls
            info = ActionInfo(name, "hold", controls)
        out.append(info)
    return out


# a dial named by the two ways it is turned ("turn_faster" / "turn_slower"): the quantity it
# sets, and the word for turning it up first (the way numbers usually grow on such a dial)
COMPARED = {
    ("faster", "slower"): "speed",
    ("coarser", "finer"): "fineness",
    ("louder", "quieter"): "volume",
    ("louder", "softer"): "volume",
    ("warmer", "cooler"): "temperature",
    ("hotter", "colder"): "temperature",
    ("brighter", "dimmer"): "brightness",
    ("stronger", "weaker"): "strength",
    ("thicker", "thinner"): "thickness",
}


def _compared_dials(first: list[tuple[str, str, str]]) -> dict[str, ActionInfo]:
    """Two turns named only by opposite comparatives (``turn_faster``, ``turn_slower``) are one
    dial turned two ways, whose quantity the pair names (speed): read apart, each would be a
    setting of its own that no sentence names. Only when both turns are there, once each."""
    turns: dict[str, list[str]] = {}
    for name, verb, rest in first:
        if verb in TURN_VERBS:
            turns.setdefault(rest, []).append(name)
    out: dict[str, ActionInfo] = {}
    for (up, down), noun in COMPARED.items():
        ups, downs = turns.get(up, []), turns.get(down, [])
        if len(ups) != 1 or len(downs) != 1 or noun in turns or out.get(ups[0]):
            continue
        out[ups[0]] = ActionInfo(ups[0], "turn_cw", (noun,))
        out[downs[0]] = ActionInfo(downs[0], "turn_ccw", (noun,))
    return out


@functools.lru_cache(maxsize=4096)
def action_info(name: str) -> ActionInfo:
    """One action name on its own (no list to find a two-key hold's partners in): what the
    agent needs to press a key the belief does not know — its skill, its control, its digit."""
    verb, rest = _split_verb(name)
    rest = _without_kind(rest, verb)
    if verb in TURN_VERBS and _KEY_KIND.fullmatch(rest):  # "turn_button": the TURN key
        return ActionInfo(name, "press", (verb,))
    if verb in TURN_VERBS:
        base = _turn_base(rest)
        ccw = rest != base and rest.rsplit("_", 1)[-1] in CCW_WORDS
        return ActionInfo(name, "turn_ccw" if ccw else "turn_cw", (base or "dial",))
    if verb in HOLD_VERBS:
        return ActionInfo(name, "hold", (rest or name,))
    if digit := _DIGIT_KEY.fullmatch(rest):  # "press_5", "key_5", "press_digit_5", "5_key"
        return ActionInfo(name, "press", (f"key_{digit[1]}",), int(digit[1]))
    return ActionInfo(name, "press", (rest or name,))


def _without_kind(rest: str, verb: str) -> str:
    """The control's name without the kind of control said after it (``menu_button`` →
    ``menu``; a turn's ``timer_dial_clockwise`` → ``timer_clockwise``); a name that is only
    the kind (``press_button``, ``turn_dial_cw``) stays."""
    if verb in TURN_VERBS:
        # "counter_clockwise", "anti_clockwise": one way written as two words
        rest = re.sub(r"(?:counter|anti)_clockwise$", "counterclockwise", rest)
        parts = rest.split("_")
        way = parts[-1] if len(parts) > 1 and parts[-1] in (*CW_WORDS, *CCW_WORDS) else ""
        base = _without_kind("_".join(parts[:-1]) if way else rest, "")
        return "_".join(p for p in (base, way) if p)
    kind = KIND_WORDS.search(rest)
    rest = rest[: kind.start()] if kind and kind.start() > 0 else rest
    # "arrow_up", "arrow_key_down": an arrow is a kind of key, the direction its name
    return re.sub(r"^arrows?_(?:(?:keys?|buttons?|btns?)_)?(?=(?:up|down|left|right)$)", "", rest)


def _turn_base(rest: str) -> str:
    parts = rest.split("_")
    if parts and parts[-1] in (*CW_WORDS, *CCW_WORDS):
        parts = parts[:-1]
    return "_".join(parts)


def _hold_controls(rest: str, single: set[str]) -> tuple[str, ...]:
    """``minus_and_plus`` → (minus, plus) when both are other actions' controls; ``dose_both``
    → the two controls named ``dose_…`` (a pair held together, named for what they share)."""
    if rest in single:
        return (rest,)
    parts = [p for p in rest.split("_") if p]
    if len(parts) > 1 and "both" in (parts[0], parts[-1]):  # hold_dose_both: DOSE - and DOSE +
        base = "_".join(p for p in parts if p != "both")
        pair = sorted(s for s in single if s.startswith(base + "_"))
        if len(pair) == 2:
            return (pair[0], pair[1])
    for cut in range(1, len(parts)):
        left = "_".join(parts[:cut])
        right_parts = parts[cut:]
        if right_parts and right_parts[0] in ("and", "with", "plus") and len(right_parts) > 1:
            right_parts = right_parts[1:]
        a, b = _known(left, single), _known("_".join(right_parts), single)
        if a and b and a != b:
            return (a, b)
    return (rest,)


def _known(part: str, single: set[str]) -> str:
    """The control ``part`` names: itself, or the one control whose name ends with it."""
    if part in single:
        return part
    ends = [s for s in single if s.endswith("_" + part)]
    return ends[0] if len(ends) == 1 else ""
