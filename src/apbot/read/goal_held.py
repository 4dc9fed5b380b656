"""Whether a start the user mentions is a request to start now: "start it tonight" or "in two
hours" is a later start, "hold off on the heating" a start put off, "so the kids can't start it"
or "wait for me to start it" no request at all, "leave it off for now" the appliance kept off
(split from ``goal_start``, which sets power and running from them)."""

from __future__ import annotations

from apbot.read.goal_text import (
    CLAUSE_ENDS,
    NUMBER_WORDS,
    STRONG_VERBS,
    Text,
)
from apbot.read.numbers import find_mentions

START_WORDS = frozenset({"start", "begin", "started", "starting", "begins", "kick", "launch"})
KEEPING = frozenset({"leave", "left", "keep", "kept"})  # "leave it off", "kept running"


_WHEN_LATER = frozenset({"tonight", "tomorrow", "later", "monday", "tuesday", "wednesday"})
_WHEN_LATER |= frozenset({"thursday", "friday", "saturday", "sunday"})


_DAY_PARTS = frozenset({"week", "weekend", "month", "year", "morning", "afternoon", "evening"})
_DAY_PARTS |= frozenset({"night", "time", "day"}) | _WHEN_LATER


def said_later(text: Text, k: int) -> bool:
    """A start word followed in its clause by "in/after N ..." (a delayed start), by a later
    day ("a holiday starting tonight": when something begins, no request to start), or by
    "at" a time of day ("start mowing at 7 in the morning": when it starts, as scheduled)."""
    if text.word(k + 1) in _WHEN_LATER and text.word(k + 2) not in ("it", "the"):
        return True
    if _at_a_time_of_day(text, k):
        return True
    if text.word(k + 1) in ("this", "next") and text.word(k + 2) in _DAY_PARTS:
        return True  # "starting next week" (but "start this wash" is a start now)
    for j in range(k + 1, min(k + 6, len(text.tokens))):
        word = text.word(j)
        if word in CLAUSE_ENDS or word == ",":
            return False
        following = text.word(j + 1)
        if following in ("a", "an"):
            following = text.word(j + 2)
        numeral = following[:1].isdigit() or following in NUMBER_WORDS | {"half", "quarter"}
        if word in ("in", "after") and numeral:
            return True
    return False


_TIME_STOPS = CLAUSE_ENDS | {",", "and", "then", "but", "so", "until", "till", "when"}


def _at_a_time_of_day(text: Text, k: int) -> bool:
    """A time of day said with "at" in the start word's clause, within a few words, before
    another verb is joined on ("start it and stop at 7 pm": the time is the stop's)."""
    end = k + 1
    while end < min(k + 7, len(text.tokens)) and text.word(end) not in _TIME_STOPS:
        end += 1
    return any(
        mention.kind == "clock" and mention.lead == "at" and mention.start < end
        for mention in find_mentions(text.tokens[:end], skip=set(range(k + 1)))
    )


def held_back(text: Text, family: frozenset[str] | None = None) -> bool:
    """ "wait with the heating", "hold off on starting": the start is put off (no time given;
    "wait 2 hours before heating" is a delay). Only a wait for the start or the appliance's own
    work counts ("I'll wait before pouring", "hold off on keep warm" start nothing later)."""
    for k, token in enumerate(text.tokens):
        if not (
            (token.text == "wait" and text.word(k + 1) in ("with", "on", "before"))
            or (token.text == "hold" and text.word(k + 1) == "off")
        ):
            continue
        j = k + 2
        while text.word(j) in ("on", "with", "the", "a", "any"):
            j += 1
        work = text.word(j) in START_WORDS or text.word(j) in ("it", "that")
        verb = text.stems[j] if j < len(text.stems) else ""
        work = work or verb in (family if family is not None else STRONG_VERBS)
        if not work and text.word(j) not in CLAUSE_ENDS | {"", ","}:
            continue
        ahead = [text.word(j) for j in range(k + 1, min(k + 6, len(text.tokens)))]
        if not any(w[:1].isdigit() or w in NUMBER_WORDS for w in ahead):
            return True
    return False


_NOT_ASKED = frozenset({"can't", "cannot", "couldn't", "won't", "i'll", "i", "we'll", "we"})


def users_own(text: Text, k: int) -> bool:
    """The user waits to start it themselves ("wait for me to start", "until we tell it to
    start"): it is to be left unstarted. ("I'll start it myself" is said either way.)"""
    for d in range(1, 4):
        word = text.word(k - d)
        if word in CLAUSE_ENDS or word == ",":
            return False
        if word == "to" and text.word(k - d - 1) in ("me", "us"):
            return True
    return False


def left_off_for_now(text: Text, k: int) -> bool:
    """ "leave it off for now", "keep it off until I'm back": the appliance itself kept off."""
    return (
        text.word(k) == "off"
        and text.word(k - 1) == "it"
        and text.word(k - 2) in KEEPING
        and (text.word(k + 1), text.word(k + 2)) in (("for", "now"), ("until", "i"))
    )


def someone_else(text: Text, k: int) -> bool:
    """The start is said of someone else or of what may not happen ("so the kids can't start
    it", "I'll start it myself"): not a request to start."""
    for d in range(1, 4):
        word = text.word(k - d)
        if word in CLAUSE_ENDS or word == ",":
            return False
        if word in _NOT_ASKED or (word == "can" and text.word(k - d + 1) == "not"):
            return True
    return False
