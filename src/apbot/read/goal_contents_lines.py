"""A contents line is no name: "4  Installation ........ 3" pairs a chapter with its page.

A manual's table of contents looks like a code chart (a number, a name), so a chapter title
("Installation", "Charging", "Setting up") would name a coded setting's value. A cell whose
name runs into a dot leader, or that is only a rule of line-drawing characters, names nothing.
"""

from __future__ import annotations

import re

_LEADER = re.compile(r"\.{4,}|(?:\. ){3,}|…{2,}")
_RULE = re.compile(r"^[\s\-–—─━═_=.·]*$")


def contents_cell(cell: str) -> bool:
    """Whether ``cell`` is a contents entry (a dot leader) or a drawn rule, not a name."""
    return bool(_LEADER.search(cell) or _RULE.match(cell))
