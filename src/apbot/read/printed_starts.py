"""A key the manual prints as "START/STOP CLOCK" while its action names only the clock
(``press_clock``): the key starts and stops the run, not a setting called clock.

Consoles and timers print the start key with what it starts ("START/STOP CLOCK", "START / STOP
TIMER", "RUN/STOP MOTOR"); the action keeps only the noun. Read by its name alone, the key
became a setting of two values, "start" and "stop clock".
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.labels import words

_PAIR = r"(?:START|RUN)\s*/\s*(?:STOP|PAUSE)"


def printed_start_stop(b: Builder, token: str) -> bool:
    """Whether a line of the manual prints the key's name right after a START/STOP pair, in
    capitals."""
    if token not in b.labels or not b.labels[token].text.strip():
        return False
    if any(_own_pair(b, i.token) for i in b.infos if i.token != token):
        return False  # (the panel's own START/STOP key, then the next key's name: review31)
    name = re.escape(b.labels[token].text.strip().upper())
    printed = re.compile(rf"(?<![\w/]){_PAIR} {name}(?![\w/])")
    # (one printed line, one space: a table's cells joined run "START/STOP  MODE" together)
    return any(printed.search(line) for line in b.manual.lines)


def _own_pair(b: Builder, token: str) -> bool:
    """Whether a key is itself named START/STOP (``press_start_stop``, a label "START/STOP")."""
    said = set(words(token)) | (set(words(b.labels[token].text)) if token in b.labels else set())
    return bool(said & {"start", "run"}) and bool(said & {"stop", "pause"})
