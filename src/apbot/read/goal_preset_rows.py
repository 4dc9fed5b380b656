"""One-touch keys the manual charts: "the TV position" is the head and foot angles its row gives.

A manual often charts what each one-touch key does, a row per key and a column per setting
("| Key | Head | Foot |" / "| TV | 45° | 15° |"). A belief read from it may have kept the key
but not what it sets, while it still has the settings themselves (HEAD and FOOT with their own
arrows). When the user names such a key ("the TV position", "into zero gravity"), the settings
its row gives are what they ask for. Only a row whose first cell is a key of the panel (its
words are an action's name: TV of ``press_tv``), under a heading row that names two or more
numeric settings of the model; only a figure in the setting's own values counts ("unchanged"
sets nothing), and a setting the sentence gives a value itself keeps it.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.model.schema import NumericVariable
from apbot.read.goal_manual import _heads, _name, _setting_words, _table_blocks
from apbot.read.goal_view import Goal, Model, domain_values
from apbot.read.goal_vocab import STOP_WORDS

_ROWS: dict[int, tuple[Model, list[tuple[tuple[str, ...], dict[str, Any]]]]] = {}
_FIGURE = re.compile(r"^\s*(-?\d+(?:\.\d+)?)\s*(?:°\s*[cf]?|%|mm|cm|min|s)?\s*$")


def charted_keys(view: Model) -> list[tuple[tuple[str, ...], dict[str, Any]]]:
    """(the key's words, {setting: value}) for each key row of the manual's charts."""
    hit = _ROWS.get(id(view))
    if hit is not None and hit[0] is view:
        return hit[1]
    rows = _charted(view)
    _ROWS[id(view)] = (view, rows)
    return rows


def _charted(view: Model) -> list[tuple[tuple[str, ...], dict[str, Any]]]:
    numeric = {
        name: words
        for name, words in _setting_words(view.model).items()
        if name in view.infos
        and view.infos[name].role == "setting"
        and isinstance(view.infos[name].var, NumericVariable)
    }
    keys = [tuple(a.casefold().split("_")) for a in view.model.actions]
    found: list[tuple[tuple[str, ...], dict[str, Any]]] = []
    for block in _table_blocks("\n".join(view.manual_lines)):
        heads = _heads(block, numeric)
        if heads is None:
            continue
        columns = {i: next(iter(h)) for i, h in enumerate(heads) if len(h) == 1}
        if 0 in columns or len(set(columns.values())) < 2:
            continue  # a chart of values per setting, not one of keys
        for row in block[1:]:
            words = tuple(re.findall(r"[a-z0-9]+", _name(row[0]) if row else ""))
            if len("".join(words)) < 2 or set(words) <= STOP_WORDS:
                continue
            if not any(_ends_with(key, words) for key in keys):
                continue
            values = {}
            for i, name in columns.items():
                m = _FIGURE.match(row[i]) if i < len(row) else None
                number = float(m[1]) if m else None
                if number is not None and number in view.infos[name].values:
                    values[name] = int(number) if number.is_integer() else number
            if values:
                found.append((words, values))
    return found


def _ends_with(key: tuple[str, ...], words: tuple[str, ...]) -> bool:
    return len(key) > len(words) and key[-len(words) :] == words


def charted_presets(view: Model, said: str, goal: Goal) -> None:
    """ "the TV position", "put the bed into zero gravity": the settings a charted key's row
    gives, for a key the sentence names (a one-letter word of the key, ZERO G's G, is named by
    a word it begins: "zero gravity")."""
    text = said.casefold()
    for words, values in charted_keys(view):
        if not _named(words, text):
            continue
        for name, value in values.items():
            if name not in goal and value in domain_values(view, view.infos[name], goal):
                goal[name] = value


_DENIED = frozenset({"not", "no", "without", "never", "skip", "than", "don't", "dont"})


def _named(words: tuple[str, ...], text: str) -> bool:
    """The key is named and not denied: "not the nap position", "no nap today" ask for none of
    its row (nor "rather than the TV one")."""
    parts = [rf"{w}[a-z]*" if len(w) == 1 else re.escape(w) for w in words]
    found = re.finditer(r"(?<![a-z0-9])" + r"\s+".join(parts) + r"(?![a-z0-9])", text)
    return any(not _denied(text[: m.start()]) for m in found)


def _denied(before: str) -> bool:
    last = re.findall(r"[a-z']+", before)[-3:]
    while last and last[-1] in ("the", "a", "an", "that", "this", "any"):
        last.pop()
    return bool(last) and last[-1] in _DENIED
