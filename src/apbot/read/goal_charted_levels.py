"""A named level chosen by the quantity the manual charts for it: "a hundred lumens" for MEDIUM
where the manual's table says "MEDIUM  100 lm", "about two hundred lumens" for HIGH (220 lm).

Manuals chart what each step of a selector gives (light output, power, flow): a line that names
one value and then a figure with its unit. People ask for the quantity, not the step's name. A
chart counts only when three or more of a setting's values have such lines with the same unit
word, each value one figure; a figure said with that unit word then picks the value charted with
it — exactly, or the nearest within a quarter when the speaker hedges ("about", "around").
"""

from __future__ import annotations

import re

from apbot.model.schema import DiscreteVariable
from apbot.read.goal_text import Text
from apbot.read.goal_view import Goal, Model
from apbot.read.numbers import find_mentions

_FIGURE = re.compile(r"(?<![\w.])(\d+(?:\.\d+)?)\s*([a-zµ]{1,8})\b")
_HEDGES = frozenset(
    {"about", "around", "roughly", "approximately", "some", "nearly", "almost", "approx"}
)
_SLACK = 0.25
_ROWS = 3
Chart = dict[str, dict[object, float]]  # unit word -> value -> figure


def _charts(view: Model, name: str) -> Chart:
    info = view.infos[name]
    names = {str(v).casefold(): v for v in info.values if str(v).isalpha()}
    if len(names) < _ROWS:
        return {}
    found: dict[str, dict[object, set[float]]] = {}
    for line in view.manual_lines:
        said = [
            (m.end(), value)
            for word, value in names.items()
            for m in re.finditer(rf"\b{re.escape(word)}\b", line)
        ]
        if len({value for _end, value in said}) != 1:
            continue  # no value, or a list of steps ("low → medium → high")
        end, value = said[0]
        figure = _FIGURE.search(line, end)
        if figure is not None:
            found.setdefault(figure[2], {}).setdefault(value, set()).add(float(figure[1]))
    charts: Chart = {}
    for unit, rows in found.items():
        if len(rows) < _ROWS or any(len(figures) != 1 for figures in rows.values()):
            continue
        figures = {value: next(iter(f)) for value, f in rows.items()}
        if len(set(figures.values())) == len(figures):
            charts[unit] = figures
    return charts


_LETTERS = {"w": "watt", "k": "kelvin", "v": "volt", "a": "amp"}


def _same_unit(said: str, unit: str) -> bool:
    """ "lumens" for the chart's "lm": the word, its plural, or a short form whose letters it
    spells in order from its first (one-letter forms only from a short list)."""
    said, unit = said.rstrip("s") or said, unit.rstrip("s") or unit
    if said == unit or _LETTERS.get(unit) == said or _LETTERS.get(said) == unit:
        return True
    short, long = sorted((said, unit), key=len)
    if len(short) < 2 or len(short) > 3 or short[0] != long[0]:
        return False
    rest = iter(long[1:])
    return all(letter in rest for letter in short[1:])


def charted_levels(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int]
) -> None:
    """Give each charted quantity said with its unit word to the value charted with it."""
    charts = {
        name: chart
        for name, info in view.infos.items()
        if info.role == "setting" and isinstance(info.var, DiscreteVariable) and name not in goal
        for chart in [_charts(view, name)]
        if chart
    }
    if not charts:
        return
    for mention in find_mentions(text.tokens, skip=claimed):
        if mention.kind != "number" or mention.end >= len(text.tokens):
            continue
        unit = text.word(mention.end).casefold()
        owners = {
            name: figures  # "lm" and "lumens" charts of one setting agree
            for name, chart in charts.items()
            if name not in goal
            for said, figures in chart.items()
            if _same_unit(unit, said)
        }
        if len(owners) != 1:
            continue
        name, figures = next(iter(owners.items()))
        value = _charted(figures, mention.value, mention.lead.casefold() in _HEDGES)
        if value is None:
            continue
        goal[name] = value
        where[name] = mention.start
        claimed.update(range(mention.start, mention.end + 1))


def _charted(figures: dict[object, float], said: float, hedged: bool) -> object | None:
    for value, figure in figures.items():
        if figure == said:
            return value
    if not hedged:
        return None
    value, figure = min(figures.items(), key=lambda item: abs(item[1] - said))
    return value if abs(figure - said) <= _SLACK * figure else None


# adjectives only: "twenty minutes maximum" and "at least" bound another setting
_MOST = frozenset({"brightest", "highest", "strongest", "greatest", "biggest", "largest"})
_LEAST = frozenset({"dimmest", "lowest", "weakest", "faintest", "smallest"})


def charted_superlatives(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int]
) -> None:
    """ "the brightest spot beam", "the dimmest white light": a superlative no other setting
    took, on a model with one charted selector, is that selector's top or bottom row."""
    charts = [
        (name, chart)
        for name, info in view.infos.items()
        if info.role == "setting" and isinstance(info.var, DiscreteVariable)
        for chart in [_charts(view, name)]
        if chart
    ]
    if len(charts) != 1 or charts[0][0] in goal:
        return
    name, chart = charts[0]
    figures = next(iter(chart.values()))
    for k, token in enumerate(text.tokens):
        if k in claimed or token.text.casefold() not in _MOST | _LEAST:
            continue
        pick = max if token.text.casefold() in _MOST else min
        goal[name] = pick(figures.items(), key=lambda item: item[1])[0]
        where[name] = k
        claimed.add(k)
        return
