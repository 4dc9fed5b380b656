"""Several settings sent to the same end at once: "turn the echo and the microphone all the
way up", "bass and treble right down". The end belongs to each setting named, joined by
"and", right before it — one end said for all of them, not a tie to leave unread."""

from __future__ import annotations

from apbot.model.values import words_to_number
from apbot.read.goal_halfway import to_an_end
from apbot.read.goal_ladders import is_off_level, ordered, ordered_values
from apbot.read.goal_text import CLAUSE_ENDS, Text, negated_before
from apbot.read.goal_view import Goal, Model, domain_values

# words that send a setting named before them its own way or to its own value ("turn the bass
# up and the treble all the way down"): the end is not said of the settings before them
_OWN_WAY = frozenset(
    {"up", "down", "higher", "lower", "louder", "softer", "more", "less", "to", "at"}
)
_REACH = 8  # tokens before the end's words: "the echo and the microphone turned"
_NAMED = 0.8  # a setting's own word (its name or its key's label), not a loose one


def _said_of_its_own(word: str) -> bool:
    """A direction, a value's "to" / "at" or a number between the settings and the end."""
    if word in _OWN_WAY or word[:1].isdigit():
        return True
    return word not in ("a", "an") and words_to_number(word) is not None


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
            if word in CLAUSE_ENDS or word == "," or _said_of_its_own(word):
                break  # ("the bass up and the treble right down": the bass's own way, not the end)
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
