"""The set29a rules, run in this order after the walks: each gives a key still read as a guess
the job its manual states (see the modules' own docstrings)."""

from __future__ import annotations

from apbot.read.build import Builder
from apbot.read.held_changes import read_held_changes
from apbot.read.held_sections import read_held_sections
from apbot.read.legend_nouns import read_legend_nouns
from apbot.read.opposite_keys import read_opposite_keys


def read_section_keys(b: Builder) -> None:
    """Holds opening their section's setting, holds named by their jobs, keys of opposite
    states, abbreviated keys named by their legend."""
    read_held_sections(b)  # (a hold still guessed: the setting its section opens)
    read_held_changes(b)  # ("to tack to PORT, hold …: the course changes (270° → 170°)")
    read_opposite_keys(b)  # ("AUTO – engage …" / "STANDBY – disengage …": one setting)
    read_legend_nouns(b)  # ("DISP – display lighting": the setting's name)
