"""What a pair of keys raises and lowers, named where the manual gives the pair its use.

A key legend or the pair's own sentence often says what the two keys move: "▲ / ▼ — Raise /
lower the heat level of the selected zone", "− and + lower or raise the water temperature",
"Increase / decrease the goal value". (The noun form, "▲ / ▼  Sensitivity up and down", is
read by :mod:`apbot.read.up_down_nouns`.) That quantity is the pair's own setting, even when its
noun is none the reader knows as an amount (heat level, goal value, brightness): a key beside
it that cycles its own list (TIMER "1 h > 2 h > …") does not take the pair over, and the
pair's setting is named after the quantity rather than the most frequent noun nearby.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import replace

from apbot.read.build import Builder
from apbot.read.end_stops import end_stops
from apbot.read.labels import words
from apbot.read.roles_common import UNIT_QUANTITY, mentions_of
from apbot.read.shapes import SETTING_NOUNS, Evidence
from apbot.read.values import find_ranges

_VERB = (
    r"(?:raise|lower|increase|decrease|reduce|turn\s+up|turn\s+down|step\s+up|step\s+down"
    r"|raises|lowers|increases|decreases|reduces)"
)
_VERB_RE = re.compile(rf"\b{_VERB}\b", re.IGNORECASE)
# "Raise / lower the heat level of …", "lower or raise the set temperature", "increases the …"
_RAISED_RE = re.compile(
    rf"\b{_VERB}(?:\s*(?:/|,|or|and)\s*{_VERB})?\s+(?:the\s+|its\s+|your\s+)?"
    r"(?P<noun>[a-z][a-z-]*(?:\s+[a-z][a-z-]*){0,2})",
    re.IGNORECASE,
)
# words that end the noun phrase ("the heat level OF the selected zone", "the value SHOWN")
_STOP = {
    "of", "on", "in", "by", "from", "to", "for", "with", "at", "shown", "that", "which",
    "while", "when", "one", "each", "and", "or", "as", "is", "are", "a", "an", "the",
    "until", "per", "step", "steps", "selected", "chosen", "flashing", "displayed", "set",
    "before", "after", "during", "then", "into", "onto", "up", "down", "if", "so", "again",
    "slightly", "gently", "fully", "only", "once", "use", "using", "it", "them", "you", "your",
    "blinking", "being", "current", "currently", "active", "highlighted", "now",
}  # fmt: skip
# stop words that are also a quantity's noun after another ("the charging current"): they end
# nothing once the noun has begun, and only lead it ("the current value") when they open it
_LEADING_ONLY = {"current"}
# nouns that name no quantity by themselves ("the value that is flashing", "the setting")
_BARE = {
    "value", "values", "setting", "settings", "number", "figure", "display", "it", "them",
    "field", "fields", "item", "items", "digit", "digits", "entry",
}  # fmt: skip


def raised_quantity(b: Builder, tokens: list[str]) -> tuple[str, int] | None:
    """The quantity the pair's own legend or sentence says it raises and lowers, as a variable
    name ("heat_level"), with the unit it was read from; None when no unit naming the pair
    says so, or when its units name two different quantities."""
    found: dict[str, int] = {}
    for i, text, label in label_units(b, tokens):
        pos = after_label(text, label)
        for m in _RAISED_RE.finditer(text, pos):
            if not _leads(text[pos : m.start()]):
                continue  # "Next lower output step": an adjective, not what the key does
            rest = text[m.start("noun") :].split(".")[0]
            other = re.search(r"\bor\b(.*)", rest)
            if (
                other
                and re.search(r"\bthe\b", other.group(1))
                and not _VERB_RE.search(other.group(1))
            ):
                return None  # "raises the delay or, on BAKE only, the bake time": two
            noun = quantity_noun(m.group("noun"))
            if noun and not (an_amount(noun, rest) or _set_section(b, noun)):
                noun = ""  # "raise the footrest", "lower the noise": no amount of the pair
            if noun:
                found.setdefault(noun, i)
            break
    if len(found) != 1:
        return None
    noun, at = next(iter(found.items()))
    return noun, at


# endings of nouns that name an amount ("brightness", "intensity", "strength", "warmth")
_AMOUNT_ENDINGS = ("ness", "ity", "th")


def an_amount(noun: str, clause: str) -> bool:
    """The raised noun is an amount the pair can set: a quantity noun the reader knows
    ("temperature", "level"), a noun of an amount ("firmness", "intensity"), a bare "value"
    or "number" someone's ("the target number"), or a noun the clause gives a range or values
    for ("the jet height, from 1 to 5"); not a part that moves ("raise the footrest")."""
    parts = noun.split("_")
    if any(w in SETTING_NOUNS for w in parts) or parts[-1] in _BARE:
        return True
    if any(w.endswith(_AMOUNT_ENDINGS) and len(w) >= 6 for w in parts):
        return True
    return re.search(r"\d", re.split(r"[.;]", clause)[0]) is not None


def _set_section(b: Builder, noun: str) -> bool:
    """The manual gives the noun a section of its own for setting it ("Setting the target
    pressure", "Set the goal"): an amount someone sets, though no number stands beside it."""
    first = noun.split("_")[0]
    heading = re.compile(
        rf"^\W*(?:\d+(?:\.\d+)*\.?\s+)?set(?:ting)?\s+(?:the\s+|a\s+)?{first}\b", re.I
    )
    return any(heading.search(u.heading) for u in b.manual.units if u.heading)


def _leads(before: str) -> bool:
    """The verb opens what the unit says of the key: first after its name and a separator
    ("▲ / ▼ | Raise / lower …", "− and + lower or raise …") or after "to" ("press + to
    increase the delay")."""
    ws = words(before)
    return (
        not ws
        or ws[-1] in {"to", "will", "then", "keys", "buttons", "key", "button"}
        or (bool(before.rstrip()) and before.rstrip()[-1] in "|:;—–")
    )


def label_units(b: Builder, tokens: list[str]) -> Iterator[tuple[int, str, str]]:
    """Each unit that names one of the keys, with its index and the key's printed name: where
    a pair's legend or sentence says what the pair moves (read here and in ``up_down_nouns``)."""
    for token in tokens:
        lab = b.labels.get(token)
        if lab is not None:
            for i in lab.mentions:
                yield i, b.manual.units[i].text, lab.text


def after_label(text: str, label: str) -> int:
    """Where the key's own part of a unit starts: after its printed name, when it is there."""
    if label:
        k = text.upper().find(label.upper())
        if k >= 0:
            return k + len(label)
    return 0


def quantity_noun(phrase: str) -> str:
    """ "heat level of the selected zone" → heat_level; "value shown" → "" (no quantity)."""
    kept: list[str] = []
    for w in words(phrase):
        if w in _STOP and not (kept and w in _LEADING_ONLY):
            if kept:
                break
            continue
        kept.append(w)
    if not kept or all(w in _BARE for w in kept):
        return ""
    known = [w for w in kept if w in SETTING_NOUNS and w != "setting"]
    if known:  # "the water temperature", "the heat level": the quantity's own noun
        return known[-1]
    return "_".join(kept[:2])


def own_sentence(b: Builder, token: str, unit: int) -> str:
    """The sentence of a unit that names the key, from its name on ("… or, after TIMER, the
    auto-off time in hours": what TIMER shows, not the heat level before it)."""
    text = b.manual.units[unit].text
    lab = b.labels.get(token)
    start = after_label(text, lab.text) if lab is not None else 0
    return text[start:].split(". ")[0]


def sets_with_pair(b: Builder, key: str, pair: list[str]) -> bool:
    """The key's own sentence says its setting is set with the stepping pair ("TIMER  Set the
    timer with − / +"): a pair that also raises a quantity of its own ("+  Raise the speed (or
    the timer)") serves both — alone its own quantity, after the key the key's setting."""
    signs = [b.labels[t].text for t in pair if t in b.labels and b.labels[t].text]
    if not signs:
        return False
    sign_re = re.compile(
        r"\bwith\s+(?:the\s+)?(?:" + "|".join(re.escape(s) for s in signs) + r")(?!\w)", re.I
    )
    return any(sign_re.search(own_sentence(b, key, i)) for i in mentions_of(b, key))


# "no other key is needed", "without pressing any other key first", "while no other setting
# is open", "while no menu is open": the pair's bare use, when no key chose anything else
_ALONE_RE = re.compile(
    r"\bno other (?:key|button|setting|menu)s?\b"
    r"|\bwithout (?:(?:pressing|touching|using)\s+)?(?:any|another)\s+(?:other\s+)?(?:key|button)"
    r"|\bno (?:menu|setting) is (?:open|shown|opened)\b"
    # "▲ and ▼ change the channel only when the display shows CH", "Press ▲ or ▼ while the
    # display shows the channel": the pair's use in the display's own view (set16)
    r"|\b(?:only\s+)?(?:when|while) the (?:display|screen) shows\b",
    re.I,
)
# "▲ and ▼ change the resistance level", "▲ / ▼ only set the days": what the pair moves
_MOVED_RE = re.compile(
    r"^\W*(?:(?:only|then|also|just)\s+)?(?:change|changes|set|sets|adjust|adjusts|move|moves)"
    r"\s+(?:the\s+|its\s+)?(?P<noun>[a-z][a-z-]*(?:\s+[a-z][a-z-]*){0,2})",
    re.I,
)


# (in any case: the view may open the sentence, "While the display shows the channel, …")
_VIEW_NOUN_RE = re.compile(
    r"^(?:only\s+)?(?:when|while) the (?:display|screen) shows the ([a-z]+)", re.I
)


def set_alone(b: Builder, pair: list[str]) -> str:
    """The setting a sentence says the pair sets by itself ("The temperature is set with ▲ and
    ▼ – no other key is needed", "Without pressing any other key first, ▲ and ▼ change the
    resistance level", "▲ / ▼ only set the days while no other setting is open"): what the
    pair changes when no key chose anything else, even when its other sentences speak of the
    times it sets after such a key; "" if none says so."""
    signs = [b.labels[t].text for t in pair if t in b.labels and b.labels[t].text]
    if not signs:
        return ""
    sign_re = re.compile("|".join(rf"(?<!\w){re.escape(s)}(?!\w)" for s in signs))
    for unit in b.manual.units:
        for sentence in re.split(r"(?<=[.;:])\s+", unit.text):
            alone = _ALONE_RE.search(sentence)
            if alone is None:
                continue
            found_signs = list(sign_re.finditer(sentence))
            if not found_signs:
                continue
            sign = found_signs[-1]  # the last sign: its verb follows it ("▲ and ▼ change …")
            moved = _MOVED_RE.match(re.sub(r"\([^)]*\)", " ", sentence[sign.end() :]))
            noun = quantity_noun(moved.group("noun")) if moved is not None else ""
            viewed = _VIEW_NOUN_RE.search(sentence[alone.start() :])
            if not noun and viewed is not None:  # "Press ▲ or ▼ while the display shows the
                noun = quantity_noun(viewed.group(1).lower())  # channel": the view's own quantity
            if noun:
                return noun
            if sign.start() > alone.start():
                continue  # (a noun before the sign is another thing's: "without any key …")
            found = [
                (m.start(), n)
                for n in SETTING_NOUNS
                if (m := re.search(rf"\b{n}\b", sentence[: alone.start()], re.I))
            ]
            if found:
                return min(found)[1]
    return ""


_DAYS_RE = re.compile(r"\d\s*days?\b", re.I)
_BY_ONE_RE = re.compile(r"\b(?:by|in steps of)\s+(?:one|1|a single)\b", re.I)  # "by one day"


def alone_range(b: Builder, pair: list[str], noun: str) -> Evidence | None:
    """The range of the pair's own setting, from a sentence naming both the pair and that
    setting ("Press ▲ or ▼. The display shows DAYS … the range is 1 to 45 days"), not the
    ranges of the settings other keys open with the same pair, nor a range in a unit measuring
    another quantity; None when no sentence gives it.
    The sentences after one naming the pair count too ("2. Press ▲ or ▼." "The range is …")."""
    stem = re.sub(r"(?<!s)s$", "", noun.split("_")[-1])  # ("brightness" keeps its double s)
    if len(stem) < 3:
        return None
    named = re.compile(rf"\b{re.escape(stem)}s?\b", re.I)
    units = b.manual.units
    mentions = sorted({i for t in pair if t in b.labels for i in b.labels[t].mentions})
    near = [  # (a step's next sentences too)
        j
        for i in mentions
        for j in range(i, min(i + 4, len(units)))
        if units[j].heading == units[i].heading
    ]
    for i in dict.fromkeys(near):
        stops = end_stops(units[i].text)  # "Nothing happens beyond 1 or 8" under its heading
        if stops and (named.search(units[i].text) or named.search(units[i].heading or "")):
            return Evidence(ranges=[stops], range_at=i)
        if not named.search(units[i].text):
            continue
        found = [
            r
            for r in find_ranges(units[i].text)
            if r.high > r.low and UNIT_QUANTITY.get(r.unit, noun)[:4] in noun
        ]  # (not "away days … held at 5 to 10 °C": a temperature is no count of days)
        if len(found) == 1:
            r = found[0]
            if r.step is None and _BY_ONE_RE.search(units[i].text):
                r = replace(r, step=1.0)
            if not r.unit and _DAYS_RE.search(units[i].text):
                r = replace(r, unit="d")  # "1 to 45 days": a count of days (the goal's "2 weeks")
            return Evidence(ranges=[r], range_at=i)
    return None
