"""Keys that each select one choice (programme pads): found in key tables and in sentences that
list them together, made one variable with a go-to feature per key."""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.roles_common import first_mention, label_of, plain
from apbot.read.shapes import GROUP_NOUNS, GROUP_PLURALS
from apbot.read.text import Unit


def pad_group(b: Builder, group: list[ActionInfo], noun: str = "", idle: str = "") -> str:
    """Keys the manual lists together: one variable, each key going to its own value (named
    ``noun`` when the caller read what they select; starting at ``idle``, a state no key
    selects, when the keys each start something and the manual names no start)."""
    noun = noun or _group_noun(b, group)
    var = b.unique(noun, b.variables)
    values = [plain(label_of(b, k.controls[0])) for k in group]
    values = [v if values.count(v) == 1 else f"{v}_{i}" for i, v in enumerate(values)]
    b.variables[var] = {"type": "discrete", "values": values, "label": noun.upper()}
    b.note(
        f"variables.{var}",
        f"keys listed together select one {noun}: {', '.join(values)}",
        first_mention(b, [g.token for g in group]),
    )
    start, at = _pad_initial(b, values)
    if start is None and idle:
        start, at = idle, first_mention(b, [g.token for g in group])
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


OPTIONS_RE = re.compile(
    r"\boptions?\b[^.]*\b(?:(?:turned|switched|set) on and off|on or off|on and off|toggle)",
    re.IGNORECASE,
)


def option_keys(b: Builder, keys: list[ActionInfo]) -> dict[str, int]:
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


SELECTS_ONE = re.compile(
    rf"\s*(?:selects?|chooses?|picks?|starts?)\s+(?:the\s+)?(?:{GROUP_PLURALS})"
    r"\s+(?!you\b|that\b|which\b|the\b)[\w\"'“]",
    re.IGNORECASE,
)


CODE_RE = re.compile(r"\b([A-Z]{1,3}-?\d{1,2})\b")


CODE_SHOWN_RE = re.compile(
    r"\b(?:code|number)\b[^.]*\b(?:appears?|shows?|shown|displayed|lights?)\b"
    r"|\bdisplay\b[^.]*\bshows?\b[^.]*\b(?:code|number)\b",
    re.IGNORECASE,
)


PAD_NOUNS = re.compile(
    rf"\b(?:{GROUP_PLURALS}|foods?|recipes?|dish(?:es)?|auto\w*)\b",
    re.IGNORECASE,
)


def listed_groups(
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


def selecting_keys(b: Builder, keys: list[ActionInfo]) -> list[ActionInfo]:
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
        named = _pressed_keys_in(b, keys, unit.cells[0].upper(), upper=True)
        if len(named) >= 2:
            by_noun.setdefault(m.group(0).lower().rstrip("s"), []).extend(named)
    best = max(by_noun.values(), key=len, default=[])
    return _dedupe_keys(best) if len(_dedupe_keys(best)) >= 3 else []


def shown_codes(b: Builder, var: str, keys: list[ActionInfo]) -> None:
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
    _show_codes(b, var, keys, codes)


def _pressed_keys_in(
    b: Builder, keys: list[ActionInfo], text: str, upper: bool = False
) -> list[ActionInfo]:
    """The pressed keys whose printed label stands as a word of ``text`` (``upper``: compared
    in capitals, the label bounded by no capital or digit; else by no word character)."""
    found = []
    for k in keys:
        label = b.labels[k.controls[0]]
        if k.skill != "press" or label.line is None:
            continue
        if upper:
            pattern = rf"(?<![A-Z0-9]){re.escape(label.text.upper())}(?![A-Z0-9])"
        else:
            pattern = rf"(?<![\w]){re.escape(label.text)}(?![\w])"
        if re.search(pattern, text):
            found.append(k)
    return found


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


KEY_COLUMN_RE = re.compile(r"^(?:keys?|buttons?|pads?|touch ?pads?|controls?)$", re.IGNORECASE)
CODE_COLUMN_RE = re.compile(r"^(?:codes?|no\.?|number|display|shown)$", re.IGNORECASE)


def column_keys(b: Builder, keys: list[ActionInfo]) -> tuple[list[ActionInfo], dict[str, str]]:
    """A chart with a column headed for the keys and one for codes ("Code | Pad | Wash | Dry …"):
    the keys named down it, each with its own code, are the choices of one setting, and the code
    is what the display shows for each (key name → code). A row whose key is named nowhere
    else goes to the one key the manual never names, as in :func:`selecting_keys`."""
    presses = [k for k in keys if k.skill == "press"]
    tables: list[list[Unit]] = []
    for unit in b.manual.units:
        if unit.cells and unit.header and any(KEY_COLUMN_RE.match(h.strip()) for h in unit.header):
            if tables and tables[-1][-1].header == unit.header:
                tables[-1].append(unit)
            else:
                tables.append([unit])
    for rows in tables:
        header = [h.strip() for h in rows[0].header]
        col = next(i for i, h in enumerate(header) if KEY_COLUMN_RE.match(h))
        code_col = next((i for i, h in enumerate(header) if CODE_COLUMN_RE.match(h)), None)
        if code_col is None:
            continue  # a key table ("Key | What it does"), not a chart of choices
        found: list[ActionInfo] = []
        codes: dict[str, str] = {}
        free: list[Unit] = []
        for unit in rows:
            if col >= len(unit.cells):
                continue
            cell = re.sub(r"\s+", "", unit.cells[col].strip(" *")).upper()
            key = next(
                (
                    k
                    for k in presses
                    if b.labels[k.controls[0]].line is not None
                    and re.sub(r"\s+", "", b.labels[k.controls[0]].text).upper() == cell
                ),
                None,
            )
            if key is None:
                free.append(unit)
                continue
            found.append(key)
            if code_col is not None and code_col < len(unit.cells):
                codes[key.name] = unit.cells[code_col].strip(" *")
        unnamed = [k for k in presses if b.labels[k.controls[0]].line is None]
        if len(found) >= 2 and len(free) == 1 and len(unnamed) == 1:
            label = b.labels[unnamed[0].controls[0]]
            text = re.sub(r"(?<=[+/&-])\s+", "", free[0].cells[col].strip(" *"))
            label.text, label.line = text, free[0].line
            label.mentions = [i for i, u in enumerate(b.manual.units) if text in u.text]
            found.append(unnamed[0])
            if code_col is not None and code_col < len(free[0].cells):
                codes[unnamed[0].name] = free[0].cells[code_col].strip(" *")
        found = _dedupe_keys(found)
        coded = [codes.get(k.name, "") for k in found]
        if len(found) >= 2 and all(CODE_RE.fullmatch(c) for c in coded):
            return found, codes  # every key its own code ("P1" … "P4"): the choices of one
    return [], {}


def codes_shown(b: Builder, var: str, keys: list[ActionInfo], codes: dict[str, str]) -> None:
    """Each value shown by its code, when every key has its own short code ("P1" … "P4")."""
    if all(CODE_RE.fullmatch(c) for c in codes.values()):
        _show_codes(b, var, keys, codes)


def _show_codes(b: Builder, var: str, keys: list[ActionInfo], codes: dict[str, str]) -> None:
    """The value each key selects is shown by that key's code (key name → code), when every key
    has a code of its own."""
    if len(codes) != len(keys) or len(set(codes.values())) != len(keys):
        return
    shown = {b.features[k.token][0]["effect"]["to"]: codes[k.name] for k in keys}
    b.variables[var]["show"] = shown
    b.note(
        f"variables.{var}.show",
        "the display shows each one's code: " + ", ".join(f"{v} {c}" for v, c in shown.items()),
    )


# "The three keys CORN, FLOUR and P share one job: they choose the programme."
_CHOOSE_ONE = re.compile(
    rf"\b(?:choose|chooses|select|selects|pick|picks)\s+(?:the|a|one|your)?\s*"
    rf"(?P<noun>{GROUP_PLURALS})\b",
    re.IGNORECASE,
)


def named_choice_keys(b: Builder, keys: list[ActionInfo]) -> tuple[list[ActionInfo], str]:
    """Three or more keys one sentence names as the keys that choose one thing ("The keys CORN,
    FLOUR and P choose the programme"): each key goes to its own choice. Read before the keys'
    own evidence, where the sentence listing them reads as each key's list of values."""
    for unit in b.manual.units:
        chosen = _CHOOSE_ONE.search(unit.text)
        if unit.cells or not chosen or not re.search(r"\b(?:keys|buttons|pads)\b", unit.text):
            continue
        head = unit.text[: chosen.start()]
        named = _pressed_keys_in(b, keys, head)
        named = _dedupe_keys(named)
        if len(named) >= 3:
            noun = chosen.group("noun").lower().rstrip("s")
            return named, "programme" if noun == "program" else noun
    return numbered_choice_keys(b, keys)


# "③ CH1, CH2, CH3 — choose a working channel.": a legend of the keys alone, then what they choose
_LEGEND_CHOICE = re.compile(
    r"^(?P<keys>.+?)\s*[—–:-]+\s*(?:choose|chooses|select|selects|pick|picks)\s+"
    r"(?:the|a|an|one|your)\s+(?:[a-z]+\s+)?(?P<noun>[a-z]{3,})\s*(?:[.;,(]|$)",
    re.IGNORECASE,
)
_NUMBERED_LABEL = re.compile(r"([A-Za-z]{1,4})\s?-?(\d{1,2})")


def numbered_choice_keys(b: Builder, keys: list[ActionInfo]) -> tuple[list[ActionInfo], str]:
    """Keys printed as one prefix numbered from 1 (CH1, CH2, CH3; M1 … M4), whose legend line
    names them alone and says what they choose ("CH1, CH2, CH3 — choose a working channel"):
    each key goes to its own choice of that noun. Read before the keys' own evidence, where a
    chart of the choices ("CH3 | 350 °C | large pads …") reads as one key's values."""
    for unit in b.manual.units:
        if unit.cells:
            continue
        text = re.sub(r"^[\W_\d①-⑳]+", "", unit.text)
        m = _LEGEND_CHOICE.match(text)
        if m is None:
            continue
        named = _dedupe_keys(_pressed_keys_in(b, keys, m.group("keys")))
        rest = m.group("keys")
        for k in named:
            rest = rest.replace(b.labels[k.controls[0]].text, " ")
        if len(named) < 2 or re.search(r"[A-Za-z0-9]", re.sub(r"\b(?:and|or)\b", " ", rest)):
            continue  # (other words beside the keys: not a legend of the keys alone)
        found = [_NUMBERED_LABEL.fullmatch(b.labels[k.controls[0]].text) for k in named]
        if not all(found):
            continue
        prefixes = {f.group(1).upper() for f in found if f}
        numbers = sorted(int(f.group(2)) for f in found if f)
        if len(prefixes) == 1 and numbers == list(range(1, len(named) + 1)):
            return named, m.group("noun").lower()
    return [], ""
