"""The column of this manual's own model in a table comparing the models of a range.

A manual written for a range prints one specifications table with a column per model ("Model
.... SM-1   SM-2   SM-3", "| | CM-3 | CM-3 Plus |") and then describes one of them: its type
number stands in the running page titles, on the cover, in "This manual describes the SM-2".
A row of that table ("BOWL key .... –   L / R   L / M / R") gives this appliance's values only
in its own model's column; the sister models' cells name keys and values it does not have.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

# a type number: letters and digits joined by a hyphen or a space ("SM-2", "RB-20U", "CM-3
# Plus" keeps its word), as a comparison table's header names the models
_TYPE_RE = re.compile(r"[A-Z]{1,5}[- ]?\d{1,4}[A-Z]{0,3}(?: [A-Z][a-z]+)?")
# one letter and a number ("P1", "L3", "H2") heads a programme's or a level's column, no model's
_CODE_RE = re.compile(r"[A-Z]\d{1,2}")


def is_type_number(cell: str) -> bool:
    """Whether ``cell`` is a model's type number ("K-3", "RB-20U"), not a programme's code."""
    return bool(_TYPE_RE.fullmatch(cell.strip())) and not _CODE_RE.fullmatch(cell.strip())


def own_column(header: Sequence[str], lines: Sequence[str]) -> int | None:
    """The index of the header cell naming the manual's own model: the model the text names
    most often (page titles repeat it), clearly more than each sister; None when the header
    names no two models or no model stands out."""
    models = [(k, c.strip()) for k, c in enumerate(header) if k and is_type_number(c)]
    if len(models) < 2 or len(models) < len(header) - 1:
        return None
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
