"""A line of factory values is no key's list of values.

"As delivered: VOL 3, LO 16 °C, HI 24 °C, sensitivity MID" gives the starting value of several
settings at once, each led by its own sign or word; read as the list of the key it stands near,
it made a key that opens one of those settings (TEMP: "1. Press TEMP. 2. Press ▲ / ▼ …") a
choice among the other settings' starts, and the setting it opens was lost. A list led by a
factory cue ("As delivered:", "Factory settings:", "Out of the box:") whose items each name an
amount is such a line.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder

# the cue, then a colon, then the list
_FACTORY_RE = re.compile(
    r"\b(?:as delivered|on delivery|out of the box|factory (?:settings?|state|values?|defaults?)"
    r"|default (?:settings?|values?))\s*(?:are|is)?\s*:\s*(?P<list>[^.]+)",
    re.I,
)


def factory_list(b: Builder, values_at: int | None) -> bool:
    """The values were read from a line of factory values of several settings: two items or
    more after the cue, each with a figure (VOL 3, LO 16 °C)."""
    if values_at is None:
        return False
    m = _FACTORY_RE.search(b.manual.units[values_at].text)
    if m is None:
        return False
    items = [i for i in re.split(r",|;", m.group("list")) if i.strip()]
    return sum(bool(re.search(r"\d", i)) for i in items) >= 2
