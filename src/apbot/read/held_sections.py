"""A hold that opens the setting its own section is about, stepped by short presses of keys.

Small panels of two or three keys have no key per setting: each setting has a section of its
own ("7 BATTERY TYPE", "8 LOW-VOLTAGE DISCONNECT") that says how a hold opens it ("keep BAT
pressed for 3 s until b1 flashes", "Press SET and BAT at the same time and hold both for 3
seconds"), which short presses then step it ("Each short press of BAT shows the next type",
"SET raises the value by 0.1 V, BAT lowers it by 0.1 V") and that a pause stores it ("Leave the
keys alone for 10 s"). The held walks (``held_walks``) read such steps only as numbered steps
"Hold KEY …" with a stepping pair the model already has; on these panels no key steps anything
outside the setting, so no pair was read and each hold stayed a guessed switch of its own.

Read here, late (after the walks): a hold still guessed as a setting named for its key, the
sentence of a section that holds its key (or, for a hold named by a word such as "both" or the
section's own subject, the two keys held together), and in the same section the keys that
step up (and down) afterwards. The setting is named by the section ("Changing the load mode"
leading the steps, else the heading), valued by the section: a table of display codes and their
names (the names, shown as the codes), a stated range with its step ("Setting range: 10.8 V to
12.0 V, in steps of 0.1 V"), else the run the step sentence prints ("0, 1, 2 … 16, 17").
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.held_guesses import drop_guess, drop_key_guesses
from apbot.read.text import Unit
from apbot.read.value_steps import find_step
from apbot.read.walk_ends import pause_seconds

_NUM = r"\d+(?:[.,]\d+)?"
_SECS = r"(?:about\s+|at\s+least\s+)?(?:\d+|one|two|three|four|five|a)\s*(?:s|secs?|seconds?)\b"
_UP = r"raises?|increases?|up|next|higher|forward|advances?|adds?"
_DOWN = r"lowers?|decreases?|down|previous|lower|back(?:wards?)?|subtracts?"
_DIR_RE = re.compile(rf"\b(?:({_UP})|({_DOWN}))\b", re.I)
# a stated range: "Setting range: 10.8 V to 12.0 V", "from 0 to 30 minutes"
_RANGE_RE = re.compile(
    rf"(?<![\d.])({_NUM})\s*([A-Za-z°%]{{0,3}})\s*(?:to|–|-)\s*({_NUM})\s*([A-Za-z°%]{{0,3}})(?![\w.])"
)
_RANGE_WORD_RE = re.compile(r"\b(?:range|from|between|adjustable|settable)\b", re.I)
# a printed run of the values a step walks: "0, 1, 2 … 16, 17"
_RUN_RE = re.compile(
    rf"(?<![\d.])({_NUM}),\s*({_NUM})(?:,\s*{_NUM})*,?\s*(?:…|\.\.\.)\s*(?:{_NUM},\s*)*({_NUM})(?![\d.])"
)
_ENDS_RE = re.compile(
    r"\b(\d{1,3})\s+is\s+the\s+lowest,?\s+(?:and\s+)?(\d{1,3})\s+(?:is\s+)?the\s+highest\b", re.I
)
_LEAD_RE = re.compile(
    r"^(?:changing|setting|to\s+(?:change|set))\s+the\s+([a-z][a-z -]{2,30}?)\s*$", re.I
)
_STOP_RE = re.compile(r"\bstops?\s+at\b|\bdoes\s+not\s+go\s+beyond\b", re.I)
_WRAP_RE = re.compile(r"\b(?:back\s+to|followed\s+by|wraps?|again)\b", re.I)
_PAUSE_RE = re.compile(
    r"\b(?:for|after)\s+(\d+)\s*(?:s|secs?)\b(?=[^.]*\b(?:stor|return|close|goes\s+back))",
    re.I,
)
_CODE_RE = re.compile(r"^[A-Za-z]{0,2}\d{1,2}$")


def read_held_sections(b: Builder) -> None:
    """Give each still-guessed hold the setting its section opens with it."""
    units = b.manual.units
    for info in b.infos:
        if info.skill != "hold" or not guessed_hold(b, info.name):
            continue
        for i, unit in enumerate(units):
            keys = _held_keys(b, info.controls, unit)
            if not keys:
                continue
            section = _section(units, i)
            after = " ".join(u.text for u in _section(units, i, back=False)[1:])
            up, down = _steppers(b, after)
            if not up:
                continue
            field = _field(b, section, after)
            if field is None:
                continue
            _apply(b, info.name, up, down, field, section, i)
            break


def guessed_hold(b: Builder, hold: str) -> bool:
    """The hold sets nothing but a setting named for its key ("bat_hold", "both_hold")."""
    found = False
    for steps in b.features.values():
        if not any(hold in s.get("actions", []) for s in steps):
            continue
        if steps[0].get("actions") != [hold] or len(steps) != 1:
            return False
        var = str(steps[0].get("variable") or "")
        if not var.endswith("_hold"):
            return False
        found = True
    return found


def _label(b: Builder, token: str) -> str | None:
    lab = b.labels.get(token)
    return lab.text if lab is not None and lab.line is not None else None


def _keys_pressed(b: Builder) -> dict[str, str]:
    """Each short press's key label → the press action."""
    out: dict[str, str] = {}
    for i in b.infos:
        if i.skill == "press" and len(i.controls) == 1:
            lab = _label(b, i.controls[0])
            if lab:
                out[lab] = i.name
    return out


def _says(text: str, label: str) -> bool:
    return re.search(rf"(?<![\w+−-]){re.escape(label)}(?![\w])", text) is not None


def _held_keys(b: Builder, controls: tuple[str, ...], unit: Unit) -> list[str]:
    """The key labels this sentence holds for a stated time, when they are the hold's: its own
    key ("Hold SET for 5 seconds", "keep BAT pressed for 3 s"), or for a hold whose name is no
    key of the panel ("both", or the subject its section is headed by: ``hold_response`` under
    "RESPONSE LEVEL"), two keys held together ("Press SET and BAT at the same time and hold
    both for 3 seconds", "Hold −1 and +1 together for one second")."""
    text = unit.text
    if len(controls) == 1 and (own := _label(b, controls[0])):
        lab = re.escape(own)
        held = (
            rf"\b(?:press\s+and\s+)?hold\s+(?:down\s+)?(?:the\s+)?{lab}(?:\s+key|\s+button)?"
            rf"\s+(?:down\s+)?for\s+{_SECS}"
            rf"|\bkeep\s+(?:the\s+)?{lab}(?:\s+key|\s+button)?\s+(?:pressed|held|down)"
            rf"(?:\s+down)?\s+for\s+{_SECS}"
        )
        return [own] if re.search(held, text, re.I) else []
    heading = set(re.findall(r"[a-z]+", unit.heading.lower()))
    if len(controls) != 1 or not (controls[0] == "both" or set(controls[0].split("_")) <= heading):
        return []  # (neither "both" nor the subject of the section: "hold_response")
    if not re.search(r"\b(?:together|at\s+the\s+same\s+time|both)\b", text, re.I):
        return []
    if not re.search(rf"\bhold\b[^.]*\bfor\s+{_SECS}", text, re.I):
        return []
    named = [lab for lab in _keys_pressed(b) if _says(text, lab)]
    return named if len(named) == 2 else []


def _section(units: list[Unit], at: int, back: bool = True) -> list[Unit]:
    """The units of the section holding ``at`` (the same heading); only from ``at`` on when
    not ``back``."""
    heading = units[at].heading
    start = at
    while back and start > 0 and units[start - 1].heading == heading:
        start -= 1
    out = []
    for u in units[start:]:
        if u.heading != heading:
            break
        out.append(u)
    return out


def _steppers(b: Builder, text: str) -> tuple[list[str], list[str]]:
    """The presses the section steps the setting with, up and down: each clause naming one key
    and a direction ("Press SET briefly to go up one code", "BAT lowers it by 0.1 V")."""
    keys = _keys_pressed(b)
    up: list[str] = []
    down: list[str] = []
    for sentence in re.split(r"(?<=[.!?])\s+", text):
        if re.search(r"\b(?:hold|held|keep)\b", sentence, re.I):
            continue  # (a hold's sentence, not a short press)
        for clause in re.split(r"[,;:]\s*", sentence):
            named = [lab for lab in keys if _says(clause, lab)]
            m = _DIR_RE.search(clause)
            if len(named) != 1 or m is None:
                continue
            act = keys[named[0]]
            side = up if m.group(1) else down
            if act not in up + down:
                side.append(act)
    return up, down


def _field(b: Builder, section: list[Unit], after: str) -> dict[str, Any] | None:
    """The setting's values, from its section."""
    whole = " ".join(u.text for u in section)
    rows = [u.cells for u in section if len(u.cells) >= 2 and _CODE_RE.match(u.cells[0])]
    if len(rows) >= 2 and len({r[0][:1] for r in rows}) == 1 and not rows[0][0].isdigit():
        names = [re.sub(r"\s*\(.*$|\s+\d+(?:\.\d+)?\s*[A-Za-z]*$", "", r[1]).strip() for r in rows]
        if all(names) and len(set(names)) == len(names):
            values = [n.lower() for n in names]
            return {"values": values, "show": {v: r[0] for v, r in zip(values, rows, strict=True)}}
    for u in section:
        if not _RANGE_WORD_RE.search(u.text):
            continue
        m = _RANGE_RE.search(u.text)
        if m is None or (m.group(2) and m.group(4) and m.group(2) != m.group(4)):
            continue
        low, high = float(m.group(1).replace(",", ".")), float(m.group(3).replace(",", "."))
        step = find_step(whole)
        if high <= low:
            continue
        return {"range": [low, high, step[0] if step else 1], "unit": m.group(2) or m.group(4)}
    m = _ENDS_RE.search(whole)
    if m is not None and int(m.group(2)) > int(m.group(1)):  # "1 is the lowest, 9 the highest"
        return {"range": [float(m.group(1)), float(m.group(2)), 1], "unit": ""}
    m = _RUN_RE.search(after)
    if m is not None:
        first, second, last = (float(g.replace(",", ".")) for g in m.groups())
        if second > first and last > second:
            return {"range": [first, last, second - first], "unit": ""}
    return None


def _name(section: list[Unit], opening: Unit) -> str:
    """The section's subject: a lead-in "Changing the load mode", else its heading less its
    number and brackets."""
    lead = re.split(r"\s+(?:[a-z]\)|\d+\.)\s+", opening.text)[0]
    m = _LEAD_RE.match(lead.strip())
    text = m.group(1) if m else re.sub(r"\([^)]*\)|\d", " ", section[0].heading)
    name = "_".join(re.findall(r"[a-z]+", text.lower())[:3])
    return name or "setting"


def _apply(
    b: Builder,
    hold: str,
    up: list[str],
    down: list[str],
    field: dict[str, Any],
    section: list[Unit],
    at: int,
) -> None:
    drop_guess(b, hold)
    name = _name(section, b.manual.units[at])
    whole = " ".join(u.text for u in section)
    label = name.replace("_", " ").upper()
    if "values" in field:
        var = b.add_discrete(name, field["values"], label, None)
        b.variables[var]["show"] = dict(field["show"])
        b.variables[var]["wrap"] = not _STOP_RE.search(whole)
    else:
        low, high, by = (_tidy(x) for x in field["range"])
        var = b.unique(name, b.variables)
        b.variables[var] = {
            "label": label,
            "type": "numeric",
            "ranges": [[low, high, by]],
            "unit": field["unit"],
            "wrap": not _STOP_RE.search(whole) and bool(_WRAP_RE.search(whole)),
        }
    effect = {**{a: "next" for a in up}, **{a: "prev" for a in down}}
    steps: list[dict[str, Any]] = [
        {"actions": [hold]},
        {"actions": up + down, "variable": var, "effect": effect},
    ]
    timeout = next((t for u in section if (t := _pause(u.text)) is not None), None)
    if timeout is not None:
        for step in steps:
            step["timeout"] = timeout
    drop_key_guesses(b, set(up + down), whole)
    b.feature(f"set_{var}", steps)
    b.note(f"variables.{var}", "the setting the hold opens in its own section", at)
    b.note(f"features.set_{var}", f"{hold} opens {var}, short presses step it", at)


def _pause(text: str) -> float | None:
    """The pause after which the setting is stored: the walks' reading, or seconds written
    short beside keys left alone ("Leave the keys alone for 10 s to store it", "After 10 s
    without a key the value is stored")."""
    seconds = pause_seconds(text)
    if seconds is not None:
        return seconds
    m = None if re.search(r"\b(?:hold|held|keep|press)\b", text, re.I) else _PAUSE_RE.search(text)
    return float(m.group(1)) if m else None


def _tidy(x: float) -> float | int:
    return int(x) if float(x).is_integer() else round(x, 6)
