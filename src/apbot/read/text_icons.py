"""Keys named by their icon → the name the guide gives them, written in the text.

Touch panels often carry pictures only (a snowflake, a sun, a light bulb), and their manuals
say so in a legend: a row giving the icon, what it looks like, and the name the guide uses
("❄  snowflake    colder key    Lower the temperature"), then write the icon alone in the
steps ("touch ❄"). The reader drops pictographs, so those steps lose their key and the
legend's rows, their first cell blank, run into one another. Writing the guide's name in
capitals wherever the icon stands ("touch COLDER") keeps both: the steps name the key the
action's words match, and each legend row keeps its first cell. A description the legend gives
("the snowflake", "the light bulb") names the same key in prose and is read the same way.
"""

from __future__ import annotations

import re
import unicodedata

# the nouns a legend puts after a key's name ("colder key", "light button")
_NOUN = r"(?:key|button|pad|field|touch field|sensor)"
_NAME = rf"([A-Za-z][A-Za-z-]*(?: [A-Za-z][A-Za-z-]*){{0,2}}) {_NOUN}\b"
# words no key's name holds: a sentence ("touch the power key"), not a name
_GENERIC = frozenset(
    {"the", "this", "that", "each", "any", "a", "an", "other", "every", "your", "its"}
    | {"press", "touch", "tap", "hold", "use", "push", "see", "with", "or", "and", "to"}
)


# a description followed by a lamp's verb is the lamp the picture also marks, not the key:
# "the sun lights while the water heats" stays prose about a lamp
_NOT_LIT = (
    r"(?!\s+(?:lamps?|lights?\b|lit\b|indicators?|flash|flashes|blinks?|glows?|appears?|"
    r"is\s+lit|comes\s+on|goes\s+out|turns\s+on))"
)


def _icon(ch: str, keep: frozenset[str]) -> bool:
    """A pictograph the reader would drop (not an arrow or mark it keeps)."""
    return (
        len(ch) == 1
        and ord(ch) > 0x7F
        and ch not in keep
        and unicodedata.category(ch) in ("So", "Sm")
        and not ("\u2500" <= ch <= "\u257f")  # box drawing is a table's rule
    )


def named_beside(text: str, keep: frozenset[str]) -> str:
    """Each icon printed right before the name of what it pictures ("☀ HOT → ◐ WARM → ❄ COOL",
    "❄ DEFROST") turned into a space: the lamp's picture of a value whose name stands beside
    it, so the name is read alone (a snowflake alone still reads COLD), at the same width."""

    def one(m: re.Match[str]) -> str:
        picture = _icon(m.group(1), keep) and unicodedata.category(m.group(1)) == "So"
        return " " * len(m.group(0)) if picture else m.group(0)  # ("LO ↔ HI": a sign)

    return re.sub(r"(?<![^\s(|\[])(\S)\ufe0f?(?= [A-Z][A-Z]+\b)", one, text)


def _legend(text: str, keep: frozenset[str]) -> dict[str, tuple[str, str]]:
    """Icon → (the guide's name for it, its description) from legend rows: a line (or a pipe
    table row) that starts with the icon and has a cell of its own naming a key ("colder
    key"); an icon in a sentence ("⚠  Do not touch the power key") names nothing."""
    found: dict[str, tuple[str, str]] = {}
    row = re.compile(
        rf"^[ \t|]*(\S)\ufe0f?(?:[ \t|]+([^|\n]*?))?(?:[ \t]*\|[ \t]*|[ \t]{{2,}}){_NAME}"
        r"(?=[ \t]{2,}|[ \t]*\||[ \t]*$)",  # the name a cell of its own
        re.M,
    )
    for m in row.finditer(text):
        icon, desc, name = m.group(1), (m.group(2) or "").strip(), m.group(3)
        if not _icon(icon, keep) or _GENERIC & set(name.lower().split()):
            continue
        desc = re.sub(r"\s*\([^)]*\)\s*$", "", desc).strip()  # "(model 46 only)"
        if not re.fullmatch(r"[a-z][a-z -]{2,40}", desc or "xxx"):
            desc = ""
        found.setdefault(icon, (name.upper(), desc))
    return found


def _put(line: str, icon: str, name: str) -> str:
    """Write ``name`` for each ``icon`` on the line, taking the width it adds out of the next
    wide gap, so the columns of a table drawn with spaces stay where they were."""
    pattern = re.compile(rf"{re.escape(icon)}\ufe0f?")
    while (m := pattern.search(line)) is not None:
        before, after = line[: m.start()], line[m.end() :]
        if before and not before[-1].isspace() and before[-1] not in "(|[":
            before += " "
        if after and not after[0].isspace() and after[0] not in ")|],.;:":
            name_here = name + " "
        else:
            name_here = name
            wide = unicodedata.east_asian_width(icon) in "WF"
            if wide and not before.strip(" \t|") and re.match(r" \S", after):
                name_here += " "  # a legend row's wide icon: "💡 light bulb"
        grown = len(before) + len(name_here) - m.end()
        gap = re.search(rf" {{{grown + 2},}}", after) if grown > 0 else None
        if gap is not None:
            after = after[: gap.start()] + after[gap.start() + grown :]
        line = before + name_here + after
    return line


def name_icons(text: str, keep: frozenset[str]) -> str:
    """The text with each icon a legend names written as that name ("touch ❄" → "touch
    COLDER"), and the legend's description of it in prose ("the snowflake") as "the COLDER
    key". Icons no legend names are left for the usual cleaning."""
    names = _legend(text, keep)
    if not names:
        return text
    lines = text.split("\n")
    for icon, (name, _desc) in names.items():
        lines = [_put(line, icon, name) if icon in line else line for line in lines]
    text = "\n".join(lines)
    for name, desc in names.values():
        if not desc:
            continue
        said = re.compile(rf"\b(the|a|each|with)(\s+){re.escape(desc)}\b{_NOT_LIT}", re.I)
        text = said.sub(rf"\1\2{name} key", text)
    return text
