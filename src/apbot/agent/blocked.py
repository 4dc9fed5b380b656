"""Screens the manual explains as a setting that cannot be changed now, and what guards it.

A key that brings up its setting's sign followed by dashes (``HRS --``, ``TEMP --``) or is
refused with a message (``PAUSE FIRST``) tells the agent that another setting blocks it. Manuals
print such screens beside their cause or remedy — a legend ("HRS -- hours cannot be set:
schedule mode is AUTO"), a troubleshooting row ("TEMP -- | ROOM water has no temperature
setting | choose HOT or COLD"), a step ("press MODE (MAN), then HOURS"). Each manual line that
prints the screen's message is searched for the values of the belief's other settings (in the
capitals displays and manuals print them) and for keys named after a verb ("press MODE"):

* a setting's current value named there is the block (schedule mode AUTO);
* values named of a setting whose current value is not among them are the way out (choose HOT
  or COLD): every other value blocks;
* a key named ("press ▶ first") blocks at the current value of the setting it switches.

The setting most lines name becomes a guard of the belief — while it holds, the key does not
work — and the planner then changes that setting before it presses the key again. Once per
message and key; nothing is written when no line of the manual prints the message.
"""

from __future__ import annotations

import re
from collections import Counter
from typing import Any

from apbot.agent.repair import RepairError, add_guard
from apbot.agent.session import Executed, Session
from apbot.model.display import display_value
from apbot.model.schema import DiscreteVariable

_DASHED = re.compile(r"[-–—]{2,}")  # a setting's sign with dashes in place of its value
_VERBS = r"(?:press|hold|touch|push|turn|tap)"
_GENERIC = frozenset({"on", "off"})  # said of too much to name a setting in a line
# a line saying a key or setting does not work now (not a legend of a value: "FRAME -- no frame")
_BLOCK = re.compile(
    r"\b(?:cannot|can't|can ?not|not (?:available|possible|adjustable)|unavailable|no effect|"
    r"(?:has|have|is) no|no (?:\w+ )?setting|do(?:es)? not|doesn't|don't|nothing|ignored|"
    r"locked|blocked|disabled|first|only)\b",
    re.IGNORECASE,
)


def blocked_by_manual(session: Session, done: Executed) -> bool:
    """Write the guard the manual gives for the screen ``done`` brought up, if it gives one.
    True when the belief changed (plan again: the planner lifts the guard first)."""
    manual = session.context.manual
    if not manual:
        return False
    model = session.belief.model
    key = done.action.name
    if key not in model.actions or not _own_key(session, key):
        return False
    own = _own_settings(session, done)
    for message in _messages(session, done):
        lines = _lines(manual, message)
        if not any(_BLOCK.search(line) for line in lines):
            continue  # no line says the key is blocked: the message may be a value's sign
        votes: Counter[tuple[str, tuple[str, ...]]] = Counter()
        for line in lines:
            for found in _blocks(session, line, own, key):
                votes[found] += 1
        if not votes or not session.budget.once("guard", f"manual:{message}:{key}"):
            continue
        (name, values), _ = votes.most_common(1)[0]
        spec = model.variables[name]
        assert isinstance(spec, DiscreteVariable)
        blocking: Any = values[0] if len(values) == 1 else list(values)
        domain = session.domain_values(name)
        when = {name: _value(domain, blocking)}
        others = [a for a in model.actions if a != key]
        try:
            new = add_guard(model, when, others, "")
        except RepairError as exc:
            session.episode.log("repair", f"could not add a guard on {name}: {exc}")
            return False
        session.adopt(
            new,
            f"{message!r}: while {name} is {blocking}, {key} does not work (the manual)",
            session.belief.pointer(),
        )
        return True
    return False


def _own_key(session: Session, key: str) -> bool:
    """Whether ``key`` belongs to one procedure only: a key shared by several (▲ for the
    clock and the timer, a knob for each menu item) works elsewhere, so a guard refusing it
    would block settings the message does not speak of."""
    features = session.belief.model.features.values()
    return sum(any(key in s.actions for s in steps) for steps in features) == 1


def _value(domain: list[Any], blocking: Any) -> Any:
    """The guard's value(s) in the setting's own values (not their strings)."""
    by_text = {str(v): v for v in domain}
    if isinstance(blocking, list):
        return [by_text.get(b, b) for b in blocking]
    return by_text.get(blocking, blocking)


def _own_settings(session: Session, done: Executed) -> set[str]:
    """The settings the key itself adjusts (every step of a procedure it is a key of): their
    values in a line say what the key does, not what blocks it."""
    model = session.belief.model
    own = {done.variable} if done.variable else set()
    for steps in model.features.values():
        if any(done.action.name in s.actions for s in steps):
            own |= {s.variable for s in steps if s.variable}
    return own


def _messages(session: Session, done: Executed) -> list[str]:
    """The parts of the screen that say the key did not work: a sign followed by dashes, or
    (a refused key) two or more words that print no value of the belief."""
    printed = _printed(session)
    out = []
    for part in re.split(r"\s{2,}", done.feedback.text.strip()):
        part = part.strip()
        if not any(c.isalpha() for c in part) or part.casefold() in printed:
            continue
        # a refusal's message of one word ("COOK", "BUSY") is said in too many lines of a
        # manual to stand for the refusal: two words at least ("HOT LOCK", "PAUSE FIRST")
        if _DASHED.search(part) or (done.refused and len(part.split()) >= 2):
            out.append(part)
    return out


def _printed(session: Session) -> set[str]:
    """Every value of the belief's list settings as printed (casefolded)."""
    model = session.belief.model
    out = set()
    for name, spec in model.variables.items():
        if isinstance(spec, DiscreteVariable):
            for v in session.domain_values(name):
                out |= {str(v).casefold(), display_value(spec, v).casefold()}
    return out


def _lines(manual: str, message: str) -> list[str]:
    """The manual's lines that print ``message`` (as a whole, its spacing loose), with the
    message cut out."""
    tokens = message.split()
    pattern = re.compile(r"(?<![\w-])" + r"\s+".join(re.escape(t) for t in tokens) + r"(?![\w])")
    return [pattern.sub(" ", line) for line in manual.splitlines() if pattern.search(line)]


def _blocks(
    session: Session, line: str, own: set[str], key: str
) -> list[tuple[str, tuple[str, ...]]]:
    """The (setting, blocking values) one manual line names."""
    model = session.belief.model
    found: list[tuple[str, tuple[str, ...]]] = []
    for name, spec in model.variables.items():
        if name in own or not isinstance(spec, DiscreteVariable):
            continue
        current = session.belief.value(name)
        if current is None:
            continue
        domain = session.domain_values(name)
        named = [v for v in domain if _names(line, spec, v)]
        if not named:
            continue
        if current in named:
            found.append((name, (str(current),)))
        elif len(named) < len(domain):
            found.append((name, tuple(str(v) for v in domain if v not in named)))
    for other, (control, label) in _labels(session).items():
        if other == key or not re.search(
            _VERBS + r"\s+(?:the\s+)?" + re.escape(label) + r"(?![\w])", line, re.IGNORECASE
        ):
            continue
        if control == model.actions[key].control:
            continue
        for steps in model.features.values():
            if len(steps) != 1 or other not in steps[0].actions:
                continue
            switched = steps[0].variable
            if switched is None or switched in own:
                continue
            if not isinstance(model.variables.get(switched), DiscreteVariable):
                continue
            current = session.belief.value(switched)
            if current is not None and len(session.domain_values(switched)) <= 3:
                found.append((switched, (str(current),)))
    return list(dict.fromkeys(found))


def _names(line: str, spec: DiscreteVariable, value: Any) -> bool:
    """Whether ``line`` names ``value`` as displays and manuals print it: in capitals."""
    forms = {display_value(spec, value), str(value).upper()}
    for form in forms:
        if form.casefold() in _GENERIC or len(form) < 2 or not any(c.isalpha() for c in form):
            continue
        if form != form.upper():
            continue
        if re.search(r"(?<![\w])" + re.escape(form) + r"(?![\w])", line):
            return True
    return False


def _labels(session: Session) -> dict[str, tuple[str, str]]:
    """Each action's (control, label) where the label is a word of two or more letters."""
    model = session.belief.model
    labels = {c.id: c.label for c in model.controls if c.label}
    out = {}
    for action, spec in model.actions.items():
        label = labels.get(spec.control or "")
        if label and len(label) >= 2 and any(c.isalpha() for c in label):
            out[action] = (spec.control or "", label)
    return out
