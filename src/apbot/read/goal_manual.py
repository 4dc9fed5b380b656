"""Names the manual gives to coded values: "2" is French bread, "A-4" a chilled ready meal.

Many panels show a programme only as a number or a short code (P2, A-4, a knob mark), and
only the manual's table says what it is. A user says "a French loaf" or "60 % humidity", so
the goal parser may read the manual it is given (a robot has it) for those names — only for
values that are codes, and only from where manuals put them: a table row that pairs a code
with a name ("| 2 | French | 3:50 |"), or a bold heading ("**2 French** – …").

>>> from apbot.model.schema import ApplianceModel
>>> model = ApplianceModel.model_validate({
...     "appliance": {"id": "m", "category": "bread_maker", "name": "m"},
...     "variables": {"menu": {"type": "discrete", "values": ["1", "2", "3"]}},
...     "controls": [{"id": "menu", "kind": "button", "label": "MENU"}],
...     "actions": {"press_menu": {"control": "menu"}},
...     "features": {"menu": [{"actions": ["press_menu"], "variable": "menu", "effect": "next"}]},
... })
>>> manual = "| No. | Programme |\\n|---|---|\\n| 1 | Basic |\\n| 2 | French (crisp) |"
>>> manual += "\\n| 3 | Cake |"
>>> coded_names(model, manual)
[('menu', '1', 'Basic'), ('menu', '2', 'French'), ('menu', '3', 'Cake')]
"""

from __future__ import annotations

import re
from itertools import pairwise
from typing import Any

from apbot.model.domain import all_values
from apbot.model.schema import ApplianceModel, DiscreteVariable, NumericVariable
from apbot.read.goal_chart_titles import chart_titles
from apbot.read.goal_contents_lines import contents_cell
from apbot.read.goal_legend_lines import legend_line_names
from apbot.read.goal_vocab import stem

_CODE = re.compile(r"[a-z]{0,2}[- ]?\d{1,3}", re.IGNORECASE)
_BOLD = re.compile(r"\*\*\s*([A-Za-z]{0,2}[- ]?\d{1,3})\s+([^*\n]{2,40}?)\s*\*\*")
_RULE = re.compile(r"^[\s|:\-–—=+]*$")
_GAP = re.compile(r"\s{2,}|\t+")
Pair = tuple[str, str]
_PROGRAMME = re.compile(r"menu|progr|mode|cycle|function|course|recipe|select", re.IGNORECASE)
MAX_WORDS = 5
"""Words of a name kept (a cell that says more is a description, not a name)."""


def _key(text: str) -> str:
    key = re.sub(r"[\s\-_.]", "", text.casefold())
    return key.lstrip("0") or key if key.isdigit() else key  # "01" in a chart is stitch 1


def _headed(name: str, var: NumericVariable, headings: frozenset[str]) -> bool:
    """The setting's name (or label) heads a column of a chart: "Stitch" for ``stitch``."""
    words = {w for w in re.split(r"[\s_]+", f"{name} {var.label or ''}".casefold()) if w}
    return len(words) == 1 and bool(words & headings)


def _headings(manual: str) -> frozenset[str]:
    """One-word column headings that stand right after a "No." heading ("No.  Stitch  Use"):
    the thing a numbered chart lists."""
    found = re.findall(r"(?im)^\s*\|?\s*(?:No\.?|Nr\.?|#)\s*(?:\||\s{2,})\s*([A-Za-z]+)\b", manual)
    return frozenset(word.casefold() for word in found) | chart_titles(manual)


def _coded_variables(
    model: ApplianceModel, headed: frozenset[str] = frozenset()
) -> dict[str, dict[str, Any]]:
    """Discrete variables whose values are mostly codes, and unitless whole-number settings
    named for a programme (a menu the reader took for a number; not a count) or named by a
    chart's column heading (``headed``: "No. | Stitch" over the stitch numbers):
    name -> {normalised value: value}."""
    found: dict[str, dict[str, Any]] = {}
    for name, var in model.variables.items():
        if isinstance(var, NumericVariable):
            # a menu numbered 1-15 the reader took for a number: its numbers are codes
            numbers = all_values(var)
            whole = all(float(v) == int(float(v)) for v in numbers)
            named = _PROGRAMME.search(f"{name} {var.label or ''}") or _headed(name, var, headed)
            if var.unit or not whole or not 2 <= len(numbers) <= 99:
                continue
            prefix = _shown_prefix(var)
            if prefix:  # shown "M{value}": the chart lists M3, M18 …
                found[name] = {_key(f"{prefix}{int(float(v))}"): int(float(v)) for v in numbers}
            elif named:
                found[name] = {str(int(float(v))): int(float(v)) for v in numbers}
            continue
        if not isinstance(var, DiscreteVariable):
            continue
        values = [str(v) for v in all_values(var)]
        coded = [v for v in values if _CODE.fullmatch(v.strip())]
        if len(coded) >= 2 and len(coded) >= 0.6 * len(values):
            found[name] = {_key(v): v for v in values}
    return found


def _shown_prefix(var: NumericVariable) -> str:
    """The letters a display puts before a number it shows as a code ("M{value}" for melody
    18 shown M18), or "": such numbers are codes, named in the manual's chart by that code."""
    show = var.show if isinstance(var.show, str) else ""
    m = re.fullmatch(r"\s*([A-Za-z]{1,2})-?\{value\}\s*", show)
    return m[1] if m else ""


def _name(cell: str) -> str:
    """The name a cell gives: markup, brackets and what follows a dash or colon dropped."""
    if contents_cell(cell):
        return ""
    text = re.sub(r"[*_`]", "", cell)
    text = re.sub(r"\([^)]*\)|\[[^\]]*\]", " ", text)
    text = re.split(r"\s[–—-]\s|[:;,]", text)[0].strip()
    return text if 0 < len(text.split()) <= MAX_WORDS else ""


_BOX = str.maketrans({**dict.fromkeys("│┃║├┤┼┬┴╋╠╣╬", "|"), **dict.fromkeys("─━═┌┐└┘╔╗╚╝", "-")})
"""Box-drawing tables ("│ N1 │ Gentle rain │", "├───┼───┤") are pipe tables drawn finer."""


def _table_blocks(manual: str) -> list[list[list[str]]]:
    """Rows of cells of each pipe-drawn table (separator rows dropped), box-drawn ones too."""
    blocks: list[list[list[str]]] = []
    current: list[list[str]] = []
    for line in manual.translate(_BOX).splitlines():
        if line.count("|") >= 2:
            if not _RULE.match(line):
                current.append([c.strip() for c in line.strip().strip("|").split("|")])
            continue
        if current:
            blocks.append(current)
            current = []
    if current:
        blocks.append(current)
    return blocks


def _aligned_blocks(manual: str) -> list[list[list[str]]]:
    """Rows of cells of each table a PDF conversion drew with spaces: runs of lines whose
    columns are set apart by two or more spaces (" 5    Gluten-free     2:40"). A blank line
    or a line of prose ends a block."""
    blocks: list[list[list[str]]] = []
    current: list[list[str]] = []
    indent = 0  # the block's first line's
    for line in manual.splitlines():
        cells = [c.strip() for c in _GAP.split(line.strip())] if "|" not in line else []
        if len(cells) >= 2:
            indent = indent if current else _indent(line)
            current.append(cells)
            continue
        if current and line.strip() and _indent(line) >= indent + 4:
            continue  # a description's second line, indented under its column
        if len(current) >= 2:
            blocks.append(current)
        current = []
    if len(current) >= 2:
        blocks.append(current)
    return blocks


def _indent(line: str) -> int:
    return len(line) - len(line.lstrip())


def _spelled_out(cell: str) -> str:
    """The name a description cell opens with, before its colon ("heart rate control: the
    console keeps…"): a chart of codes whose short name is an abbreviation (HRC) spells it
    out where it says what the code does. Two to five words, else no name."""
    m = re.match(r"([A-Za-z][A-Za-z'-]*(?: [A-Za-z'-]+){1,4}):\s", cell)
    return m[1] if m else ""


def _setting_words(model: ApplianceModel) -> dict[str, frozenset[str]]:
    """Each setting's own words (its name's and its label's, stemmed): what a chart's column
    heading says when the column holds that setting ("Massage", "Bubbles", "Heating")."""
    out = {}
    for name, var in model.variables.items():
        text = f"{name} {getattr(var, 'label', '') or ''}"
        out[name] = frozenset(stem(w) for w in re.findall(r"[A-Za-z]{3,}", text))
    return out


def _heads(block: list[list[str]], settings: dict[str, frozenset[str]]) -> list[set[str]] | None:
    """The settings each column of a chart holds, by its heading row (the block's first row
    that is not a rule): a heading of one or two words that are a setting's own words names
    it. None when the first row names no setting (a chart without such headings)."""
    first = next((r for r in block if not all(_RULE.match(c) for c in r)), None)
    if first is None:
        return None
    heads = []
    for cell in first:
        words = {stem(w) for w in re.findall(r"[A-Za-z]{3,}", cell)}
        named = len(words) <= 2 and len(re.findall(r"\S+", cell)) <= 3
        heads.append({n for n, own in settings.items() if named and words and words <= own})
    return heads if any(heads) else None


def _in_column(
    row: list[str],
    i: int,
    heads: list[set[str]] | None,
    holds: dict[str, set[str]],
    plain: dict[str, set[str]],
) -> bool:
    """Whether cell ``i`` and the next of ``row`` may be a code and its name under the chart's
    headings: in a chart that gives one setting per column ("Purpose | Heating | Massage |
    Bubbles | Timer"), a cell is a value of ITS column's setting, so a code stands only under a
    heading of a setting that has it, and the next cell names it only when no other setting
    heads that column. ``holds``: setting -> the codes (keyed) it has; ``plain``: a listed
    setting -> its own values (keyed)."""
    if heads is None:
        return True
    if len(row) != len(heads) and not (i == 0 and 2 <= len(row) < len(heads)):
        return sum(1 for h in heads if h) < 2  # its cells' columns are not known
    # a row with cells run together further right ("2 Hz bursts 200 µs") keeps its first two
    # cells under the first two headings
    key = _key(row[i])
    # "Power" over "P1" where POWER is only on/off: the heading calls the coded level by
    # another word; the column is still the on/off setting's when the cell is one of its values
    code_heads = {n for n in heads[i] if holds.get(n) or key in plain.get(n, {key})}
    name_heads = heads[i + 1]
    if code_heads and not any(key in holds.get(n, set()) for n in code_heads):
        return False
    return not name_heads or any(key in holds.get(n, set()) for n in name_heads)


def _pairs(
    block: list[list[str]],
    variables: dict[str, dict[str, Any]],
    settings: dict[str, frozenset[str]] | None = None,
    plain: dict[str, set[str]] | None = None,
) -> list[list[Pair]]:
    """The (code, name) pairs a block can give: along its rows ("| 2 | French |"), and down
    its columns where a row of codes sits over a row of names ("Knob mark  1  2" over
    "Approx. RH  70 %  60 %"). ``settings`` (each setting's own words) lets a heading row
    keep a row's cells to their columns (see ``_in_column``)."""

    def code(cell: str) -> bool:
        if re.search(r"\d[.,]\d", cell):
            return False  # "2.5" mm is a measure, not code 25
        return bool(_CODE.fullmatch(cell)) or any(_key(cell) in v for v in variables.values())

    heads = _heads(block, settings) if settings else None
    holds = {name: set(values) for name, values in variables.items()}
    rows = [
        (r[i], r[i + 1])
        for r in block
        for i in range(len(r) - 1)
        if code(r[i]) and _in_column(r, i, heads, holds, plain or {})
    ]
    rows += [
        (r[i], said)
        for r in block
        for i in range(len(r) - 2)
        if code(r[i]) and not code(r[i + 1]) and (said := _spelled_out(r[i + 2]))
    ]
    columns = [
        (top[i], below[i])
        for top, below in pairwise(block)
        if len(top) == len(below) >= 3
        for i in range(len(top))
        if code(top[i]) and not code(below[i])
    ]
    return [p for p in (rows, columns) if p]


def _best(
    pairs: list[Pair], variables: dict[str, dict[str, Any]]
) -> tuple[str | None, tuple[float, float]]:
    """The setting whose values most of the pairs' codes are; then the one they cover most."""
    best, score = None, (0.0, 0.0)
    codes = {_key(code) for code, _ in pairs}
    for name, values in variables.items():
        hits = len(codes & set(values))
        fraction = (hits / max(len(codes), 1), hits / max(len(values), 1))
        if hits >= 2 and fraction > score:
            best, score = name, fraction
    return best, score


def _named(pairs: list[Pair], values: dict[str, Any], name: str) -> list[tuple[str, Any, str]]:
    out = []
    for code, cell in pairs:
        value = values.get(_key(code))
        label = _name(cell)
        if value is not None and label and _key(label) != _key(str(value)):
            out.append((name, value, label))
    return out


def coded_names(model: ApplianceModel, manual: str) -> list[tuple[str, Any, str]]:
    """(variable, value, name) for each coded value the manual names."""
    variables = _coded_variables(model, _headings(manual) if manual else frozenset())
    if not variables or not manual:
        return []
    settings = _setting_words(model)
    plain = {
        name: {_key(str(v)) for v in var.values or ()}
        for name, var in model.variables.items()
        if isinstance(var, DiscreteVariable)
    }
    out: list[tuple[str, Any, str]] = []
    for block in _table_blocks(manual):
        for pairs in _pairs(block, variables, settings, plain)[:1]:
            best, score = _best(pairs, variables)
            if best is not None and score[0] >= 0.6:
                out.extend(_named(pairs, variables[best], best))
    # tables drawn with spaces, for settings no pipe table named: a parts legend ("1  Lid") is
    # drawn the same way, so only a block that names most of the setting's values and fits it
    # best names it
    named = {name for name, _, _ in out}
    chosen: dict[str, tuple[tuple[float, float, int], list[Pair]]] = {}
    for block in _aligned_blocks(manual):
        for pairs in _pairs(block, variables, settings, plain):
            best, score = _best(pairs, variables)
            if best is None or best in named or score[0] < 0.6 or score[1] < 0.5:
                continue
            rank = (*score, -len(chosen))
            if best not in chosen or rank[:2] > chosen[best][0][:2]:
                chosen[best] = (rank, pairs)
    for name, (_, pairs) in chosen.items():
        out.extend(_named(pairs, variables[name], name))
    for code, text in _BOLD.findall(manual):
        homes = [n for n, values in variables.items() if _key(code) in values]
        label = _name(text)
        if len(homes) == 1 and label:
            out.append((homes[0], variables[homes[0]][_key(code)], label))
    named = {name for name, _, _ in out}
    unnamed = {name: values for name, values in variables.items() if name not in named}
    out += legend_line_names(unnamed, settings, manual)
    return list(dict.fromkeys(out))


_NOT_HEADS = frozenset(
    {"manual", "manuals", "instructions", "instruction", "guide", "handbook", "booklet", "use"}
    | {"operating", "owner", "owners", "user", "users", "care", "and", "for", "the", "with"}
)


_APPLIANCE_NOUNS = frozenset(
    {"machine", "washer", "dryer", "cooker", "multicooker", "oven", "microwave", "fryer", "kettle"}
    | {"urn", "dispenser", "boiler", "heater", "maker", "breadmaker", "toaster", "blender", "mixer"}
    | {"juicer", "grinder", "hob", "cooktop", "range", "stove", "griddle", "grill", "steamer"}
    | {"steriliser", "sterilizer", "purifier", "humidifier", "dehumidifier", "conditioner", "pot"}
    | {"cooler", "fan", "dishwasher", "brewer", "percolator", "warmer", "iron", "cleaner", "fridge"}
    | {"refrigerator", "freezer", "appliance", "unit", "device", "processor", "airfryer"}
)
"""Head nouns that name an appliance (a title's "Safety" or "Light" names none)."""

_NOT_AGENTS = frozenset(
    {"water", "power", "timer", "filter", "cover", "paper", "order", "number", "center", "centre"}
    | {"adapter", "adaptor", "controller", "monitor", "sensor", "indicator", "colour", "color"}
)

_SEGMENTS = re.compile(r"\s[-–—·|:]\s|[–—·|:,()]")
_TAIL = re.compile(r"\s(?:with|for|incl\w*|plus)\s.*", re.IGNORECASE)
_JOIN = re.compile(r"\s+and\s+|\s*&\s*", re.IGNORECASE)


def _words(text: str) -> list[str]:
    return [w for w in re.findall(r"[a-z]{3,}", text.casefold()) if w not in _NOT_HEADS]


def _head(segment: str) -> str | None:
    """A title part's head noun: its last word before "with" or "for". "And"/"&" join words of
    one name ("Bread & Pastry Maker": a maker), unless the word before already names an
    appliance ("Soup Urn & Warmer": an urn that also warms)."""
    name = _TAIL.sub("", segment)
    first = _words(_JOIN.split(name)[0])
    if _JOIN.search(name) and first and first[-1] in _APPLIANCE_NOUNS:
        return first[-1]
    words = _words(name)
    return words[-1] if words else None


def title_nouns(manual: str, known: frozenset[str]) -> set[str]:
    """What the manual's title calls the appliance ("Instant Hot Water Dispenser", "Digital Air
    Fryer with Viewing Window", "Bread & Pastry Maker"): the head noun (see ``_head``) of the
    first title part whose head names an appliance (a word of ``known``, the category's words, a
    common appliance noun, else a doer's "-er"/"-or" noun). A person says "switch the dispenser
    on" of an appliance the reader could not name. Titles are the opening headings of the top
    level (a section's "### Inner pot" is a part, not the appliance), or else the opening lines
    with a word of ``known``; "Important Safety Instructions" names none and a later title is
    taken."""
    lines = [line.strip() for line in manual.splitlines()[:40] if line.strip()][:12]
    headings = [line for line in lines if line.startswith("#")]
    top = min((len(h) - len(h.lstrip("#")) for h in headings), default=0)
    titles = [h.lstrip("#").strip() for h in headings if len(h) - len(h.lstrip("#")) == top]
    if not titles:
        titles = [
            line for line in lines if known & {w.casefold() for w in re.findall(r"[A-Za-z]+", line)}
        ]
    heads = [h for t in titles for part in _SEGMENTS.split(t) if (h := _head(part)) is not None]
    for head in heads:
        if head in known or head in _APPLIANCE_NOUNS:
            return {head}
    for head in heads:
        if re.search(r"(?:er|or)$", head) and head not in _NOT_AGENTS:
            return {head}
    return set()
