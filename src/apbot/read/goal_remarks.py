"""Remarks around an instruction: the clauses that ask nothing of the appliance.

Users say more than what they want set: "Cook the rice, I'll be back in an hour", "…, we are
4 at the table", "… — put the dish on the lower rack". The numbers and times in such a clause
are about the user's day, not a setting, so the parser drops the clause before it reads.

A clause (after the first; clauses part at a comma, semicolon, colon, dash, bracket or
sentence end, or at "and", "but", "because" … before a new subject) is a remark when

* its subject is the user or other people, not the appliance: "I'll", "we are", "my kids",
  "our guests", "dinner is", "the last one", "it's for", "it's my", "there are" — and it asks for
  nothing ("want", "need", "please", "set", "start", "make sure", "have it ready" keep it) and
  names none of the model's values; or
* it tells the user to put something somewhere ("put the dish on the lower rack"): a verb of
  placing with a thing, not "it", as its object, and a place with an article ("on the …",
  not "on 4" or "on"), and no word of a setting's name ("put the child lock on" is a setting).

"start in 90 minutes", "ready in 2 hours" and "delay it 3 hours" have no such subject and
stay settings.
"""

from __future__ import annotations

import re

from apbot.read.goal_names import value_matches
from apbot.read.goal_text import Text
from apbot.read.goal_view import Model, own_stems

_PEOPLE = (
    r"i|i'm|im|i'll|i've|i'd|i was|we|we're|we'll|we've|we'd|they|they're|they'll|he|she|"
    r"he's|she's|my|our|his|her|their|dinner|lunch|breakfast|supper|tea time|the guests|"
    r"guests|the kids|kids|everyone|nobody|the last (?:one|time|batch|load)|last time|"
    r"the old one|(?:it|this|that)(?:'s| is) (?:for|my|our|the first)|this one is for|there are|"
    r"there's|there will be"
)
_CONJUNCTIONS = r"and|but|because|since|as|while|though|although|cause"
_SPLIT = re.compile(
    rf"\s*(?:[,;()]|[.!?:]\s|\s[-–—]+\s|[–—])\s*|\s+(?:{_CONJUNCTIONS})\s+(?=(?:{_PEOPLE})\b)",
    re.IGNORECASE,
)
_SUBJECT = re.compile(rf"(?:(?:{_CONJUNCTIONS})\s+)?(?:{_PEOPLE})\b", re.IGNORECASE)
_ASKS = re.compile(
    r"\b(?:want|wants|wanted|need|needs|prefer|like|please|should|must|make sure|set|start|"
    r"stop|switch|turn|keep|use|(?:have|get|leave) (?:it|them)|(?:it|them)(?:'s| is| are)? "
    r"(?:ready|done|finished|hot|warm|cooked))\b",
    re.IGNORECASE,
)
_THING = r"(?:the|a|an|your|my|our|some|this|that|these|those|its|their|all the)\s"
_PLACING = re.compile(
    rf"(?:(?:and|then)\s+)?(?:put|place|lay|stand|sit|set down|slide|load)\s+{_THING}"
    rf".*?\b(?:on|in|into|onto|inside|under|on top of)\s+{_THING}",
    re.IGNORECASE,
)

# "on the gentlest level", "on its highest setting": what is put there is set to a level
_ON_A_LEVEL = re.compile(
    r"\b(?:on|at|to)\s+(?:the|its|their)\s+(?:\w+\s+){0,2}(?:level|setting)s?\b", re.IGNORECASE
)


def without_remarks(view: Model, instruction: str) -> str:
    """The instruction without its remark clauses (unchanged when it has none)."""
    text = instruction.replace("’", "'")
    pieces: list[str] = []
    kept_at = last_end = start = 0
    first = True
    for match in [*_SPLIT.finditer(text), None]:
        end = match.start() if match else len(text)
        clause = text[start:end].strip()
        if not first and clause and _remark(view, clause):
            pieces.append(text[kept_at:last_end])
            kept_at = end
            if match and ")" in match[0]:  # "… (it's my first try) for 20 minutes"
                pieces.append(" ")
                kept_at = match.end()
        if clause:
            first = False
        last_end = end
        if match:
            start = match.end()
    if not pieces:
        return instruction
    pieces.append(text[kept_at:])
    return "".join(pieces).strip()


def _remark(view: Model, clause: str) -> bool:
    """A clause about the user or others that asks nothing and names no value, or one that
    tells the user where to put something."""
    if _PLACING.match(clause):
        if _ON_A_LEVEL.search(clause):
            return False  # "put the rollers on the gentlest level": a level, not a place
        said = set(Text.of(clause).stems)
        return not any(own_stems(info) & said for info in view.infos.values())
    if not _SUBJECT.match(clause) or _ASKS.search(clause):
        return False
    return not value_matches(view, Text.of(clause))
