"""A key's lamps in one line of a panel drawing split by bars ("( ON/OFF ) | HEAT  COOL  WARM
HOT | SPEED | START"): the piece of the line that is the key's place on the panel.

Apart from the table readers because such a line is no table: it has no rule, no header and
often no bar at either end (a panel drawn in a code fence or in plain text), so the reader holds
it as a sentence. A drawing puts each key with the lamps printed beside it: a piece that starts
with the key's printed name and goes on with words in capitals only names what the key lights,
its settings in order; a piece of the key's name alone names nothing. Pieces are also read one
by one as a row of marks ("MODE | SOFT | CRISP | GRILL"), the key's piece first.
"""

from __future__ import annotations

import re

from apbot.read.labels import words
from apbot.read.table_transposed import key_row_marks

# a glyph drawn beside a lamp's word ("○ LOW", "● HIGH", "▲", "[", "]"): no word of its own
_GLYPH_RE = re.compile(r"^[^\w]+$")


def drawn_piece_marks(
    text: str, key_words: set[str], key_names: set[str], other_names: set[str]
) -> list[str] | None:
    """The key's marks from a line of a panel drawing split by two bars or more, or ``None``:
    a piece led by the key's printed name (``key_names``, its words joined by spaces) and
    followed by two words or more in capitals (amounts among them, "LOW  HIGH  2H  4H") that
    name no other key (``other_names``), or the pieces read as a row of marks
    (:func:`key_row_marks`)."""
    if text.count("|") < 2:
        return None
    pieces = [p.strip() for p in text.strip().strip("|").split("|")]
    if len(pieces) < 3:
        return None
    row = key_row_marks(tuple(pieces), key_words, (), False, key_names)
    if row:
        return row
    found = [marks for p in pieces if (marks := _piece_marks(p, key_names, other_names))]
    return found[0] if len(found) == 1 else None  # (two pieces of one key: no telling which)


def _piece_marks(piece: str, key_names: set[str], other_names: set[str]) -> list[str] | None:
    """The capital words after the key's printed name that leads ``piece``: spread by runs of
    two spaces or more when the drawing spaces them so (a lamp's name of two words stays one),
    else one word each."""
    for name in sorted(key_names, key=len, reverse=True):
        spelled = r"\W+".join(map(re.escape, name.split()))
        match = re.match(rf"\W*{spelled}(?![A-Za-z0-9])", piece, re.I)
        if not match:
            continue
        rest = piece[match.end() :].strip(" :-–")
        parts = re.split(r"\s{2,}", rest) if re.search(r"\s{2,}", rest) else rest.split()
        if any(re.fullmatch(r"[-–—~]|to|TO", p) for p in parts):
            return None  # "TIMER  0:00 – 9:59": a range drawn, not lamps
        marks = [p.strip(" ○●◯◉•·*") for p in parts if not _GLYPH_RE.match(p)]
        marks = [m for m in marks if m]
        if len(marks) < 2 or not all(_word_caps(m) for m in marks):
            return None
        if not any(re.fullmatch(r"[A-Z]{2,}(?: [A-Z]+)*", m) for m in marks):
            return None  # "DELAY  2H  4H": amounts only, a time's steps drawn, read elsewhere
        if any(" ".join(words(m)) in other_names | key_names for m in marks):
            return None  # "MODE  TIMER  START": the keys drawn side by side, no lamps
        return marks
    return None


def _word_caps(mark: str) -> bool:
    """A lamp's name as the panel prints it: no lower-case letter, three words at most, letters
    or an amount with its unit ("LOW", "KEEP WARM", "4H", "60°")."""
    return (
        mark.upper() == mark
        and bool(re.fullmatch(r"[A-Z0-9][A-Z0-9\-/.:°%]*(?: [A-Z0-9\-/.:°%]+){0,2}", mark))
        and sum(c.isalnum() for c in mark) >= 1
        and len(mark) <= 16
    )
