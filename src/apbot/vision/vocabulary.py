"""Words for matching action names to printed labels: verbs → skills, synonyms, symbols.

General knowledge of appliance panels, not of any one appliance: ``press_power`` may be
printed ``ON/OFF``, ``I/O`` or ⏻; ``up`` may be ``▲`` or ``+``; ``temp`` abbreviates
``temperature``.
"""

from __future__ import annotations

import re
from difflib import SequenceMatcher

VERBS: dict[str, str] = {
    "press": "press", "push": "press", "tap": "press", "touch": "press", "flip": "press",
    "slide": "press", "toggle": "press", "switch": "press", "hold": "hold", "turn": "turn",
    "rotate": "turn", "twist": "turn", "wait": "wait",
}  # fmt: skip
DIRECTIONS: dict[str, str] = {
    "cw": "turn_cw", "clockwise": "turn_cw", "right": "turn_cw",
    "ccw": "turn_ccw", "anticlockwise": "turn_ccw", "counterclockwise": "turn_ccw",
    "left": "turn_ccw", "acw": "turn_ccw",
}  # fmt: skip
FILLER = frozenset(
    {"button", "key", "pad", "touch", "knob", "dial", "switch", "the", "btn", "rocker", "ring",
     "selector", "control"}
)  # fmt: skip

SYMBOL_WORDS: dict[str, tuple[str, ...]] = {
    "⏻": ("power", "on", "off", "onoff", "standby"),
    "+": ("plus", "up", "more", "increase", "add"),
    "−": ("minus", "down", "less", "decrease"),
    "-": ("minus", "down", "less", "decrease"),
    "▲": ("up", "increase", "more", "plus"),
    "▼": ("down", "decrease", "less", "minus"),
    "◀": ("left", "prev", "previous", "back"),
    "◄": ("left", "prev", "previous", "back"),
    "◁": ("left", "prev", "previous", "down", "back"),
    "▶": ("right", "next", "start", "play", "forward"),
    "►": ("right", "next", "forward"),
    "▷": ("right", "next", "start", "play", "up", "forward"),
    "✕": ("cancel", "clear", "stop", "close"),
    "×": ("cancel", "clear", "stop", "close"),
    "🔒": ("lock", "child", "locked"),
    "🔓": ("unlock", "lock"),
    "🔑": ("lock", "key", "child"),
    "💡": ("light", "lamp", "bulb"),
    "⏱": ("timer", "time", "stopwatch"),
    "⏲": ("timer", "time"),
    "⌚": ("delay", "clock", "time", "timer"),
    "☀": ("dry", "drying", "sun"),
    "½": ("half",),
    "☕": ("cup", "coffee", "strength", "small"),
    "❄": ("ice", "cool", "frozen", "cold"),
    "↕": ("vertical", "v", "updown"),
    "↔": ("horizontal", "h", "leftright"),
    "°": ("temp", "temperature", "heat"),
}
WORD_SYNONYMS: dict[str, tuple[str, ...]] = {
    "power": ("onoff", "io", "on", "off"),
    "onoff": ("power", "on", "off", "io"),
    "temp": ("temperature", "tmp"),
    "prog": ("program", "programme"),
    "program": ("programme", "prog", "p"),
    "programme": ("program", "prog", "p"),
    "colour": ("color",),
    "color": ("colour",),
    "min": ("minute", "minutes"),
    "hour": ("hr", "h"),
    "one": ("1",),
    "two": ("2",),
    "three": ("3",),
    "add30": ("+30",),
    "start": ("go", "run"),
    "cancel": ("clear", "stop", "reset"),
    "conv": ("convection",),
    "sec": ("seconds", "s"),
    "func": ("function",),
    "select": ("selector",),
    "light": ("lamp",),
    "warm": ("keep",),
    "rinse": ("rinse+",),
    "dry": ("extradry", "dry+"),
    "left": ("l",),
    "right": ("r",),
    "spin": ("rpm",),
    "rpm": ("spin",),
}
UNITS = {"℃": "°C", "℉": "°F"}
"""One-character units OCR may return, as they are usually printed."""

_SPLIT = re.compile(r"[^0-9a-z+½]+")
_ALNUM = re.compile(r"[a-z]+|[0-9]+|\+[0-9]*|½")


_CAMEL = re.compile(r"[A-Za-z]*[a-z][A-Z][A-Za-z]*")
_CAMEL_PART = re.compile(r"[A-Z]?[a-z]+|[A-Z]+(?![a-z])")
_IO = re.compile(r"(?:^|\s)[1il|]\s?/\s?[0o](?=\s|$)")
_STANDALONE = re.compile(r"(?:^|\s)([+\-−])(?=\s|$|[0-9])")
_SIGNED = re.compile(r"^\+([0-9]+)$")
_MIXED = re.compile(r"^([a-z]+)([0-9]+)$")


_HALF = re.compile(r"(?:^|(?<=\s))1\s?/\s?2(?=\s|$)")


def _units(text: str) -> str:
    """Units and signs as usually printed: ``℃`` → ``°C``, a lone ``1/2`` → ``½``."""
    return _HALF.sub("½", "".join(UNITS.get(c, c) for c in text))


def label_symbols(text: str) -> list[str]:
    """Symbols printed in a label's text: any of :data:`SYMBOL_WORDS` except ``+`` and ``-``,
    which count only standing alone (``TEMP −``, not ``ADD-IN`` or ``RINSE+``).

    >>> label_symbols("TEMP −"), label_symbols("ADD-IN"), label_symbols("▲ UP")
    (['−'], [], ['▲'])
    """
    text = _units(text)
    found = [c for c in text if c in SYMBOL_WORDS and c not in "+-−"]
    found += ["−" if m in "-−" else "+" for m in _STANDALONE.findall(text)]
    return found


def label_tokens(text: str) -> list[str]:
    """Tokens of a printed label: words and numbers, lower case (``+30 SEC`` → +30, 30, sec).

    >>> label_tokens("1/0")
    ['io', '1', '0']
    """
    text = _units(text)
    tokens: list[str] = []
    if _IO.search(text.casefold()):  # an I/O switch that OCR read as 1/0
        tokens.append("io")
    for word in _CAMEL.findall(text):  # "IntensiveZone", "varioSpeed": its words too
        tokens += [w.casefold() for w in _CAMEL_PART.findall(word)]
    for part in _SPLIT.split(text.casefold()):
        if not part:
            continue
        tokens.append(part)
        pieces = _ALNUM.findall(part)
        if len(pieces) > 1:
            tokens += pieces
        signed = _SIGNED.match(part)
        if signed:  # "+1": the sign's key for zone 1
            tokens.append(signed.group(1))
    return tokens


def name_parts(action: str) -> tuple[str, list[str]]:
    """The skill an action name asks for and the words naming its control(s).

    >>> name_parts("turn_timer_dial_clockwise")
    ('turn_cw', ['timer'])
    >>> name_parts("press_and_hold_lock")
    ('hold', ['lock'])
    """
    words = [w for w in action.casefold().split("_") if w]
    skill = "press"
    if words and words[0] in VERBS:
        skill = VERBS[words.pop(0)]
        if len(words) > 1 and words[0] == "and" and words[1] in VERBS:  # press_and_hold_x
            skill = VERBS[words[1]]
            words = words[2:]
    rest = [w for w in words if w not in FILLER]
    if skill == "turn":
        direction = next((DIRECTIONS[w] for w in reversed(rest) if w in DIRECTIONS), "turn_cw")
        rest = [w for w in rest if w not in DIRECTIONS]
        skill = direction
    return skill, rest


def similarity(word: str, token: str) -> float:
    """How well one name word matches one label token (1 exact or synonym, <1 fuzzy)."""
    if word == token or {word, token} in ({"0", "o"}, {"1", "i"}, {"1", "l"}, {"5", "s"}):
        return 1.0
    if token in WORD_SYNONYMS.get(word, ()) or word in WORD_SYNONYMS.get(token, ()):
        return 0.95
    if len(word) >= 3 and (token.startswith(word) or (word.startswith(token) and len(token) >= 3)):
        return 0.85
    if word[:1] != token[:1] or min(len(word), len(token)) < 4:
        return 0.0
    ratio = SequenceMatcher(None, word, token).ratio()
    return ratio if ratio >= 0.84 else 0.0


def words_score(words: list[str], tokens: list[str], symbols: list[str]) -> float:
    """How well the name words match a label (its tokens and recognised symbols), 0..1."""
    if not words:
        return 0.0
    meanings = [w for symbol in symbols for w in SYMBOL_WORDS.get(symbol, ())]
    meanings += [w for token in tokens if token == "+" for w in SYMBOL_WORDS["+"]]
    joined = [tokens[i] + tokens[i + 1] for i in range(len(tokens) - 1)]
    pool = tokens + joined
    if not pool and not meanings:
        return 0.0
    matched = []
    for word in words:
        best = _word_score(word, pool, meanings)
        mixed = _MIXED.match(word)
        if mixed and best < 0.9:  # "plus1" printed "+ 1", "menu2" printed "MENU 2"
            parts = [_word_score(p, pool, meanings) for p in mixed.groups()]
            best = max(best, 0.95 * min(parts))
        if best == 0.0 and len(word) > 4:  # a compound name word: "temptime" = TEMP/TIME
            best = 0.9 if any(word == "".join(tokens[i:j]) for i in range(len(tokens))
                              for j in range(i + 2, len(tokens) + 1)) else 0.0  # fmt: skip
        matched.append(best)
    score = sum(matched) / len(words)
    if min(matched) == 0.0:
        score *= 0.5
    extra = max(0, len([t for t in tokens if not t.isdigit() or len(tokens) == 1]) - len(words))
    return max(0.0, score - 0.06 * extra)


def _word_score(word: str, pool: list[str], meanings: list[str]) -> float:
    best = max([similarity(word, token) for token in pool] + [0.0])
    if word in meanings:  # a symbol means a word exactly, never by spelling
        best = max(best, 0.97)
    return best
