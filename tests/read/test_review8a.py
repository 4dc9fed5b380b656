"""Round-8 reader rules that fired on ordinary manual text (fresh-eyes review), each on a
small manual of our own words."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.text import parse_manual

# a cooking-time chart with dot leaders and bare minutes: no table of contents
CHART = """Quickboil Rice Cooker RC-7

PROGRAMMES

Press MENU to choose a programme. Cooking times (minutes):

White rice ........ 35
Brown rice ........ 50
Porridge .......... 90
Steam ............. 120

Press START to begin cooking.
"""


def test_a_dot_leader_chart_of_minutes_is_no_table_of_contents() -> None:
    text = " ".join(u.text for u in parse_manual(CHART).units)
    assert "Porridge" in text and "120" in text


def test_a_table_of_contents_without_a_heading_still_goes() -> None:
    toc = "".join(
        f"{t} .......... {p}\n"
        for t, p in [
            ("Safety", 2),
            ("The keys", 3),
            ("Programmes", 5),
            ("Cleaning", 8),
            ("Warranty", 9),
        ]
    )
    text = " ".join(u.text for u in parse_manual("Tower fan\n\n" + toc + "\nPress SPEED.\n").units)
    assert "Warranty" not in text and "SPEED" in text
