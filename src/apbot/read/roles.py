"""Give every action a role and build the model's variables, features and guards from them.

The order matters: the name-evident roles first (power, start, stop, lock, digits, stepping
pairs, dials), then setting keys by what their sentences say, then the keys the manual only
lists together, then whatever is left, as a guess. Each kind of role has its module
(``roles_fixed``, ``roles_pads``, ``roles_lists``, ``roles_amounts``); this one runs them in
order and sorts the setting keys by what their sentences say (the tests on a key's own legend
are in ``roles_legends``, a dial lent to other keys in ``roles_dials``).
"""

from __future__ import annotations

from dataclasses import replace

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder, united_amounts
from apbot.read.factory_lists import factory_list
from apbot.read.held_flips import assign_flips, flipped_values
from apbot.read.held_power_only import power_key_steps
from apbot.read.labels import words
from apbot.read.legend_ends import legend_end_pairs
from apbot.read.own_cycles import stated_for_key
from apbot.read.press_hold_pairs import press_hold_pairs
from apbot.read.roles_again import toggled_again
from apbot.read.roles_amount_keys import amount_keys
from apbot.read.roles_amounts import ADD_RE, assign_amounts
from apbot.read.roles_common import (
    FUNCTION_WORDS,
    NUMERIC_WORDS,
    TIME_WORDS,
    held_switch,
    hold_use,
    label_of,
    shown_prefix,
    token_of,
    used_actions,
    var_name,
)
from apbot.read.roles_confirm import ends_entry
from apbot.read.roles_dials import _lend_dial, _turned_after_keys
from apbot.read.roles_digits import assign_direct_digits
from apbot.read.roles_fasthold import fold_fast_holds
from apbot.read.roles_fixed import assign_power, standby_only
from apbot.read.roles_functions import assign_functions, function_keys
from apbot.read.roles_heldshown import show_held_word
from apbot.read.roles_heldvalues import held_section_list, list_of_earlier_key, others_list
from apbot.read.roles_holdcell import held_toggle, held_values, way_switched
from apbot.read.roles_hourmin import assign_hour_minute, hour_minute_keys
from apbot.read.roles_keyed import assign_keyed_amounts
from apbot.read.roles_legends import _hold_row, _named_cycle, _numbered
from apbot.read.roles_lent_dial import add_lent, lent_dial_keys
from apbot.read.roles_lists import (
    dial_values,
    list_evidence,
    listed_min_sec,
    more_less_pair,
    numeric_list,
    pair_of_names,
)
from apbot.read.roles_locks import assign_locks
from apbot.read.roles_menu import assign_menu
from apbot.read.roles_mode_keys import mode_keys
from apbot.read.roles_nounpads import noun_pads
from apbot.read.roles_own_dials import assign_dials, assign_leftovers
from apbot.read.roles_pads import (
    codes_shown,
    column_keys,
    listed_groups,
    named_choice_keys,
    option_keys,
    pad_group,
    selecting_keys,
    shown_codes,
)
from apbot.read.roles_pairafter import lists_own, pair_follows
from apbot.read.roles_raiselower import raise_lower_pairs, signed_pairs
from apbot.read.roles_running import assign_running
from apbot.read.roles_shared import add_clock_steps, assign_shared, clock_steps, dial_after_keys
from apbot.read.roles_switched import switched_time
from apbot.read.shapes import CHOICE_WORDS, GENERIC_DIALS, adjuster_direction
from apbot.read.side_keys import read_side_keys


def assign(b: Builder) -> None:
    """Give every action of ``b`` a role, adding variables, features and guards to it."""
    infos = b.infos
    done: set[str] = set()
    power_actions = assign_power(b)
    done |= set(power_actions)
    lock_actions = assign_locks(b, done)
    assign_running(b, done, power_actions, lock_actions)

    done |= legend_end_pairs(b, infos, done)  # SPIN BACK / SPIN TOP over "B3 … 0 … T3"
    done |= read_side_keys(b, infos, done)  # ◄ / ► "left indicator", only one side at a time

    # stepping pairs, digits, dials -------------------------------------------------------
    pairs: dict[str, dict[str, list[str]]] = {}
    for info in infos:
        if info.name in done:
            continue
        d = adjuster_direction(info)
        if d:
            pairs.setdefault(d[0], {"up": [], "down": []})[d[1]].append(info.name)
    unnamed = [i for i in infos if i.name not in done and not adjuster_direction(i)]
    for noun, pair in raise_lower_pairs(b, unnamed).items():  # WARMER / COOLER, ☀ / ❄
        pairs.setdefault(noun, pair)
    taken = {n for p in pairs.values() for ns in p.values() for n in ns}
    for noun, pair in press_hold_pairs(b, [i for i in unnamed if i.name not in taken]).items():
        pairs.setdefault(noun, pair)  # "next size (press) / previous size (hold 2 s)"
    taken = {n for p in pairs.values() for ns in p.values() for n in ns}
    for noun, pair in signed_pairs(b, [i for i in unnamed if i.name not in taken]).items():
        pairs.setdefault(noun, pair)  # A- / A+, POSITION < / POSITION >
    digits = [i.name for i in infos if i.digit is not None and i.name not in done]
    if assign_direct_digits(b, [i for i in infos if i.name in digits]):
        digits = []  # a row of levels 1–5: no keypad
    dials: dict[str, list[ActionInfo]] = {}
    for info in infos:
        if info.skill.startswith("turn") and info.name not in done:
            dials.setdefault(info.token, []).append(info)
    for base in list(pairs):
        if pair_of_names(b, base, pairs[base]) or more_less_pair(b, base, pairs[base]):
            del pairs[base]  # it moves through a list of names: no amount for other keys
    # a numbered settings menu ("hold SET 3 s: F1 … F5") takes its keys and the pair
    done |= assign_menu(b, [i for i in infos if i.name not in done], pairs)
    paired = {n for p in pairs.values() for ns in p.values() for n in ns}
    done |= paired | set(digits) | used_actions(b)
    hour_minute = hour_minute_keys(infos, done)
    if hour_minute:  # HOUR / MIN move whichever time CLOCK, TIMER, READY AT… opened
        others = [i for i in infos if i.name not in done and not i.skill.startswith("turn")]
        done |= set(assign_hour_minute(b, others, hour_minute))

    # a key that switches a stepping pair between two settings ("TEMP/TIME") -------------
    lent = _lend_dial(pairs, dials)  # "SET switches the dial between temperature and time"
    done |= assign_shared(b, [i for i in infos if i.name not in done], pairs)
    if lent is not None and lent in dials:
        if any(m.name in done for m in dials[lent]):
            del dials[lent]  # the dial is the shared adjuster now, not a setting of its own
        else:
            pairs.pop("", None)
    clocks = clock_steps(b, [i for i in infos if i.name not in done], dials, pairs)
    done |= {c[0].name for c in clocks}  # (its feature once the dial has its own setting)

    # setting keys -------------------------------------------------------------------------
    keys = [i for i in infos if i.name not in done and not i.skill.startswith("turn")]
    adders = [k for k in keys if k.skill == "press" and ADD_RE.match(k.token)]
    keys = [k for k in keys if k not in adders]
    functions = function_keys(b, keys)
    keyed_time: str | None = None
    if functions:  # MICRO, GRILL, CONVECTION…: each starts its own procedure, then START
        keyed_time = assign_functions(b, functions[0], functions[1], digits)
        chosen = [p.key for p in functions[1]]
        keys = [k for k in keys if k not in chosen]
    selecting = [] if functions else selecting_keys(b, keys)
    if selecting:
        var = pad_group(b, selecting)
        keys = [k for k in keys if k not in selecting]
        shown_codes(b, var, selecting)
    elif not functions:  # a chart with a column of keys ("Code | Pad | …")
        selecting, codes = column_keys(b, keys)
        if selecting:
            var = pad_group(b, selecting)
            keys = [k for k in keys if k not in selecting]
            codes_shown(b, var, selecting, codes)
        else:  # "| HOT | selects hot water |": keys selecting kinds of one thing
            noun, selecting, idle = noun_pads(b, keys)
            if selecting:
                pad_group(b, selecting, noun, idle)
                keys = [k for k in keys if k not in selecting]
    if not functions and not selecting:  # "The keys CORN, FLOUR and P choose the programme"
        selecting, noun = named_choice_keys(b, keys)
        if selecting:
            pad_group(b, selecting, noun)
            keys = [k for k in keys if k not in selecting]
    pads = [k for k in keys if k.skill == "press" and not set(words(k.token)) & FUNCTION_WORDS]
    named = [k for k in keys if k.skill == "press" and k not in pads]
    for group in listed_groups(b, pads + named, tables_only=True):
        if sum(k in pads for k in group) >= 3:
            # a row of a programme table names a key a function word would keep out ("QUICK
            # COOK" among WHITE RICE, BROWN RICE…): one of the choices all the same
            pad_group(b, group)
            keys = [k for k in keys if k not in group]
    toggled = mode_keys(b, keys)  # "Modes: NORMAL, COVER, BOOST" beside COVER and BOOST keys
    keys = [k for k in keys if k not in toggled]
    evidence = {k.name: b.evidence(list(k.controls)) for k in keys}
    # (or a dial's: "For PORRIDGE, STEAM and CAKE you can set the time" names the menus)
    dial_lists = [set(b.evidence([t]).values or []) for t in dials]
    for key in keys:  # "Cooking rice (WHITE RICE, BROWN RICE)" near COOK TIME: FUNCTION's values
        ev = evidence[key.name]
        mine = set(ev.values or [])
        if (
            len(mine) >= 2
            and not numeric_list(list(mine))
            and not stated_for_key(b, key, ev)  # "press DRY again …: LOW -> MID -> HIGH": DRY's
            and (
                any(mine < set(evidence[o.name].values or []) for o in keys if o.name != key.name)
                or any(mine < theirs for theirs in dial_lists)
            )
        ):
            evidence[key.name] = replace(ev, values=None, values_at=None)
    for key in keys:  # a push-turn dial's list ("a ring of programs round the dial"): its turns'
        turned = any(t in key.controls for t in dials)
        if turned and key.skill == "press" and evidence[key.name].values:
            evidence[key.name] = replace(evidence[key.name], values=None, values_at=None)
    options = option_keys(b, keys)
    shared_pair = pairs.get("")
    generic_dials = [
        t
        for t in dials
        if t.split("_")[0] in GENERIC_DIALS
        and (not dial_values(b, t) or _turned_after_keys(b, t, keys) or dial_after_keys(b, t, keys))
    ]
    entry_keys: list[ActionInfo] = []
    silent: list[ActionInfo] = []
    paired_tokens = {c for i in infos if i.name in paired for c in i.controls}
    pair_tokens = (
        [token_of(b, n) for n in shared_pair["up"] + shared_pair["down"]]
        if shared_pair and shared_pair["up"] and shared_pair["down"]
        else []
    )
    flips = assign_flips(b, keys, paired)  # "hold 2 s: KM/H <-> MPH": the hold's two values
    for key in keys:
        if key.name in flips:
            continue
        ev = evidence[key.name]
        name = var_name(b, key)
        lab = label_of(b, key.controls[0])
        if flipped_values(flips, ev.values, ev.values_at):  # (a hold's, not the press's)
            ev = evidence[key.name] = replace(ev, values=None, values_at=None)
        held_list = held_section_list(b, key)
        if held_list:  # "Automatic switch-off: 30 min → 60 min → …" where HAIR TYPE is only held
            ev = evidence[key.name] = replace(ev, values=held_list[0], values_at=held_list[1])
        switched = held_switch(b, key)  # "hold 3 s to switch the sound off"
        if (
            not held_list
            and key.skill == "hold"
            and set(words(hold_use(b, key))) & TIME_WORDS
            and (shared_pair or digits or generic_dials)
            and switched is None  # ("… the zone timer changes between on and off": switched)
        ):
            entry_keys.append(key)  # "rear timer (touch and hold)", then + / −
            continue
        if switched is not None:
            var = b.add_toggle(name, switched[0].upper(), switched[1])  # not the key's name
            b.feature(var, [{"actions": [key.name], "variable": var, "effect": "toggle"}])
            continue
        if key.skill == "hold" and set(key.controls) <= paired_tokens:
            silent.append(key)  # holding ▲ / ▼ moves faster: no list of its own ("00:00 00:30 …")
            continue
        if others_list(b, key, ev.values or [], ev.values_at) or (
            ev.values and list_of_earlier_key(b, key, ev.values_at)  # ROTATE's angles, not MIRROR's
        ):  # "Hold LIGHT …: WHT, BLU …"
            ev = evidence[key.name] = replace(ev, values=None, values_at=None)
        if ev.values and factory_list(b, ev.values_at):  # "As delivered: VOL 3, LO 16 °C, …"
            ev = evidence[key.name] = replace(ev, values=None, values_at=None)
        amount = bool(set(words(name)) & NUMERIC_WORDS)
        if key.skill == "press" and (_hold_row(b, key, ev.toggle_at) or power_key_steps(b, key)):
            ev = evidence[key.name] = replace(ev, toggle_at=None)  # the hold's on/off
        if held := held_values(b, key, ev.toggle_at):  # the touch's on/off; held: °C / °F
            ev = evidence[key.name] = replace(
                ev, toggle_at=None, values=held, values_at=ev.toggle_at
            )
        own_toggle = (
            ev.toggle_at is not None
            and any(ev.toggle_at in b.labels[c].mentions for c in key.controls if c in b.labels)
            and not _named_cycle(b, key, ev)
        ) or (key.token in options and not ev.values)
        own_toggle = own_toggle or toggled_again(b, key, ev.toggle_at)  # "Press again to …"
        if held_toggle(b, key):  # "Hold for 2 seconds: twin-needle mode on/off": the hold's own
            own_toggle = True
            ev = evidence[key.name] = replace(ev, toggle_at=ev.toggle_at or ev.values_at)
        if key.token in options and ev.toggle_at is None:
            ev.toggle_at = options[key.token]
        if own_toggle and switched_time(b, key, shared_pair):
            continue  # "TIMER switches the ready-time on or off", then ▲ / ▼ move it
        way = way_switched(b, key) if own_toggle and set(words(name)) & NUMERIC_WORDS else ""
        if way:  # "touch: daily drying timer on / off  hold 3 s: set the time": a way's own
            name, lab = "_".join(words(way)), way.upper()  # (not the key's name: its setting's)
        if own_toggle and (way or not set(words(name)) & NUMERIC_WORDS):
            var = b.add_toggle(name, lab, ev.toggle_at)  # "press KEEP WARM to switch it on or off"
            b.feature(var, [{"actions": [key.name], "variable": var, "effect": "toggle"}])
            show_held_word(b, key, var)  # "hold DRY for 3 seconds: LOW appears"
        elif (
            key.skill == "press"
            and pair_tokens
            and pair_follows(b, key, pair_tokens) is not None
            and not lists_own(b, key, ev.values_at)
        ):
            entry_keys.append(key)  # "1. Press RUN TIME." "2. Press ▲ or ▼ …": the pair's
        elif (
            ev.values
            and len(ev.values) >= 2
            and set(ev.values) != {"on", "off"}
            and not _numbered(b, key, ev)
        ):
            numbered = set(words(name)) & CHOICE_WORDS and all(v.isdigit() for v in ev.values)
            prefix = shown_prefix(ev.values)  # "r0° → r90° …": angles the display marks r
            amounts = [v.strip()[len(prefix) :] for v in ev.values]
            if numeric_list(amounts) and not (numbered and len(ev.values) <= 40):
                said = b.manual.units[ev.values_at].text if ev.values_at is not None else ""
                ev2 = replace(ev, values=amounts)
                ev2 = list_evidence(ev2, listed_min_sec(b, key, ev.values_at), said)
                var = b.add_number(name, lab, ev2, True, united_amounts(name, amounts))
                if prefix:
                    b.variables[var]["show"] = prefix + "{value}"
                    if all(v.strip().endswith("°") for v in amounts):
                        b.variables[var]["unit"] = "°"  # "r90°": an angle, no temperature
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
        elif ends_entry(b, key):
            silent.append(key)  # "OK  Confirms an entry": the end of a typed entry, not its own
        elif ev.ranges or (ev.step and ev.toggle_at is None):
            entry_keys.append(key)
        elif digits and ev.keypad_at is not None and (ev.toggle_at is None or amount):
            entry_keys.append(key)  # "TIMER — the keypad then takes the time in minutes"
            # (on/off wording near an amount's key is about something else: "… and switch the
            # lamp on or off")
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

    # keys printed with amounts ("10s 30s 60s"): one setting they set directly
    shortcuts = amount_keys(b, silent)
    silent = [k for k in silent if k not in shortcuts]
    # "1. Press BASS. 2. Turn the VOLUME knob: −6 to +6 dB": a named dial lent to a key
    dial_lent = lent_dial_keys(b, silent, dials)
    silent = [k for k in silent if k not in [found[0] for found in dial_lent]]
    # keys the manual lists together: one variable with a go-to value each
    groups = listed_groups(
        b, [k for k in silent if k.skill == "press" and not set(words(k.token)) & FUNCTION_WORDS]
    )
    for group in groups:
        pad_group(b, group)
        silent = [k for k in silent if k not in group]
    silent = assign_amounts(
        b, entry_keys, silent, evidence, pairs, digits, dials, generic_dials, adders, keyed_time
    )
    silent = assign_dials(b, dials, silent)
    silent += add_lent(b, dial_lent, dials)  # (after the dial's own setting: its turns are used)
    add_clock_steps(b, clocks)
    assign_leftovers(b, silent, evidence)
    assign_keyed_amounts(b, digits)
    standby_only(b)
    fold_fast_holds(b)  # "hold ▲ for 2 s: ten steps at once", not a switch of its own
