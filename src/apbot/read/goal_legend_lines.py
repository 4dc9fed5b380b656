"""Names a manual gives coded values in its running text, not in a chart.

Besides tables, manuals name a numbered position in two plain ways: a legend line that opens
with the code and the name in capitals, then a dash and what it does ("2 FINE — 600 grit,
refines the edge"), and the setting's word, the code and the name in brackets ("choose stage
2 (FINE) for a touch-up"). A user says the name ("the fine stage"), the panel shows the code.

Kept narrow: the name is in capitals (how manuals print a panel's word), the code belongs to
exactly one coded setting (or the setting's own word stands before it), and a setting gets
names only where two or more of its codes are named so, all with different names — one line
of the kind is more likely prose ("1 CUP — fill to the line").
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.goal_vocab import stem

_LEGEND = re.compile(
    r"^[\s>*•·-]*\(?([A-Za-z]{0,2}\d{1,3})\)?\s+([A-Z][A-Z]+(?: [A-Z][A-Z]+){0,2})\s+[—–-]\s",
    re.MULTILINE,
)
_BRACKETED = re.compile(r"\b([A-Za-z]+)\s+([A-Za-z]{0,2}\d{1,3})\s+\(([A-Z][A-Z]+(?: [A-Z]+)?)\)")


def _key(text: str) -> str:
    key = re.sub(r"[\s\-_.]", "", text.casefold())
    return key.lstrip("0") or key if key.isdigit() else key


def legend_line_names(
    variables: dict[str, dict[str, Any]], own_words: dict[str, frozenset[str]], manual: str
) -> list[tuple[str, Any, str]]:
    """(setting, value, name) from legend lines and bracketed names (see the module's doc).
    ``variables``: coded setting -> {keyed code: value}; ``own_words``: setting -> its own
    words (stemmed), for "stage 2 (FINE)"."""
    found: dict[str, dict[Any, set[str]]] = {}

    def add(homes: list[str], code: str, name: str) -> None:
        if len(homes) == 1:
            value = variables[homes[0]][_key(code)]
            found.setdefault(homes[0], {}).setdefault(value, set()).add(name.casefold())

    for code, name in _LEGEND.findall(manual):
        add([n for n, values in variables.items() if _key(code) in values], code, name)
    for word, code, name in _BRACKETED.findall(manual):
        homes = [
            n
            for n, values in variables.items()
            if _key(code) in values and stem(word.casefold()) in own_words.get(n, frozenset())
        ]
        add(homes, code, name)
    out: list[tuple[str, Any, str]] = []
    for setting, names in found.items():
        single = {value: next(iter(said)) for value, said in names.items() if len(said) == 1}
        if len(single) >= 2 and len(set(single.values())) == len(single):
            out += [(setting, value, name) for value, name in single.items()]
    return out
