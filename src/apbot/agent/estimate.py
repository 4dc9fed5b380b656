"""State estimation: read an environment's feedback in the belief model's own terms.

Feedback names values the environment's way ("Spd": "Medium", "Temp": "40°C", "lock": True);
the belief has its own variable names and value spellings. The estimator matches each feedback
name to at most one belief variable — by name first, then by which values fit which domain —
and normalises each value into that variable's domain. A value of the right type that the
domain lacks is kept apart in ``outside``: it is the closed loop's evidence that the belief is
wrong.

>>> from apbot.examples import load_example
>>> estimator = StateEstimator(load_example("washing_machine"))
>>> seen = estimator.estimate(Feedback("", {"Program": "Wool", "Temp": "30°C", "SPIN": 1000}))
>>> seen.values, seen.outside
({'programme': 'wool', 'temperature': '30'}, {'spin_speed': 1000})
>>> seen.mapping
{'Program': 'programme', 'Temp': 'temperature', 'SPIN': 'spin_speed'}
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from apbot.agent.environment import Feedback
from apbot.agent.reader import DisplayReader
from apbot.model.domain import (
    AnyVariable,
    Domain,
    ValueProblem,
    all_values,
    build_domain,
    case_domains,
    normalise,
    parse_value,
)
from apbot.model.schema import ApplianceModel, DiscreteVariable
from apbot.model.values import normalise_text, parse_quantity

# How a feedback name matched a belief variable, strongest first. Up to LABEL a name decides
# on its own; weaker matches must also be able to hold the value shown.
EXACT, NORMALISED, LABEL, WORDS, PREFIX, ABBREVIATION, SIMILAR = range(7)
WEAK = WORDS  # from here on a name match must also be able to hold the value
SIMILARITY = 0.75  # difflib ratio for a misspelt name ("humidty")
ABSENT = frozenset({"", "-", "--", "---", "\u2014"})  # how displays show "no value here"
_TRUE = ("on", "yes", "true", "enabled", "1")
_FALSE = ("off", "no", "false", "disabled", "0")
_MAX_PLANS = 4096
_MISSING = object()
_NOTHING: Mapping[str, Any] = {}


@dataclass
class Estimate:
    """What one feedback says about the belief's variables.

    ``values``: belief variable → canonical value in its belief domain (parents before the
    variables that depend on them). ``outside``: belief variable → the observed value read for
    that variable's type but *not* in its belief domain (35 when the belief has 0..30 in tens;
    "turbo" for a list without it). ``unmatched``: feedback name → why it was not used (no
    similar name, ambiguous, a value that cannot be read for its variable). ``mapping``:
    feedback name → the belief variable it was matched to. A name shown without a value
    ("--", None) is mapped but lands in neither ``values`` nor ``outside``.
    """

    values: dict[str, Any] = field(default_factory=dict)
    outside: dict[str, Any] = field(default_factory=dict)
    unmatched: dict[str, str] = field(default_factory=dict)
    mapping: dict[str, str] = field(default_factory=dict)


@dataclass(frozen=True, slots=True)
class _Variable:
    """A belief variable prepared for matching: its domains and the forms of its name."""

    name: str
    spec: AnyVariable
    rank: tuple[int, int]
    domain: Domain | None  # an independent variable's domain
    parent: str | None
    cases: dict[str, Domain]
    union: Domain | None  # a dependent variable: every value of every case
    forms: tuple[tuple[tuple[str, ...], str], ...]  # (words, joined) of the name, then label
    label: str


@dataclass(frozen=True, slots=True)
class _Plan:
    """The resolution of one set of feedback names: reused while the names recur."""

    entries: tuple[tuple[str, _Variable], ...]  # (feedback name, variable), parents first
    mapping: dict[str, str]
    unmatched: dict[str, str]


class StateEstimator:
    """Maps feedback onto a belief model; learnt name matches survive model repairs."""

    def __init__(self, belief: ApplianceModel) -> None:
        self._learnt: dict[str, tuple[int, str]] = {}
        self._bind(belief)

    def rebind(self, belief: ApplianceModel) -> None:
        """Use a repaired belief, keeping the name matches learnt so far."""
        self._bind(belief)
        self._learnt = {
            name: (tier, var) for name, (tier, var) in self._learnt.items() if var in self._vars
        }

    def _bind(self, belief: ApplianceModel) -> None:
        self.belief = belief
        self._vars = {
            name: _prepare(name, spec, i) for i, (name, spec) in enumerate(belief.variables.items())
        }
        self._candidates: dict[str, list[tuple[int, tuple[str, ...]]]] = {}
        self._plans: dict[frozenset[str], _Plan] = {}
        self._reader: DisplayReader | None = None

    def estimate(self, feedback: Feedback, context: Mapping[str, Any] | None = None) -> Estimate:
        """Read ``feedback`` in belief terms.

        ``context``: the belief's current values, so that a programme-dependent setting is
        read against the domain of the current programme (a parent shown in the same
        feedback takes precedence); without it, against every value of every programme.
        """
        shown = feedback.values
        if not shown:
            return Estimate()
        key = frozenset(shown)
        plan = self._plans.get(key)
        if plan is None:
            plan, reusable = self._resolve(shown, context)
            if reusable:
                if len(self._plans) >= _MAX_PLANS:
                    self._plans.clear()
                self._plans[key] = plan
        values: dict[str, Any] = {}
        outside: dict[str, Any] = {}
        unmatched = dict(plan.unmatched)
        for name, var in plan.entries:
            raw = shown[name]
            if _absent(raw):
                continue
            domain = _domain_for(var, values, context, outside)
            if domain is not None and raw.__class__ is not bool:
                try:
                    index = domain.index.get(raw)
                except TypeError:  # unhashable: not a canonical value
                    index = None
                if index is not None:
                    values[var.name] = domain.values[index]
                    continue
            try:
                if domain is None:
                    raise ValueProblem("the belief has no such setting here")
                values[var.name] = normalise(var.spec, _as_text(raw, var.spec, domain), domain)
            except ValueProblem:
                printed = self._as_printed(var.name, raw, {**(context or {}), **values})
                if printed is not None:
                    target = values if printed[0] == "value" else outside
                    target[var.name] = printed[1]
                    continue
                try:
                    outside[var.name] = parse_value(var.spec, raw)
                except ValueProblem as exc:
                    unmatched[name] = (
                        f"{name!r} shows {raw!r}, which is not a {var.spec.type} "
                        f"value for {var.name}: {exc}"
                    )
        return Estimate(values, outside, unmatched, dict(plan.mapping))

    def _as_printed(
        self, name: str, raw: Any, context: Mapping[str, Any]
    ) -> tuple[str, Any] | None:
        """A value reported the way the display prints it ("PL7" for a ``show: "PL{value}"``),
        read back through the belief's own display rules."""
        if not isinstance(raw, str) or not raw.strip():
            return None
        if self._reader is None:
            self._reader = DisplayReader(self.belief)
        for hypothesis in self._reader.read(raw, context).hypotheses:
            if hypothesis.screen.variable == name and not hypothesis.partial:
                if name in hypothesis.values:
                    return "value", hypothesis.values[name]
                if name in hypothesis.outside:
                    return "outside", hypothesis.outside[name]
        return None

    # --- name matching ----------------------------------------------------------------------

    def _resolve(
        self, shown: Mapping[str, Any], context: Mapping[str, Any] | None
    ) -> tuple[_Plan, bool]:
        """Match every feedback name; True when the result depends on the names alone."""
        decided: dict[str, tuple[int, str]] = {}
        unmatched: dict[str, str] = {}
        undecided: list[str] = []
        for name in shown:
            learnt = self._learnt.get(name)
            if learnt is not None:
                decided[name] = learnt
                continue
            tiers = self._name_candidates(name)
            if not tiers:
                unmatched[name] = f"no belief variable has a name like {name!r}"
            elif tiers[0][0] < WEAK and len(tiers[0][1]) == 1:
                decided[name] = (tiers[0][0], tiers[0][1][0])
            else:
                undecided.append(name)
        claimed = {var: name for name, (_, var) in decided.items()}
        checked: set[str] = set()  # decided by looking at the value: learnt if they keep it
        reusable = True
        for name in undecided:
            outcome = self._choose(name, shown[name], claimed, context)
            if isinstance(outcome, str):
                unmatched[name] = outcome
                reusable = False
            else:
                decided[name] = outcome
                if _absent(shown[name]):
                    reusable = False  # a guess on the name alone: decide again next time
                else:
                    checked.add(name)
        by_var: dict[str, list[str]] = {}
        for name, (_, var) in decided.items():
            by_var.setdefault(var, []).append(name)
        for var, names in by_var.items():
            if len(names) == 1:
                continue
            best = min(decided[n][0] for n in names)
            winners = [n for n in names if decided[n][0] == best]
            for name in names:
                if len(winners) > 1:
                    unmatched[name] = (
                        f"{_either([repr(w) for w in winners], 'and')} "
                        f"{'both' if len(winners) == 2 else 'all'} look like {var}"
                    )
                elif name != winners[0]:
                    unmatched[name] = f"{var} is already shown as {winners[0]!r}"
                else:
                    continue
                del decided[name]
                reusable = reusable and name not in checked
        for name in [n for n in decided if n in checked]:
            self._learnt[name] = decided[name]
        entries = sorted(
            ((name, self._vars[var]) for name, (_, var) in decided.items()),
            key=lambda entry: entry[1].rank,
        )
        mapping = {name: var.name for name, var in entries}
        return _Plan(tuple(entries), mapping, unmatched), reusable

    def _choose(
        self, name: str, raw: Any, claimed: Mapping[str, str], context: Mapping[str, Any] | None
    ) -> tuple[int, str] | str:
        """Pick the variable for a name whose name alone does not decide: the best tier
        whose variables can hold the value, then the one whose domain has it."""
        wrong_type: list[str] = []
        for tier, names in self._name_candidates(name):
            options = [n for n in names if n not in claimed]
            if not options:
                return "; ".join(f"{var} is already shown as {claimed[var]!r}" for var in names)
            if tier >= WEAK and not _absent(raw):
                typed = [n for n in options if _can_hold(self._vars[n], raw)]
                wrong_type += [n for n in options if n not in typed]
                if not typed:
                    continue
                options = typed
            if len(options) == 1:
                return tier, options[0]
            if not _absent(raw):
                fitting = [n for n in options if _fits(self._vars[n], raw, context)]
                if len(fitting) == 1:
                    return tier, fitting[0]
            return f"{name!r} could be {_either(options, 'or')}"
        kinds = ", ".join(f"{n} is {self._vars[n].spec.type}" for n in wrong_type)
        return f"no variable named like {name!r} can show {raw!r} ({kinds})"

    def _name_candidates(self, name: str) -> list[tuple[int, tuple[str, ...]]]:
        """Belief variables by how well their names match ``name`` (best tier first)."""
        found = self._candidates.get(name)
        if found is None:
            by_tier: dict[int, list[str]] = {}
            words = _words(name)
            for var in self._vars.values():
                tier = _name_tier(name, words, var)
                if tier is not None:
                    by_tier.setdefault(tier, []).append(var.name)
            found = [(tier, tuple(by_tier[tier])) for tier in sorted(by_tier)]
            self._candidates[name] = found
        return found


# --- names ------------------------------------------------------------------------------------

_CAMEL = re.compile(r"(?<=[a-z0-9])(?=[A-Z])")
_WORD = re.compile(r"[^\W_]+")
_VOWELS = frozenset("aeiou")


def _words(text: str) -> tuple[str, ...]:
    """Case-, separator- and plural-insensitive words: "Spin_Speeds" and "spinSpeed" agree."""
    return tuple(_singular(w) for w in _WORD.findall(_CAMEL.sub(" ", str(text)).casefold()))


def _singular(word: str) -> str:
    if len(word) > 3 and word.endswith("ies"):
        return word[:-3] + "y"
    if len(word) > 3 and word.endswith("s") and not word.endswith(("ss", "us", "is")):
        return word[:-1]
    return word


def _prepare(name: str, spec: AnyVariable, order: int) -> _Variable:
    forms = [(_words(name), "".join(_words(name)))]
    label = (spec.label or "").strip()
    if label and _words(label):
        forms.append((_words(label), "".join(_words(label))))
    if spec.depends_on is None:
        domain, cases, union = build_domain(spec), {}, None
    else:
        domain, cases = None, case_domains(spec)
        union = Domain(next(iter(cases.values())).kind, tuple(all_values(spec)), 0, spec.wrap)
    return _Variable(
        name,
        spec,
        (0 if spec.depends_on is None else 1, order),
        domain,
        spec.depends_on,
        cases,
        union,
        tuple(forms),
        label,
    )


def _name_tier(name: str, words: tuple[str, ...], var: _Variable) -> int | None:
    """How ``name`` (split into ``words``) matches ``var``'s name or label, if at all."""
    if name == var.name:
        return EXACT
    if var.label and name.strip() == var.label:
        return LABEL
    if not words:
        return None
    joined = "".join(words)
    for tier, (form, form_joined) in zip((NORMALISED, LABEL), var.forms, strict=False):
        if words == form or joined == form_joined:
            return tier
    tiers: list[int] = []
    for form, form_joined in var.forms:
        if (len(words) == 1 and words[0] in form) or _contains(words, form):
            tiers.append(WORDS)
        elif len(joined) >= 2 and (
            form_joined.startswith(joined)
            or any(w.startswith(joined) for w in form)
            or (
                len(words) == len(form) > 1
                and all(b.startswith(a) for a, b in zip(words, form, strict=True))
            )
        ):
            tiers.append(PREFIX)
        elif _abbreviates(joined, form_joined):
            tiers.append(ABBREVIATION)
        elif difflib.SequenceMatcher(None, " ".join(words), " ".join(form)).ratio() >= SIMILARITY:
            tiers.append(SIMILAR)
    return min(tiers, default=None)


def _contains(words: tuple[str, ...], part: tuple[str, ...]) -> bool:
    """Whether ``part`` occurs as consecutive words inside the longer ``words``."""
    n = len(part)
    return 0 < n < len(words) and any(words[i : i + n] == part for i in range(len(words) - n + 1))


def _abbreviates(short: str, long: str) -> bool:
    """ "spd" for "speed", "tmr" for "timer": the first letter, then consonants in order (a
    word with vowels, such as "clock", is a word, not an abbreviation of "child lock")."""
    if short[0] != long[0] or (len(short) > 2 and _VOWELS.intersection(short[1:])):
        return False
    letters = iter(long)
    return all(c in letters for c in short)


def _either(names: list[str] | tuple[str, ...], word: str) -> str:
    names = list(names)
    return names[0] if len(names) == 1 else f"{', '.join(names[:-1])} {word} {names[-1]}"


# --- values -----------------------------------------------------------------------------------


def _absent(raw: Any) -> bool:
    return raw is None or (isinstance(raw, str) and raw.strip() in ABSENT)


def _domain_for(
    var: _Variable,
    values: Mapping[str, Any],
    context: Mapping[str, Any] | None,
    outside: Mapping[str, Any] = _NOTHING,
) -> Domain | None:
    """The domain to read ``var`` in: its parent's case when the parent is known (shown in
    this feedback, else believed); None when the belief says it does not exist there. A
    parent shown with a value the belief lacks leaves every case possible."""
    if var.parent is None:
        return var.domain
    if var.parent in outside:
        return var.union
    parent = values.get(var.parent, _MISSING)
    if parent is _MISSING and context is not None:
        parent = context.get(var.parent, _MISSING)
    if parent is _MISSING or parent is None:
        return var.union
    return var.cases.get(str(parent))


def _as_text(raw: Any, spec: AnyVariable, domain: Domain) -> Any:
    """A switch shown as True/False, read as the domain's own word for on/off."""
    if not isinstance(raw, bool) or not isinstance(spec, DiscreteVariable):
        return raw
    keys = {normalise_text(v): v for v in domain.values}
    return next((keys[w] for w in (_TRUE if raw else _FALSE) if w in keys), str(raw).lower())


def _can_hold(var: _Variable, raw: Any) -> bool:
    """Whether ``raw`` reads as a value of ``var``'s type, in its domain or not. For a list
    of words or of numbers, a value of the other shape does not count ("SpinSpeed": 3 is not
    a fan speed of low/medium/high)."""
    try:
        parse_value(var.spec, raw)
    except ValueProblem:
        return False
    if not isinstance(var.spec, DiscreteVariable) or _fits(var, raw, None):
        return True
    domain = var.domain or var.union
    assert domain is not None
    return _is_number(raw) in {_is_number(v) for v in domain.values}


def _is_number(raw: Any) -> bool:
    if isinstance(raw, bool):
        return False
    if isinstance(raw, int | float):
        return True
    quantity = parse_quantity(str(raw))
    return quantity is not None and quantity[1] is None


def _fits(var: _Variable, raw: Any, context: Mapping[str, Any] | None) -> bool:
    """Whether ``raw`` normalises into ``var``'s (current) domain."""
    domain = _domain_for(var, {}, context)
    if domain is None:
        return False
    try:
        normalise(var.spec, _as_text(raw, var.spec, domain), domain)
    except ValueProblem:
        return False
    return True
