"""Adverbs that name no value even where their stem is one: a time adverb says when the job is
done, not how ("it should be done shortly" is no SHT read as "short"), and an adverb of the
user's own act says how the user acts, not what the appliance runs ("I will stop it manually"
is no MAN read as "manual")."""

from __future__ import annotations

from apbot.read.goal_text import CLAUSE_ENDS, Text
from apbot.read.goal_vocab import stem

# adverbs saying when, never how: "done shortly" names no SHT (short). Not "daily", "weekly",
# "nightly", "hourly": an interval setting's values are named so ("water daily" is DAILY)
_TIME_ADVERBS = frozenset({"shortly", "lately"})
# the user's own act in a clause: "I will …", "we'll …", "… myself"; or stopping it oneself
_OWN_ACT = frozenset({"i'll", "we'll", "myself", "ourselves"})
_WILL = frozenset({"will", "'ll", "ll", "shall"})
_STOP_STEMS = frozenset({stem("stop"), stem("end"), stem("finish"), stem("cancel")})


def adverb_of_no_value(text: Text, k: int) -> bool:
    """Whether token k is an adverb that names no value even where its stem is one: a time
    adverb ("shortly") says when, not how; an adverb of the user's own act says how
    the user acts, not what the appliance runs: its clause says what the user will do ("I will
    stop it manually", not "I want it dried gently") or has a verb of stopping ("stop it
    manually": the user stopping it)."""
    word = text.word(k)
    if not word.endswith("ly") or len(word) <= 5:
        return False
    if word in _TIME_ADVERBS:
        return True
    j = k - 1
    while j >= 0 and text.word(j) not in CLAUSE_ENDS and text.word(j) != ",":
        if text.stems[j] in _STOP_STEMS or text.word(j) in _OWN_ACT:
            return True
        if text.word(j) in ("i", "we") and text.word(j + 1) in _WILL:
            return True
        j -= 1
    return False
