"""Ranges that reach below zero: "-6 to +6 semitones", "−70 … 0 dB", "from −6 dB to +6 dB",
"the knob stops at −70 dB and 0 dB", "-16 to -24 °C".

Audio levels, tone controls, transposition, pitch, keystone and freezer temperatures are set
on either side of zero, and the manual writes the ends with their signs (a hyphen or the
typographic minus "−", a plus for the top). The range patterns of ``values.py`` read unsigned
figures only, so such a setting was given a guessed 0–10. Here a pair of amounts of which at
least one carries a minus is read as a range; two negative ends written from the warmer to
the colder ("-16 to -24 °C") are put in order. A tolerance ("±0.5 °C") is no range and is not
read. The figures' unit is the one printed beside them; decibels count here (a negative
decibel figure is a level someone sets, never a rating).
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from functools import lru_cache
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from apbot.read.text import Unit
    from apbot.read.values import Range

# a figure with its sign; the sign touches the digit ("-6", "−70", "+6"), so a dash between
# two words or figures ("Level 1 - 5") is no sign
_SIGNED = r"(?:[-−+](?=\d))?\d+(?:[.,]\d+)?"
# what joins the two ends: "to", an ellipsis, a long dash (never a hyphen: "-6--3" is no text)
_JOIN = r"\s*(?:to|…|\.{3}|–|—)\s*"
# what the appliance stands, works or is kept in, and what it measures or how exactly: the
# room's or the sensor's span, no setting's ("operating temperature −10 to +40 °C", "storage
# −20 … 60 °C", "measuring range -50 to 300 °C", "accuracy -1 to +1 °C")
_NOT_A_SETTING = re.compile(
    r"\b(?:operat\w*|working|storage|store[sd]?|kept|ambient|surroundings|environment\w*"
    r"|outdoors?|outside|room|climate|transport\w*|measur\w*|sensor|reading|accuracy|tolerance"
    r"|deviation|precision|resolution|calibrat\w*)\b",
    re.IGNORECASE,
)
# words in brackets after a figure: "(quietest)", "(factory)"
_ASIDE_RE = re.compile(r"\s*\([^()\d]{2,30}\)")


@lru_cache(maxsize=4)
def _span_re(unit: str) -> re.Pattern[str]:
    """Two or more figures joined by "to", an ellipsis or a long dash (a scale printed stop by
    stop, "−70 dB … −40 dB … 0 dB", spans its first to its last)."""
    figure = rf"{_SIGNED}\s*(?:(?:{unit}|dB)(?!\w))?"
    return re.compile(
        rf"(?<![\w.:,+−-])(?:from\s+)?(?P<run>{figure}(?:{_JOIN}{figure})+)(?![\w.,]\d|\w)",
        re.IGNORECASE,
    )


@lru_cache(maxsize=4)
def _stops_re(unit: str) -> re.Pattern[str]:
    units = rf"(?:{unit}|dB)"
    return re.compile(
        rf"\bstops?\s+at\s+(?P<a>{_SIGNED})\s*(?P<au>{units})?(?!\w)\s*(?:,\s*)?and\s+(?:at\s+)?"
        rf"(?P<b>{_SIGNED})\s*(?P<bu>{units})?(?![\w:])",
        re.IGNORECASE,
    )


def _figure(text: str) -> float:
    return float(text.replace("−", "-").replace(",", "."))


def _figures(run: str, unit: str) -> tuple[list[float], set[str]]:
    found = re.findall(rf"({_SIGNED})\s*((?:{unit}|dB)(?!\w))?", run, re.IGNORECASE)
    return [_figure(f) for f, _ in found], {u.lower().replace(" ", "") for _, u in found if u}


def signed_spans(text: str, unit: str) -> list[tuple[float, float, str]]:
    """Each (low, high, unit as printed) written with a negative end in ``text``; ``unit`` is
    the pattern of the units a setting is set in. Words in brackets after a figure are asides
    ("−70 dB (quietest) … 0 dB (maximum)")."""
    if _NOT_A_SETTING.search(text):
        return []
    text = _ASIDE_RE.sub("", text)
    out: list[tuple[float, float, str]] = []
    runs = [m.group("run") for m in _span_re(unit).finditer(text)]
    runs += [f"{m.group('a')} {m.group('au') or ''} to {m.group('b')} {m.group('bu') or ''}"
             for m in _stops_re(unit).finditer(text)]  # fmt: skip
    for run in runs:
        figures, units = _figures(run, unit)
        if not any(f < 0 for f in figures) or len(units) > 1:
            continue  # no minus: the unsigned patterns read it
        if figures == sorted(figures, reverse=True) and figures[0] < 0:
            figures.reverse()  # "-16 to -24 °C": from the warmer end to the colder
        if figures != sorted(set(figures)):
            continue  # not a climbing scale
        printed = re.search(rf"(?:{unit}|dB)(?!\w)\s*$", run.strip(), re.IGNORECASE)
        found = (figures[0], figures[-1], printed.group(0).strip() if printed else "")
        if found not in out:
            out.append(found)
    return out


def signed_in_section(units: Sequence[Unit], name: str, label: str) -> tuple[Range, int] | None:
    """The first range below zero written in the section whose heading names the setting
    (a heading word starting with a word of its name or label, three letters at least: "TIME
    ZONE FOR THE RADIO CLOCK" for ``zone``, "TRANSPOSE" for ``trans``), and its unit; None when
    there is none. Asked only for a setting whose range the manual gave nowhere else, so a
    sign read here never displaces a range read the usual way."""
    from apbot.read.values import UNIT, Range, unit_name

    own = {w for w in re.findall(r"[a-z]+", f"{name} {label}".lower()) if len(w) >= 3}
    if not own:
        return None
    for i, unit in enumerate(units):
        heading = re.findall(r"[a-z]+", unit.heading.lower())
        if not any(h.startswith(w) for h in heading for w in own):
            continue
        for low, high, said in signed_spans(unit.text, UNIT):
            named = "dB" if said.lower() == "db" else unit_name(said)
            return Range(low, high, named), i
    return None
