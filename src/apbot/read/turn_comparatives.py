"""Two turns of one dial named for what they do, not for a way (``turn_faster`` /
``turn_slower``, ``turn_coarser`` / ``turn_finer``): one dial, stepped both ways.

An environment may name a dial's two turns by their effect, as the panel prints it beside the
arrows ("finer ↺  ↻ coarser"). Read on their own the two names are two dials with no values;
together they are the two ways of the dial the manual names beside both words ("SPEED knob …
clockwise faster, anticlockwise slower"). The way that raises the printed number is the one
whose superlative the manual puts beside the higher number ("1 (finest) to 12 (coarsest)"), or
else the one that says "more" of a quantity (faster, higher, warmer).
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo

# opposite comparatives: the first of each pair says more of the quantity it turns
OPPOSITES = (
    ("faster", "slower"), ("higher", "lower"), ("warmer", "cooler"), ("hotter", "colder"),
    ("louder", "quieter"), ("louder", "softer"), ("stronger", "weaker"), ("longer", "shorter"),
    ("brighter", "dimmer"), ("thicker", "thinner"), ("bigger", "smaller"), ("larger", "smaller"),
    ("wider", "narrower"), ("heavier", "lighter"), ("darker", "lighter"), ("more", "less"),
    ("coarser", "finer"), ("harder", "softer"), ("deeper", "shallower"),
)  # fmt: skip
_CONTROL = r"(?:dial|knob|wheel|ring|control|selector)"
_NOT_NAMES = {"the", "a", "an", "this", "that", "its", "your", "rotary", "control", "turn"}


def _superlative_at(text: str, word: str) -> list[int]:
    """The numbers the manual puts beside the superlative of a comparative: "12 (coarsest)",
    "1 is the finest", "finest (1)"."""
    stem = word[:-2] if word.endswith("er") else word
    sup = rf"(?:{re.escape(stem)}e?st|most)\b" if word != "more" else r"most\b"
    if word in ("more", "less"):
        return []
    found = re.findall(rf"\b(\d{{1,3}})\s*(?:\(|=|:|-|–|is\s+the)?\s*(?:the\s+)?{sup}", text, re.I)
    found += re.findall(rf"\b{sup}\s*(?:\)|,)?\s*\(?(?:=|:|is|at)?\s*(\d{{1,3}})\b", text, re.I)
    return [int(n) for n in found]


def _up_first(text: str, a: str, b: str) -> bool:
    """Whether ``a`` (else ``b``) is the way that raises the number: by the superlatives the
    manual places at the two ends, else by the word's own sense."""
    at_a, at_b = _superlative_at(text, a), _superlative_at(text, b)
    if at_a and at_b and max(at_a) != max(at_b):
        return max(at_a) > max(at_b)
    return any(p[0] == a for p in OPPOSITES) or not any(p[0] == b for p in OPPOSITES)


def _dial_name(text: str, a: str, b: str) -> str:
    """The word the manual names the dial by, on a line that has both comparatives (or the
    two lines after it do): "SPEED knob .... clockwise faster, anticlockwise slower"."""
    lines = text.split("\n")
    name_re = re.compile(rf"\b([A-Za-z][A-Za-z-]+)\s+{_CONTROL}\b", re.I)
    for i, line in enumerate(lines):
        near = " ".join(lines[i : i + 3]).lower()
        if not (re.search(rf"\b{a}\b", near) and re.search(rf"\b{b}\b", near)):
            continue
        for m in name_re.finditer(line):
            word = m.group(1).lower()
            if word not in _NOT_NAMES and word not in (a, b):
                return word.replace("-", "_")
    return ""


def compared_turns(infos: list[ActionInfo], text: str) -> list[ActionInfo]:
    """``infos`` with every pair of turns named by opposite comparatives made the two ways of
    one dial (the way raising the number clockwise), on the control the manual names."""
    turns = {i.token: i for i in infos if i.skill.startswith("turn") and len(i.controls) == 1}
    taken = set(turns) | {c for i in infos for c in i.controls}
    out = {i.name: i for i in infos}
    for a, b in OPPOSITES:
        if a not in turns or b not in turns or turns[a].name not in out:
            continue
        if out[turns[a].name] is not turns[a] or out[turns[b].name] is not turns[b]:
            continue  # (one of them is already the half of another pair)
        name = _dial_name(text, a, b)
        if not name or name in taken:
            name = f"{a}_{b}" if f"{a}_{b}" not in taken else ""
        if not name:
            continue
        up, down = (a, b) if _up_first(text, a, b) else (b, a)
        out[turns[up].name] = ActionInfo(turns[up].name, "turn_cw", (name,))
        out[turns[down].name] = ActionInfo(turns[down].name, "turn_ccw", (name,))
    return [out[i.name] for i in infos]
