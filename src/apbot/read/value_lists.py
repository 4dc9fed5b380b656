"""Lists of values in manual prose, tables and panel drawings.

"AUTO → CONTINUOUS → LAUNDRY", "switch between HIGH and LOW", "3, 6 or 9 hours", "marked 20 30
40 60 90", "50, 55 ... 95, 100": the shapes manuals use to name a setting's values one by one.
Apart from values.py (ranges and steps) because lists are a job of their own: each finder
returns the items it read and nothing it did not (None).
"""

from __future__ import annotations

import re

from apbot.read.bracket_lists import bracket_opens, letter_run, wrapped_run
from apbot.read.value_gaps import elision_apart, filled_amounts, filled_codes, unit_tail
from apbot.read.value_items import _LEAD_COLON, _PER_NAME, _clean_item, _dedupe, _value_like
from apbot.read.value_list_shapes import (
    _ARROW,
    _BOTH_WAYS,
    _FUSED_ARROW,
    _SPACED_ARROW,
    _after_case_label,
    _arrow_cell,
    _dotted_run,
    _nothing_as_zero,
    _range_table_header,
    _shared_noun_dropped,
    _triangle_arrows,
    _two_named,
)
from apbot.read.value_runs_back import counted_figures, drawn_sign
from apbot.read.values import NUM, UNIT

_CUE = re.compile(  # a lookahead, so that every cue in a sentence is tried
    r"(?=(?:\bbetween|\bamong|\bchoose(?: from)?|\bselect(?:s| from)?|\bcycles?(?: through)?|"
    r"\boptions?(?: are)?|\bsettings?(?: are)?|\blevels?(?: are)?|\bmodes?(?: are)?|\border|"
    r"\bpositions?(?: are)?|\bpick|\bsteps? through|\bchanges?|:)\s+(.*))",
    re.IGNORECASE,
)


_NUMBER_LIST = re.compile(
    r"(?<![\w.])(\d+(?:[.,]\d+)?(?:\s*,\s*\d+(?:[.,]\d+)?)*)\s*,?\s*(?:or|and)\s*"
    r"(\d+(?:[.,]\d+)?)\s*([A-Za-z%°]{1,8})?(?!\w)",
)


def find_list(text: str) -> tuple[list[str], str] | None:
    """A list of values in one sentence, and how it was written ("arrows", "list")."""
    letters = letter_run(text)  # "A → B → … → F → A": the letters, "A" no article here
    if letters:
        return letters, "arrows"
    text = _arrow_cell(_triangle_arrows(text))
    # "FWD ►  ↔  ◄ REV": each name's own sign, drawn pointing at the two-way arrow between them
    text = re.sub(r"[►▶]\s*((?:<->|<=>|↔|⇄|⇔))\s*[◄◀]", r"\1", text)
    both = bool(_BOTH_WAYS.search(text))
    text = _BOTH_WAYS.sub(" → ", text)
    if _SPACED_ARROW.search(text):  # "OPEN → →IN IN ONLY → OUT→ OUT ONLY": the spaced arrows
        text = _FUSED_ARROW.sub(" ", text)  # part the list, one fused to a word is a symbol
    wrapped = wrapped_run(text)  # "1, 2, 3, 4, 5, and after 5 back to 1": the run, once
    if wrapped:
        return wrapped, "list"
    numbers = _NUMBER_LIST.search(text)
    if numbers:  # "3, 6 or 9 hours"
        items = [*re.split(r"\s*,\s*", numbers.group(1)), numbers.group(2)]
        unit = numbers.group(3) or ""
        known = bool(unit) and bool(re.fullmatch(UNIT, unit, re.IGNORECASE))
        if len(items) >= 3:
            return [f"{i} {unit}" if known else i for i in items], "list"
    parts = [_clean_item(p) for p in _ARROW.split(text)]
    parts = [q for p in parts for q in elision_apart(p)]  # "4 h … → 12 h": "4 h", "…"
    for k, part in enumerate(parts[1:-1], start=1):  # "regular → … → regular … SUSHI regular
        came_round = re.match(r"([a-z][\w ]*?)\s*(?:…|\.\.\.)\s*[A-Z][A-Z,& ]*\s[a-z]", part)
        if came_round and parts[0].lower().endswith(came_round.group(1).lower()):
            parts = parts[: k + 1]  # → …": back at its start, then the next order
            break
    if (
        len(parts) >= 3 or both
    ):  # "… → HIGH, and from HIGH the next press …": the list ends at the comma
        last = re.split(
            r"[,;]\s|\s[—–]\s|(?:^|\s+)(?:and\s+)?(?:then|back|again)\b|\.\s|\s*[()]|\s*(?:…|\.\.\.)"
            # "LOW → HIGH from left to right", "… clockwise": the direction, no value
            r"|\s+(?:from\s+(?:left|right)|(?:anti|counter-?)?clockwise)\b",
            parts[-1],
        )[0]  # "… → P1. The display …", "FIRM → SOFT … (not every …)": nor at a sentence's end
        parts[-1] = _clean_item(last)
        parts = filled_amounts(filled_codes(parts))
    if len(parts) == 2 and not both and (pair := _two_named(parts)):
        return pair, "arrows"
    amount = re.search(rf"(?<![\w.])({NUM}\s*{UNIT})\s*$", parts[0], re.I)
    if len(parts) >= 3 or both or (len(parts) == 2 and all(_value_like(p, True) for p in parts)):
        # "in this order: AUTO → ...", "Clockwise: Cotton"; a clock's colon ("0:30 → 1:00") stays
        head = _LEAD_COLON.split(parts[0])[-1].split()
        opened = bracket_opens(head)  # "press MODE (SPOT → FLOOD → …)": the list opens there
        if head and head[-1].startswith("(") and len(head[-1]) > 1:
            head[-1] = head[-1][1:]  # "… the next programme code (P0 → P1 → …)": in brackets
        # "COLOUR 3000K → 4500K → 6500K": a figure with its unit before the first arrow, where
        # every other item is one too, is the list's first item, not a key's name
        figure_first = bool(head) and all(
            re.fullmatch(rf"{NUM}[a-z°%]{{1,3}}", w, re.IGNORECASE)
            for w in [head[-1], *(p.split()[0] for p in parts[1:] if p)]
        )
        capital = [w for w in head if w.upper() == w and any(c.isalpha() for c in w)]
        if figure_first and (len(capital) >= 2 or head[-1] not in capital):
            capital = [head[-1]]  # (two capitals: which key's is unsure; "DOSES … 1x → 2x":
            # a figure in lower case is no capital, but it is the first item all the same)
        trailing: list[str] = []  # "Tap FAN to step through AUTO →": the run before the arrow
        for w in reversed(head):
            if w.upper() != w or not any(c.isalpha() for c in w):
                break
            trailing.insert(0, w)
        if trailing and len(trailing) < len(capital):
            capital = trailing
        capital = _after_case_label(head, parts[1:]) or capital
        if opened and capital[-len(opened) :] == opened and len(capital) > len(opened):
            capital = opened  # the key's name before the bracket is no part of the first item
        if (
            (  # "HDMI 1 → HDMI 2 → …": the first item's figure, as the others carry theirs
                len(head) >= 2
                and head[-1].isdigit()
                and capital[-1:] == [head[-2]]
                and any(p.split()[:1] == [head[-2]] for p in parts[1:])
            )
            or (  # "1 TONE → 2 TONE → …": the figure before the first item's word, as in the others
                len(head) >= 2
                and head[-2].isdigit()
                and capital[-1:] == [head[-1]]
                and len(head[-1]) >= 3  # ("5 A → 10 A": an amount in amperes, no word)
                and not re.fullmatch(UNIT, head[-1], re.IGNORECASE)
                and all(re.fullmatch(rf"\d+ {re.escape(head[-1])}", p) for p in parts[1:] if p)
            )
        ):
            capital = [head[-2], head[-1]]
        parts[0] = _clean_item(" ".join(capital) or " ".join(head[-2:]) or parts[0])
        if len(head) > 3 and not capital:
            parts[0] = _clean_item(head[-1])
        if not capital and not _value_like(parts[0], False):
            # "mist level 1 → 2 → 3", "night light off → dim": as many words as the others
            size = max(len(p.split()) for p in parts[1:] if p) if any(parts[1:]) else 1
            parts[0] = _clean_item(" ".join(head[-size:]))
        # "BOTH → LOWER only → UPPER only": which one alone, the value is its name
        parts = [re.sub(r"(?<=\S)\s+only$", "", p) for p in parts]
        if amount and (len(parts) >= 3 or both):  # "… 1.0 LB → 1.5 LB": the amount first
            parts[0] = amount.group(1)
        # "… → OFF → …": no item; "… → ⊣⊢ → …": a sign printed on the panel, an item
        items = [p for p in parts if p and (re.search(r"\w", p) or drawn_sign(p))]
        if items and items[0] in items[1:]:
            items = items[: items.index(items[0], 1)]  # "OFF → 2H → 4H → OFF": the cycle, once
        items = _nothing_as_zero(items)
        if all(_value_like(p, False) for p in unit_tail(items)) and len(items) >= 2:
            return _dedupe(items), "arrows"
        signs = [p for p in items if not _value_like(p, False)]
        if (
            len(items) >= 4
            and signs
            and len(signs) * 3 <= len(items)
            and all(map(drawn_sign, signs))
        ):
            return _dedupe(items), "arrows"  # "OFF > V~ > Ω·)))▶| > ⊣⊢ > TEMP": signs on a dial
        figures = counted_figures(items)  # "1/6 stop > 1/3 stop > 1 stop": the figures
        if figures:
            return figures, "arrows"
    for m in _CUE.finditer(text):
        segment = re.split(r"[.;]\s|\s[—–]\s|\bwhile\b|\bwhen\b|\bto (?!\d)", m.group(1))[0]
        # "between STANDARD and QUIET (lamp; display FAN quiet …)": the aside ends the list
        segment = re.split(r"\s\((?=[^)]*\b(?:display|lamp|shows?|see)\b)", segment)[0]
        if _title_pair(_pair_before_aside(segment)):  # "Gentle or Strong (Gentle at first)"
            segment = segment.split(" (", 1)[0]
        segment = re.sub(r"\s+only\W*$", "", segment, flags=re.I)  # "SOFT or FIRM only."
        items = [
            _clean_item(p)
            for p in re.split(r",\s*|\s*/\s*|\s*[·•|]\s*|\s{2,}|\s+or\s+|\s+and\s+", segment)
        ]
        items = _shared_noun_dropped([i for i in items if i])
        if re.search(r"\sor\s", segment):
            items = _pair_noun_dropped(items)
        if _range_table_header(items):
            continue
        caps = sum(1 for i in items if i.upper() == i and any(c.isalpha() for c in i))
        if len(items) >= 2 and all(_value_like(i, caps >= 2) for i in items):
            lower_ok = len(items) >= 3 and all(len(i.split()) <= 2 for i in items)
            numeric = all(re.fullmatch(rf"{NUM}\s*{UNIT}?", i, re.I) for i in items)
            between = text[m.start() :].lower().startswith("between")
            either = between or bool(re.search(r"\sor\s", segment))
            if caps >= 2 or numeric or lower_ok or (either and _title_pair(items)):
                return _dedupe(items), "list"
        if caps >= 3:  # names in capitals, then the prose that describes the first one
            head = []
            for item in items:
                if not _value_like(item, True):
                    break
                head.append(item)
            if len(head) >= 3:
                return _dedupe(head), "list"
    dotted = _dotted_run(text)  # the last resort: a dotted run inside a flattened sentence
    return (dotted, "list") if dotted else None


def _title_pair(items: list[str]) -> bool:
    """Two names each capitalised in mid-sentence after a cue ("choose Gentle or Strong"): a
    manual capitalises a setting's value names as it prints them, plain prose it does not. The
    caller asks for a choice ("X or Y", "between X and Y"): "Select Date and Time" names two
    menu entries to open, not two values of one setting."""
    return len(items) == 2 and all(
        i.upper() != i and all(w[:1].isupper() for w in i.split()) and len(i.split()) <= 2
        for i in items
    )


def _pair_noun_dropped(items: list[str]) -> list[str]:
    """Two Title-case names and a plain noun said once after the second ("Coarse or Fine
    mesh", "Eco or Turbo mode"): the noun belongs to both, the names are the values."""
    if len(items) != 2 or len(items[0].split()) != 1 or len(items[1].split()) != 2:
        return items
    name, noun = items[1].split()
    if re.fullmatch(r"[a-z]{3,}", noun) and _title_pair([items[0], name]):
        return [items[0], name]
    return items


def _pair_before_aside(segment: str) -> list[str]:
    """The two items "X or Y" / "X and Y" said right before an aside in brackets."""
    head = segment.split(" (", 1)[0] if " (" in segment else ""
    return [_clean_item(p) for p in re.split(r"\s+(?:or|and)\s+", head)] if head else []


_CAPS_ITEM = r"[A-Z][A-Z0-9+-]*(?: [A-Z0-9+-]+){0,2}"
_CAPS_RUN = re.compile(
    rf"(?<![\w/])({_CAPS_ITEM}(?:\s*(?:,|/|·|\s[–—]\s)\s*{_CAPS_ITEM})*\s*(?:,\s*)?"
    rf"(?:or|and|,|/|[–—])\s*{_CAPS_ITEM})(?![\w/])"
)
_QTY = r"\d+(?:[.,]\d+)?\s*(?:[a-zA-Z%°]{1,4}\b|%|°[CF])?"
_QTY_RUN = re.compile(rf"(?<![\w.])({_QTY}(?:\s*,\s*{_QTY})+\s*,?\s*(?:or|and)\s+{_QTY})")


def quantity_run(text: str) -> list[str] | None:
    """Three or more amounts in a row in a key's own sentence ("750 g, 1000 g or 1250 g")."""
    m = _QTY_RUN.search(text)
    if not m:
        return None
    items = [i.strip() for i in re.split(r"\s*,\s*(?:or\s+|and\s+)?|\s+(?:or|and)\s+", m.group(1))]
    items = [i for i in items if i]
    return _dedupe(items) if len(items) >= 3 else None


def caps_run(text: str, exclude: set[str]) -> list[str] | None:
    """Three or more names in capitals written in a row in a key's own sentence ("COLOUR –
    crust colour, LIGHT, MEDIUM or DARK"), the key's own names excluded."""
    for m in _CAPS_RUN.finditer(text):
        items = [i.strip() for i in re.split(r"\s*(?:,|/|·|[–—])\s*|\s+(?:or|and)\s+", m.group(1))]
        items = [i for i in items if i and i.upper() not in exclude]
        if len(items) >= 3 and all(len(i) <= 16 for i in items):
            return _dedupe(items)
    return None


def bare_list(text: str) -> list[str] | None:
    """A line that is nothing but a list ("OFF · 1 · 2 · 3 · CONT", "WARM   BAKE   TOAST"), as
    printed round a knob or under a key after a sentence ending in a colon. An aside in
    brackets is no item ("BUZZ (🔔 bell icon)": its spaces and slashes split nothing)."""
    text = re.sub(r"\s*\([^()]*\)", "", text)
    items = [
        _clean_item(p)
        for p in re.split(r"\s*[·•|,]\s*|\s*/\s*|\s{2,}|\s+or\s+|\s*[→>]\s*", text.strip())
    ]
    items = [re.sub(r"\s*(?:…|\.\.\.)$", "", i) for i in items]  # "… → OFF …": and so on
    # a lone dash between wide-spaced marks ("100 W  –  DEFROST") or an icon's remains ("+")
    # is a separator, never a mark
    items = _uncounted([i for i in items if re.search(r"[^\W_]", i)])
    if len(items) < 3 or len(items) > 16:
        return None
    if all(len(i) <= 20 and len(i.split()) <= 3 and not i.endswith(":") for i in items):
        return _dedupe(items)
    return None


_COUNTED_ITEM_RE = re.compile(r"(.*?\D)\s+(\d{1,2})")


def _uncounted(items: list[str]) -> list[str]:
    """Names each followed by how many presses or clicks reach it, counting up from 0 or 1
    ("AUTO 0 | STER+DRY 1 | STER 2", "WARM 0 · BAKE 1 · CONV BAKE 2"): the names alone. The
    counts must run on one by one, so "P 1 · P 2" style codes are left as they are."""
    found = [_COUNTED_ITEM_RE.fullmatch(i) for i in items]
    if len(items) < 3 or not all(found):
        return items
    counts = [int(m.group(2)) for m in found if m]
    if counts[0] not in (0, 1) or counts != list(range(counts[0], counts[0] + len(counts))):
        return items
    names = [m.group(1).strip() for m in found if m]
    return names if len({n.lower() for n in names}) == len(names) else items


# "3/4", "16:9", "1/2": one value written as a ratio of two counts (a slash with no space)
_RATIO_RE = re.compile(r"\+?\s*\d{1,2}/\d{1,2}")


def cell_list(text: str) -> list[str] | None:
    """A table cell that is nothing but a list of values ("22, 26, 30 … 58 L", "Low, Medium
    and High", "400 / 800 / 1200 rpm"): three to sixteen short items, no sentence."""
    items = [
        _clean_item(p)
        for p in re.split(r"\s*[·•,;/]\s*(?:(?:and|or)\s+)?|\s+(?:and|or)\s+", text.strip())
    ]
    items = [i for i in items if i]
    ratios = [r.strip() for r in re.split(r"\s*[·•,;]\s*|\s+(?:and|or)\s+", text.strip())]
    if len(ratios) >= 2 and all(_RATIO_RE.fullmatch(r) for r in ratios if r):
        items = [r for r in ratios if r]  # "2/4, 3/4, 6/8": time signatures, not eight numbers
    if not 3 <= len(items) <= 16 or len(text) > 160 or re.search(r"[.:!?]\s*$|:\s", text):
        return None  # a sentence describing the key, not a cell of values
    if all(len(i) <= 20 and len(i.split()) <= 2 for i in items):
        return _dedupe(items)
    return None


def anchored_lists(text: str, word: str) -> list[list[str]]:
    """Lists tied to a setting's word: "loaf weight (500 / 750 / 1000)", "a light, medium or
    dark crust"."""
    out: list[list[str]] = []
    if word.lower() not in text.lower():
        return out
    w = re.escape(word)
    for m in re.finditer(rf"\b{w}\w*(?:\s+\w+){{0,2}}\s*\(([^()]{{3,80}})\)", text, re.I):
        if _ASIDE_PAREN_RE.match(m.group(1)):
            continue  # "choose the menu (and texture, if needed)": an aside, not the values
        items = [_clean_item(i) for i in re.split(r"\s*/\s*|,\s*|\s+or\s+", m.group(1))]
        if len(items) >= 2 and all(
            i and len(i) <= 16 and len(i.split()) <= 2 and not _PER_NAME.search(i) for i in items
        ):
            out.append(items)
    pattern = (
        r"\b(?:choose|select|set|pick)\s+(?:an?\s+|the\s+)?"
        rf"((?:[\w-]+,\s*)+[\w-]+\s+or\s+[\w-]+)\s+{w}"
    )
    for m in re.finditer(pattern, text, re.I):
        items = [_clean_item(i) for i in re.split(r",\s*|\s+or\s+", m.group(1))]
        if len(items) >= 2:
            out.append(items)
    found = named_list(text, word)
    if found:
        out.append(found)
    return out


def named_list(text: str, word: str) -> list[str] | None:
    """A sentence that is the setting's list of names: "The menu names printed on the lid: WHITE
    · BROWN · PORRIDGE". Unlike a passing "(for the menus (WHITE, BROWN))", the whole sentence
    is about that setting, so it says nothing about the key next to it."""
    w = re.escape(word)
    named = re.search(rf"\b{w}\w*\s+{_NAMES_NOUN}\b[^:.;]{{0,60}}:\s*(.+)$", text, re.I)
    return bare_list(named.group(1)) if named else None


_ASIDE_PAREN_RE = re.compile(r"\s*(?:and|or|also|plus|e\.g\.|i\.e\.|see|if)\b", re.I)
"""A parenthesis that adds a step, an example or a reference, not the setting's values."""
_NAMES_NOUN = r"(?:names|settings|options|choices|positions)"
