"""How an order is worded around what it asks: request lead-ins and typographic apostrophes.

Phones and word processors type "o’clock" and "don’t" with a typographic apostrophe; the
parser's words are spelled with the plain one, so every apostrophe-like mark becomes "'".

People rarely speak in bare imperatives to a helper: "Could you heat the water to 80", "Can you
please start the rice", "I'd like you to bake a loaf", "Go ahead and dry the towels", "Hey,
can you boil the kettle?". The order inside is what the parser reads — its verb starts the
appliance, as "Heat the water to 80" does — so the lead-in is cut from the start of each
sentence, leaving the verb first. Only whole lead-ins at a sentence's
start are cut: "if you can" or "please" later in a sentence is left to the other readers.

"An extra hour of drying", "another ten minutes": a word of adding put between the article and
the unit it counts; the number readers take "an hour", so the word goes after the quantity
("an hour of extra drying", "ten minutes more"), where it still names an EXTRA setting.
"""

from __future__ import annotations

import re

_OPENER = r"(?:(?:hey|hi|ok|okay|right|so|now|alright)\b[,!]?\s+)?"
_ASK = (
    r"(?:(?:could|can|would|will)\s+you\s+(?:please\s+|kindly\s+|just\s+)?"
    r"|(?:i'?d|i\s+would|i\s+want|i\s+need)\s+(?:you\s+to|like\s+you\s+to)\s+"
    r"|(?:please|kindly)\s+(?:could\s+you\s+|can\s+you\s+)?"
    r"|go\s+ahead\s+and\s+)"
)
_LEAD_IN = re.compile(rf"(?:^|(?<=[.!?;]\s))\s*{_OPENER}{_ASK}", re.IGNORECASE)


_APOSTROPHES = str.maketrans({"\u2019": "'", "\u2018": "'", "\u02bc": "'", "\u00b4": "'", "`": "'"})


_TIME_UNITS = r"(?:hours?|minutes?|mins?|seconds?|secs?|days?|weeks?|nights?)"
_ADDED_OF = re.compile(
    rf"\b(an?|one)\s+(extra|additional|added)\s+({_TIME_UNITS})\s+of\s+", re.IGNORECASE
)
_ADDED = re.compile(rf"\b(an?|one)\s+(extra|additional|added)\s+({_TIME_UNITS})\b", re.IGNORECASE)


def added_time(instruction: str) -> str:
    """ "an extra hour of drying" read as "an hour of extra drying", "an additional day" as
    "a day additional": the quantity said whole, its word of adding kept after it."""
    instruction = _ADDED_OF.sub(r"\1 \3 of \2 ", instruction)
    return _ADDED.sub(r"\1 \3 \2", instruction)


def plain_order(instruction: str) -> str:
    """``instruction`` with plain apostrophes and each sentence's request lead-in cut (the
    question mark that closed the request now ends an order)."""
    instruction = added_time(instruction.translate(_APOSTROPHES))
    out = _LEAD_IN.sub("", instruction)
    if out == instruction:
        return instruction
    return re.sub(r"\?(\s|$)", r".\1", out)
