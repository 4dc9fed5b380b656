"""``read_manual``: manual text + action names → a checked model and its reading report.

Whatever the text, the result passes the checker: a part of the read model the checker rejects
is replaced by the cheapest guess (a toggle of the action's own), and the replacement is noted,
so a bad reading degrades into a model the closed loop can still explore and repair.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

from pydantic import ValidationError

from apbot.model.schema import ApplianceModel
from apbot.model.validate import check_model
from apbot.read.action_rank import in_manual_order, listed_as_given
from apbot.read.actions import ActionInfo, action_info, parse_actions
from apbot.read.bar_levels import read_bar_levels
from apbot.read.belief_name import UNNAMED
from apbot.read.build import Builder
from apbot.read.build_base import PLACEHOLDERS
from apbot.read.cases import apply_cases
from apbot.read.cases_chosen import chosen_cases
from apbot.read.cases_fixed import read_fixed_in_mode
from apbot.read.cases_lines import choice_ranges, table_choice_ranges
from apbot.read.cases_only import read_only_modes
from apbot.read.cases_positions import position_cases, position_shows
from apbot.read.cases_resets import apply_resets
from apbot.read.cases_units import unit_ranges
from apbot.read.cases_zones import zone_twins
from apbot.read.circled_shows import circled_shows
from apbot.read.closing_start import close_with_start
from apbot.read.code_amounts import read_code_amounts
from apbot.read.code_cycles import read_code_cycles
from apbot.read.code_glosses import name_glossed_words
from apbot.read.code_levels import read_code_levels
from apbot.read.code_numbers import name_numbered_codes
from apbot.read.code_rows import read_code_rows
from apbot.read.code_walks import read_code_walks
from apbot.read.code_words import name_code_words
from apbot.read.codes import name_codes
from apbot.read.confirm_starts import read_confirmed_starts
from apbot.read.cycle_words import read_cycle_words
from apbot.read.drop_victim import feature_to_drop
from apbot.read.guards_enabled import read_enabling_switches
from apbot.read.held_walks import read_held_walks
from apbot.read.hold_seconds import hold_seconds, pair_hold_seconds
from apbot.read.initials import read_initials
from apbot.read.keyed_cycles import read_keyed_cycles
from apbot.read.labels import find_labels
from apbot.read.mode_cases import read_mode_cases
from apbot.read.mode_scales import read_mode_scales
from apbot.read.numbered_keys import read_numbered_keys
from apbot.read.off_positions import read_off_positions
from apbot.read.off_words import read_held_off_words, read_off_words
from apbot.read.ordinal_lamps import read_ordinal_lamps
from apbot.read.pair_lists import read_pair_lists
from apbot.read.position_charts import read_position_charts
from apbot.read.prefixed_codes import name_prefixed_codes
from apbot.read.press_opened import read_press_opened
from apbot.read.press_tables import read_press_tables
from apbot.read.pressed_walks import read_pressed_walks
from apbot.read.range_codes import read_range_codes
from apbot.read.report import Note, Report
from apbot.read.roles import assign
from apbot.read.running_locks import read_running_locks
from apbot.read.section_keys import read_section_keys
from apbot.read.shapes import CHOICE_WORDS
from apbot.read.shown_bars import read_bar_shows
from apbot.read.shown_examples import read_shown_examples
from apbot.read.shown_figures import read_prefixed_figures
from apbot.read.shown_pairs import read_shown_pairs
from apbot.read.sign_glosses import read_sign_glosses
from apbot.read.signed_keys import read_signed_keys
from apbot.read.stated_ranges import read_stated_ranges
from apbot.read.text import check_text, parse_manual
from apbot.read.turn_refusals import read_turn_refusals
from apbot.read.typed_minutes import read_typed_minutes
from apbot.read.typed_prefix import read_typed_prefixes
from apbot.read.value_codes import read_value_codes
from apbot.read.value_keys import read_value_keys
from apbot.read.value_shows import read_bracket_shows

MAX_REPAIRS = 40


@dataclass
class Reading:
    """A read model and the report of where each part came from."""

    model: ApplianceModel
    report: Report


def read_manual(
    text: str, actions: list[str], appliance_id: str = "read_appliance", category: str = "appliance"
) -> Reading:
    """Read a manual; raise :class:`ReaderError` only for input that is not a manual at all."""
    check_text(text)  # (before the actions: a manual that is none is the first error)
    waits = {a: _wait_seconds(a) for a in actions if isinstance(a, str)}
    waits = {a: w for a, w in waits.items() if w is not None}
    infos = parse_actions([a for a in actions if a not in waits] or list(actions))
    manual = parse_manual(text, sorted({c for i in infos for c in i.controls}))
    appliance_id = _ident(appliance_id, "read_appliance")
    category = _ident(category, "appliance")
    tokens = sorted({c for i in infos for c in i.controls if i.digit is None})
    labels = find_labels(manual, tokens)
    infos = in_manual_order(infos, manual, labels)  # (the given order carries no meaning)
    builder = Builder(manual, infos, labels)
    note_compared_dials(builder)
    assign(builder)
    read_ordinal_lamps(builder)  # (a key guessed a toggle whose lamps, by place, are levels)
    read_press_tables(builder)  # (and one whose press-count rows list its values)
    position_cases(builder)  # (before: the key read with the dial's positions as its values)
    position_shows(builder)
    apply_cases(builder)
    chosen_cases(builder)
    zone_twins(builder)
    unit_ranges(builder)
    table_choice_ranges(builder)  # ("| MMA | Arc force | 0 ... 10 |": the Range column's)
    choice_ranges(builder)  # ("MMA  20 - 160 A" / "TIG  10 - 200 A": a range per choice)
    read_mode_cases(builder)  # ("the lamp shows PLATE or PROBE"; a paragraph per mode)
    read_only_modes(builder)
    read_fixed_in_mode(builder)  # "In Sleep mode the speed is fixed at 1"
    read_value_keys(builder)  # ("Press 33 or 45 to select that speed": one setting)
    read_signed_keys(builder)  # ("+1 +2 +3 −1" per team: one score each key adds to)
    read_typed_minutes(builder)  # ("type the minutes and the seconds": a game clock, not 23:59)
    read_cycle_words(builder)  # ("PER 1 → PER 2", "(no arrow) → ◄POSS (home)": user's values)
    read_mode_scales(builder)  # ("6.1 TTL …", "6.2 M and MULTI …": the dial's scale per mode)
    read_numbered_keys(builder)  # (T1 / T2 / T3 read key by key: one choice, a guess)
    read_code_cycles(builder)  # ("After P8 … P1 again": the key's run of codes)
    read_keyed_cycles(builder)  # ("NATURE: N1 → N2 … NOISE: S1 → …": a cycle per key)
    read_off_positions(builder)  # ("positions: OFF and levels 1 to 8": the knob is power too)
    name_codes(builder)
    name_numbered_codes(builder)  # ("Fn 1 > Fn 2 …" a count; a chart names each code)
    name_code_words(builder)
    read_code_rows(builder)  # ("| TRACK SID | sidereal |": a three-letter code's word)
    name_prefixed_codes(builder)  # ("OSC-N   narrow: …": the name's letter spelt out)
    name_glossed_words(builder)
    read_sign_glosses(builder)  # ("C for continuous", "∞ (continuous)": a letter or a sign)
    read_code_amounts(builder)
    read_code_levels(builder)
    read_position_charts(builder)
    read_typed_prefixes(builder)
    read_off_words(builder)
    read_held_off_words(builder)
    read_range_codes(builder)
    read_pair_lists(builder)  # ("Beat (SHIFT + TEMPO)" and its list: a second function's)
    read_initials(builder)
    read_bar_levels(builder)  # ("▮▮▯▯▯  level 2": a guessed range's levels, by its bars)
    read_bar_shows(builder)
    read_shown_examples(builder)  # ("e.g. DISC LV 10": the display's label)
    circled_shows(builder)  # ("① first dog / ② second dog": the numbers shown circled)
    read_bracket_shows(builder)
    read_value_codes(builder)  # (after the other display words: only where none was read)
    read_prefixed_figures(builder)  # ("SPM 20": only where no stage read a show or a unit)
    apply_resets(builder)
    read_held_walks(builder)  # (after the resets: those were read for the switch it replaces)
    read_pressed_walks(builder)  # (after the held walks: a press moving through one is theirs)
    read_press_opened(builder)  # (a press's guessed setting its numbered steps give)
    read_section_keys(builder)  # (holds, opposite keys, legend nouns still read as guesses)
    read_stated_ranges(builder)  # (a guessed range its section states: "The range is …")
    read_code_walks(builder)  # (a key's chart codes, each row a field: MENU walks them)
    read_shown_pairs(builder)  # ("HEMI N  northern …" / "HEMI S  southern …": a guessed on/off)
    read_enabling_switches(builder)
    read_confirmed_starts(builder)  # ("the first press only asks for confirmation")
    read_running_locks(builder)  # ("While FRY is shown, MENU … are locked")
    read_turn_refusals(builder)  # ("finer positions only while the motor runs")
    close_with_start(builder)  # (last: the keypad entries as built, whatever renamed them)
    data = _assemble(builder, appliance_id, category)
    data["actions"].update({a: {"skill": "wait", "seconds": w} for a, w in waits.items()})
    notes = builder.notes
    model = listed_as_given(_checked(data, infos, notes), list(actions))
    return Reading(model, Report(notes))


_WAIT_RE = re.compile(r"wait(?:_(\d{1,4})_?(s|sec|secs|seconds?|m|min|mins|minutes?)?)?")


def _wait_seconds(name: str) -> int | None:
    """An action of waiting, no key at all ("wait_5s", "wait_2_min"): how long it lasts."""
    m = _WAIT_RE.fullmatch(name)
    if not m:
        return None
    amount = int(m.group(1) or 1)
    return amount * 60 if (m.group(2) or "s").startswith("m") else amount


def _ident(text: str, default: str) -> str:
    out = re.sub(r"[^a-z0-9_]+", "_", str(text).lower()).strip("_")
    return out if out and out[0].isalpha() else default


def _controls(b: Builder) -> list[dict[str, Any]]:
    kinds: dict[str, str] = {}
    for info in b.infos:
        for token in info.controls:
            kind = (
                "key"
                if info.digit is not None
                else "knob"
                if info.skill.startswith("turn")
                else "button"
            )
            if kinds.get(token) != "knob":
                kinds[token] = kind
    out = []
    for token, kind in kinds.items():
        label = (
            str(next(i.digit for i in b.infos if i.controls == (token,) and i.digit is not None))
            if kind == "key"
            else (b.labels[token].text if token in b.labels else token.upper())
        )
        out.append({"id": _control_id(token), "kind": kind, "label": label})
    return out


def _control_id(token: str) -> str:
    """The control's id; a key named by its amount ("10s", "3h") keeps that amount in its id,
    so that several such keys stay apart."""
    named = token if token[:1].isalpha() else f"key_{token}"
    return _ident(named, "control") + ("" if token.startswith("key_") else "_control")


def _action(info: ActionInfo) -> dict[str, Any]:
    spec: dict[str, Any] = {"skill": info.skill}
    if len(info.controls) == 1:
        spec["control"] = _control_id(info.controls[0])
    else:
        spec["controls"] = [_control_id(c) for c in info.controls]
    if info.skill == "hold":
        spec["seconds"] = 3
    if info.digit is not None:
        spec["digit"] = info.digit
    return spec


def _actions(b: Builder) -> dict[str, dict[str, Any]]:
    """Each action's spec; a hold lasts as long as the manual says for its key."""
    actions = {i.name: _action(i) for i in b.infos}
    for info in b.infos:
        if info.skill != "hold" or not all(c in b.labels for c in info.controls):
            continue
        texts = [b.labels[c].text for c in info.controls]
        if len(texts) == 1:
            held = hold_seconds(b.manual.lines, texts[0])
        elif len(texts) == 2:  # two keys held at once ("hold ▲ and ▼ together for 5 s")
            held = pair_hold_seconds(b.manual.lines, *texts)
        else:
            continue
        if held is not None and held > 0:
            actions[info.name]["seconds"] = held
    return actions


def _main_variable(b: Builder) -> str | None:
    """What the display most likely shows when idle: the programme, else the first amount."""
    fixed = {v for g in b.guards for v in g["when"]} | {"running"}
    # (nor a selector whose choices are placeholders: the manual never says it is shown, and a
    # lit screen predicted to show one would read as the power still off)
    fixed |= {n.subject.split(".")[1] for n in b.notes if n.what == PLACEHOLDERS}
    names = [n for n in b.variables if n not in fixed and not b.variables[n].get("depends_on")]
    for name in names:
        spec = b.variables[name]
        if spec.get("type") in ("discrete", "numeric") and set(name.split("_")) & CHOICE_WORDS:
            return name
    return None  # an amount on an idle screen is too often wrong to predict (tried: worse)


def _assemble(b: Builder, appliance_id: str, category: str) -> dict[str, Any]:
    main = _main_variable(b)
    idle = ""
    if main is not None:
        idle = "{" + main + "}"
        b.note("display.idle", f"the display shows {main} when nothing is being set")
    power = b.variables.get("power")
    if power is not None and "show" not in power:
        # switching on shows the idle screen; with none read, a lit screen the belief does not
        # try to read (a guessed word would be misread as a wrong power state)
        power["show"] = {"off": "", "on": idle}
        if not idle:
            b.note(
                "variables.power.show", "switching on lights the display (what it shows: not read)"
            )
    return {
        "appliance": {"id": appliance_id, "category": category, "name": UNNAMED},
        "controls": _controls(b),
        "variables": b.variables,
        "actions": _actions(b),
        "features": b.features,
        "guards": b.guards,
        "display": {
            "idle": idle,
            "indicators": [v for v in dict.fromkeys(b.indicators) if v in b.variables],
        },
    }


def _checked(data: dict[str, Any], infos: list[ActionInfo], notes: list[Note]) -> ApplianceModel:
    """Validate, replacing what the checker rejects, until the model passes."""
    for _ in range(MAX_REPAIRS):
        try:
            model = ApplianceModel.model_validate(data)
        except ValidationError as exc:
            path = tuple(exc.errors()[0]["loc"])
            if not _drop(data, path, notes, exc.errors()[0]["msg"]):
                break
            continue
        errors = [p for p in check_model(model) if p.severity == "error"]
        if not errors:
            return model
        if not _drop(data, errors[0].path, notes, errors[0].message):
            break
    notes.append(
        Note(
            "(model)",
            "the reading could not be checked; every action toggles its own setting",
            guess=True,
        )
    )
    return ApplianceModel.model_validate(_fallback(data, infos))


def _drop(data: dict[str, Any], path: tuple[Any, ...], notes: list[Note], why: str) -> bool:
    """Remove the part of the model a problem points at; False when nothing can be removed."""
    if not path:
        return False
    head = path[0]
    if head == "guards" and data["guards"]:
        index = path[1] if len(path) > 1 and isinstance(path[1], int) else 0
        gone = data["guards"].pop(min(index, len(data["guards"]) - 1))
        notes.append(Note(f"guards.{gone.get('name')}", f"dropped: {why}", guess=True))
        return True
    if head == "display":
        data["display"] = {"idle": ""}
        return True
    if head in ("features", "variables") and len(path) > 1:
        name = str(path[1])
        victims = {feature_to_drop(data, name, why, notes) if head == "features" else name}
        if head == "variables":
            victims = {
                f
                for f, steps in data["features"].items()
                if any(s.get("variable") == name for s in steps)
            }
            data["variables"].pop(name, None)
        for feature in sorted(victims):
            steps = data["features"].pop(feature, None)
            if steps is None:
                continue
            for step in steps:
                var = step.get("variable")
                if var and not any(
                    s.get("variable") == var for ss in data["features"].values() for s in ss
                ):
                    data["variables"].pop(var, None)
            notes.append(Note(f"features.{feature}", f"replaced by toggles: {why}", guess=True))
            for step in steps:
                for action in step["actions"]:
                    if not any(
                        action in s["actions"] for ss in data["features"].values() for s in ss
                    ):
                        _toggle_for(data, action)
        data["guards"] = [g for g in data["guards"] if set(g["when"]) <= set(data["variables"])]
        data["display"]["indicators"] = [
            v for v in data["display"].get("indicators", []) if v in data["variables"]
        ]
        return True
    return False


def _toggle_for(data: dict[str, Any], action: str) -> None:
    digit = data["actions"][action].get("digit")
    if digit is not None:
        data["actions"][action].pop("digit")
        control = data["actions"][action]["control"]
        for c in data["controls"]:
            if c["id"] == control:
                c["kind"] = "button"
    var = action
    while var in data["variables"]:
        var += "_"
    data["variables"][var] = {"type": "discrete", "values": ["off", "on"]}
    name = var
    while name in data["features"]:
        name += "_"
    data["features"][name] = [{"actions": [action], "variable": var, "effect": "toggle"}]


def _fallback(data: dict[str, Any], infos: list[ActionInfo]) -> dict[str, Any]:
    controls = {}
    for info in infos:
        for token in info.controls:
            controls[token] = {
                "id": _control_id(token),
                "kind": "knob" if info.skill.startswith("turn") else "button",
                "label": token.upper(),
            }
    actions = {}
    for info in infos:
        spec = _action(info)
        spec.pop("digit", None)
        actions[info.name] = spec
    for info in infos:
        if info.skill.startswith("turn"):
            controls[info.controls[0]]["kind"] = "knob"
    actions.update({a: v for a, v in data["actions"].items() if v.get("skill") == "wait"})
    return {
        "appliance": data["appliance"],
        "controls": list(controls.values()),
        "variables": {
            f"{i.name}_state": {"type": "discrete", "values": ["off", "on"]} for i in infos
        },
        "actions": actions,
        "features": {
            f"use_{i.name}": [
                {"actions": [i.name], "variable": f"{i.name}_state", "effect": "toggle"}
            ]
            for i in infos
        },
    }


def note_compared_dials(b: Builder) -> None:
    """Record as a guess each turn read as one way of a dial its pair names (``turn_faster``
    and ``turn_slower`` as the speed dial): the name comes from the actions, not the manual."""
    for info in b.infos:
        if info.skill.startswith("turn") and info.controls != action_info(info.name).controls:
            way = "up" if info.skill == "turn_cw" else "down"
            b.note(f"actions.{info.name}", f"turns the {info.token} dial {way} (named by its pair)")
