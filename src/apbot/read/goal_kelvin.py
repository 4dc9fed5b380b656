"""Colour temperatures said the way people say them: a light's white is set in kelvin (2700,
4000, 6500 K), and people ask for "warm white", "neutral", "cool daylight" or "the warmest".
By the lighting trade's own convention warm white is about 2700 K, neutral 4000 K, cool white
5000 K and daylight 6500 K, and the warmest is the lowest kelvin, the coolest the highest — so on
a setting whose values are colour temperatures those words name its nearest value.
"""

from __future__ import annotations

from apbot.model.schema import NumericVariable
from apbot.read.goal_text import Text, negated_before
from apbot.read.goal_values import bare_number, name_words
from apbot.read.goal_view import Goal, Model, VarInfo, domain_values

_ANCHORS = {"warm": 2700.0, "neutral": 4000.0, "cool": 5000.0, "daylight": 6500.0}
"""The trade's kelvin for each named white."""
_ENDS = {"warmest": 0, "coolest": -1, "coldest": -1, "bluest": -1, "yellowest": 0}
_NAMES = frozenset({"colour", "color", "temperature", "cct", "white", "kelvin", "tone", "k"})
_LOWEST_KELVIN, _HIGHEST_KELVIN = 1500.0, 10000.0
_LIGHT_WORDS = _NAMES | {"light", "lighting", "tone", "glow", "bulb", "lamp", "shade", "hue"}
"""Words a named white stands beside when it is a colour: "warm light", "a cool tone"."""


def _kelvin_setting(info: VarInfo) -> bool:
    """Two or more values, all numbers in the kelvin range, on a setting named for colour."""
    numbers = [bare_number(v) for v in info.values]
    if isinstance(info.var, NumericVariable):
        numbers = [float(v) for v in info.values]
    if len(numbers) < 2 or any(
        n is None or not _LOWEST_KELVIN <= n <= _HIGHEST_KELVIN for n in numbers
    ):
        return False
    words = {w.casefold() for w in name_words(f"{info.name} {info.var.label or ''}")}
    unit = str(getattr(info.var, "unit", "") or "").casefold()
    return bool(words & _NAMES) or unit in ("k", "kelvin")


def kelvin_words(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int]
) -> None:
    """Set the one open colour-temperature setting from "warm(est)", "neutral", "cool(est)",
    "daylight"; the last such word wins ("cool daylight" is daylight)."""
    settings = [
        info
        for name, info in view.infos.items()
        if name not in goal and info.role == "setting" and _kelvin_setting(info)
    ]
    if len(settings) != 1:
        return
    info = settings[0]
    values = domain_values(view, info, goal)
    numbers = [(float(bare_number(v) or v), v) for v in values]
    numbers.sort()
    chosen = None
    for k, token in enumerate(text.tokens):
        word = token.text
        if k in claimed or negated_before(text, k):
            continue
        if word in _ENDS:
            chosen = (k, numbers[_ENDS[word]][1])
        elif word in _ANCHORS and _said_of_light(text, k, info):
            anchor = _ANCHORS[word]  # "cool daylight": the later word says which
            chosen = (k, min(numbers, key=lambda pair: abs(pair[0] - anchor))[1])
    if chosen is None:
        return
    k, value = chosen
    goal[info.name] = value
    where[info.name] = k
    claimed.update(j for j, t in enumerate(text.tokens) if t.text in _ANCHORS or t.text in _ENDS)


def _said_of_light(text: Text, k: int, info: VarInfo) -> bool:
    """Whether the named white at ``k`` is said of a colour: its run of such words ("cool
    daylight") stands right beside a word of light or colour or of the setting's own name
    ("warm white", "light: neutral"), or holds two of them. Alone, "warm" and "cool" are the
    weather or the room ("it's warm in here", "to cool the room"), not the light."""
    start, end = k, k
    while text.word(start - 1) in _ANCHORS:
        start -= 1
    while text.word(end + 1) in _ANCHORS:
        end += 1
    if end > start:
        return True
    for j in (start - 1, end + 1):
        if text.word(j) in _LIGHT_WORDS:
            return True
        if 0 <= j < len(text.tokens) and info.vocab.get(text.concepts[j], 0.0) >= 0.8:
            return True
    return False
