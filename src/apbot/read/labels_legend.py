"""A key whose printed name has nothing of its action's words, found by its key table's row.

A panel may print a key as a sign ("A-", "POSITION <") or an icon the text spells otherwise,
while the action is named for what it does (``smaller``, ``position_back``, ``fridge``). No
capitalised phrase of the manual matches the action's words, so the key would go unnamed and
every sentence about it lost. The key table says what each printed key does ("| A- | Smaller
characters |", "| (G) | POSITION < | nozzle further back |", "| ❄ | the food comes from the
fridge … |"): the one row whose description holds all the action's words, and whose printed name
no other action claims, names the key.
"""

from __future__ import annotations

import re

from apbot.read.text import Manual, Unit

# a table column of keys or of their printed names: "Key", "Key / part", "Name / icon", "Button";
# "Part" alone heads a list of the appliance's parts (lid, basket), whose rows name no key
_KEY_OR_NAME = r"(?:keys?|buttons?|controls?|symbols?|names?)"
_KEY_HEAD = re.compile(
    rf"^\W*(?:{_KEY_OR_NAME}(?:\s*/\s*(?:{_KEY_OR_NAME}|icons?|parts?|elements?))?"
    rf"|(?:parts?|elements?)\s*/\s*(?:{_KEY_OR_NAME}|icons?))\W*$",
    re.IGNORECASE,
)
# a cell that only counts or letters the rows: "3", "(2)", "④", "(G)", "c"
_ROW_MARK = re.compile(r"\s*(?:[\u2460-\u2473\u2776-\u277f]|\(?\d{1,2}[.)]?\)?|\(?[A-Za-z]\)?)\s*")


def _words(text: str) -> list[str]:
    return re.findall(r"[a-z0-9]+", text.lower())


def _said(word: str, said: list[str]) -> bool:
    """The action's word among a row's words: itself, a word it begins ("pos" of "position"), or
    a word it abbreviates by its consonants in order ("fwd" of "forward"; "set" is no
    abbreviation of "sweet")."""
    skeleton = not re.search(r"[aeiou]", word[1:])
    for w in said:
        if w == word or (len(word) >= 3 and w.startswith(word)):
            return True
        if skeleton and len(word) >= 3 and w[:1] == word[:1] and len(w) > len(word):
            rest = iter(w)
            if all(c in rest for c in word):
                return True
    return False


def _name_cell(unit: Unit) -> tuple[int, str] | None:
    """The row's cell under a header for keys or names (after any column counting the rows)."""
    for k, (head, cell) in enumerate(zip(unit.header, unit.cells, strict=False)):
        if _KEY_HEAD.match(head) and cell.strip() and not _ROW_MARK.fullmatch(cell):
            return k, cell.strip(" *")
    return None


def legend_name(
    manual: Manual, token_words: list[str], claimed: set[str]
) -> tuple[str, int] | None:
    """The printed name of an unnamed key: the one key-table row whose description (the cells
    after the name) holds every word of the action, its name claimed by no other action; with
    the line of that row. None when no row, or several, fit."""
    if not token_words:
        return None
    found: dict[str, int] = {}
    for unit in manual.units:
        if len(unit.cells) < 2 or not unit.header:
            continue
        named = _name_cell(unit)
        if named is None or named[0] + 1 >= len(unit.cells):
            continue
        name = named[1]
        said = _words(" ".join([name, *unit.cells[named[0] + 1 :]]))
        if name.upper() in claimed or len(name) > 24:
            continue
        if all(_said(w, said) for w in token_words):
            found.setdefault(name, unit.line)
    if not found:
        found = _legend_line_names(manual, token_words, claimed)
    if len(found) != 1:
        return None
    return next(iter(found.items()))


# a legend's item set as a line, not a table: the printed name, a gap, what it does ("hPa
# steps the air-pressure unit" after its mark "(b)"); the name is printed (a capital in it),
# at most two short words
_LEGEND_LINE = re.compile(r"^(\S{1,10}(?: \S{1,10})?)\s{2,}(\S.*)$")


def _legend_line_names(manual: Manual, token_words: list[str], claimed: set[str]) -> dict[str, int]:
    """The names of legend lines whose description holds every word of the action (the line
    form of the key table's row that :func:`legend_name` reads)."""
    found: dict[str, int] = {}
    for unit in manual.units:
        m = _LEGEND_LINE.match(unit.text) if unit.bullet and not unit.cells else None
        if m is None or not re.search(r"[A-Z]", m.group(1)):
            continue  # (a sign alone, "▶/", stays the sign the panel's other rules read)
        if m.group(1).upper() in claimed:
            continue
        said = re.split(r"\s(?:\([A-Za-z]\)|[\u2460-\u2473])\s", m.group(2))[0]  # (its own)
        if all(_said(w, _words(said)) for w in token_words):
            found.setdefault(m.group(1), unit.line)
    return found
