"""Amounts: entry keys set through the stepping pair, a generic dial or the keypad; stepping
pairs of their own; add-time keys. Dials of their own and the keys left over are in
:mod:`apbot.read.roles_own_dials`."""

from __future__ import annotations

import re
from typing import Any

from apbot.model.values import format_hms
from apbot.read.actions import ActionInfo
from apbot.read.added_time import added_time
from apbot.read.bracket_lists import lettered
from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.pair_own_ranges import pair_keeps_range
from apbot.read.roles_common import (
    TIME_WORDS,
    UNIT_QUANTITY,
    label_of,
    mentions_of,
    numeric_list,
    stepped_noun,
    token_of,
    turns,
    var_name,
)
from apbot.read.roles_confirm import ends_entry
from apbot.read.roles_lists import dial_amount, dial_list, list_evidence
from apbot.read.roles_numbered import numbered_entry
from apbot.read.roles_pairafter import pair_follows, pair_serves_only
from apbot.read.roles_pushed import pushed_dials
from apbot.read.roles_raised import (
    alone_range,
    own_sentence,
    raised_quantity,
    set_alone,
    sets_with_pair,
)
from apbot.read.shapes import Evidence
from apbot.read.typed_seconds import as_seconds, typed_as_seconds
from apbot.read.typed_whole import typed_every_whole
from apbot.read.up_down_nouns import up_down_noun

# units that name what a pair sets by themselves (a range in °C is a temperature)
_UNIT_NOUNS = {"°C", "°F", "%", "min", "h", "s", "W"}
ADD_RE = re.compile(r"^(add|plus|extra)_?(\d+)_?(s|sec|secs|seconds|m|min|mins|minutes)?$")


_COOK_TIME_RE = re.compile(r"\bcook(?:ing)? time\b", re.I)
_COOK_TIMER_RE = re.compile(r"\bcook(?:ing)? timer\b", re.I)


def assign_amounts(
    b: Builder,
    entry_keys: list[ActionInfo],
    silent: list[ActionInfo],
    evidence: dict[str, Evidence],
    pairs: dict[str, dict[str, list[str]]],
    digits: list[str],
    dials: dict[str, list[ActionInfo]],
    generic_dials: list[str],
    adders: list[ActionInfo],
    keyed_time: str | None = None,
) -> list[ActionInfo]:
    """Entry keys take the stepping pair, a generic dial or the keypad; then the steppers no key
    took, the keypad alone, add-time keys and named stepping pairs; returns the keys still
    without a role. ``keyed_time``: the time function keys' procedures already type."""
    infos = b.infos
    shared_pair = pairs.get("")
    steppers: list[tuple[list[str], list[str]]] = []
    if shared_pair and shared_pair["up"] and shared_pair["down"]:
        steppers.append((shared_pair["up"], shared_pair["down"]))
    for t in generic_dials:
        cw, ccw = turns(dials[t])
        if cw and ccw:
            steppers.append((cw, ccw))
    entry_keys = pushed_dials(b, entry_keys, evidence, dials, generic_dials, steppers)
    if not any(k.skill == "press" for k in entry_keys) and (steppers or digits):
        # (a key's hold that sets a timer leaves its press to set the key's own amount)
        # (a key that only closes an entry, "OK  Confirms an entry", types nothing itself)
        guessed = [k for k in silent if k.skill == "press" and not ends_entry(b, k)]
        entry_keys = entry_keys + guessed
        silent = [k for k in silent if k not in entry_keys]
    else:
        guessed = []
    used_steppers: set[int] = set()
    used_digits = keyed_cook = keyed_time is not None
    raised = None  # what the shared pair's legend says it raises and lowers ("heat level")
    own_noun: str | None = None  # the pair's own quantity when entry keys share it too
    up_down = False  # the pair's quantity read from "NOUN up / down" (up_down_nouns)
    if shared_pair and shared_pair["up"] and shared_pair["down"]:
        pair_tokens_ = [token_of(b, n) for n in shared_pair["up"] + shared_pair["down"]]
        raised = raised_quantity(b, pair_tokens_)
        named = up_down_noun(b, pair_tokens_)  # "▲ / ▼ ..... output up / down"
        if raised is None:  # the noun before the directions
            raised = named
        # the legend's noun, whether or not a verb names it too ("raise the heat level" and
        # "heat level up / down"): the legend then says what the pair sets, and keys guessed
        # as entry keys give it back
        up_down = named is not None and raised is not None and named[0] == raised[0]
    if steppers and shared_pair and entry_keys:
        # a stepping pair whose own sentences name what it sets, and no entry key sets that,
        # keeps its own setting: the entry keys then step theirs by themselves
        pair_tokens = [token_of(b, n) for n in steppers[0][0] + steppers[0][1]]
        pair_noun = stepped_noun(b, pair_tokens, None)
        names = [set(words(var_name(b, k))) for k in entry_keys]
        direct_nouns = {"temperature", "humidity", "volume", "weight", "speed"}  # set alone
        own_pair = pair_noun in direct_nouns and not _named_by(names, [pair_noun])
        own_pair = own_pair and not pair_serves_only(b, pair_tokens)
        if (not own_pair or up_down) and raised is not None:
            # (a legend's "Speaker volume" says it better than the nouns counted round the pair)
            # the pair's legend says what it raises ("Raise / lower the heat level"), and no
            # entry key's name or own sentence names it (TIMER "sets the delay" while + "raises
            # the delay" stays TIMER's)
            nouns = raised[0].split("_")
            for key in entry_keys:
                if up_down and key in guessed:
                    continue  # (a key made an entry key by default says nothing of the pair)
                said = [own_sentence(b, c, i) for c in key.controls for i in mentions_of(b, c)]
                names.append({w for t in said for w in words(t) if len(w) >= 4})
            own_pair = not _named_by(names, nouns)
            pair_noun = raised[0]
        if not own_pair and pair_keeps_range(b, pair_tokens, entry_keys, evidence):
            own_pair = True  # "▲ and ▼ set … from 10 % to 100 %" beside "after ADDR, …"
            pair_noun = stepped_noun(b, pair_tokens, b.evidence(pair_tokens)) or "level"
        if own_pair:
            steppers = steppers[1:] + steppers[:1]
            used_steppers = set()
            # an entry key set "with − / +" keeps the pair after it (the pair alone sets its own)
            shared_too = [
                k
                for k in entry_keys
                if sets_with_pair(b, k.controls[0], pair_tokens)
                or pair_follows(b, k, pair_tokens) is not None  # "1. Touch TIME. 2. Use ▲ / ▼"
            ]
            if up_down:  # keys taken as entry keys by default go back to the keys left over
                silent += [k for k in guessed if k not in shared_too]
            for key in (k for k in entry_keys if k not in shared_too):
                if up_down and key in guessed:
                    continue
                own = evidence[key.name]
                if own.values and len(own.values) >= 3 and numeric_list(own.values):
                    own = list_evidence(own)  # "1 h > 2 h > 3 h > 4 h > 6 h …": each one listed
                var = b.add_number(var_name(b, key), label_of(b, key.controls[0]), own, True)
                b.feature(
                    f"set_{var}", [{"actions": [key.name], "variable": var, "effect": "next"}]
                )
                b.note(f"features.set_{var}", f"{key.name} steps its setting (+/− set {pair_noun})")
            entry_keys = shared_too
            own_noun = pair_noun if shared_too else None
    if shared_pair and own_noun is None:
        # "the temperature is set with ▲ and ▼ – no other key is needed": the pair keeps that
        # setting alone, whatever keys it serves after them
        alone = set_alone(b, [token_of(b, n) for n in shared_pair["up"] + shared_pair["down"]])
        if alone and not _named_by([set(words(var_name(b, k))) for k in entry_keys], [alone]):
            own_noun = alone
    for key in entry_keys:
        ev = evidence[key.name]
        name = var_name(b, key)
        lab = label_of(b, key.controls[0])
        timeish = bool(ev.ranges and ev.ranges[0].unit in ("s", "min", "h")) or bool(
            set(words(name)) & TIME_WORDS
        )
        if digits and (timeish or not steppers):
            keyed = ev.step
            if keyed and keyed[1] == "h" and keyed[0] % 1:  # keyed in as hours and minutes
                keyed = (keyed[0] * 60, "min")
            var = b.add_number(
                name,
                lab,
                Evidence(**{**ev.__dict__, "step": keyed})
                if ev.ranges
                else Evidence(ranges=[], step=keyed, step_at=ev.step_at),
                cyclic=False,
            )
            spec = b.variables[var]
            cook = not ev.step and "cook" in words(name.replace("_", " "))
            if var in b.unread and (cook or (not ev.ranges and keyed == (1.0, "s"))):
                # a cooking time typed on the keypad with no range read (or any time keyed
                # in seconds, "enter the minutes and seconds"): minutes and seconds, as the
                # four number keys enter them
                spec.update(type="time", ranges=[["00:00:00", "01:39:59", 1]], format="mm:ss")
                spec.pop("unit", None)
                b.note(f"variables.{var}", "a cooking time typed as minutes and seconds")
            if spec["type"] == "time" and typed_as_seconds(b.manual, var):
                as_seconds(spec)  # "type the delay in seconds": 4 5 is 45 s, not 00:45
            _keypad_entry(spec)
            typed_every_whole(spec, ev, keyed)
            if spec.get("entry", {}).get("format") == "mm:ss" and (
                not ev.step or keyed == (1.0, "s")
            ):
                # minutes and seconds typed digit by digit: any second, whatever step was guessed
                # (and up to the top read, which a coarse guessed step fell short of)
                tops = [format_hms(int(r.high)) for r in ev.ranges if r.unit == "s"]
                if len(tops) != len(spec["ranges"]):
                    tops = [hi for _, hi, _ in spec["ranges"]]
                spec["ranges"] = [
                    [lo, top, 1] for (lo, _, _), top in zip(spec["ranges"], tops, strict=True)
                ]
            b.feature(
                f"set_{var}", [{"actions": [key.name]}, {"actions": list(digits), "variable": var}]
            )
            b.note(f"features.set_{var}", f"{lab} then the number keys", ev.range_at)
            used_digits = True
            said = [b.manual.units[i].text for i in mentions_of(b, key.controls[0])]
            said = [t for t in said if t.lstrip(" *|").upper().startswith(lab.upper())]
            if spec["type"] == "time" and any(_COOK_TIME_RE.search(t) for t in said):
                keyed_cook = True  # "TIMER — the keypad then takes the cooking time"
        elif steppers:
            up, down = steppers[0]
            if own_noun is None:
                used_steppers.add(0)
            else:  # the pair also keeps its own quantity
                up, down = shared_pair["up"], shared_pair["down"]  # type: ignore[index]
            if ev.values and len(ev.values) >= 3 and numeric_list(ev.values):
                ev = list_evidence(ev)  # the settings listed one by one, not only the ends
            if ev.values and len(ev.values) >= 2 and not numeric_list(ev.values) and not ev.ranges:
                var = b.add_discrete(name, ev.values, lab, ev)  # "0 … 9, P": the pair walks it
            else:
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
        cw, ccw = turns(dials[t])
        if cw and ccw and (dial_list(b, t, cw, ccw) or dial_amount(b, t, cw, ccw)):
            used_steppers |= {k for k, pair in enumerate(steppers) if pair == (cw, ccw)}
    for index, (up, down) in enumerate(steppers):
        if index not in used_steppers:
            tokens_ = [n for n in up + down]
            ev = b.evidence([token_of(b, n) for n in tokens_])
            noun = stepped_noun(b, [token_of(b, n) for n in tokens_], ev) or "level"
            own_here = own_noun if shared_pair and up == shared_pair["up"] else None
            if own_here is not None and own_here != noun:
                noun = own_here  # (its sentences' ranges and steps are the other settings')
                ev = alone_range(b, [token_of(b, n) for n in tokens_], noun) or Evidence(
                    values=None if ev.ranges else ev.values
                )
            if (
                own_here is None
                and raised is not None
                and shared_pair
                and up == shared_pair["up"]
                and (up_down or not (ev.ranges and ev.ranges[0].unit in _UNIT_NOUNS))
            ):  # (a legend's "airflow up / down" names it better than its unit, %)
                noun = raised[0]  # "Raise / lower the goal value": the pair's own quantity
                if up_down and _other_quantity(ev, noun):  # (a limit's °C is no volume's)
                    ev = alone_range(b, [token_of(b, n) for n in tokens_], noun) or Evidence()
            var = b.add_number(noun, noun.upper(), ev, cyclic=False)
            if raised is not None and noun == raised[0]:
                b.note(f"variables.{var}", "the quantity the pair raises and lowers", raised[1])
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
    cooking = any(_COOK_TIME_RE.search(u.text) for u in b.manual.units)
    cook_timer = any(_COOK_TIMER_RE.search(u.text) for u in b.manual.units)
    named_cook = keyed_cook or any(  # a cooking time already keyed in after a TIME key is the one
        (spec.get("type") == "time" and ("cook" in v or (v == "time" and "entry" in spec)))
        or (v == "timer" and "entry" in spec and cook_timer)  # "TIMER … Cook timer": the same
        for v, spec in b.variables.items()
    )  # (AUTO COOK's list of menus is no cooking time)
    direct: str | None = None
    if digits and not used_digits and (ended := numbered_entry(b, digits, silent)) is not None:
        silent = [k for k in silent if k is not ended]  # "OK  Ends the entry of a stitch number"
        used_digits = named_cook = True
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
        target = direct or keyed_time or added_time(b, key)
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
        toks = [token_of(b, n) for n in pair["up"] + pair["down"]]
        ev = b.evidence(toks + ([base] if base in b.labels else []))
        if ev.values and len(ev.values) >= 3 and numeric_list(ev.values):
            ev = list_evidence(ev)  # "75 ◄► 80 ◄► 100 … 250 mic": the settings one by one
        if ev.values and lettered(ev.values):  # "BANK ▲ (A → B → … → F → A)": the letters
            var = b.add_discrete(base, ev.values, base.upper(), ev)
            b.note(f"variables.{var}.values", ", ".join(ev.values), ev.values_at)
        else:
            var = b.add_number(base, base.upper(), ev, cyclic=False)
        eff = {**{a: "next" for a in pair["up"]}, **{a: "prev" for a in pair["down"]}}
        b.feature(
            f"set_{var}", [{"actions": pair["up"] + pair["down"], "variable": var, "effect": eff}]
        )
    return silent


def _other_quantity(ev: Evidence, noun: str) -> bool:
    """The range read round the pair is in a unit measuring another quantity than the noun its
    legend names (°C for "Speaker volume"); a percentage measures anything."""
    unit = ev.ranges[0].unit if ev.ranges else ""
    quantity = UNIT_QUANTITY.get(unit, "") if unit != "%" else ""
    return bool(quantity) and quantity[:4] not in noun


def _named_by(names: list[set[str]], nouns: list[str]) -> bool:
    """Whether a set of words names one of the nouns (a shared stem of four letters)."""
    return any(
        noun.startswith(w[:4]) or w.startswith(noun[:4])
        for n in names
        for w in n
        if len(w) >= 3
        for noun in nouns
    )


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
