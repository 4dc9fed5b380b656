"""Several settings sent to the same end at once: "turn the echo and the microphone all the
way up", "bass and treble right down". The end belongs to each setting named, joined by
"and", right before it — one end said for all of them, not a tie to leave unread."""

from __future__ import annotations

from apbot.read.goal_halfway import to_an_end
from apbot.read.goal_ladders import is_off_level, ordered, ordered_values
from apbot.read.goal_text import CLAUSE_ENDS, Text, negated_before
from apbot.read.goal_view import Goal, Model, domain_values

_REACH = 8  # tokens before the end's words: "the echo and the microphone turned"
_NAMED = 0.8  # a setting's own word (its name or its key's label), not a loose one


def joined_ends(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int]
) -> None:
    """Set each open ordered setting of an "X and Y all the way up / right down" to that end."""
    for k in range(len(text.tokens)):
        end = to_an_end(text, k)
        if end is None or k in claimed:
            continue
        start = k - 3 if text.word(k - 1) == "way" else k - 1
        named: list[str] = []
        joined = False
        for j in range(start - 1, max(-1, start - 1 - _REACH), -1):
            word = text.word(j)
            if word in CLAUSE_ENDS or word == ",":
                break
            if word == "and":
                joined = joined or bool(named)
                continue
            for name, info in view.infos.items():
                if (
                    name not in goal
                    and name not in named
                    and info.role == "setting"
                    and ordered(info)
                    and info.vocab.get(text.concepts[j], 0.0) >= _NAMED
                ):
                    named.append(name)
                    first = j
        if len(named) < 2 or not joined or negated_before(text, first):
            continue  # one setting named: goal_halfway reads it; none: nothing joined
        for name in named:
            info = view.infos[name]
            values = ordered_values(domain_values(view, info, goal))
            if len(values) > 2 and is_off_level(info, values[0]):
                values = values[1:]
            if len(values) < 3:
                continue
            goal[name] = values[end]
            where[name] = k
        claimed.add(k)
