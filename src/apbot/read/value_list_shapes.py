"""The shapes ``value_lists.find_list`` reads a list in beyond plain prose: arrows typed or drawn
(both ways, fused to a word, a key's triangle), dotted runs, two named values, a range table's
header, a case label, and a leading word for none.

Apart from ``value_lists`` because each is a small test on one sentence or cell that
``find_list`` only calls; the finders themselves stay there.
"""

from __future__ import annotations

import re

from apbot.read.value_items import _LEAD_COLON, _clean_item, _dedupe, _value_like
from apbot.read.values import UNIT

# an arrow, typed or drawn with a line before its head ("0 ──► 15 ──► 30 min", "--►" once box
# characters are cleaned); a head alone ("touch ►") is a key
# (also with the key that makes the step written on its line, as a state chart draws it:
# "MAN ──MODE──► TIMER")
_ARROW = re.compile(  # ("40° › 55°": a single guillemet)
    r"\s*(?:[─━—–-]+\s*[A-Z][A-Z0-9+]{0,11}\s*[─━—–-]+\s*►|→|->|⇒|>|»|›|⟶|[─━—–-]+\s*►)\s*"
)


# "Touch: DRY <-> MOIST", "75 ◄► 80 ◄► 100": a key that flips between two values, or a pair
# stepping one list both ways
_BOTH_WAYS = re.compile(r"\s*(?:<->|<=>|↔|⇄|⇔|◄[-─—]*►|◀[-─—]*▶)\s*")


# an arrow with a space on both sides parts a list; one fused to a word ("→IN", "OUT→") is
# a symbol printed on the display beside the value's name
_SPACED_ARROW = re.compile(r"(?:^|\s)(?:→|->)\s")


_FUSED_ARROW = re.compile(r"(?<!\S)(?:(?:→|->)[A-Za-z]+|[A-Za-z]+(?:→|->))(?!\S)")


def _nothing_as_zero(items: list[str]) -> list[str]:
    """A list of durations led by a word for none ("no timer → 2H → 4H", "OFF, 1 h, 2 h"): the
    first is zero of their unit."""
    rest = [
        re.fullmatch(r"(\d+(?:[.,]\d+)?)\s*(h|hr|hrs|hours?|min|mins|minutes?)", i.strip(), re.I)
        for i in items[1:]
    ]
    if len(items) < 3 or not all(rest):
        return items
    if not re.fullmatch(r"(?:no\b.{0,12}|none|off|-+|–|—)", items[0].strip(), re.I):
        return items
    unit = rest[0].group(2) if rest[0] else "h"
    return [f"0 {unit}"] + [f"{m.group(1)} {m.group(2)}" for m in rest if m]


def _range_table_header(items: list[str]) -> bool:
    """ "Timer settings: Range Step 0.5 – 4 h …": the head of a table of ranges and their
    steps, not a list of named values."""
    said = {i.lower() for i in items}
    return "range" in said and bool(said & {"step", "steps", "increment", "increments"})


_LOWER_WORD = re.compile(r"[a-z][a-z'-]*")


def _after_case_label(head: list[str], rest: list[str]) -> list[str]:
    """The first item of an arrow list in lower case led by a setting's name in capitals
    ("WHITE  regular → softer → harder": the order on WHITE): the lower-case words before the
    first arrow, as many as the other items have; [] when the list is not written so."""
    rest = [p for p in rest if p]
    if not rest or any(re.search(r"[A-Z]", p) for p in rest):
        return []
    if not any(w.isupper() and any(c.isalpha() for c in w) for w in head):
        return []
    size = max(len(p.split()) for p in rest)
    run: list[str] = []
    for word in reversed(head):
        if len(run) >= size or not _LOWER_WORD.fullmatch(word):
            break
        run.insert(0, word)
    return run


_TRIANGLE_RUN = re.compile(r"(?:[\w+]{1,12}[ \t]*[►▶][ \t]*){2,}[\w+]{1,12}")


def _triangle_arrows(text: str) -> str:
    """A run of names joined by the next key's triangle that comes back round ("P1 ► P2 ►
    P1"): the order the key steps, as arrows; a menu path never comes round ("MENU ▶ Clock ▶
    Format"), one triangle stays the key. The run ends the list (then "P1 ◄ P6 ◄ …")."""
    for run in _TRIANGLE_RUN.finditer(text):
        names = re.split(r"[ \t]*[►▶][ \t]*", run.group(0))
        if names[0].casefold() == names[-1].casefold():
            return text[: run.start()] + re.sub(r"[►▶]", "→", run.group(0))
    return text


def _arrow_cell(text: str) -> str:
    """A table row's one cell holding a run of arrows ("TIMER | off → 1H → 2H → off | with
    MODE, 3 s: lock"): the list lies inside that cell, not across the row."""
    cells = text.split(" | ")
    arrowed = [c for c in cells if len(_ARROW.split(c)) >= 3]
    if not arrowed:  # ("FOAM | Tap: THIN › THICK | (starts THICK)": two names, one arrow)
        arrowed = [c for c in cells if len(_ARROW.split(c)) == 2]
    return arrowed[0] if len(cells) > 1 and len(arrowed) == 1 else text


def _shared_noun_dropped(items: list[str]) -> list[str]:
    """Names in capitals each followed by the same noun ("between the BODY zone and the FEET
    zone", "the LEFT burner or the RIGHT burner"): the names alone are the values."""
    found = [re.fullmatch(r"(?:the\s+)?([A-Z][A-Z0-9-]*)\s+([a-z]{3,})", i) for i in items]
    if len(items) < 2 or not all(found):
        return items
    nouns = {m.group(2) for m in found if m}
    return [m.group(1) for m in found if m] if len(nouns) == 1 else items


_CAPS_WORD = re.compile(r"[A-Z][A-Z0-9.+-]*")


def _two_named(parts: list[str]) -> list[str] | None:
    """Two display words joined by one arrow ("Tap: THIN › THICK (starts THICK)"): the capital
    run right before the arrow and the one right after it, up to an aside or a new clause. Two
    names alone, in capitals, as a short key cycles between them; lower-case words on either
    side are prose ("from here → see page 4")."""
    head = _LEAD_COLON.split(parts[0])[-1].split()
    first: list[str] = []
    for w in reversed(head):
        if not _CAPS_WORD.fullmatch(w):
            break
        first.insert(0, w)
    tail = re.split(r"[,;]\s|\s[—–]\s|\.\s|\s*[()]|\s{2,}|\s*(?:…|\.\.\.)", parts[1].strip())[0]
    last = tail.split()
    if not (1 <= len(first) <= 2 and 1 <= len(last) <= 2):
        return None
    if not all(_CAPS_WORD.fullmatch(w) for w in last) or first == last:
        return None
    if len(head) > len(first) and head[-len(first) - 1].upper() in ("PRESS", "TOUCH", "THEN"):
        return None
    return [" ".join(first), " ".join(last).rstrip(".")]


_QUANTITY = re.compile(rf"\d\s*{UNIT}\b", re.IGNORECASE)


def _dotted_run(text: str) -> list[str] | None:
    """Names run together with middle dots inside a longer sentence, as text flattened from a
    PDF prints a knob's positions ("… starting from OFF: OFF · Cottons · Eco Cottons · … ·
    Spin/Drain Programme Default temp."): the first and last names are cut to the length most
    of the names have."""
    parts = re.split(r"\s*[·•]\s*", text)
    if len(parts) < 5 or ":" not in parts[0]:
        return None  # a list a colon introduces, not a legend or a row of figures
    middle = [_clean_item(p) for p in parts[1:-1]]
    names = all(
        _value_like(p, False) and re.match(r"[A-Za-z]", p) and not _QUANTITY.search(p)
        for p in middle
    )
    if not names:
        return None
    counts = [len(p.split()) for p in middle]
    k = max(set(counts), key=lambda c: (counts.count(c), -c))
    first = _clean_item(" ".join(_LEAD_COLON.split(parts[0])[-1].split()[-k:]))
    last = _clean_item(" ".join(parts[-1].split()[:k]))
    items = [i for i in [first, *middle, last] if i]
    return _dedupe(items)
