"""Keys offered as alternatives for one named thing ("Touch ROOM, COLD or HOT. The display
shows the name of the water chosen."): each key picks one value of that setting, whatever its
name says (a washing machine's temperature keys, a kettle's 70 / 80 / 100 keys). The sentence
offering the keys and the words "the water chosen" together say it, so such keys are one
variable with a go-to feature each, before any stray on/off or range near a key's name (a
table row "| Sports bottle | COLD | 7 – 10 °C |") gives a key a setting of its own."""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.roles_common import label_of

# "the water chosen", "the name of the water selected", "the selected water", "the chosen
# outlet": the thing the offered keys pick, said of it as a choice
CHOSEN_RE = re.compile(
    r"\bthe\s+(?:(?:chosen|selected)\s+([a-z]+)\b|([a-z]+)\s+(?:chosen|selected)\b)"
)
# words naming no thing of the appliance's own ("the setting chosen", "the key selected")
VAGUE_NOUNS = frozenset(
    {"setting", "settings", "value", "values", "key", "keys", "button", "buttons", "one", "item"}
)
OFFER_VERBS = r"(?:press|touch|tap|push|select|choose)"


def offered_groups(b: Builder, keys: list[ActionInfo]) -> list[tuple[str, list[ActionInfo]]]:
    """Groups of pressed keys that one sentence offers as alternatives ("Touch A, B or C"),
    with the thing they choose named as chosen in that sentence or the next (noun, keys)."""
    presses = [k for k in keys if k.skill == "press" and k.controls[0] in b.labels]
    if len(presses) < 2:
        return []
    by_label = {label_of(b, k.controls[0]).upper(): k for k in presses}
    names = "|".join(re.escape(n) for n in sorted(by_label, key=len, reverse=True))
    one = rf"(?<![\w+])(?:{names})(?![\w+])(?:\s*\([A-Za-z0-9]\))?"
    offer = re.compile(
        rf"\b{OFFER_VERBS}\s+(?:the\s+)?({one}(?:\s*,\s*{one})*\s*,?\s+or\s+{one})",
        re.IGNORECASE,
    )
    units = b.manual.units
    out: list[tuple[str, list[ActionInfo]]] = []
    taken: set[str] = set()
    for i, unit in enumerate(units):
        if unit.cells:
            continue  # a table row ("| Press TEMP, TIME or PROBE first |") offers no choice
        m = offer.search(unit.text)
        if not m:
            continue
        noun = _chosen_noun(unit.text[m.end() :]) or (
            _chosen_noun(units[i + 1].text) if i + 1 < len(units) else None
        )
        if noun is None:
            continue
        found = re.findall(rf"(?<![\w+])(?:{names})(?![\w+])", m.group(1), re.IGNORECASE)
        group = [by_label[f.upper()] for f in dict.fromkeys(x.upper() for x in found)]
        if len(group) >= 2 and not {k.name for k in group} & taken:
            taken |= {k.name for k in group}
            out.append((noun, group))
    return out


def _chosen_noun(text: str) -> str | None:
    m = CHOSEN_RE.search(text.lower())
    if not m:
        return None
    noun = m.group(1) or m.group(2)
    return None if noun in VAGUE_NOUNS else noun
