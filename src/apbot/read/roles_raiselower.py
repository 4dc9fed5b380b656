"""Two keys named for what they do, not for a direction (WARMER / COOLER, a sun and a snowflake,
MORE / LESS under other names), whose own legend rows or sentences say one raises and the other
lowers the SAME quantity ("Raise the temperature of the zone" / "Lower the temperature …"): one
stepped pair on that quantity, exactly as ▲ / ▼ keys are. The rule reads the structure — a verb
of direction and the noun it acts on ("Raise the temperature", "makes the crust darker"), in
rows that name one key and not the other — never the keys' own words. A bare comparative
("lower temperature for all-day cooking") describes a level a key selects, not a step."""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.labels import words

UP_VERBS = {
    "raise", "raises", "increase", "increases", "extend", "extends", "lengthen", "lengthens",
}  # fmt: skip
DOWN_VERBS = {
    "lower", "lowers", "decrease", "decreases", "reduce", "reduces", "shorten", "shortens",
}  # fmt: skip
UP_MORE = {"warmer", "hotter", "longer", "higher", "stronger", "faster", "more"}
DOWN_MORE = {"cooler", "colder", "shorter", "lower", "weaker", "slower", "less"}
_MAKE = {"make", "makes"}
# a verb acts on an object: "Lower THE temperature", not "lower temperature" (a LOW key's level)
_DETERMINERS = {"the", "its", "your"}
_SKIP = {"the", "a", "an", "its", "your", "set", "selected", "current"}
_STOP = {
    "of", "by", "for", "in", "on", "to", "at", "from", "with", "and", "or", "while", "when",
    "until", "each", "per", "one", "step", "steps", "it",
}  # fmt: skip
_CONTROLS = {"key", "keys", "button", "buttons", "pad", "field", "symbol", "icon", "switch", "knob"}
_CLAUSE_RE = re.compile(r"[.;:!?]|\|")


def _object(tokens: list[str]) -> str | None:
    """The head noun of the phrase after a verb: "the cooking time by 1 min" → ``time``."""
    phrase: list[str] = []
    for w in tokens:
        if w in _STOP or w in _CONTROLS or w.isdigit():
            break
        if w in _SKIP and not phrase:
            continue
        if w in _SKIP:
            break
        phrase.append(w)
        if len(phrase) == 3:
            break
    return phrase[-1] if phrase else None


def directions(text: str) -> set[tuple[str, str]]:
    """Every (direction, quantity) a text states: "Raise the temperature" → (up, temperature)."""
    found: set[tuple[str, str]] = set()
    for clause in _CLAUSE_RE.split(text):
        ws = words(clause)
        for i, w in enumerate(ws):
            nxt = ws[i + 1] if i + 1 < len(ws) else ""
            way: str | None = None
            noun: str | None = None
            if nxt in _DETERMINERS and w in UP_VERBS | DOWN_VERBS:  # "Raise the temperature"
                way, noun = ("up" if w in UP_VERBS else "down"), _object(ws[i + 1 :])
            elif w in _MAKE and nxt in _DETERMINERS:  # "makes the toast darker"
                more = next(
                    (j for j in range(i + 2, min(i + 6, len(ws))) if ws[j] in UP_MORE | DOWN_MORE),
                    None,
                )
                if more is not None:
                    way, noun = ("up" if ws[more] in UP_MORE else "down"), _object(ws[i + 1 : more])
            if way and noun and noun not in UP_MORE | DOWN_MORE | _CONTROLS and len(noun) > 2:
                found.add((way, noun))
    return found


def _own_rows(b: Builder, key: ActionInfo, other: ActionInfo) -> set[tuple[str, str]]:
    """What the rows naming ``key`` and not ``other`` say it does (its legend row, its
    sentences); a row naming both keys says nothing about either alone."""
    mine = {i for t in key.controls if t in b.labels for i in b.labels[t].mentions}
    theirs = {i for t in other.controls if t in b.labels for i in b.labels[t].mentions}
    said: set[tuple[str, str]] = set()
    for i in sorted(mine - theirs):
        said |= directions(b.manual.units[i].text)
    return said


_VERB = "(" + "|".join(sorted(v for v in UP_VERBS | DOWN_VERBS if not v.endswith("s"))) + ")s?"
_SLASHED_RE = re.compile(rf"\b{_VERB}\s*/\s*{_VERB}\s+(?=(?:the|its|your)\b)", re.IGNORECASE)


def _shared_row(b: Builder, key: ActionInfo, other: ActionInfo) -> tuple[str, str] | None:
    """A row naming both keys in order and two verbs in the same order ("COOLER / WARMER |
    Lower / raise the temperature"): (``key``'s direction, the quantity)."""
    mine = {i for t in key.controls if t in b.labels for i in b.labels[t].mentions}
    theirs = {i for t in other.controls if t in b.labels for i in b.labels[t].mentions}
    a = b.labels[key.controls[0]].text if key.controls[0] in b.labels else ""
    c = b.labels[other.controls[0]].text if other.controls[0] in b.labels else ""
    for i in sorted(mine & theirs):
        text = b.manual.units[i].text
        m = _SLASHED_RE.search(text)
        if not (m and a and c and a in text and c in text):
            continue
        first, second = (m.group(1).lower(), m.group(2).lower())
        ways = ["up" if v in UP_VERBS else "down" for v in (first, second)]
        noun = _object(words(text[m.end() :]))
        if ways[0] == ways[1] or not noun or noun in _CONTROLS:
            continue
        return (ways[0] if text.index(a) < text.index(c) else ways[1]), noun
    return None


def _measured(text: str, noun: str) -> bool:
    """Whether the manual gives the noun a number anywhere ("the temperature by 1 °C", "fan
    speed can be set from 1 to 8", "5 levels of brightness"): a quantity has one, a part the
    keys move (a lid, a basket) has none."""
    n = re.escape(noun)
    after = rf"\b{n}s?\b[^.;:!?|\n]{{0,40}}?\d"
    before = rf"\d+\s+(?:levels?|settings?|steps?|stages?)\s+(?:of\s+)?(?:the\s+)?{n}\b"
    return re.search(f"{after}|{before}", text, re.I) is not None


def raise_lower_pairs(b: Builder, keys: list[ActionInfo]) -> dict[str, dict[str, list[str]]]:
    """Pairs of press keys, one raising and one lowering a quantity no other key moves: the
    quantity's name → {"up": [...], "down": [...]}. A key that says both ways is no half."""
    keys = [k for k in keys if k.skill == "press" and k.digit is None]
    found: dict[str, list[tuple[str, str]]] = {}
    for k in keys:
        for o in keys:
            if o.name >= k.name:
                continue
            ks, os_ = _own_rows(b, k, o), _own_rows(b, o, k)
            if (shared := _shared_row(b, k, o)) is not None:
                ks.add(shared)
                os_.add(("down" if shared[0] == "up" else "up", shared[1]))
            for way, noun in sorted(ks):
                other_way = "down" if way == "up" else "up"
                if (
                    (other_way, noun) in os_
                    and (other_way, noun) not in ks
                    and (way, noun) not in os_
                ):
                    up, down = (k.name, o.name) if way == "up" else (o.name, k.name)
                    found.setdefault(noun, []).append((up, down))
    pairs: dict[str, dict[str, list[str]]] = {}
    used: set[str] = set()
    for noun, twos in sorted(found.items()):
        if len(set(twos)) != 1:
            continue  # more than one pair claims the quantity: not read
        if not _measured("\n".join(u.text for u in b.manual.units), noun):
            continue  # "raise the lid" / "lower the lid": a part moved, not a quantity stepped
        up, down = twos[0]
        if {up, down} & used:
            continue
        used |= {up, down}
        pairs[noun] = {"up": [up], "down": [down]}
    return pairs


# a key printed as a name and a sign: "A+", "A-", "POSITION <", "TEMP −"
_SIGNED_RE = re.compile(r"^(?P<stem>.*?[^\s+−–<>-])\s?(?P<sign>[+−–<>-])$")
_UP_SIGNS = "+>"


def signed_pairs(b: Builder, keys: list[ActionInfo]) -> dict[str, dict[str, list[str]]]:
    """Pairs of press keys printed as the same name with opposite signs ("A- / A+",
    "POSITION < / POSITION >"), whatever their actions are called (``smaller``, ``larger``): one
    stepped pair, named by the stem's words → {"up": [...], "down": [...]}. A stem printed with
    one sign only, or more than two keys on a stem, is no pair."""
    by_stem: dict[str, dict[str, list[str]]] = {}
    for k in keys:
        if k.skill != "press" or k.digit is not None or k.controls[0] not in b.labels:
            continue
        label = b.labels[k.controls[0]]
        m = _SIGNED_RE.match(label.text.strip()) if label.line is not None else None
        if m is None:
            continue
        way = "up" if m.group("sign") in _UP_SIGNS else "down"
        by_stem.setdefault(m.group("stem").strip(), {"up": [], "down": []})[way].append(k.name)
    pairs: dict[str, dict[str, list[str]]] = {}
    for stem, pair in by_stem.items():
        if len(pair["up"]) == 1 and len(pair["down"]) == 1:
            named = _pair_noun(b, pair["up"][0], pair["down"][0])
            pairs[named or "_".join(words(stem)) or "setting"] = pair
    return pairs


def _pair_noun(b: Builder, up: str, down: str) -> str:
    """What a signed pair sets, when a heading or sentence names it before the two keys in
    brackets ("Character size (A- / A+)"): "character_size"; else ""."""
    labels = [
        re.escape(b.labels[c].text)
        for n in (down, up)
        for i in b.infos
        if i.name == n
        for c in i.controls[:1]
        if c in b.labels
    ]
    if len(labels) != 2:
        return ""
    keys = rf"\(\s*(?:{labels[0]}\s*/\s*{labels[1]}|{labels[1]}\s*/\s*{labels[0]})\s*\)"
    said = re.compile(rf"\b([A-Za-z][a-z]+(?: [a-z]+)?)\s*{keys}")
    for unit in b.manual.units:
        m = said.search(unit.text)
        if m:
            return "_".join(words(m.group(1)))
    return ""
