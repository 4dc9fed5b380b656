"""Open goal entries: a setting the user names that a read belief lacks, kept for the closed loop.

A belief read from a manual can miss a setting altogether (its variable, its procedure), while
the panel still has its key and the display still shows it. When the instruction says a value
no belief variable took, next to a word that names such a setting, the parser keeps it as an
*open* entry — a variable the belief does not have, named after that word, with the value as
said — and the agent's variable finder (:mod:`apbot.agent.discovery`) looks for it on the panel.

Only for a read belief (``parse_instruction(..., outside=[...])``), and only from words the
instruction says. Precision matters more than recall: the entries are made only where the
panel itself points at a setting the belief gives no role —

- *a key's own noun*: the quantity stands beside a word of the name of a key the belief gives no
  role (``press_weight``: "600 g weight", "weight 600 g");
- *a level on stepping keys*: a bare number right after a noun ("level 7", "heat on 2") when the
  panel has ▲/▼ (or +/−, a dial) keys the belief gives no role, which is how such a number is
  set, and the noun is no word of a setting the belief has;
- *a quantity of a kind the belief has no setting for*: "for 45 minutes", "at 600 W", "for
  14 days" when no belief setting takes a duration (a power, ...) and none is named beside it
  (a restatement: "the lowest power, 200 W"), while some key has no role: named by its kind
  (``time``, ``wattage``, ``days``);
- *a value word beside a key's own noun*: "the fan to high", "a gentle fan", "the light on".

If the finder cannot find it, the agent sets the rest of the goal (``agent/loop.py``).
"""

from __future__ import annotations

from collections.abc import Collection
from typing import Any

from apbot.model.key_roles import adjusted_by, is_switch, misread_key
from apbot.model.schema import ApplianceModel, DiscreteVariable, TimeVariable
from apbot.read.goal_said import (
    NEVER_NAMES,
    NOT_LEVELS,
    as_said,
    counted_stems,
    in_days,
    manual_stems,
    per_period,
    remark,
    tally,
)
from apbot.read.goal_text import CLAUSE_ENDS, Text, near_vocab, repeat_for_a_length
from apbot.read.goal_view import Goal, Model, own_stems
from apbot.read.goal_vocab import STOP_WORDS, stem
from apbot.read.numbers import Mention

_KEY_VERBS = frozenset(
    {"press", "hold", "turn", "push", "touch", "tap", "long", "short", "button", "key", "knob"}
)
_STEPPING = frozenset(
    {"up", "down", "plus", "minus", "cw", "ccw", "next", "prev", "inc", "dec", "more", "less"}
)
_LINKS = frozenset({"to", "at", "on", "of"})  # "level to 7", "heat on 2", "weight of 600 g"
_NOT_NAMES = STOP_WORDS | _LINKS | {"for", "with", "by", "in", "and", "or", "it", "number"}


def open_entries(
    view: Model,
    text: Text,
    mentions: list[Mention],
    goal: Goal,
    claimed: set[int],
    where: dict[str, int],
    manual: str = "",
) -> dict[str, Any]:
    """Open entries (name → value as said) for the quantities and words no belief variable
    took; names are new (never a variable the belief has, never one the goal holds). With the
    ``manual``, a noun that names an entry must be one the manual uses: a user names a setting
    the way its manual does ("level 7"), and a remark about people ("my kids are 5") uses
    words no manual has."""
    model = view.model
    printed = manual_stems(manual)
    counted = counted_stems(manual)
    roleless = _roleless_keys(model)
    nouns = {w: key for key in roleless for w in _key_words(key)}  # noun -> its key
    roled: dict[str, list[str]] = {}  # noun -> the keys with a role it names
    for key in _roled_keys(model, roleless):
        for w in _key_words(key):
            roled.setdefault(w, []).append(key)
    stepping = any(set(key.split("_")) & _STEPPING for key in roleless)
    known = _belief_stems(view)
    placed = set(where.values())  # kept as said for a setting the belief has
    taken = set(claimed) | {k for m in mentions if m.start in placed for k in range(m.start, m.end)}
    found: dict[str, Any] = {}
    walked: set[str] = set()  # keys an entry already says the reader misread
    for mention in mentions:
        if mention.kind == "clock" or any(k in taken for k in range(mention.start, mention.end)):
            continue
        if tally(text, mention) or per_period(text, mention):
            continue  # "20 times", "three doses a day": counts, no setting
        value = as_said(text, mention)
        if value is None:
            continue
        name = _key_noun(text, mention, nouns, known)
        if name is None and remark(text, mention):
            continue
        if name is None:
            name, keys = _misread_noun(view, text, mention, value, roled, goal)
            if keys & walked:
                continue  # one setting sought under a key: "auto menu A-6, 800 g"
            walked |= keys
        if name is None and stepping and mention.kind == "number":
            name = _level_noun(text, mention, known, printed)
        if name is None and not _of_its_kind(view, mention, text):
            name = KIND_NAMES.get(quantity_kind(mention) or "")
            if name == "time" and in_days(text, mention):
                name = "days"  # a number of days away, not a cooking time ("48 hours" is one)
            count = quantity_kind(mention) == "count"
            if name is not None and not roleless:  # no key to try: the programme's next step
                chosen = _chosen_beside(view, text, mention, goal, where, count)
                name = None if chosen is None else f"{chosen}_{name}"
            elif count and manual and stem(mention.unit) not in counted:
                name = None  # "it's for 2 people": a count of what the manual never counts
        if name is None or name in NEVER_NAMES or name in view.infos or name in goal:
            continue
        if name in found:
            continue
        found[name] = value
    for name, value in _worded(text, nouns, known, taken).items():
        if not ({name} & (set(view.infos) | set(found) | NEVER_NAMES | set(goal))):
            found[name] = value
    return found


_VERBS = frozenset(
    {
        "set", "turn", "put", "switch", "use", "select", "choose", "press", "make", "start",
        "run", "give", "keep", "leave", "change", "pick", "want", "need", "get", "have", "do",
        "please", "then", "also", "just", "now", "go", "let", "like", "would", "could",
        "bring", "adjust", "raise", "lower", "increase", "decrease", "enable", "disable",
        "activate", "add", "pour", "cook", "brew", "heat", "wash", "dry", "bake", "only",
    }
)  # fmt: skip
_SWITCHED = frozenset({"on", "off"})


def _worded(text: Text, nouns: dict[str, str], known: set[str], taken: set[int]) -> dict[str, str]:
    """A value word beside a role-less key's noun: "fan to high", "the high fan" (a word no
    belief variable took), "the light on" (a lamp switched)."""
    found: dict[str, str] = {}
    for k in range(len(text.tokens)):
        if k in taken or text.stems[k] in known:
            continue
        noun = _noun_at(text, k, nouns)
        if noun is None:
            continue
        after, later = text.word(k + 1), text.word(k + 2)
        if after in ("to", "at") and _value_word(text, k + 2, known, taken):
            found.setdefault(noun, later)
        elif after in _SWITCHED and (later in CLAUSE_ENDS or later in (",", "and", "")):
            found.setdefault(noun, after)
        elif _value_word(text, k - 1, known, taken) and text.word(k - 2) not in _SWITCHED:
            found.setdefault(noun, text.word(k - 1))
    return found


def _noun_at(text: Text, k: int, nouns: Collection[str]) -> str | None:
    """The role-less key noun the word at ``k`` is (``fans`` for FAN), if any."""
    word = text.word(k)
    if not word.isalpha() or word in _NOT_NAMES:
        return None
    here = text.stems[k]
    for noun in nouns:
        key = stem(noun)
        if len(here) >= 3 and (here.startswith(key) or key.startswith(here)):
            return noun
    return None


def _value_word(text: Text, k: int, known: set[str], taken: set[int]) -> bool:
    """A word that can be a value as said: letters, no setting's own word, not read already,
    no verb of asking."""
    word = text.word(k)
    return (
        0 <= k < len(text.tokens)
        and k not in taken
        and word.isalpha()
        and len(word) >= 2
        and word not in _NOT_NAMES
        and word not in _VERBS
        and word not in _SWITCHED
        and text.stems[k] not in known
    )


KIND_NAMES = {
    "time": "time",
    "mass": "weight",
    "temperature": "temperature",
    "volume": "volume",
    "power": "wattage",
    "length": "length",
    "count": "quantity",  # how many, typed or stepped as a number
}


def quantity_kind(mention: Mention) -> str | None:
    """What a quantity with a unit measures (None: a bare number, a clock time)."""
    if mention.kind == "duration":
        return "time"
    if mention.kind == "fahrenheit":
        return "temperature"
    if mention.kind == "number" and mention.unit:
        return "count"  # "3 cups", "two slices": a number of things
    return mention.dimension if mention.kind == "quantity" else None


def _of_its_kind(view: Model, mention: Mention, text: Text) -> bool:
    """The belief has a setting that takes quantities of this kind, or one its words name
    right there ("the lowest power, 200 W": a restatement of a level the belief has), or the
    mention has no kind: the parser's own steps gave it, or judged it a remark."""
    kind = quantity_kind(mention)
    if kind is None:
        return True
    for info in view.infos.values():
        if info.role != "setting":
            continue
        timed = isinstance(info.var, TimeVariable) or info.dimension == "time"
        # a setting that could hold it: a time for a time, a number for any other
        could = not isinstance(info.var, DiscreteVariable) and timed == (kind == "time")
        # (a time of day, the clock or when something starts, holds no duration)
        could = could and not (mention.kind == "duration" and info.timing in ("clock", "at"))
        near = near_vocab(info, text, mention.start, mention.end, reach=4)
        repeat = repeat_for_a_length(text, mention, info)
        if could and near and not (repeat and near < 0.5):
            return True
        if repeat:
            continue  # "cleaning every two hours" is no sleep period's LENGTH
        lasting = timed and info.timing not in ("clock", "finish", "at")  # not a time of day
        if (kind == "time" and lasting) or (kind != "time" and info.dimension == kind):
            return True
    return False


def _chosen_beside(
    view: Model,
    text: Text,
    mention: Mention,
    goal: Goal,
    where: dict[str, int],
    count: bool = False,
) -> str | None:
    """The choice the goal makes in the quantity's clause, nearest to it ("450 g of fish" with
    the automatic defrost: the defrost menu's fish): a weight, a time the belief lacks is
    likely that choice's next step, as on an automatic menu. A ``count`` must be in the
    choice's own stretch between commas ("the beverage menu for two mugs"): an aside after
    a comma ("…, it's for 2 people") counts the household, not the menu's servings."""
    ends = CLAUSE_ENDS | {","} if count else CLAUSE_ENDS
    best: tuple[int, str] | None = None
    for name, at in where.items():
        info = view.infos.get(name)
        if name not in goal or info is None or info.role != "setting":
            continue
        if not isinstance(info.var, DiscreteVariable):
            continue
        low, high = sorted((at, mention.start))
        if any(text.word(k) in ends for k in range(low, high)):
            continue
        distance = abs(at - mention.start)
        if best is None or distance < best[0]:
            best = (distance, name)
    return None if best is None else best[1]


def _roled_keys(model: ApplianceModel, roleless: list[str]) -> list[str]:
    """Keys the belief gives a setting to adjust (not digits, not waiting)."""
    return [
        name
        for name, spec in model.actions.items()
        if name not in roleless
        and spec.skill != "wait"
        and not name.rsplit("_", 1)[-1].isdigit()
        and adjusted_by(model, name)
    ]


def _misread_noun(
    view: Model, text: Text, mention: Mention, value: Any, roled: dict[str, list[str]], goal: Goal
) -> tuple[str | None, set[str]]:
    """ "Defrost 400 g" with a DEFROST key the belief reads as a switch: the quantity beside
    a key's own noun (or a switch's, in its clause: "thaw a kilo with the defrost pad"), which
    no setting that key adjusts could hold, is likely the key's real setting (one per key).
    Named after the noun, or after the noun and the quantity's kind where the noun names a
    belief variable already (``defrost_weight``); with the keys it names."""
    near = _neighbours(text, mention)
    if text.word(mention.start - 1) == "for":  # "soak for 8 hours"
        near.append(mention.start - 2)
    beside = len(near)
    if quantity_kind(mention) is not None:  # a quantity with its unit, not a bare number
        near += _in_clause(text, mention)
    for at, k in enumerate(near):
        noun = _noun_at(text, k, roled)
        if noun is None:
            continue
        keys = roled[noun]  # every key it names: "zone" for ZONE and for ZONE+TIMER held
        if not all(misread_key(view.model, key, value) for key in keys):
            continue
        if at >= beside and not all(
            is_switch(view.model, name) for key in keys for name in adjusted_by(view.model, key)
        ):
            continue  # further off, only a switch's key: it holds no quantity at all
        if any(_chose(view, name, goal) for key in keys for name in adjusted_by(view.model, key)):
            return None, set()  # "the lower zone at 40 W": the key chose, the quantity is another's
        if noun not in view.infos and noun not in goal:
            return noun, set(keys)
        return f"{noun}_{KIND_NAMES.get(quantity_kind(mention) or '', 'level')}", set(keys)
    return None, set()


_REACH = 5  # words between a quantity and a switch's noun in its phrase
_PHRASE_ENDS = CLAUSE_ENDS | {",", "and", "then", "but"}


def _in_clause(text: Text, mention: Mention) -> list[int]:
    """The words of the quantity's phrase (up to a comma, an "and") within reach of it,
    nearest first ("thaw a kilo of meat with the defrost pad")."""
    out: list[tuple[int, int]] = []
    for side in (-1, 1):
        k = mention.start - 1 if side < 0 else mention.end
        edge = k
        while 0 <= k < len(text.tokens) and abs(k - edge) < _REACH:
            if text.word(k) in _PHRASE_ENDS:
                break
            out.append((abs(k - edge), k))
            k += side
    return [k for _, k in sorted(out)]


def _chose(view: Model, name: str, goal: Goal) -> bool:
    """The goal sets ``name`` to a word of a list (not a switch on or off): the key's role
    was taken as read."""
    spec = view.model.variables.get(name)
    return name in goal and isinstance(spec, DiscreteVariable) and not is_switch(view.model, name)


def _roleless_keys(model: ApplianceModel) -> list[str]:
    """Keys that start nothing the belief knows — in no procedure's first step that sets
    something, not acting from anywhere, not waiting, no digit — the keys the finder tries
    (a key met only as a later step may well be the missed setting's)."""
    roled: set[str] = set()
    for steps in model.features.values():
        first = steps[0]
        if first.variable is not None or first.set or len(steps) > 1:
            roled.update(first.actions)
    for entry in model.anywhere:
        roled.update(entry.actions)
    return [
        name
        for name, spec in model.actions.items()
        if name not in roled and spec.skill != "wait" and not name.rsplit("_", 1)[-1].isdigit()
    ]


def _key_words(key: str) -> list[str]:
    """The nouns of a key's name (``press_weight`` → weight; ``turn_time_cw`` → time)."""
    return [
        w
        for w in key.split("_")
        if len(w) >= 3 and w.isalpha() and w not in _KEY_VERBS and w not in _STEPPING
    ]


def _belief_stems(view: Model) -> set[str]:
    """Stems of the words that name the belief's variables: a noun among them names a setting
    the belief has, which the parser's own steps had their chance at."""
    return {s for info in view.infos.values() for s in own_stems(info)}


def _neighbours(text: Text, mention: Mention) -> list[int]:
    """The word before the quantity (past one linking word) and the word after it, in its
    clause: where a setting's name stands beside its value."""
    out: list[int] = []
    k = mention.start - 1
    if text.word(k) in _LINKS:
        k -= 1
    if k >= 0 and text.word(k) not in CLAUSE_ENDS and text.word(k) != ",":
        out.append(k)
    after = mention.end
    if after < len(text.tokens) and text.word(after) not in CLAUSE_ENDS:
        out.append(after)
    return out


def _key_noun(text: Text, mention: Mention, nouns: dict[str, str], known: set[str]) -> str | None:
    """The noun of a role-less key standing beside the quantity."""
    for k in _neighbours(text, mention):
        noun = None if text.stems[k] in known else _noun_at(text, k, nouns)
        if noun is not None:
            return noun
    return None


def _level_noun(
    text: Text, mention: Mention, known: set[str], printed: frozenset[str] = frozenset()
) -> str | None:
    """ "level 7", "heat on 2": the noun right before a bare whole number (past one linking
    word), when it names no setting the belief has — a word, not a verb ("the kids are 5"),
    and one the manual uses when there is a manual."""
    if mention.value != int(mention.value) or mention.words:
        return None
    k = mention.start - 1
    if text.word(k) in _LINKS:
        k -= 1
    word = text.word(k)
    if len(word) < 3 or not word.isalpha() or word in _NOT_NAMES or text.stems[k] in known:
        return None
    if word in _VERBS or word in NOT_LEVELS or (printed and text.stems[k] not in printed):
        return None
    if word.endswith("ed") and not word.endswith("eed"):
        return None  # a verb's past ("the door opened 20 times"), not a setting's noun
    return word
