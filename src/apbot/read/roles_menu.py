"""Settings reached through a numbered menu: "hold SET for 3 s; the display shows F1 …".

Many panels have no key per setting. A held key opens a settings menu whose items carry codes
(F1 … F5, P1 … P3, d1 … d4), the stepping pair changes the item shown, and a press of the
same key moves on to the next item (after the last one it leaves the menu). Read key by key,
the held key looks like a toggle of its own, the short press like an amount of its own, and
the pair like one more amount, so no item can be set. This rule reads the menu as one
feature whose steps follow the manual's procedure: enter, pair on the first item, next key,
pair on the second item, …, next key (the model format's sequential steps; the
"SET/TIME then ▲/▼" switch of ``roles_shared`` is written the same way).

What marks a menu (structural, whatever the appliance): a family of codes of one prefix
numbered from 1 (or 0) without gaps, each led by its own line or table row that names a
setting ("F3  Humidity target", "| P2 | automatic close | -- · 1 · 2 · 5 · 10 min |"); a
sentence tying the codes to a menu, programming or settings mode; and the key that opens it,
from the step that opens it ("Hold PROG for 3 seconds. The display shows P1 …") or from its
own legend ("| SET | … | 3 s: open the setting menu |"). Each item's values come from its own
row or the lines under its heading. The display shows the code with the value, so each
item's label is its code.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.menu_cells import CODE_HEAD
from apbot.read.menu_values import DEFAULT_HEAD, MenuItem, item_variable
from apbot.read.roles_menu_home import home_quantity

_CODE = r"(?P<pre>[A-Za-z]{1,2})-?(?P<num>\d{1,2})"
_CODE_RE = re.compile(rf"^{_CODE}$")
_LEAD_RE = re.compile(rf"^\s*{_CODE}\b\s*[:.=–-]?\s+(?P<rest>[A-Za-z][^|]*)$")
_MENU_RE = re.compile(
    r"\b(?:menu|programming|program(?:me)?\s+mode|settings?\s+mode|set-?up\s+mode|"
    r"parameters?|settings|set-?up|options|functions?\s+codes?)\b",
    re.IGNORECASE,
)
_SHOWS_RE = re.compile(r"\b(?:shows?|appears?|displays?|reads?|flash(?:es)?)\b", re.IGNORECASE)
_HOLD_CLAUSE = re.compile(r"\b(?:hold\w*|\d+\s*s(?:ec\w*)?)\b[^.;|]*", re.IGNORECASE)
_NEXT_RE = re.compile(r"\bnext\s+(?:item|parameter|setting|function|code|menu\s+item|step)\b", re.I)
# "moves from one setting code to the next": the item's noun, then "to the next"
_ON_TO_NEXT_RE = re.compile(
    r"\b(?:item|parameter|setting|code)s?\b[^.;|]{0,20}\bto\s+the\s+next\b", re.IGNORECASE
)
_BARE_STEP = re.compile(r"^\W*(?:\d+[.)]\s*)?(?:press|touch|push|tap)\s+\S{1,12}\s*\.?\s*$", re.I)
_VALUES_HEAD = re.compile(r"\b(?:values?|range|settings?|options?|choices?)\b", re.IGNORECASE)
# a column headed as the code a small display prints (menu_cells.CODE_HEAD); its cells are
# short letter codes ("rA", "EP", "MASK"), numbered by their row's place
_LETTER_CODE = re.compile(r"^[A-Za-z]{1,4}$")


def _name_of(rest: str) -> str:
    """The setting a lead line names: its words up to a new sentence or a value ("Light time
    How long …" → "Light time"; "Incubation temperature" stays)."""
    out: list[str] = []
    for k, w in enumerate(rest.split()):
        if k and ((w[:1].isupper() and not w.isupper()) or re.match(r"[\d(.\-–]", w)):
            break
        if k >= 5:
            break
        out.append(w)
    return " ".join(out).strip(" .:,")


def _row_item(unit: Any) -> tuple[str, str, int, int] | None:
    """(prefix, name, number, code cell) of a table row led by a code ("| P1 | light time … |")."""
    for k, cell in enumerate(unit.cells[:2]):
        m = _CODE_RE.match(cell.strip())
        if m and k + 1 < len(unit.cells) and re.match(r"[A-Za-z]", unit.cells[k + 1].strip()):
            return m.group("pre"), unit.cells[k + 1].strip(), int(m.group("num")), k
    return None


def _headed_item(unit: Any) -> tuple[str, str, int] | None:
    """(table key, name, code cell) of a row whose code sits in a column headed "Code" and is
    a short word of letters ("| rA | Ramp time | OFF, AUTO, 5 … 45 |"): codes with no number,
    which only their column's head tells from a setting's name."""
    head = unit.header or ()
    for k, cell in enumerate(unit.cells[:2]):
        if k >= len(head) or not CODE_HEAD.match(head[k]):
            continue
        code = cell.strip()
        named = k + 1 < len(unit.cells) and re.match(r"[A-Za-z]", unit.cells[k + 1].strip())
        if named and _LETTER_CODE.match(code):
            return "#" + "|".join(head), unit.cells[k + 1].strip(), k
    return None


def find_items(b: Builder) -> list[MenuItem]:
    """The menu's items in order, or [] when the manual has no numbered settings menu."""
    units = b.manual.units
    found: dict[str, dict[int, MenuItem]] = {}
    last: MenuItem | None = None  # a headed-code item, which a row with no code goes on
    for i, unit in enumerate(units):
        if unit.cells:
            row = _row_item(unit)
            headed = _headed_item(unit) if row is None else None
            if headed is not None:
                key, name, k = headed
                row = key, name, len(found.get(key, {})) + 1, k
            elif row is None:
                if last is not None and unit.header and not unit.cells[0].strip():
                    last.texts += [(i, c) for c in unit.cells[1:] if c.strip()]
                else:
                    last = None
                continue
            pre, name, num, k = row
            code = unit.cells[k].strip()
            item = found.setdefault(pre, {}).setdefault(num, MenuItem(code, name, i))
            cells = unit.cells[k + 2 :]
            heads = unit.header[k + 2 :] if unit.header else ()
            for c, cell in enumerate(cells):
                head = heads[c] if c < len(heads) else ""
                if DEFAULT_HEAD.search(head):
                    item.initial = cell.strip()
                elif not head or _VALUES_HEAD.search(head) or c == 0:
                    item.texts.append((i, cell))
            if len(name.split()) < len(item.name.split()):
                item.name = name
            last = item if headed is not None else None
            continue
        m = _LEAD_RE.match(unit.text)
        if m is None:
            lead = _letter_lead(b, unit.text)
            if lead is not None:  # "SLP — sleep delay. …": an item coded by letters alone
                code, rest = lead
                key = "@" + unit.heading
                num = len(found.get(key, {})) + 1
                item = found.setdefault(key, {}).setdefault(num, MenuItem(code, _name_of(rest), i))
                item.texts += _body(b, i, key, rest[len(item.name) :])
            continue
        rest = m.group("rest")
        if re.search(rf"\b{re.escape(m.group('pre'))}-?\d", rest):
            continue  # "F1 unit C F2 temperature …": a list of several items, not one's lead
        name = _name_of(rest)
        if not name or len(words(name)) == 0:
            continue
        pre, num = m.group("pre"), int(m.group("num"))
        code = unit.text.strip().split()[0].rstrip(":.=")
        item = found.setdefault(pre, {}).setdefault(num, MenuItem(code, name, i))
        if len(name.split()) < len(item.name.split()) or (item.at != i and not item.texts):
            item.name = name
        item.texts += _body(b, i, pre, rest[len(name) :])
    for pre, items in found.items():
        nums = sorted(items)
        if len(nums) < 2 or nums[0] not in (0, 1) or nums != list(range(nums[0], nums[-1] + 1)):
            continue
        if not _tied_to_menu(b, pre, items[nums[0]].at):
            continue
        return [items[n] for n in nums]
    return []


# "SLP — sleep delay.": a code of capitals, a dash and the setting it names in small letters
_LETTER_LEAD_RE = re.compile(
    r"^\s*(?P<code>[A-Z]{2,4})\s+[—–]\s+(?P<rest>[a-z][a-z -]{2,40}[^|]*)$"
)


def _letter_lead(b: Builder, text: str) -> tuple[str, str] | None:
    """(code, rest) of a line led by a code of letters alone ("SLP — sleep delay"), which is
    no key's printed name (a key legend "TEMP — sets the heat" is not a menu item)."""
    m = _LETTER_LEAD_RE.match(text)
    if m is None:
        return None
    if any(lab.text and lab.text.upper() == m.group("code") for lab in b.labels.values()):
        return None
    return m.group("code"), m.group("rest")


def _body(b: Builder, i: int, pre: str, tail: str) -> list[tuple[int, str]]:
    """The text under an item's own lead line, up to the next item or heading (at most 6 units)."""
    units = b.manual.units
    out = [(i, tail)] if tail.strip() else []
    for j in range(i + 1, min(i + 7, len(units))):
        text = units[j].text
        if _LEAD_RE.match(text) or units[j].heading != units[i].heading:
            break
        if pre.startswith("@") and _LETTER_LEAD_RE.match(text):
            break
        out.append((j, text))
    return out


def _tied_to_menu(b: Builder, pre: str, first: int) -> bool:
    """A sentence or heading ties the codes to a settings menu ("THE SETTING MENU (F1 - F5)",
    "P1 … / P2 …  programming, parameter and value"), or the line that leads into the first
    item names one ("User settings:"), or the section the first item's table row stands in is
    headed so ("The setup menu" over "| P01 | Ice size | … |"; codes may be zero-padded) or
    one of the two lines right above the table names one."""
    units = b.manual.units
    if pre.startswith("@"):  # letter codes: the section is a menu, or a sentence names both
        code = re.compile(rf"(?<!\w){re.escape(units[first].text.split()[0])}(?!\w)")
        return bool(_MENU_RE.search(units[first].heading)) or any(
            code.search(u.text) and _MENU_RE.search(u.text) for u in units if not u.cells
        )
    lead = units[first - 1].text if first else ""
    if lead.rstrip().endswith(":") and _MENU_RE.search(lead):
        return True
    if units[first].cells and _MENU_RE.search(units[first].heading):
        return True
    if units[first].cells:  # (no heading kept: the lines right above the table name the menu)
        top = first
        while top > 0 and units[top - 1].cells:
            top -= 1
        if any(_MENU_RE.search(u.text) for u in units[max(0, top - 2) : top]):
            return True
    code = re.compile(rf"\b{re.escape(pre)}-?0?[01]\b")
    return any(
        code.search(u.text) and _MENU_RE.search(u.text) for u in b.manual.units if not u.cells
    ) or any(code.search(u.heading) and _MENU_RE.search(u.heading) for u in b.manual.units)


def _label_at(b: Builder, token: str, text: str) -> bool:
    lab = b.labels.get(token)
    return bool(lab and lab.text and re.search(rf"(?<!\w){re.escape(lab.text)}(?!\w)", text))


def find_entry(b: Builder, keys: list[ActionInfo], first: str) -> ActionInfo | None:
    """The action that opens the menu: the held (or pressed) key of the step after which the
    display shows the first item ("Hold PROG for 3 seconds. The display shows P1 …"), else a
    hold whose own legend opens the menu ("| SET | … | 3 s: open the setting menu |")."""
    units = b.manual.units
    code = re.compile(rf"(?<!\w){re.escape(first)}(?!\w)")
    for i, unit in enumerate(units):
        if not (code.search(unit.text) and _SHOWS_RE.search(unit.text)):
            continue
        for j in (i, i - 1):
            if j < 0:
                continue
            text = units[j].text
            for skill in ("hold", "press"):
                verb = re.search(
                    r"\bhold\b|\bkeep\b.*\bpressed\b"
                    if skill == "hold"
                    else r"\b(?:press|touch|push|tap)\b",
                    text,
                    re.IGNORECASE,
                )
                if verb is None:
                    continue
                for key in keys:
                    if (
                        key.skill == skill
                        and len(key.controls) == 1
                        and _label_at(b, key.controls[0], text[verb.start() :])
                    ):
                        return key
    for key in keys:
        if key.skill != "hold" or len(key.controls) != 1:
            continue
        lab = b.labels.get(key.controls[0])
        for i in lab.mentions if lab else []:
            unit = units[i]
            told = " ".join(unit.cells) if unit.cells else unit.text
            if any(_MENU_RE.search(c.group(0)) for c in _HOLD_CLAUSE.finditer(told)):
                return (
                    key  # "| SET | … | 3 s: open the setting menu |", "Hold 3 seconds: programming"
                )
    return None


def _says_next(b: Builder, key: ActionInfo) -> bool:
    """Whether a sentence naming ``key`` says it goes to the next item or setting ("Press MODE
    again for the next setting"), not to the next programme or food of a chart."""
    lab = b.labels.get(key.controls[0])
    if lab is None:
        return False
    units = b.manual.units
    told = [units[i].text for i in lab.mentions]
    # "3. Press SET." "The next code appears.": a bare step's effect is the sentence after it
    told += [
        units[i + 1].text
        for i in lab.mentions
        if i + 1 < len(units) and _BARE_STEP.match(units[i].text)
    ]
    return any(_NEXT_RE.search(t) or _ON_TO_NEXT_RE.search(t) for t in told)


def _names_second(b: Builder, key: ActionInfo, code: str) -> bool:
    """Whether the key's own legend names the menu's second item ("moves from SLP to AO")."""
    lab = b.labels.get(key.controls[0])
    named = re.compile(rf"\bto\s+{re.escape(code)}(?!\w)")
    return bool(lab and any(named.search(b.manual.units[i].text) for i in lab.mentions))


def _next_key(b: Builder, keys: list[ActionInfo], entry: ActionInfo) -> ActionInfo | None:
    """The key that moves to the next item: a press of the entry's own key (or the entry
    itself when it is a press), else a key whose sentence says it goes to the next item."""
    for key in keys:
        if key.skill == "press" and key.controls == entry.controls:
            return key
    for key in keys:
        if key.skill == "press" and _says_next(b, key):
            return key
    return None


def _own_pair(b: Builder, base: str, entry: ActionInfo) -> bool:
    """A stepping pair printed with a name of its own ("TEMP +", "TEMP −") changes that
    quantity; it serves the menu only when that name is the menu key's own ("SET ▲ / SET ▼")."""
    lab = b.labels.get(entry.controls[0])
    return bool(lab and set(words(base)) <= set(words(lab.text)))


def assign_menu(
    b: Builder, keys: list[ActionInfo], pairs: dict[str, dict[str, list[str]]]
) -> set[str]:
    """Read a numbered settings menu into one feature; returns the actions it took (and drops
    the stepping pair it uses from ``pairs``)."""
    items = find_items(b)
    if not items or not pairs:
        return set()
    entry = find_entry(b, keys, items[0].code)
    if entry is None:
        return set()
    # a pressed entry whose own sentence goes on ("Press MENU … the next code appears") is
    # also the key that goes on; a held entry's short press, or a key saying "next item"
    own = entry if entry.skill == "press" and _says_next(b, entry) else None
    if own is None and entry.skill == "press" and _names_second(b, entry, items[1].code):
        own = entry  # "SET — opens the menu and moves from SLP to AO"
    nxt = own or _next_key(b, [k for k in keys if k.name != entry.name], entry)
    if nxt is None:  # (a press that steps a chart, "AUTO MENU … the next food", is no menu)
        return set()
    by_name = {k.name: k for k in b.infos}
    base = "" if "" in pairs else next(iter(pairs))
    if base and not _own_pair(b, base, entry):
        return set()  # "TEMP + / TEMP −" sets the temperature, not the menu's items
    pair = pairs[base]
    ups = [a for a in pair["up"] if by_name[a].skill == "press"]
    downs = [a for a in pair["down"] if by_name[a].skill == "press"]
    if len(ups) != 1 or len(downs) != 1:
        return set()
    steps: list[dict[str, Any]] = [{"actions": [entry.name]}]
    made = 0
    for k, item in enumerate(items):
        if k:
            steps.append({"actions": [nxt.name]})
        var = item_variable(b, item)
        if var is None:  # an item the manual gives no values for: passed with ▲ / ▼ all the same
            steps.append({"actions": [ups[0], downs[0]]})
            continue
        made += 1
        steps.append(
            {
                "actions": [ups[0], downs[0]],
                "variable": var,
                "effect": {ups[0]: "next", downs[0]: "prev"},
            }
        )
        b.note(f"variables.{var}", f"menu item {item.code}", item.at)
    if made == 0:
        return set()
    steps.append({"actions": [nxt.name]})
    b.feature("settings_menu", steps)
    b.note(
        "features.settings_menu", f"{entry.name} opens the menu, {nxt.name} goes on", items[0].at
    )
    # a menu of letter codes alone (a column headed Code, "SLP — sleep delay") keeps the
    # pair only when its home-screen quantity is read here: otherwise the pair goes on to the
    # readers of what it sets outside the menu ("▲ and ▼: raise or lower the temperature")
    lettered = all(_LETTER_CODE.match(item.code) for item in items)
    if home_quantity(b, ups[0], downs[0]) or not lettered:
        del pairs[base]
        return {entry.name, nxt.name, ups[0], downs[0]}
    return {entry.name, nxt.name}
