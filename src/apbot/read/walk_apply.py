"""Write a walk read from the manual into the model: drop the guessed switch of the key that
opens it, add the fields it walks and the feature whose steps walk them (or, for a clock walk,
the hours then the minutes of one time of day)."""

from __future__ import annotations

from typing import Any

from apbot.model.values import format_hms
from apbot.read.build import Builder
from apbot.read.code_words import own_lines
from apbot.read.held_guesses import drop_guess, drop_key_guesses, drop_unused
from apbot.read.walk_fields import code_words
from apbot.read.walk_flashed import clock_effects, clock_steps, held_steps
from apbot.read.walk_known import use_known
from apbot.read.walk_like import absorb_pair_setting, drop_opener_setting
from apbot.read.walk_listed import drop_guessed_pair
from apbot.read.walk_steps import drop_adjuster_settings


def apply_walk(
    b: Builder, hold: str, press: str | None, walk: dict[str, Any], named: bool = True
) -> None:
    """Drop the hold's guessed setting; add the two fields and the feature walking them (named
    after what the hold was read to set, "sleep_period", when that was more than the key's name
    and "hold"; not when ``named`` is false: a short press opening the walk was a mere guess)."""
    if "clock" in walk:
        _apply_clock(b, hold, press, walk)
        return
    prefix = drop_guess(b, hold) if named else (drop_guess(b, hold) and "")
    if len(walk["fields"]) == 1:  # one setting: the name the hold was read with, else its own
        field = walk["fields"][0]
        field["name"] = field["name"] if walk.get("own") or not prefix else prefix[:-1]
        prefix = ""
    up, down = walk["pair"]
    if len(walk["fields"]) > 1:
        _drop_one_field_guess(b, hold, set(up + down))
    effect = {**{a: "next" for a in up}, **{a: "prev" for a in down}}
    steps: list[dict[str, Any]] = [{"actions": [hold]}]
    names = []
    for k, field in enumerate(walk["fields"]):
        if field.get("known"):  # "The temperature flashes": the one read from the chart
            var = use_known(b, field["name"], set(up + down))
        elif "spec" in field:
            var = b.unique(_prefix(prefix, field) + field["name"], b.variables)
            b.variables[var] = {"label": field["label"], **field["spec"]}
            b.note(f"variables.{var}", "a time of day the held key's steps set", walk["at"])
        elif "values" in field:
            var = b.add_discrete(
                _prefix(prefix, field) + field["name"], field["values"], field["label"], None
            )
            glossed = code_words(own_lines(b), field["values"])
            if glossed:  # "r1 near – r2 middle – r3 far": the words, the codes shown
                b.variables[var]["values"] = [glossed[c] for c in field["values"]]
                b.variables[var]["show"] = {w: c for c, w in glossed.items()}
            if field.get("show"):  # "(M = male, F = female)": the words, the codes shown
                b.variables[var]["show"] = dict(field["show"])
            if field.get("stops"):
                b.variables[var]["wrap"] = False
            b.note(f"variables.{var}", "the values the held key's walk steps through", walk["at"])
        else:
            var = b.add_number(
                _prefix(prefix, field) + field["name"],
                field["label"],
                field["evidence"],
                cyclic=False,
            )
        if k:
            steps.append({"actions": [press]})
        if field.get("split"):  # the hours, then the minutes, of one time of day
            steps += clock_steps(var, up, down, press, field.get("minute", 60))
        else:
            steps.append({"actions": up + down, "variable": var, "effect": dict(effect)})
        if not down:  # "MEM held 2 s adds ten months"
            held_steps(b, up, steps[-3:] if field.get("split") else steps[-1:], field)
        if field.get("optional") and k < len(walk["fields"]) - 1:
            steps[-1]["optional"] = True  # "to keep it, go straight to step 3"
        names.append(var)
    if walk["timeout"] is not None:  # the walk ends by itself once no key is touched
        for step in steps:
            step["timeout"] = walk["timeout"]
    drop_key_guesses(b, {a for a in (press, *up, *down) if a}, walk["said"])
    feature = f"set_{names[0]}"
    b.feature(feature, steps)
    if not down:  # one key adjusting every field
        drop_adjuster_settings(b, up)
    absorb_pair_setting(b, steps, walk["at"])
    drop_opener_setting(b, steps)
    if walk.get("listed"):
        drop_guessed_pair(b, steps)  # (the pair's guessed "0–10" was this list all along)
    said = f"{hold} opens {names[0]}" + (f", {press} moves to {names[1]}" if names[1:] else "")
    b.note(f"features.{feature}", said, walk["at"])


def _drop_one_field_guess(b: Builder, opener: str, pair: set[str]) -> None:
    """Drop a reading of the same opener as one setting the pair then sets ("hold SET, then +
    / −": a "period"): the walk through several fields is what the key opens, and one key
    opens one procedure (the model keeps only one of two features the key begins)."""
    for fname, old in list(b.features.items()):
        if len(old) != 2 or old[0].get("actions") != [opener] or "variable" in old[0]:
            continue
        if not set(old[1].get("actions", [])) <= pair:
            continue
        del b.features[fname]
        drop_unused(b, str(old[1].get("variable")))


def _prefix(prefix: str, field: dict[str, Any]) -> str:
    """A field named by what flashes, or a clock joined from hours and minutes, has a name of
    its own: the hold's guessed name leads it not."""
    return "" if field.get("own_name") or field.get("split") else prefix


def _day_clock(spec: dict[str, Any]) -> bool:
    """A time of day set to the minute (00:00–23:59 by one minute), not a duration or a time
    set in steps of half an hour."""
    ranges = spec.get("ranges") or []
    return (
        spec.get("type") == "time"
        and len(ranges) == 1
        and str(ranges[0][1]) >= "23:59"
        and ranges[0][2] == 60
    )


def _apply_clock(b: Builder, hold: str, press: str | None, walk: dict[str, Any]) -> None:
    """Add the clock walk; the time it sets is the time the key's press was read to open with
    the pair (that reading, a press alone opening the minutes, is dropped), else a new one."""
    drop_guess(b, hold)
    up, down = walk["pair"]
    var = None
    for fname, old in list(b.features.items()):
        if (
            len(old) == 2
            and old[0].get("actions") == [press]
            and "variable" not in old[0]
            and set(up + down) <= set(old[1].get("actions", []))
            and _day_clock(b.variables.get(str(old[1].get("variable")), {}))
        ):
            var = old[1]["variable"]
            del b.features[fname]
            break
    minute = walk["minute"]
    if var is None:
        var = b.unique(walk["name"] or "clock", b.variables)
        b.variables[var] = {
            "label": walk["clock"],
            "type": "time",
            "ranges": [["00:00:00", format_hms(24 * 3600 - minute), minute]],
            "format": "hh:mm",
        }
        b.note(f"variables.{var}", "a time of day the held key's steps set", walk["at"])
    b.variables[var]["wrap"] = True
    hours, minutes = clock_effects(up, down, minute)
    minutes.update({a: {"add": n} for a, n in walk["holds"].items()})
    steps: list[dict[str, Any]] = [
        {"actions": [hold]},
        {"actions": up + down, "variable": var, "effect": hours},
        {"actions": [press]},
        {"actions": list(minutes), "variable": var, "effect": minutes},
    ]
    if walk["confirm"]:
        steps.append({"actions": [press]})
    if walk["timeout"] is not None:
        for step in steps:
            step["timeout"] = walk["timeout"]
    feature = b.unique(f"set_{var}", b.features)
    b.feature(feature, steps)
    b.note(
        f"features.{feature}", f"{hold} opens the hours of {var}, {press} its minutes", walk["at"]
    )
