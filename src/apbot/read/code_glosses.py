"""Display words the manual glosses with a longer name: "SIDE = side to side", "WALL – floor
and walls", "NOISE (white noise)".

A panel with lamps or a small display prints a setting's values as one short word each, and the
manual says once what each word stands for, after an equals sign or a dash or in brackets. The
user says the longer name ("head-to-toe swinging", "white noise", "clean the floor and the
walls"), so a value read as the display word takes the gloss as its name and keeps the word as
what the display shows. A gloss counts only when it holds the display word itself — as a word
("head to toe"), its plural ("floor and walls") or the end of a compound ("waterline"), at
either end of the gloss — so the gloss names the same thing and is not a description ("the
ring flashes", "the overhead rain head", "LULLABY (10 lullabies in a row)", "NATURE (birds,
stream, rain)"); letter codes that abbreviate their words ("LO low") are
:mod:`apbot.read.code_words`' job.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.code_words import own_lines
from apbot.read.codes import rename_codes
from apbot.read.labels import words as name_words
from apbot.read.off_words import unit_at

_WORD_CODE = re.compile(r"[a-z]{3,10}")  # a display word: "side", "wall", "noise"
_MARK = r"\s*(?:=|–|—|-{1,2})\s*"
_GLOSS = r"([A-Za-z][A-Za-z' -]{2,40})"
_WORDS = 4  # a gloss names the value; a longer text describes it
# leading words a name drops ("STEAM – with steam" names no more than "steam")
_FILLER = frozenset({"the", "a", "an", "with"})
# "HAND/FOOT (lamp FOOT)": where the word is shown, not a longer name for it
_SHOWN = frozenset({"lamp", "lamps", "light", "led", "icon", "symbol", "display", "indicator"})
_TRAILING = frozenset({"only"})
# an aside that says where a setting starts ("THICK (starts THICK)", "(default LOW)") is no name
_START_LEADS = frozenset({"starts", "start", "default", "preset", "initially", "factory"})
_JOINERS = frozenset({"to", "and", "or", "of", "with"})
# a switch's words gloss what is switched ("OFF = appliance off"), not a value of its own
_SWITCH_WORDS = frozenset({"on", "off"})  # "LINE – waterline only": the name is "waterline"
_CUT = re.compile(r"\s*(?:[(,.;:]|\s-\s|\s–\s|\s{2,})")  # where a gloss's name ends
# a gloss followed by a warning tells of a state ("HOT (surface hot) – do not touch"): no name
_WARNING = re.compile(
    r"[\s–—:;,.!-]*(?:do\s+not|don't|never|caution|warning|danger)\b", re.IGNORECASE
)


def name_glossed_words(b: Builder) -> None:
    """Give each display word of a setting the longer name the manual glosses it with."""
    lines = own_lines(b)
    # a value a key is named by ("FISH" pad of a fish preset) is the key's printed name: its
    # gloss describes the key's picture ("FISH (fish outline)")
    keys = {token for info in b.infos for token in info.controls}
    for var, spec in b.variables.items():
        values = [str(v) for v in spec.get("values") or []]
        if spec.get("type") != "discrete" or not 2 <= len(values) <= 8 or spec.get("show"):
            continue
        names: dict[str, str] = {}
        first = 0
        own = set(name_words(f"{var} {spec.get('label') or ''}"))
        for value in values:
            if not _WORD_CODE.fullmatch(value) or value in _SWITCH_WORDS or value in keys:
                continue
            found = _gloss(lines, value, own, values)
            if found is not None:
                names[value] = found[0]
                first = first or found[1]
        if not names or len(set(names.values()) | set(values)) != len(values) + len(names):
            continue  # nothing glossed, or two values glossed alike
        if _shared_frame(names):
            continue  # "temperature too high / too low": one frame around each word, no names
        rename_codes(b, var, spec, {v: names.get(v, v) for v in values})
        b.note(
            f"variables.{var}.values",
            "display words glossed by the manual: "
            + ", ".join(f"{c.upper()} {n}" for c, n in names.items()),
            unit_at(b, first),
        )


def _gloss(lines: list[str], code: str, own: set[str], values: list[str]) -> tuple[str, int] | None:
    """The first gloss of the display word ``code`` (printed in capitals) that names it, and
    its line's index; a gloss adding only the setting's ``own`` words ("LOW = low heat" of
    HEAT) names nothing new. The gloss is one of a legend of the setting's ``values``: another
    of them is printed on its line or the next or last one ("SIDE = …" over "HEAD = …"), not
    a display message elsewhere that happens to end in the word ("HIGH – room too hot")."""
    printed = re.escape(code.upper())
    patterns = (
        re.compile(rf"(?<![\w+-]){printed}{_MARK}{_GLOSS}"),
        re.compile(rf"(?<![\w+-]){printed}\s*\(\s*{_GLOSS}\)"),
    )
    others = [
        re.compile(rf"(?<![\w+-]){re.escape(v.upper())}(?![\w+-])") for v in values if v != code
    ]
    for number, line in enumerate(lines):
        near = lines[max(0, number - 1) : number + 2]
        if not any(o.search(text) for o in others for text in near):
            continue
        for pattern in patterns:
            for match in pattern.finditer(line):
                name = _name(match.group(1), code, own)
                if name is not None and not _warned(line, match, pattern is patterns[1]):
                    return name, number
    return None


def _warned(line: str, match: re.Match[str], bracketed: bool) -> bool:
    """The gloss's line goes on with a warning ("HOT (surface hot) – do not touch", "HOT –
    surface hot, never touch"): the gloss tells of a state to beware of, not a value's name."""
    if bracketed:
        rest = line[match.end() :]
    else:
        parts = _CUT.split(line[match.start(1) :], maxsplit=1)
        rest = parts[1] if len(parts) > 1 else line[match.end() :]
    return _WARNING.match(rest) is not None


def _shared_frame(names: dict[str, str]) -> bool:
    """Two glosses that are one text around their display words ("temperature too high",
    "temperature too low"): the frame names no value, it tells of a state."""
    frames = [re.sub(rf"\b{re.escape(code)}\w*", "", name) for code, name in names.items()]
    return len(frames) != len(set(frames))


def _capitals(printed: list[str], words: list[str]) -> bool:
    """Whether the word after the first of ``words`` is printed in capitals, as on the panel."""
    at = len(printed) - len(words) + 1
    return at < len(printed) and printed[at].isupper()


def _name(gloss: str, code: str, own: set[str]) -> str | None:
    """The gloss's leading words as a name when they hold the code ("walls", "waterline"), else
    None: a gloss up to its first bracket, comma or stop, without an article or "only"."""
    text = _CUT.split(gloss.strip())[0]
    printed = text.split()
    words = [w.casefold() for w in printed]
    # ("lamp PEDAL": where the word shows, the word printed after it; "light mist" is a name)
    while words and (words[0] in _FILLER or (words[0] in _SHOWN and _capitals(printed, words))):
        words = words[1:]
    while words and words[-1] in _TRAILING:
        words = words[:-1]
    if not words or len(words) > _WORDS or [w for w in words if w not in own] == [code]:
        return None
    if words[0] in _START_LEADS:
        return None
    # the display word ends the name ("white noise", "floor and walls", "waterline") or leads
    # a pair joined by a small word ("head to toe"): not a sentence about it ("the ring
    # flashes", "overhead rain head", "both lamps lit")
    last = words[-1].endswith(code) or words[-1] == code + "s"
    paired = len(words) >= 3 and words[0] in (code, code + "s") and words[1] in _JOINERS
    if not (last or paired):
        return None
    return " ".join(words)
