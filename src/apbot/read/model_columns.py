"""The column of this manual's own model in a table comparing the models of a range.

A manual written for a range prints one specifications table with a column per model ("Model
.... SM-1   SM-2   SM-3", "| | CM-3 | CM-3 Plus |") and then describes one of them: its type
number stands in the running page titles, on the cover, in "This manual describes the SM-2".
A row of that table ("BOWL key .... –   L / R   L / M / R") gives this appliance's values only
in its own model's column; the sister models' cells name keys and values it does not have.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence

from apbot.read.labels import words
from apbot.read.text import Unit

# a type number: letters and digits joined by a hyphen or a space ("SM-2", "RB-20U", "CM-3
# Plus", "BP-500 TALK", "HT-28 W" keep their word), as a comparison table's header names them
# (one capital after a hyphened number, "HT-28 W", is a variant; "AMP 10 A" is an amount)
_TYPE_RE = re.compile(
    r"[A-Z]{1,5}[- ]?\d{1,4}[A-Z]{0,3}(?: (?:[A-Z][a-z]+|[A-Z]{2,}))?"
    r"|[A-Z]{1,5}-\d{1,4}[A-Z]{0,3} [A-Z]"
)
# the row of a comparison table that lists each model's keys ("Keys", "Buttons", "Controls")
_KEYS_ROW_RE = re.compile(r"(?:operating |control )?(?:keys|buttons|controls|key pad|keypad)\b")
# a cell's keys: "START/STOP, USER, MEM, SET", "as BP-300 + VOICE, ▼"
_KEY_SPLIT_RE = re.compile(r"\s*(?:,|\+|;|·|\band\b)\s*")
# one letter and a number ("P1", "L3", "H2") heads a programme's or a level's column, no model's
_CODE_RE = re.compile(r"[A-Z]\d{1,2}")


def is_type_number(cell: str) -> bool:
    """Whether ``cell`` is a model's type number ("K-3", "RB-20U"), not a programme's code."""
    return bool(_TYPE_RE.fullmatch(cell.strip())) and not _CODE_RE.fullmatch(cell.strip())


def compares_models(header: Sequence[str]) -> bool:
    """Whether a table's header heads its columns with two or more models' type numbers and
    nothing else ("| | RK-30 | RK-50 | RK-90 |"): its first column names what is compared
    (payload, power, the keys fitted), no setting's values."""
    models = [c for c in header[1:] if is_type_number(c)]
    return len(models) >= 2 and len(models) == len(header) - 1


def own_column(
    header: Sequence[str],
    lines: Sequence[str],
    units: Sequence[Unit] = (),
    keys: Iterable[str] = (),
) -> int | None:
    """The index of the header cell naming the manual's own model: the model the text names
    most often (page titles repeat it), clearly more than each sister; else the one whose row
    of keys is the panel's (``keys``: the panel's key names and printed labels); None when the
    header names no two models or no model stands out."""
    models = [(k, c.strip()) for k, c in enumerate(header) if k and is_type_number(c)]
    if len(models) < 2 or len(models) < len(header) - 1:
        return None
    named = _named_most(models, lines)
    return named if named is not None else _keys_match(header, models, units, keys)


def _named_most(models: list[tuple[int, str]], lines: Sequence[str]) -> int | None:
    """The model the text names at least three times and twice as often as each sister."""
    text = "\n".join(lines)
    counts: dict[int, int] = {}
    for k, name in models:
        said = len(re.findall(rf"(?<![\w-]){re.escape(name)}(?![\w-])", text))
        # a longer sister name that starts with this one ("CM-3 Plus" after "CM-3") is hers
        longer = [n for _, n in models if n != name and n.startswith(name)]
        said -= sum(len(re.findall(rf"(?<![\w-]){re.escape(n)}(?![\w-])", text)) for n in longer)
        counts[k] = said
    best = max(counts, key=lambda k: counts[k])
    rest = [n for k, n in counts.items() if k != best]
    return best if counts[best] >= 3 and all(counts[best] >= 2 * n for n in rest) else None


def _keys_match(
    header: Sequence[str], models: list[tuple[int, str]], units: Sequence[Unit], keys: Iterable[str]
) -> int | None:
    """The model whose "Keys" row names only keys this panel has, and the most of them: a
    robot knows its panel's keys, and a sister model's cell names one it lacks ("as BP-300 +
    VOICE") or fewer of them. A cell "as <sister> + …" takes the sister's keys too."""
    own = {w for key in keys for w in words(key.replace("_", " "))}
    own_marks = {ch for key in keys for ch in key if not ch.isascii()}
    rows = [
        u
        for u in units
        if u.header == tuple(header) and u.cells and _KEYS_ROW_RE.match(u.cells[0].strip().lower())
    ]
    if not own or len(rows) != 1:
        return None
    cells = rows[0].cells
    names = {name: k for k, name in models}
    scores: dict[int, int] = {}
    for k, _ in models:
        pieces = _key_pieces(cells[k] if k < len(cells) else "", cells, names)
        known = [p for p in pieces if _is_own_key(p, own, own_marks)]
        if pieces and len(known) == len(pieces):
            scores[k] = len(known)
    if not scores:
        return None
    best = max(scores, key=lambda k: scores[k])
    return best if sum(v == scores[best] for v in scores.values()) == 1 else None


def _key_pieces(cell: str, cells: Sequence[str], names: dict[str, int]) -> list[str]:
    pieces: list[str] = []
    for piece in _KEY_SPLIT_RE.split(cell.strip()):
        sister = next((n for n in names if re.search(rf"\b{re.escape(n)}\b", piece)), None)
        if sister is not None:  # "as BP-300": that model's keys
            at = names[sister]
            pieces += (
                [p for p in _KEY_SPLIT_RE.split(cells[at].strip()) if p] if at < len(cells) else []
            )
        elif piece and piece not in "—–-":
            pieces.append(piece)
    return pieces


def _is_own_key(piece: str, own: set[str], own_marks: set[str]) -> bool:
    """A key the panel has: one of its words ("START/STOP" → start) or its symbol (▼)."""
    said = words(piece)
    if said:
        return any(w in own for w in said)
    return any(ch in own_marks for ch in piece)
