"""A lamp drawn as a symbol and named for its setting: "Mirror lamp ⇋ (lit when the design is
mirrored)", "the ❄ symbol of EXTRA COLD".

A panel often lights a small symbol for an on/off setting instead of printing a word, and the
legend gives the setting's name, "lamp" (or symbol, icon, indicator) and the symbol. The symbol
is then what the display shows while the setting is on; without it the agent reads the setting
as unreadable and keeps pressing its key.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from apbot.read.shown import NOT_GLYPHS
from apbot.read.text import Unit

_GLYPH = rf"([^\w\s()\[\]{{}}.,;:!?'\"/\\|*{NOT_GLYPHS}]{{1,3}})"
_NOUNS = r"(?:lamp|light|symbol|icon|indicator|LED)"


def symbol_lamp(units: Sequence[Unit], label: str) -> tuple[str, int] | None:
    """The symbol of the setting's own lamp ("Mirror lamp ⇋" for MIRROR) and where it is said,
    or None."""
    if not label or not re.search(r"[A-Za-z]{3}", label):
        return None
    name = r"\s+".join(re.escape(w) for w in label.split())
    pattern = re.compile(rf"(?<![\w]){name}\s+{_NOUNS}\s+{_GLYPH}(?=\s|$)", re.IGNORECASE)
    for i, unit in enumerate(units):
        m = pattern.search(unit.text)
        if m:
            return m.group(1), i
    return None


# "The PACER lamp is lit when the pacer is on (factory setting)": a lamp printed with the
# setting's name, lit while it is on; the bracket after "on" says it starts on
_WORD_LAMP = (
    r"(?<![\w])(?P<word>[A-Z][A-Z0-9+-]{1,11})\s+(?:lamp|light|indicator|LED)\s+(?:is\s+)?"
    r"(?:lit|lights(?:\s+up)?|on)\s+(?:when|while)\s+(?:the\s+)?{name}\s+is\s+on\b"
    r"(?P<start>\s*\(\s*(?:factory|default|start)[^)]*\))?"
)


def word_lamp(units: Sequence[Unit], name: str) -> tuple[str, bool, int] | None:
    """The word of the setting's own lamp, lit while it is on, whether the manual says it
    starts on, and where; None when no sentence says so."""
    if not re.fullmatch(r"[a-z][a-z ]{2,30}", name):
        return None
    noun = r"\s+".join(re.escape(w) for w in name.split())
    pattern = re.compile(_WORD_LAMP.replace("{name}", noun), re.IGNORECASE)
    for i, unit in enumerate(units):
        m = pattern.search(unit.text)
        if m and m.group("word").isupper() and m.group("word").lower().startswith(name[:4]):
            return m.group("word"), bool(m.group("start")), i
    return None


# "◷ lit = zone timer on", "✱ lit: on (factory setting)": a sign whose lamp lit means the
# setting is on, with the setting named or said right under its own heading; a bracket after
# "on" that says it starts so
_LIT_MEANS = (
    r"(?:^|\s)(?P<glyph>[^\w\s()\[\]{{}}.,;:!?'\"/\\|*=·-]{{1,2}})\s+lit\s*[=:]\s*"
    r"(?:the\s+)?(?P<name>{name}\s+)?on\b"
    r"(?P<start>\s*\(\s*(?:[^)]*\b(?:factory|delivery|default)\b)[^)]*\))?"
)


def lit_sign(lines: Sequence[str], name: str, near: int | None) -> tuple[str, bool, int] | None:
    """The sign whose lamp is lit while the setting is on (``lines`` are the raw lines, signs
    kept), whether the manual says it starts on, and its line: the setting named after the
    "=" anywhere, or not named on a line at most two after ``near`` (the setting's own line)."""
    if not re.fullmatch(r"[a-z][a-z ]{2,30}", name):
        return None
    noun = r"\s+".join(re.escape(w) for w in name.split())
    pattern = re.compile(
        _LIT_MEANS.replace("{name}", noun).replace("{{", "{").replace("}}", "}"), re.I
    )
    found: list[tuple[str, bool, int]] = []
    for n, line in enumerate(lines, start=1):
        for m in pattern.finditer(line):
            if m.group("glyph") in NOT_GLYPHS:
                continue
            if m.group("name") or (near is not None and 0 <= n - near <= 2):
                found.append((m.group("glyph"), bool(m.group("start")), n))
    if not found or len({g for g, _, _ in found}) > 1:
        return None  # (two signs for one setting: neither is sure)
    return found[0][0], any(start for _, start, _ in found), found[0][2]


# a display legend's sign with the setting it means on: "☼ (backlight on)", "④ ♪  flag beep on
# (MUTE when off)" — the word in brackets after it is what the display shows while off
_SIGN_MEANS = re.compile(
    r"(?:^|\s)(?P<glyph>[^\w\s()\[\]{}.,;:!?'\"/\\|*=·<>-]{1,2})\s+\(?(?:the\s+)?"
    # (not a key's "on / off")
    r"(?P<noun>[a-z][a-z -]{2,30}?)\s+on\b(?!\s*(?:/|or\b|and\b)\s*off)\)?"
    r"(?:\s*\((?P<off>[A-Z][A-Z0-9]{1,7})\s+when\s+off\))?"
)


def sign_meaning(lines: Sequence[str], name: str) -> tuple[str, str, int] | None:
    """The sign a display legend says means the setting is on, the word it says the display
    shows while off ("" for none), and its line; the setting named as in the legend, or as the
    legend's noun's last part ("backlight" for a setting called light). None when no line, or
    two different signs, say so."""
    said = [w for w in name.split() if w]
    if said and said[-1] == "on":
        said = said[:-1]  # ("flag beep on": a name read with its state)
    if not said or not all(w.isalpha() for w in said):
        return None
    found: list[tuple[str, str, int]] = []
    for n, line in enumerate(lines, start=1):
        for m in _SIGN_MEANS.finditer(line):
            if m.group("glyph") in NOT_GLYPHS or re.search(r"[\w]", m.group("glyph")):
                continue
            noun = m.group("noun").split()
            if noun == said or (
                len(said) == 1
                and len(noun) == 1
                and len(said[0]) >= 4
                and noun[0].endswith(said[0])
            ):
                found.append((m.group("glyph"), m.group("off") or "", n))
    if not found or len({g for g, _, _ in found}) > 1:
        return None
    return found[0]
