"""Control names → the label printed on the panel and the manual sentences that mention it.

Manuals name keys in capitals (``COOK TIME``, ``START/PAUSE``), symbols (``▲``, ``+``) or plain
words ("the timer button"). A control's action token (``cook_time``, ``temp_up``) is matched to
those spellings by words, abbreviations ("temp" for "TEMPERATURE") and symbol names, never by
any one manual's wording.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from apbot.read.labels_abbrev import abbreviated_signed_name
from apbot.read.labels_legend import legend_name
from apbot.read.labels_signed_amounts import signed_amount
from apbot.read.text import Manual, Unit
from apbot.read.value_lists import find_list

SYMBOLS: dict[str, tuple[str, ...]] = {
    "up": ("▲", "↑", "△", "∧"),
    "down": ("▼", "↓", "▽", "∨"),
    "plus": ("+",),
    "minus": ("−", "-"),
    "more": ("+",),
    "less": ("−", "-"),
    "left": ("◀", "◄", "◁", "←", "<"),
    "right": ("▶", "►", "▷", "→", ">"),
    "prev": ("◀", "◄", "◁", "←"),
    "next": ("▶", "►", "▷", "→"),
    "power": ("⏻",),
    "on_off": ("⏻",),
    "play": ("▶/", "▶"),  # a play key printed ▶ or ▶/❚❚ (the pause bars are dropped as pictographs)
    "temp": ("°C", "°F"),  # a knob labelled only with the unit of what it sets
    "temperature": ("°C", "°F"),
    "spin": ("RPM",),
    "star": ("*", "✱"),  # a keypad's two sign keys, named for their sign
    "hash": ("#",),
    "pound": ("#",),
}
CONTROL_NOUNS = r"(?:button|key|pad|touch ?pad|dial|knob|switch|control|selector|sensor)"
_CAPS = re.compile(r"(?<![A-Za-z0-9])([A-Z0-9][A-Z0-9+&'./-]*(?:[ /][A-Z0-9+&'.-]+)*)(?![a-z])")


def words(text: str) -> list[str]:
    return [w for w in re.split(r"[^a-z0-9]+", text.lower()) if w]


def squash(text: str) -> str:
    return "".join(words(text))


@dataclass
class Label:
    """A control's label and the units that mention it (in manual order)."""

    token: str
    text: str
    line: int | None  # where the label was found (None: guessed from the action name)
    mentions: list[int] = field(default_factory=list)  # indices into the manual's units


POWER_SPELLINGS = frozenset({"onoff", "io", "power", "onstandby", "standby"})


def caps_phrases(manual: Manual) -> tuple[dict[str, int], dict[str, str]]:
    """Every capitalised phrase with the first line it appears on, and for a part of a
    slashed key name (START of START/PAUSE) the whole name."""
    found: dict[str, int] = {}
    whole: dict[str, str] = {}
    seen: dict[str, int] = {}  # how often each phrase is printed
    for unit in manual.units:
        for match in _CAPS.finditer(unit.text):
            phrase = match.group(1).strip(" ./-'")
            if len(phrase) >= 2 and any(c.isalpha() for c in phrase):
                found.setdefault(phrase, unit.line)
                seen[phrase] = seen.get(phrase, 0) + 1
                for part in re.split(r"\s*/\s*", phrase):  # START/PAUSE also names START
                    if len(part) >= 2 and part != phrase:
                        found.setdefault(part, unit.line)
                        if re.search(r"\S/\S", phrase) and len(phrase) <= 24:
                            whole.setdefault(part, phrase)
    # "Speed levels HOT/COLD" once in a data table, COLD alone all through the text: the
    # slashed phrase names two values, not the key
    text = "\n".join(u.text for u in manual.units)
    whole = {
        p: w
        for p, w in whole.items()
        if seen.get(p, 0) < 2
        or len(re.findall(r"\s*/\s*".join(map(re.escape, w.split("/"))), text)) > 1
    }
    return found, whole


def _score(token_words: list[str], phrase: str) -> float:
    pw = words(phrase)
    if not pw:
        return 0.0
    tw = token_words
    if "".join(pw) == "".join(tw):
        return 1.0
    if "".join(tw) in ("power", "onoff") and "".join(pw) in POWER_SPELLINGS:
        return 0.8
    digits = "".join(c for c in "".join(tw) if c.isdigit())
    if digits and "+" in phrase and digits == "".join(c for c in phrase if c.isdigit()):
        return 0.7  # add30 for "+30 SEC"
    if pw == tw[: len(pw)] and len(pw) < len(tw):
        return 0.0  # "TEMP" for temp_up: a shorter phrase names another control
    if tw == pw[: len(tw)]:
        if pw[len(tw) :] in (["on"], ["off"]) and "/" not in phrase:
            return 0.7  # "FRESH ON": the state a display shows; KEEP FRESH is the key's name
        return 0.85 if "/" in phrase or len(pw) - len(tw) <= 1 else 0.6
    if (
        all(any(p == t or (len(t) >= 3 and p.startswith(t)) for p in pw) for t in tw)
        and len(pw) <= len(tw) + 1
        and not _part_of_compound(tw, phrase)
    ):
        return 0.75
    if len(tw) == 1 and len(tw[0]) >= 3 and pw[0].startswith(tw[0]) and len(pw) == 1:
        return 0.7
    if len(tw) == 1 and len(pw) == 1 and len(pw[0]) >= 5 and tw[0].startswith(pw[0]):
        return 0.65  # PROGRAM for programme
    return 0.0


def _part_of_compound(token_words: list[str], phrase: str) -> bool:
    """A token word that is only a part of a hyphenated word ("up" of WARM-UP): one word, which
    the token does not name."""
    for compound in re.findall(r"[a-z0-9]+(?:-[a-z0-9]+)+", phrase.lower()):
        parts = compound.split("-")
        if any(t in parts for t in token_words) and not set(parts) <= set(token_words):
            return True
    return False


NOUN_TOKENS = frozenset({"knob", "dial", "selector", "switch", "wheel", "ring", "lever"})


def _named_by_noun(manual: Manual, noun: str) -> tuple[str, int] | None:
    """The capitalised name written before a control noun ("HUMIDISTAT knob"): an action
    named only ``knob`` is that control."""
    pattern = re.compile(rf"(?<![A-Za-z0-9])([A-Z][A-Z0-9+&'.-]+(?: [A-Z0-9+&'.-]+)*)\s+{noun}\b")
    for unit in manual.units:
        m = pattern.search(unit.text)
        if m and len(m.group(1)) >= 3:
            return m.group(1), unit.line
    return None


# "the main switch I / O", "the power button ⏻": a control called by its words and a noun, then
# its printing (capitals or a symbol, a slashed pair spaced or not)
_PRINTED = r"((?:[A-Z0-9⏻]{1,6})(?:\s?/\s?[A-Z0-9]{1,6})?)(?![\w/])"


def _printed_after_noun(manual: Manual, token_words: list[str]) -> tuple[str, int] | None:
    """The printing named right after the token's words and a control noun ("main switch
    I / O"): the manual saying which printed control the token is, rather than a longer word
    the token only begins (MAINTENANCE for ``main``)."""
    name = r"\s+".join(re.escape(w) for w in token_words)
    nouns = "switch|key|button|knob|dial|selector"
    # the words in any case, the printing in capitals as printed: "hold the timer button 3
    # seconds" prints no "3", and "the power button on the left" no "ON"
    pattern = re.compile(rf"\b(?i:{name}\s+(?:{nouns}))\s+{_PRINTED}")
    for unit in manual.units:
        m = pattern.search(unit.text)
        if m and (m.group(1).isupper() or "⏻" in m.group(1)):
            return m.group(1), unit.line
    return None


# the signs printed after a setting's name on a key of a stepping pair ("TEMP +", "POUCH −");
# not SYMBOLS, which a key prints alone: after a name "+" is up and "–" (a dash) down, and the
# arrows of up and down keys other than ▲ ▼ (↑ △ ∧) do not follow a name
_SIGNS: dict[str, str] = {
    "up": "+▲", "plus": "+", "more": "+", "down": "−–-▼", "minus": "−–-", "less": "−–-"
}  # fmt: skip


def _signed_name(manual: Manual, token_words: list[str]) -> tuple[str, int] | None:
    """The key printed as a setting's name and a sign ("POUCH +", "POUCH −") for a token
    naming the setting and a direction (``pouch_up``): that printing, where first seen."""
    name = r"\s+".join(re.escape(w.upper()) for w in token_words[:-1])
    signs = re.escape(_SIGNS[token_words[-1]])
    pattern = re.compile(rf"(?<![A-Za-z0-9]){name}\s?([{signs}])(?![\w+−–-])")
    for unit in manual.units:
        m = pattern.search(unit.text)
        if m:
            return m.group(0), unit.line
    return abbreviated_signed_name(manual, name, signs, token_words[-2])


def find_labels(manual: Manual, tokens: list[str]) -> dict[str, Label]:
    """The label and mentions of each control token."""
    phrases, whole = caps_phrases(manual)
    labels: dict[str, Label] = {}
    for token in tokens:
        tw = words(token.replace("_", " "))
        best, best_score, line = "", 0.0, None
        for phrase, at in phrases.items():
            score = _score(tw, phrase)
            if score > best_score or (score == best_score and score and len(phrase) < len(best)):
                best, best_score, line = phrase, score, at
        if best_score < 0.85 and tw:
            printed = _printed_after_noun(manual, tw)  # "main switch I / O" for ``main``
            if printed is not None:
                best, best_score, line = printed[0], 0.85, printed[1]
        if best_score < 0.6 and tw and tw[-1] in NOUN_TOKENS:
            named = _named_by_noun(manual, tw[-1])  # "the HUMIDISTAT knob" for ``knob``
            if named is not None:
                best, best_score, line = named[0], 0.6, named[1]
        if best_score < 0.6 and len(tw) >= 2 and tw[-1] in _SIGNS:
            signed = _signed_name(manual, tw)  # "POUCH +" for ``pouch_up``
            if signed is not None:
                best, best_score, line = signed[0], 0.6, signed[1]
        one_letter = len(tw) == 1 and len(tw[0]) == 1 and tw[0].isalpha()
        if one_letter and best.upper() != tw[0].upper():
            # a key printed as one letter ("M"): the letter where the text shows it is a key,
            # not a phrase that holds the letter among others ("Example C - P at 130 °C")
            letter = _letter_key(manual, tw[0].upper())
            if letter is not None:
                best, best_score, line = tw[0].upper(), 0.6, letter
        if best_score < 0.6 and (amount := signed_amount(manual, token)) is not None:
            best, best_score, line = amount[0], 0.6, amount[1]  # "−10" for ``minus10``
        if best_score < 0.6:
            best, line = " ".join(tw).upper() or token.upper(), None
            symbols = [s for w in (token, *tw[-1:]) for s in SYMBOLS.get(w, ())]
            for symbol in symbols:
                if any(symbol in u.text for u in manual.units):
                    best = symbol
                    break
        if best_score == 1.0:
            head = _row_head(manual, best, tokens)
            if head is not None:
                best, line = head
        labels[token] = Label(token, best, line)
    _legend_names(manual, labels)
    claimed = {label.text for label in labels.values()}
    for label in labels.values():
        full = whole.get(label.text)
        if full and not (set(re.split(r"\s*/\s*", full)) - {label.text}) & claimed:
            label.text = full
    for token, label in labels.items():
        label.mentions = _mentions(manual.units, token, label)
        if label.line is None and label.mentions:
            label.line = manual.units[label.mentions[0]].line
    from apbot.read.labels_sign_pairs import narrow_sign_pairs  # (it reads Label and SYMBOLS)

    narrow_sign_pairs(manual.units, labels)  # "TIME ▲" is no mention of "SPEED ▲"
    return labels


def _legend_names(manual: Manual, labels: dict[str, Label]) -> None:
    """Keys still unnamed, printed as signs or icons ("A-", "POSITION <"): the name their key
    table's row gives them (:func:`legend_name`)."""
    claimed = {label.text.upper() for label in labels.values() if label.line is not None}
    for token, label in labels.items():
        if label.line is not None or any(label.text == s for w in SYMBOLS.values() for s in w):
            continue
        found = legend_name(manual, words(token.replace("_", " ")), claimed)
        if found is not None:
            label.text, label.line = found
            claimed.add(found[0].upper())


_ROW_HEAD = re.compile(
    r"^\s*(?:[①-⑳❶-❿]\s*|\d{1,2}[.)]?\s+)?"  # "④ PUMP", "2. TIMER": a legend row's mark
    r"([A-Z][A-Z0-9+&'./-]*(?: [A-Z0-9+&'./-]+)*)(?:\s{2,}|\s*:\s)\S"
)  # a key's name in capitals heading a row, then its description after a gap or a colon


def _row_head(manual: Manual, name: str, tokens: list[str]) -> tuple[str, int] | None:
    """A key's name one word longer than its action's token, when only that longer name heads a
    legend row and its description lists the short name as a value ("CUP SIZE   Each touch moves
    to the next amount: CUP → MUG → POT"): CUP is then a value, the key is CUP SIZE."""
    heads: dict[str, int] = {}
    listed: set[str] = set()
    said = re.compile(rf"(?<![A-Za-z0-9]){re.escape(name)}(?![A-Za-z0-9])")
    for number, raw in enumerate(manual.lines, 1):
        m = _ROW_HEAD.match(raw)
        if m is not None:
            heads.setdefault(m.group(1), number)
            found = find_list(raw[m.end(1) :]) if said.search(raw, m.end(1)) else None
            if found and any(said.fullmatch(item.strip()) for item in found[0]):
                listed.add(m.group(1))  # an item of a list, not any later mention ("press STEAM")
    if name in heads:
        return None
    short = words(name)
    longer = [
        (head, at)
        for head, at in heads.items()
        if len(words(head)) == len(short) + 1
        and words(head)[: len(short)] == short
        and words(head)[-1].isalpha()
        and words(head)[-1] not in ("on", "off")
    ]
    owned = {squash(t) for t in tokens}
    if len(longer) != 1 or longer[0][0] not in listed or squash(longer[0][0]) in owned:
        return None
    return longer[0]


def _letter_said(letter: str) -> re.Pattern[str]:
    """A key printed as one capital letter, where the text shows it is a key: pressed, held
    or touched ("Press M briefly", "hold the M key"), or called a key or button."""
    return re.compile(
        rf"\b(?i:press|hold|touch|push|tap)\w*\s+(?:(?i:of|on)\s+)?(?:the\s+)?{letter}(?![\w'.-])|"
        rf"(?<![\w.-]){letter}\s+(?i:key|button)\b",
    )


def _letter_key(manual: Manual, letter: str) -> int | None:
    """The line of the first unit that names a one-letter key ("M") as a key: a legend row
    it heads (its first cell), or a sentence that presses or holds it. A capital letter
    alone is otherwise a size, a grade or a callout, never taken for a key."""
    said = _letter_said(letter)
    for unit in manual.units:
        if (unit.cells and unit.cells[0] == letter and len(unit.cells) >= 2) or said.search(
            unit.text
        ):
            return unit.line
    return None


def _mentions(units: list[Unit], token: str, label: Label) -> list[int]:
    tw = words(token.replace("_", " "))
    patterns = []
    if label.line is not None and len(label.text) == 1 and label.text.isalpha():
        said = _letter_said(label.text)
        return [
            i
            for i, u in enumerate(units)
            if (u.cells and u.cells[0] == label.text and len(u.cells) >= 2) or said.search(u.text)
        ]
    if label.line is not None:
        for text in {label.text, *re.split(r"\s*/\s*", label.text)} - {""}:
            if len(text) >= 2 or not text.isalnum():
                printed = _sign_spaced(text)  # "VOL+" also as "VOL +", "VOL −" as "VOL−"
                patterns.append(re.compile(rf"(?<![A-Za-z0-9]){printed}(?![A-Za-z0-9])"))
    plain = r"[\s-]+".join(re.escape(w) for w in tw)
    if plain:
        patterns.append(re.compile(rf"\b{plain}\w*(?:\s+\w+)?\s+{CONTROL_NOUNS}\b", re.IGNORECASE))
    if len(tw) >= 2 and re.fullmatch(CONTROL_NOUNS, tw[-1]):
        # the action names its own control noun (``press_heat_selector``): "the heat selector
        # chooses ..." in lower-case prose names this control as surely as HEAT SELECTOR
        patterns.append(re.compile(rf"\b{plain}s?\b", re.IGNORECASE))
    spoken = _inflected(label.text if label.line is not None else "")
    if spoken:
        patterns.append(spoken)
    symbols = [s for w in (token, *tw[-1:]) for s in SYMBOLS.get(w, ())]
    for symbol in symbols:
        if len(symbol) == 1 and symbol in "+-−–<>":
            patterns.append(re.compile(rf"(?:^|[\s(/]){re.escape(symbol)}(?=[\s)/,.:]|$)"))
        else:
            patterns.append(re.compile(re.escape(symbol)))
    return [i for i, u in enumerate(units) if any(p.search(u.text) for p in patterns)]


def _sign_spaced(text: str) -> str:
    """A pattern for a key printed as a word and a sign, with or without a space between them
    ("VOL+" is written "VOL +" in the prose, "TEMP ▲" as "TEMP▲"); else the text as it is."""
    m = re.fullmatch(r"([A-Za-z][A-Za-z .'-]*?)\s?([+−–\-▲▼△▽<>◀▶◄►])", text)
    pair = re.fullmatch(r"([A-Za-z][A-Za-z0-9]*)\+([A-Za-z][A-Za-z0-9]*)", text)
    if pair:  # two keys pressed together: "SHIFT+KIT" is written "SHIFT + KIT" too
        return rf"{re.escape(pair[1])}\s?\+\s?{re.escape(pair[2])}"
    if m is None:
        return re.escape(text)
    return rf"{re.escape(m.group(1))}\s?{re.escape(m.group(2))}"


def _inflected(label: str) -> re.Pattern[str] | None:
    """A key of two or more words named in running prose with its first word inflected:
    "HEAT TIME" as "the heating time", "DRY TIME" as "drying time". Only the inflected form (the
    plain words in lower case, "the water level", are the setting, not always this key), and
    only for labels of several words, so that a one-word key (HEAT) never claims every
    "heating" in the manual."""
    ws = words(label)
    if len(ws) < 2 or not all(w.isalpha() for w in ws) or len(ws[0]) < 3:
        return None
    first = ws[0][:-1] if ws[0].endswith("e") else ws[0]
    rest = r"[\s-]+".join(re.escape(w) for w in ws[1:])
    return re.compile(rf"\b{re.escape(first)}(?:ing|ed)[\s-]+{rest}\b", re.IGNORECASE)


# the units among SYMBOLS: a key printed TEMP is also found by the "°F" of its sentences
_UNIT_SYMBOLS = ("°C", "°F", "RPM")


def unit_only_mention(label: Label, text: str) -> bool:
    """Whether ``text`` names this key (printed as a word) only by a unit ("the probe target
    changes in 5 °F steps" for TEMP): another setting's sentence in the same unit."""
    if label.line is None or not label.text or label.text in _UNIT_SYMBOLS:
        return False
    if not any(u in text for u in _UNIT_SYMBOLS):
        return False
    printed = re.compile(rf"(?<![A-Za-z0-9]){re.escape(label.text)}(?![A-Za-z0-9])", re.I)
    return not printed.search(text) and not any(
        re.search(rf"\b{re.escape(w)}", text, re.I) for w in words(label.token) if len(w) >= 4
    )
