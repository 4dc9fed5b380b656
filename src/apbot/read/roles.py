"""Give every action a role and build the model's variables, features and guards from them.

The order matters: the name-evident roles first (power, start, stop, lock, digits, stepping
pairs, dials), then setting keys by what their sentences say, then the keys the manual only
lists together, then whatever is left, as a guess.
"""

from __future__ import annotations

import itertools
import re
from typing import Any

from apbot.read.actions import ActionInfo
from apbot.read.build import (
    GENERIC_DIALS,
    GROUP_NOUNS,
    RUNNING_RE,
    SETTING_NOUNS,
    STOP_WORDS,
    Builder,
    Evidence,
    _next_table_column,
    adjuster_direction,
)
from apbot.read.labels import words
from apbot.read.shown import LOCK_CUE, RUNNING_CUE, shown_words
from apbot.read.text import Unit


def assign(b: Builder) -> None:
    infos = b.infos
    by_token: dict[str, list[ActionInfo]] = {}
    for info in infos:
        by_token.setdefault(info.token, []).append(info)
    done: set[str] = set()
    power_actions: list[str] = []
    lock_actions: list[str] = []
    run_actions: list[str] = []

    def label(token: str) -> str:
        return b.labels[token].text if token in b.labels else token.upper()

    def first_mention(tokens: list[str]) -> int | None:
        for t in tokens:
            if t in b.labels and b.labels[t].mentions:
                return b.labels[t].mentions[0]
        return None

    # power -------------------------------------------------------------------------------
    tokens = {i.token for i in infos if i.skill == "press" and i.digit is None}
    power_token: str | None = next(
        (t for t in ("on_off", "onoff", "power_on_off", "standby") if t in tokens), None
    )
    if power_token is None and "power" in tokens:
        ctx = " ".join(b.manual.units[i].text for i in b.context(["power"]))
        if not re.search(r"\b(?:level|watt|output)\b", ctx, re.I) or re.search(
            r"\b(?:switch|turn)\w*\b[^.]*\b(?:on|off)\b", ctx, re.I
        ):
            power_token = "power"
    if power_token:
        press = [i for i in by_token[power_token] if i.skill == "press"]
        holds = [i for i in by_token[power_token] if i.skill == "hold"]
        var = b.add_toggle("power", label(power_token), first_mention([power_token]))
        b.indicators.remove(var) if var in b.indicators else None
        if holds and press:
            b.feature(
                "power_on", [{"actions": [press[0].name], "variable": var, "effect": {"to": "on"}}]
            )
            b.feature(
                "power_off",
                [{"actions": [holds[0].name], "variable": var, "effect": {"to": "off"}}],
            )
            b.note(
                "features.power_off",
                "holding the power key switches off (a short press switches on)",
                first_mention([power_token]),
            )
            power_actions += [press[0].name, holds[0].name]
        else:
            acts = [i.name for i in press]
            b.feature("power", [{"actions": acts, "variable": var, "effect": "toggle"}])
            power_actions += acts
        done |= set(power_actions)
        b.guards.append(
            {
                "name": "power off",
                "when": {var: "off"},
                "only": list(power_actions),
                "display": "",
                "hide": True,
            }
        )
        b.note("guards.power off", "keys do nothing while the appliance is off")

    # locks -------------------------------------------------------------------------------
    for info in infos:
        if info.name in done:
            continue
        is_lock = "lock" in words(info.token) and info.skill in ("hold", "press")
        if info.skill == "hold" and not is_lock:
            texts = [b.manual.units[i].text for i in b.context(list(info.controls))]
            is_lock = len(info.controls) > 1 or any(
                re.search(r"\bhold\b", t, re.I) and re.search(r"\block", t, re.I) for t in texts
            )
        if not is_lock:
            continue
        at = first_mention(list(info.controls))
        var = "child_lock"
        if var not in b.variables:
            var = b.add_toggle("child_lock", "LOCK", at)
            word = (
                _lock_word(b, info)
                or _state_word(b, list(info.controls), LOCK_CUE, re.compile(r"^RUN", re.I))[0]
            )
            b.variables[var]["show"] = {"off": "", "on": word or "LOCK"}
            b.feature("child_lock", [{"actions": [info.name], "variable": var, "effect": "toggle"}])
        else:
            b.features["child_lock"][0]["actions"].append(info.name)
        lock_actions.append(info.name)
        done.add(info.name)
    if lock_actions:
        shown = b.variables["child_lock"]["show"]["on"]
        b.guards.insert(
            0,
            {
                "name": "child lock",
                "when": {"child_lock": "on"},
                "only": list(lock_actions),
                "display": shown,
            },
        )
        b.note("guards.child lock", "only the lock action works while locked")

    # start / stop ------------------------------------------------------------------------
    starts = [
        i for i in infos if i.name not in done and "start" in words(i.token) and i.skill == "press"
    ]
    stops = [
        i
        for i in infos
        if i.name not in done
        and i not in starts
        and i.digit is None
        and (set(words(i.token)) & STOP_WORDS)
        and not set(words(i.token)) & NUMERIC_WORDS  # END TIME, CLEAR TIMER: a setting
        and i.skill in ("press", "hold")
    ]
    if starts or stops:
        var = b.unique("running", b.variables)
        b.variables[var] = {"type": "discrete", "values": ["off", "on"], "label": "RUN"}
        word, at = _state_word(
            b, [i.token for i in starts + stops], RUNNING_CUE, re.compile(r"LOC|^C?L$|^Lc$", re.I)
        )
        if word:
            b.variables[var]["show"] = {"off": "", "on": word}
            b.note(f"variables.{var}.show", f"the panel shows {word} while it runs", at)
        else:  # no word read: the belief does not predict the screen (the loop cannot misread it)
            b.variables[var]["visible"] = False
            b.note(f"variables.{var}.visible", "the manual names no sign of running")
        b.note(
            f"variables.{var}",
            "the appliance runs after START",
            first_mention([i.token for i in starts + stops]),
        )
        for info in starts:
            toggle = bool(set(words(info.token)) & (STOP_WORDS | {"pause"})) or not stops
            b.feature(
                info.token if info.token != "start" else "start",
                [
                    {
                        "actions": [info.name],
                        "variable": var,
                        "effect": "toggle" if toggle else {"to": "on"},
                    }
                ],
            )
            run_actions.append(info.name)
        for info in stops:
            b.feature(
                info.name if info.skill == "hold" else info.token,
                [{"actions": [info.name], "variable": var, "effect": {"to": "off"}}],
            )
            run_actions.append(info.name)
        for info in infos:
            if (
                info.skill == "hold"
                and info.name not in done | set(run_actions)
                and info.token in {s.token for s in starts}
            ):
                b.feature(
                    "cancel", [{"actions": [info.name], "variable": var, "effect": {"to": "off"}}]
                )
                run_actions.append(info.name)
                b.note("features.cancel", "holding START stops the programme")
        done |= set(run_actions)
        ctx_units = [u for u in b.manual.units if RUNNING_RE.search(u.text)]
        if ctx_units:
            allowed = _dedupe(run_actions + power_actions + lock_actions)
            b.guards.append(
                {"name": "running", "when": {var: "on"}, "only": allowed, "display": ""}
            )
            line = b.manual.units.index(ctx_units[0])
            b.note("guards.running", "only start/stop (and power, lock) work while running", line)

    # stepping pairs, digits, dials -------------------------------------------------------
    pairs: dict[str, dict[str, list[str]]] = {}
    for info in infos:
        if info.name in done:
            continue
        d = adjuster_direction(info)
        if d:
            pairs.setdefault(d[0], {"up": [], "down": []})[d[1]].append(info.name)
    digits = [i.name for i in infos if i.digit is not None and i.name not in done]
    dials: dict[str, list[ActionInfo]] = {}
    for info in infos:
        if info.skill.startswith("turn") and info.name not in done:
            dials.setdefault(info.token, []).append(info)
    for base in list(pairs):
        if _pair_of_names(b, base, pairs[base]):
            del pairs[base]  # it moves through a list of names: no amount for other keys
    paired = {n for p in pairs.values() for ns in p.values() for n in ns}
    done |= paired | set(digits) | _used(b)

    # setting keys -------------------------------------------------------------------------
    keys = [i for i in infos if i.name not in done and not i.skill.startswith("turn")]
    adders = [k for k in keys if k.skill == "press" and ADD_RE.match(k.token)]
    keys = [k for k in keys if k not in adders]
    selecting = _selecting(b, keys)
    if selecting:
        var = _pad_group(b, selecting, label, first_mention)
        keys = [k for k in keys if k not in selecting]
        _shown_codes(b, var, selecting)
    pads = [k for k in keys if k.skill == "press" and not set(words(k.token)) & FUNCTION_WORDS]
    for group in _groups(b, pads, tables_only=True):
        if len(group) >= 3:
            _pad_group(b, group, label, first_mention)
            keys = [k for k in keys if k not in group]
    evidence = {k.name: b.evidence(list(k.controls)) for k in keys}
    options = _option_keys(b, keys)
    shared_pair = pairs.get("")
    generic_dials = [
        t for t in dials if t.split("_")[0] in GENERIC_DIALS and not _dial_values(b, t)
    ]
    entry_keys: list[ActionInfo] = []
    silent: list[ActionInfo] = []
    for key in keys:
        ev = evidence[key.name]
        name = _var_name(b, key)
        lab = label(key.controls[0])
        own_toggle = (
            ev.toggle_at is not None
            and any(ev.toggle_at in b.labels[c].mentions for c in key.controls if c in b.labels)
        ) or (key.token in options and not ev.values)
        if key.token in options and ev.toggle_at is None:
            ev.toggle_at = options[key.token]
        if own_toggle and not set(words(name)) & NUMERIC_WORDS:
            var = b.add_toggle(name, lab, ev.toggle_at)  # "press KEEP WARM to switch it on or off"
            b.feature(var, [{"actions": [key.name], "variable": var, "effect": "toggle"}])
        elif (
            ev.values
            and len(ev.values) >= 2
            and set(ev.values) != {"on", "off"}
            and not _numbered(b, key, ev)
        ):
            if _numeric_list(ev.values):
                ev2 = _list_evidence(ev)
                var = b.add_number(name, lab, ev2, cyclic=True)
            else:
                var = b.add_discrete(name, ev.values, lab, ev)
                b.note(
                    f"variables.{var}.values", ", ".join(b.variables[var]["values"]), ev.values_at
                )
            b.feature(f"set_{var}", [{"actions": [key.name], "variable": var, "effect": "next"}])
        elif ev.ranges and ev.each_press_at is not None:
            var = b.add_number(name, lab, ev, cyclic=True)
            b.feature(f"set_{var}", [{"actions": [key.name], "variable": var, "effect": "next"}])
            b.note(f"features.set_{var}", "each press steps to the next value", ev.each_press_at)
        elif ev.ranges or (ev.step and ev.toggle_at is None):
            entry_keys.append(key)
        elif digits and ev.keypad_at is not None and ev.toggle_at is None:
            entry_keys.append(key)  # "TIMER — the keypad then takes the time in minutes"
        elif (
            set(words(key.token)) & TIME_WORDS
            and ev.toggle_at is None
            and (shared_pair or digits or generic_dials)
        ):
            entry_keys.append(key)  # a clock or timer key: a time entered after it
        elif (ev.values and set(ev.values) == {"on", "off"}) or (
            ev.toggle_at is not None and not set(words(name)) & NUMERIC_WORDS
        ):
            var = b.add_toggle(name, lab, ev.toggle_at)
            b.feature(var, [{"actions": [key.name], "variable": var, "effect": "toggle"}])
        else:
            silent.append(key)

    # keys the manual lists together: one variable with a go-to value each
    groups = _groups(
        b, [k for k in silent if k.skill == "press" and not set(words(k.token)) & FUNCTION_WORDS]
    )
    for group in groups:
        _pad_group(b, group, label, first_mention)
        silent = [k for k in silent if k not in group]

    # entry keys take the stepping pair, a generic dial or the keypad
    steppers: list[tuple[list[str], list[str]]] = []
    if shared_pair and shared_pair["up"] and shared_pair["down"]:
        steppers.append((shared_pair["up"], shared_pair["down"]))
    for t in generic_dials:
        cw = [i.name for i in dials[t] if i.skill == "turn_cw"]
        ccw = [i.name for i in dials[t] if i.skill == "turn_ccw"]
        if cw and ccw:
            steppers.append((cw, ccw))
    if not entry_keys and (steppers or digits):
        entry_keys = [k for k in silent if k.skill == "press"]
        silent = [k for k in silent if k not in entry_keys]
    used_steppers: set[int] = set()
    used_digits = False
    if steppers and shared_pair and entry_keys:
        # a stepping pair whose own sentences name what it sets, and no entry key sets that,
        # keeps its own setting: the entry keys then step theirs by themselves
        pair_tokens = [_token_of(b, n) for n in steppers[0][0] + steppers[0][1]]
        pair_noun = _noun(b, pair_tokens, None)
        names = [set(words(_var_name(b, k))) for k in entry_keys]
        direct_nouns = {"temperature", "humidity", "volume", "weight", "speed"}  # set alone
        if pair_noun in direct_nouns and not any(
            any(
                pair_noun.startswith(w[:4]) or w.startswith(pair_noun[:4]) for w in n if len(w) >= 3
            )
            for n in names
        ):
            steppers = steppers[1:] + steppers[:1]
            used_steppers = set()
            for key in entry_keys:
                var = b.add_number(
                    _var_name(b, key), label(key.controls[0]), evidence[key.name], True
                )
                b.feature(
                    f"set_{var}", [{"actions": [key.name], "variable": var, "effect": "next"}]
                )
                b.note(f"features.set_{var}", f"{key.name} steps its setting (+/− set {pair_noun})")
            entry_keys = []
    for key in entry_keys:
        ev = evidence[key.name]
        name = _var_name(b, key)
        lab = label(key.controls[0])
        timeish = bool(ev.ranges and ev.ranges[0].unit in ("s", "min", "h")) or bool(
            set(words(name)) & TIME_WORDS
        )
        if digits and (timeish or not steppers):
            var = b.add_number(
                name, lab, ev if ev.ranges else Evidence(ranges=[], step=ev.step), cyclic=False
            )
            spec = b.variables[var]
            _keypad_entry(spec)
            b.feature(
                f"set_{var}", [{"actions": [key.name]}, {"actions": list(digits), "variable": var}]
            )
            b.note(f"features.set_{var}", f"{lab} then the number keys", ev.range_at)
            used_digits = True
        elif steppers:
            up, down = steppers[0]
            used_steppers.add(0)
            if ev.values and len(ev.values) >= 3 and _numeric_list(ev.values):
                ev = _list_evidence(ev)  # the settings listed one by one, not only the ends
            var = b.add_number(name, lab, ev, cyclic=False)
            b.feature(
                f"set_{var}",
                [
                    {"actions": [key.name]},
                    {
                        "actions": up + down,
                        "variable": var,
                        "effect": {**{a: "next" for a in up}, **{a: "prev" for a in down}},
                    },
                ],
            )
            b.note(f"features.set_{var}", f"{lab} then the stepping keys", ev.range_at)
        else:
            var = b.add_number(name, lab, ev, cyclic=True)
            b.feature(f"set_{var}", [{"actions": [key.name], "variable": var, "effect": "next"}])
            b.note(
                f"features.set_{var}",
                "each press steps to the next value (the manual names no other way)",
            )
    for t in generic_dials:  # turned by itself, the dial picks the list its sentence names
        cw = [i.name for i in dials[t] if i.skill == "turn_cw"]
        ccw = [i.name for i in dials[t] if i.skill == "turn_ccw"]
        if cw and ccw and _dial_list(b, t, cw, ccw):
            used_steppers |= {k for k, pair in enumerate(steppers) if pair == (cw, ccw)}
    for index, (up, down) in enumerate(steppers):
        if index not in used_steppers:
            tokens_ = [n for n in up + down]
            ev = b.evidence([_token_of(b, n) for n in tokens_])
            noun = _noun(b, [_token_of(b, n) for n in tokens_], ev) or "level"
            var = b.add_number(noun, noun.upper(), ev, cyclic=False)
            b.feature(
                f"set_{var}",
                [
                    {
                        "actions": up + down,
                        "variable": var,
                        "effect": {**{a: "next" for a in up}, **{a: "prev" for a in down}},
                    }
                ],
            )
    cooking = any(re.search(r"\bcook(?:ing)? time\b", u.text, re.I) for u in b.manual.units)
    named_cook = any("cook" in v for v in b.variables)
    direct: str | None = None
    if digits and (not used_digits or (cooking and not named_cook)):
        var = b.add_number(
            "cook_time" if cooking else "time", "TIME", Evidence(ranges=[], step=(1, "s")), False
        )
        spec = b.variables[var]
        spec["ranges"] = [["00:00:00", "01:39:59", 1]]
        spec["format"] = "mm:ss"
        spec["entry"] = {"format": "mm:ss"}
        b.feature(f"set_{var}", [{"actions": list(digits), "variable": var}])
        b.note(f"features.set_{var}", "the number keys enter a time directly")
        direct = var
    for key in adders:
        m = ADD_RE.match(key.token)
        amount = int(m.group(2)) if m else 30
        minutes = bool(m and m.group(3) and m.group(3).startswith("m"))
        seconds_ = amount * (60 if minutes else 1)
        target = direct or next(
            (v for v, spec in b.variables.items() if spec.get("type") == "time"), None
        )
        if target is None:
            target = b.add_number("cook_time", "TIME", Evidence(ranges=[], step=(1, "s")), False)
        step = f"{seconds_ // 3600:02d}:{seconds_ % 3600 // 60:02d}:{seconds_ % 60:02d}"
        effect = {"add": step} if b.variables[target].get("type") == "time" else {"add": amount}
        b.feature(key.token, [{"actions": [key.name], "variable": target, "effect": effect}])
        b.note(
            f"features.{key.token}",
            f"{key.name} adds {amount} {'min' if minutes else 's'} to {target}",
        )
    for base, pair in pairs.items():
        if base == "":
            if not (pair["up"] and pair["down"]):
                for n in pair["up"] + pair["down"]:
                    silent.append(next(i for i in infos if i.name == n))
            continue
        toks = [_token_of(b, n) for n in pair["up"] + pair["down"]]
        ev = b.evidence(toks + ([base] if base in b.labels else []))
        var = b.add_number(base, base.upper(), ev, cyclic=False)
        eff = {**{a: "next" for a in pair["up"]}, **{a: "prev" for a in pair["down"]}}
        b.feature(
            f"set_{var}", [{"actions": pair["up"] + pair["down"], "variable": var, "effect": eff}]
        )

    # dials with their own values (a generic dial already taken as a stepper is skipped)
    for token, turns in dials.items():
        cw = [i.name for i in turns if i.skill == "turn_cw"]
        ccw = [i.name for i in turns if i.skill == "turn_ccw"]
        used = {a for steps in b.features.values() for st in steps for a in st["actions"]}
        if set(cw + ccw) & used:
            continue
        ev = b.evidence([token])
        lab = label(token)
        if ev.values and not _numeric_list(ev.values):
            var = b.add_discrete(token, ev.values, lab, ev)
            b.note(f"variables.{var}.values", ", ".join(b.variables[var]["values"]), ev.values_at)
        elif ev.values:
            var = b.add_number(token, lab, _list_evidence(ev), cyclic=False)
        else:
            var = b.add_number(token, lab, ev, cyclic=False)
        eff = {**{a: "next" for a in cw}, **{a: "prev" for a in ccw}}
        b.feature(f"select_{var}", [{"actions": cw + ccw, "variable": var, "effect": eff}])
        _dial_ends(b, token, var)
        values = b.variables[var].get("values") or []
        if (
            values
            and values[0] == "off"
            and "power" not in b.variables
            and not any(g["name"] == "power off" for g in b.guards)
        ):  # a knob whose first position is OFF is the on/off switch: off, nothing else works
            b.guards.append(
                {"name": "power off", "when": {var: "off"}, "only": cw + ccw, "display": "",
                 "hide": True}
            )  # fmt: skip
            b.note("guards.power off", f"the {lab} knob at OFF switches the appliance off")
        for k in [k for k in silent if k.token == token]:
            b.feature(
                f"{k.token}_press",
                [{"actions": [k.name]}, {"actions": cw + ccw, "variable": var, "effect": eff}],
            )
            silent.remove(k)

    # whatever is left: a toggle the closed loop can repair
    for key in silent:
        name = _var_name(b, key)
        if set(words(name)) & NUMERIC_WORDS and key.skill == "press":
            var = b.add_number(name, label(key.controls[0]), evidence[key.name], cyclic=True)
            b.feature(f"set_{var}", [{"actions": [key.name], "variable": var, "effect": "next"}])
            b.note(f"features.set_{var}", f"{key.name} steps an amount (the manual says no more)")
            continue
        var = b.add_toggle(name, label(key.controls[0]), None)
        b.feature(var, [{"actions": [key.name], "variable": var, "effect": "toggle"}])
        b.note(
            f"features.{var}",
            f"{key.name} toggles a setting of its own (the manual says nothing clear)",
        )


ADD_RE = re.compile(r"^(add|plus|extra)_?(\d+)_?(s|sec|secs|seconds|m|min|mins|minutes)?$")
NUMERIC_WORDS = {
    "time", "timer", "delay", "clock", "humidity", "temperature", "temp", "level", "watt",
    "speed", "weight", "volume", "duration", "hour", "min", "minute", "preset", "reserve",
}  # fmt: skip  # settings that are amounts: "switch the timer off" does not make them toggles
TIME_WORDS = {"time", "timer", "clock", "delay", "duration", "preset", "reserve", "ready"}
FUNCTION_WORDS = {
    *SETTING_NOUNS,
    *GROUP_NOUNS,
    "clock",
    "hour",
    "min",
    "minute",
    "sec",
    "texture",
    "timer",
    "keep",
    "warm",
    "light",
    "lock",
    "delay",
    "preset",
    "size",
    "crust",
    "colour",
    "color",
    "loaf",
    "start",
    "stop",
    "cancel",
    "temp",
    "fan",
    "auto",
    "select",
    "set",
    "memory",
    "sound",
    "quick",
    "express",
    "reserve",
    "taste",
    "add",
    "weight",
    "child",
    "display",
    "eco",
    "rinse",
    "spin",
    "dry",
    "wash",
    "turbo",
    "swing",
    "pump",
    "water",
    "soil",
    "option",
    "options",
}  # what a key does, not a programme it names


LIST_WORDS = {"left", "right", "prev", "previous", "next", "forward"}


def _used(b: Builder) -> set[str]:
    return {a for steps in b.features.values() for st in steps for a in st["actions"]}


def _pair_of_names(b: Builder, base: str, pair: dict[str, list[str]]) -> bool:
    """A stepping pair whose sentences give a list of names (◄ ► "move through the cooking
    functions" above a table of them) steps that list as a setting of its own, both ways."""
    if not (pair["up"] and pair["down"]):
        return False
    tokens = [_token_of(b, n) for n in pair["up"] + pair["down"]]
    if not all(set(t.split("_")) & LIST_WORDS for t in tokens):
        return False  # + − and ▲ ▼ set amounts (often for other keys); ◄ ► move through lists
    ev = b.evidence(tokens + ([base] if base in b.labels else []))
    if not ev.values:
        named = _named_column(b, tokens)
        if named is not None:
            ev = Evidence(values=[v.lower() for v in named[0]], values_at=named[1])
    if not ev.values or len(ev.values) < 3 or _numeric_list(ev.values):
        return False
    noun = base or _list_noun(b, ev) or _noun(b, tokens, None) or "selection"
    var = b.add_discrete(noun, ev.values, noun.upper(), ev)
    eff = {**{a: "next" for a in pair["up"]}, **{a: "prev" for a in pair["down"]}}
    b.feature(
        f"select_{var}", [{"actions": pair["up"] + pair["down"], "variable": var, "effect": eff}]
    )
    b.note(f"variables.{var}.values", ", ".join(b.variables[var]["values"]), ev.values_at)
    return True


def _dial_list(b: Builder, token: str, cw: list[str], ccw: list[str]) -> bool:
    """A generic dial ("SELECT dial: turn to pick a program, or to change the temperature
    after TEMP") whose sentences name a list of names: turning it alone steps that list."""
    ev = b.evidence([token])
    values = ev.values if ev.values and not _numeric_list(ev.values) else None
    at = ev.values_at
    named = _named_column(b, [token]) if values is None else None
    if named is not None:
        values, at = [v.lower() for v in named[0]], named[1]
    if not values or len(values) < 3:
        return False
    found = Evidence(values=values, values_at=at)
    noun = _list_noun(b, found) or "programme"
    var = b.add_discrete(noun, values, noun.upper(), found)
    eff = {**{a: "next" for a in cw}, **{a: "prev" for a in ccw}}
    b.feature(f"select_{var}", [{"actions": cw + ccw, "variable": var, "effect": eff}])
    b.note(f"variables.{var}.values", ", ".join(b.variables[var]["values"]), at)
    return True


def _named_column(b: Builder, tokens: list[str]) -> tuple[list[str], int] | None:
    """A table column of names headed by a noun the keys' own sentences use ("◄ ► move
    through the cooking functions" and a table with a "Function" column)."""
    units = b.manual.units
    said = {
        w[:5]
        for t in tokens
        if t in b.labels
        for i in b.labels[t].mentions
        for w in words(units[i].text)
        if len(w) >= 4
    }
    for i, unit in enumerate(units):
        if not unit.cells or unit.header:
            continue  # only header rows
        for column, cell in enumerate(unit.cells):
            cw = words(cell)
            if len(cw) == 1 and len(cw[0]) >= 4 and cw[0][:5] in said:
                values = _next_table_column(units, i - 1, column)
                if len(values) >= 3:
                    return values, i
    return None


def _list_noun(b: Builder, ev: Evidence) -> str:
    """The header of the table column a list was read from ("Function"), if any."""
    if ev.values_at is None:
        return ""
    units = b.manual.units
    for unit in units[ev.values_at : ev.values_at + 3]:
        if unit.header:
            for cell in unit.header:
                if words(cell) and not re.fullmatch(r"[#n]o?\.?|", cell.strip().lower()):
                    return "_".join(words(cell)[:2])
    return ""


def _pad_group(b: Builder, group: list[ActionInfo], label: Any, first_mention: Any) -> str:
    """Keys the manual lists together: one variable, each key going to its own value."""
    noun = _group_noun(b, group)
    var = b.unique(noun, b.variables)
    values = [_v(label(k.controls[0])) for k in group]
    values = [v if values.count(v) == 1 else f"{v}_{i}" for i, v in enumerate(values)]
    b.variables[var] = {"type": "discrete", "values": values, "label": noun.upper()}
    b.note(
        f"variables.{var}",
        f"keys listed together select one {noun}: {', '.join(values)}",
        first_mention([g.token for g in group]),
    )
    start, at = _pad_initial(b, values)
    if start is None:
        b.note(f"variables.{var}.initial", f"starts at {values[0]} (the manual does not say)")
    elif start in values:
        b.variables[var]["initial"] = start
        b.note(f"variables.{var}.initial", f"starts at {start}", at)
    else:  # a state no key selects ("Manual mode is selected every time you switch on")
        b.variables[var]["values"] = [start, *values]
        b.note(f"variables.{var}.initial", f"starts at {start}, which no key selects", at)
    for key, value in zip(group, values, strict=True):  # one go-to feature per key
        b.feature(key.token, [{"actions": [key.name], "variable": var, "effect": {"to": value}}])
    return var


START_RE = re.compile(
    r"\b(?:(?:is|comes)\s+(?:set|preset)\s+(?:for|to)|starts?\s+(?:in|with|on)|defaults?\s+to"
    r"|by default(?:,)?\s+(?:it is|is)|comes on in)\s+(?:the\s+)?"
    r"([A-Za-z][\w-]*(?: [A-Za-z][\w-]*)?)"
    r"|\b([A-Z][\w-]*)\s+(?:mode|programme|program|setting)\s+is\s+(?:selected|chosen|set)"
    r"\s+(?:automatically|by default|(?:each|every) time)",
)


def _pad_initial(b: Builder, values: list[str]) -> tuple[str | None, int | None]:
    """What a pad of go-to keys starts at: a value the manual says it is set for out of the box,
    or a named mode selected on switching on that no key selects."""
    for i, unit in enumerate(b.manual.units):
        for m in START_RE.finditer(unit.text):
            if m.group(1):
                words_ = m.group(1).lower().split()
                for k in (2, 1):
                    if " ".join(words_[:k]) in values:
                        return " ".join(words_[:k]), i
            elif m.group(2):
                return m.group(2).lower(), i
    return None, None


def _keypad_entry(spec: dict[str, Any]) -> None:
    """Digits typed for a variable: mm:ss for short times, hh:mm (minute steps) for long ones."""
    from apbot.model.values import parse_hms

    if spec["type"] != "time":
        spec["entry"] = {"format": "number"}
        return
    top = max(parse_hms(r[1]) for r in spec["ranges"])
    if top < 6000 and any(int(r[2]) < 60 for r in spec["ranges"]):
        spec["entry"] = {"format": "mm:ss"}
        spec["format"] = "mm:ss"
        return
    spec["entry"] = {"format": "hh:mm"}
    spec["format"] = "h:mm"
    fixed = []
    for lo, hi, step in spec["ranges"]:
        step = max(60, round(int(step) / 60) * 60)
        span = parse_hms(hi) - parse_hms(lo)
        end = parse_hms(lo) + span // step * step
        if end > parse_hms(lo):
            fixed.append([lo, f"{end // 3600:02d}:{end % 3600 // 60:02d}:00", step])
    spec["ranges"] = fixed or [["00:00:00", "23:59:00", 60]]


def _var_name(b: Builder, key: ActionInfo) -> str:
    """The setting's name: the key's printed name when it spells out the action's word
    ("KITCHEN TIMER" for timer, "WATER LEVEL" for water), else the action's word."""
    base = key.token if key.skill == "press" else f"{key.token}_hold"
    lab = b.labels.get(key.controls[0])
    if key.skill != "press" or lab is None or lab.line is None:
        return base
    lw = [w for w in words(lab.text) if w.isalpha()]
    tw = words(key.token.replace("_", " "))
    if 1 < len(lw) <= 3 and all(any(x == t or x.startswith(t) for x in lw) for t in tw):
        return "_".join(lw)
    return base


def _dedupe(items: list[str]) -> list[str]:
    return list(dict.fromkeys(items))


def _v(text: str) -> str:
    return re.sub(r"\s+", " ", text.lower()).strip()


def _token_of(b: Builder, action: str) -> str:
    return next(i.token for i in b.infos if i.name == action)


def _state_word(
    b: Builder, tokens: list[str], cue: re.Pattern[str], reject: re.Pattern[str] | None = None
) -> tuple[str, int | None]:
    """The word the panel shows in a state (running, locked): first in the sentences about the
    keys that enter it (the sentence that names the key, or the one right after it), then in any
    sentence about the state; a word ``reject`` matches belongs to another state."""
    keys = {lab.text for lab in b.labels.values() if lab.text}
    mentions = {m for t in tokens for m in _mentions(b, t)}
    near = [i for i in b.context(tokens) if i < len(b.manual.units)]
    rest = [i for i, u in enumerate(b.manual.units) if cue.search(u.text) and i not in near]
    for i in near + rest:
        text = b.manual.units[i].text
        if not cue.search(text) and not (i - 1 in mentions and i not in mentions):
            continue
        for word in shown_words(text, keys):
            if reject is None or not reject.search(word):
                return word, i
    return "", None


ENDLESS_RE = re.compile(
    r"\bno (?:end )?stops?\b|\bturns? (?:freely|endlessly|all the way round)\b|\bendless\w*"
    r"|\b(?:simply )?continues with the first\b|\bround and round\b",
    re.IGNORECASE,
)
STOPS_RE = re.compile(
    r"\bstops? at (?:each|either|both|the) ends?\b|\bstops? at \S+ and (?:at )?\S+"
    r"|\bend stops?\b|\bwill not turn (?:past|beyond)"
    r"|\bcannot be turned (?:past|beyond)",
    re.IGNORECASE,
)


def _dial_ends(b: Builder, token: str, var: str) -> None:
    """A knob the manual says stops at its ends clamps; one with no end stop goes round."""
    units = b.manual.units
    noun = re.compile(rf"\b{re.escape(token.replace('_', ' '))}\b", re.IGNORECASE)
    near = b.context([token]) + [i for i, u in enumerate(units) if noun.search(u.text)]
    for i in dict.fromkeys(near):
        text = units[i].text
        if ENDLESS_RE.search(text):
            b.variables[var]["wrap"] = True
            b.note(f"variables.{var}.wrap", "the knob has no end stop", i)
            return
        if STOPS_RE.search(text):
            b.variables[var]["wrap"] = False
            b.note(f"variables.{var}.wrap", "the knob stops at its ends", i)
            return


OPTIONS_RE = re.compile(
    r"\boptions?\b[^.]*\b(?:(?:turned|switched|set) on and off|on or off|on and off|toggle)",
    re.IGNORECASE,
)


def _option_keys(b: Builder, keys: list[ActionInfo]) -> dict[str, int]:
    """Keys of an options section ("Options are turned on and off by touching their pad"):
    those named in it, up to a heading that names no key."""
    units = b.manual.units
    labels = {k.token: b.labels[k.controls[0]].text for k in keys if k.controls[0] in b.labels}
    found: dict[str, int] = {}
    for o, unit in enumerate(units):
        if not OPTIONS_RE.search(unit.text):
            continue
        for j in range(o, min(o + 40, len(units))):
            text = units[j].text
            if (
                j > o
                and text == units[j].heading
                and not any(lab and lab.upper() in text.upper() for lab in labels.values())
            ):
                break
            for token, lab in labels.items():
                if lab and re.search(rf"(?<![A-Za-z0-9]){re.escape(lab)}(?![A-Za-z0-9])", text):
                    found.setdefault(token, o)
    return found


def _numbered(b: Builder, key: ActionInfo, ev: Evidence) -> bool:
    """A key whose own sentence gives a bare number range ("Next menu number (1–15)") sets a
    number, whatever names a table elsewhere gives the numbers."""
    own = set(_mentions(b, key.controls[0]))
    return (
        bool(ev.ranges)
        and ev.range_at in own
        and ev.values_at not in own
        and not ev.ranges[0].unit
        and ev.ranges[0].high - ev.ranges[0].low >= 2
    )


def _mentions(b: Builder, token: str) -> list[int]:
    return b.labels[token].mentions if token in b.labels else []


def _lock_word(b: Builder, info: ActionInfo) -> str:
    for i in b.context(list(info.controls)):
        for m in re.finditer(
            r"\b([A-Z][A-Z-]*LOC[A-Z]*|LOC|LOCK(?:ED)?|[A-Z]-?L)\b", b.manual.units[i].text
        ):
            if "CLOCK" not in m.group(1):
                return m.group(1)
    return ""


def _numeric_list(values: list[str]) -> bool:
    return all(re.fullmatch(r"\d+(?:[.,]\d+)?\s*[a-z%°]*", v.strip().lower()) for v in values)


def _nums(values: list[str]) -> list[float]:
    found = [re.match(r"\d+(?:[.,]\d+)?", v.strip()) for v in values]
    return sorted({float(m.group(0).replace(",", ".")) for m in found if m})


def _list_evidence(ev: Evidence) -> Evidence:
    """A printed row of numbers as piecewise ranges, exactly those numbers (equal gaps share a
    piece: 20 30 40 60 90 is 20–40 by 10, 40–60 by 20, 60–90 by 30)."""
    from apbot.read.values import Range, unit_name

    nums = _nums(ev.values or [])
    unit = unit_name(re.sub(r"[\d.,\s]", "", (ev.values or [""])[-1]))
    pieces: list[Range] = []
    for lo, hi in itertools.pairwise(nums):
        gap = round(hi - lo, 6)
        if pieces and pieces[-1].step == gap:
            pieces[-1] = Range(pieces[-1].low, hi, unit, gap)
        else:
            pieces.append(Range(lo, hi, unit, gap))
    return Evidence(
        ranges=pieces or [_list_range(ev.values or [])],
        range_at=ev.values_at,
        initial=ev.initial,
        initial_at=ev.initial_at,
    )


def _list_range(values: list[str]) -> Any:
    from apbot.read.values import Range, unit_name

    nums = _nums(values)
    unit = unit_name(re.sub(r"[\d.,\s]", "", values[-1])) if values else ""
    return Range(nums[0], nums[-1], unit)


def _list_step(values: list[str]) -> tuple[float, str] | None:
    nums = _nums(values)
    if len(nums) < 2:
        return None
    diffs = {round(b - a, 6) for a, b in itertools.pairwise(nums)}
    return (min(diffs), "") if diffs else None


def _dial_values(b: Builder, token: str) -> bool:
    if token not in b.labels or b.labels[token].line is None:
        return False
    ev = b.evidence([token])
    return bool(ev.values or ev.ranges)


SELECTS_ONE = re.compile(
    r"\s*(?:selects?|chooses?|picks?|starts?)\s+(?:the\s+)?(?:programs?|programmes?|menus?|modes?"
    r"|functions?|cycles?|courses?|presets?)\s+(?!you\b|that\b|which\b|the\b)[\w\"'“]",
    re.IGNORECASE,
)
CODE_RE = re.compile(r"\b([A-Z]{1,3}-?\d{1,2})\b")
CODE_SHOWN_RE = re.compile(
    r"\b(?:code|number)\b[^.]*\b(?:appears?|shows?|shown|displayed|lights?)\b"
    r"|\bdisplay\b[^.]*\bshows?\b[^.]*\b(?:code|number)\b",
    re.IGNORECASE,
)
PAD_NOUNS = re.compile(
    r"\b(?:programs?|programmes?|menus?|modes?|functions?|cycles?|courses?|presets?|foods?|"
    r"recipes?|dish(?:es)?|auto\w*)\b",
    re.IGNORECASE,
)


def _groups(
    b: Builder, keys: list[ActionInfo], tables_only: bool = False
) -> list[list[ActionInfo]]:
    """Keys the manual lists together as the choices of one thing: named in one sentence, or in
    the first cells of one table, that also says what they choose (a programme, a menu…)."""
    if len(keys) < 2:
        return []
    units = b.manual.units
    parent = {k.name: k.name for k in keys}

    def find(x: str) -> str:
        while parent[x] != x:
            x = parent[x]
        return x

    for unit_index in range(0 if tables_only else len(units)):
        if not PAD_NOUNS.search(units[unit_index].text):
            continue
        present = [k for k in keys if unit_index in b.labels[k.controls[0]].mentions]
        for k in present[1:]:
            parent[find(k.name)] = find(present[0].name)
    # table columns: labels in the first cells of consecutive rows
    rows: list[list[ActionInfo]] = []
    current: list[ActionInfo] = []
    said = False
    for unit in units:
        if unit.cells and unit.header:
            if not current:  # a table of programmes: its first column is headed by what they are
                said = bool(unit.header and PAD_NOUNS.search(unit.header[0]))
            first = unit.cells[0].upper()
            current += [k for k in keys if b.labels[k.controls[0]].text.upper() in first]
        elif current:
            if said:
                rows.append(current)
            current = []
    if current and said:
        rows.append(current)
    for row in rows:
        for k in row[1:]:
            parent[find(k.name)] = find(row[0].name)
    out: dict[str, list[ActionInfo]] = {}
    for k in keys:
        out.setdefault(find(k.name), []).append(k)
    return [g for g in out.values() if len(g) >= 2]


def _selecting(b: Builder, keys: list[ActionInfo]) -> list[ActionInfo]:
    """Keys whose rows in a key table each say they select one named choice ("| DRY |
    Selects programme P4 |"): one choice variable, whatever words the keys' names hold."""
    rows = [u for u in b.manual.units if len(u.cells) >= 2 and SELECTS_ONE.match(u.cells[1])]
    out: list[ActionInfo] = []
    free: list[Unit] = []
    for unit in rows:
        name = unit.cells[0].strip(" *").upper()
        found = [
            k
            for k in keys
            if k.skill == "press"
            and b.labels[k.controls[0]].line is not None
            and b.labels[k.controls[0]].text.upper() == name
        ]
        out += found
        if not found and not any(lab.text.upper() == name for lab in b.labels.values()):
            free.append(unit)
    unnamed = [k for k in keys if k.skill == "press" and b.labels[k.controls[0]].line is None]
    if len(out) >= 2 and len(free) == 1 and len(unnamed) == 1:
        # the one key the manual never names is the one row no key claims ("FULL" is
        # "WASH+STERILISE+DRY")
        label = b.labels[unnamed[0].controls[0]]
        label.text, label.line = free[0].cells[0].strip(" *"), free[0].line
        label.mentions = [i for i, u in enumerate(b.manual.units) if label.text in u.text]
        out.append(unnamed[0])
    out = _dedupe_keys(out)
    if len(out) >= 2:
        return out
    # rows naming several keys that are all one kind of choice ("| WHITE · BROWN | Rice modes |")
    by_noun: dict[str, list[ActionInfo]] = {}
    for unit in b.manual.units:
        if len(unit.cells) < 2:
            continue
        m = PAD_NOUNS.search(unit.cells[1])
        if not m or len(unit.cells[1].split()) > 4:
            continue  # a short cell that only says what they are
        named = [
            k
            for k in keys
            if k.skill == "press"
            and b.labels[k.controls[0]].line is not None
            and re.search(
                rf"(?<![A-Z0-9]){re.escape(b.labels[k.controls[0]].text.upper())}(?![A-Z0-9])",
                unit.cells[0].upper(),
            )
        ]
        if len(named) >= 2:
            by_noun.setdefault(m.group(0).lower().rstrip("s"), []).extend(named)
    best = max(by_noun.values(), key=len, default=[])
    return _dedupe_keys(best) if len(_dedupe_keys(best)) >= 3 else []


def _shown_codes(b: Builder, var: str, keys: list[ActionInfo]) -> None:
    """Rows saying "Selects programme P3" for every key, and a manual saying the code is what
    the display shows: each value is shown by its code."""
    if not any(CODE_SHOWN_RE.search(u.text) for u in b.manual.units):
        return
    codes: dict[str, str] = {}
    for unit in b.manual.units:
        if len(unit.cells) < 2 or not SELECTS_ONE.match(unit.cells[1]):
            continue
        m = CODE_RE.search(unit.cells[1])
        for k in keys:
            if m and b.labels[k.controls[0]].text.upper() == unit.cells[0].strip(" *").upper():
                codes[k.name] = m.group(1)
    if len(codes) != len(keys) or len(set(codes.values())) != len(keys):
        return
    spec = b.variables[var]
    shown = {}
    for k in keys:
        effect = b.features[k.token][0]["effect"]
        shown[effect["to"]] = codes[k.name]
    spec["show"] = shown
    b.note(
        f"variables.{var}.show",
        "the display shows each one's code: " + ", ".join(f"{v} {c}" for v, c in shown.items()),
    )


def _dedupe_keys(keys: list[ActionInfo]) -> list[ActionInfo]:
    return [k for i, k in enumerate(keys) if k not in keys[:i]]


def _group_noun(b: Builder, group: list[ActionInfo]) -> str:
    counts: dict[str, int] = {}
    for k in group:
        for i in b.labels[k.controls[0]].mentions:
            unit = b.manual.units[i]
            text = (unit.text + " " + " ".join(unit.header) + " " + unit.heading).lower()
            for noun in GROUP_NOUNS:
                if re.search(rf"\b{noun}", text):
                    counts[noun] = counts.get(noun, 0) + 1
    return max(counts, key=lambda n: counts[n]) if counts else "programme"


def _noun(b: Builder, tokens: list[str], ev: Evidence | None = None) -> str:
    """What a pair of stepping keys sets: the quantity its range is in, else the setting noun
    its sentences name most often."""
    unit = ev.ranges[0].unit if ev is not None and ev.ranges else ""
    by_unit = {"°C": "temperature", "°F": "temperature", "%": "humidity", "min": "time",
               "h": "time", "s": "time", "W": "power"}  # fmt: skip
    if unit in by_unit:
        return by_unit[unit]
    counts: dict[str, int] = {}
    # another key's name ("while the TIMER is being set they change the hours") is what the
    # pair sets for that key, not its own setting
    keys = {lab.text.lower() for t, lab in b.labels.items() if t not in tokens and lab.text}
    for i in b.context(tokens):
        text = b.manual.units[i].text.lower()
        for noun in (n for n in SETTING_NOUNS if n not in keys):
            counts[noun] = counts.get(noun, 0) + len(re.findall(rf"\b{noun}\b", text))
    best = max(SETTING_NOUNS, key=lambda n: (counts.get(n, 0), -SETTING_NOUNS.index(n)))
    return best if counts.get(best) else ""
