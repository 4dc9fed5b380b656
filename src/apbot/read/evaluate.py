"""How well the reader reads: precision and recall against the ground-truth models.

A read model names things its own way (``fan`` for ``fan_speed``), so it is first *aligned* with
the truth, and only aligned parts are compared:

* **variables** — an optimal one-to-one assignment (``scipy.optimize.linear_sum_assignment``)
  on a score that is half name similarity (the better of names and labels; a word one name
  abbreviates in the other counts as a match) and half value similarity (Jaccard of the value
  sets); a pair is kept when the score is at least ``MIN_VARIABLE_SCORE``.
* **values** — for each variable, its value set (a discrete variable's values, every value of a
  numeric or time variable's ranges, all cases of a programme-dependent one together; numbers
  compared as numbers, times in seconds). Discrete values are counted over all variables (micro);
  numeric ranges are scored per variable (the value-set precision and recall, averaged), so one
  long cooking-time range does not outweigh everything else. Values of an unaligned variable all
  count as wrong (read) or missed (true).
* **features** (macro actions) — aligned one-to-one on Jaccard of their action sets plus a little
  name similarity; an aligned pair is correct when its steps hold exactly the same actions in
  the same order.
* **placements** — (action, feature, step index) triples, the read feature renamed to the true
  feature it is aligned with: which feature step each action belongs to.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from difflib import SequenceMatcher
from typing import Any

import numpy as np
from scipy.optimize import linear_sum_assignment

from apbot.model.domain import all_values
from apbot.model.schema import ApplianceModel, DiscreteVariable, NumericVariable, TimeVariable
from apbot.model.values import normalise_text, parse_hms

MIN_VARIABLE_SCORE = 0.4  # a name match of 0.8 alone is enough: "timer" for "start_timer"
MIN_FEATURE_JACCARD = 0.2


def _words(name: str) -> list[str]:
    return [w for w in re.split(r"[^a-z0-9]+", name.lower()) if w]


def name_similarity(a: str, b: str) -> float:
    """1 for the same words; abbreviations and shared words count ("temp" ~ "temperature")."""
    wa, wb = _words(a), _words(b)
    if not wa or not wb:
        return 0.0
    if wa == wb:
        return 1.0
    ratio = SequenceMatcher(None, " ".join(wa), " ".join(wb)).ratio()
    shared = sum(
        1
        for x in wa
        if any(
            x == y or (min(len(x), len(y)) >= 3 and (x.startswith(y) or y.startswith(x)))
            for y in wb
        )
    )
    overlap = shared / max(len(wa), len(wb))
    return max(ratio, 0.4 + 0.6 * overlap if shared else 0.0)


TIME_UNITS = {"s": 1, "min": 60, "h": 3600}


def value_set(model: ApplianceModel, name: str) -> set[str]:
    """A variable's values as comparable strings (numbers as numbers, times in seconds)."""
    var = model.variables[name]
    try:
        values = all_values(var)
    except Exception:  # a read model always builds; this guards against a bad truth file
        return set()
    out: set[str] = set()
    for value in values:
        if isinstance(var, TimeVariable):
            out.add(f"t{parse_hms(str(value))}")
        else:
            out |= value_set_of(var, value)
    return out


def jaccard(a: set[Any], b: set[Any]) -> float:
    return len(a & b) / len(a | b) if a or b else 0.0


def align_variables(read: ApplianceModel, true: ApplianceModel) -> dict[str, str]:
    """read variable → true variable, the optimal assignment over the documented score."""
    rn, tn = list(read.variables), list(true.variables)
    if not rn or not tn:
        return {}
    rv = {n: value_set(read, n) for n in rn}
    tv = {n: value_set(true, n) for n in tn}
    score = np.zeros((len(rn), len(tn)))
    for i, r in enumerate(rn):
        rl = read.variables[r].display_label(r)
        for j, t in enumerate(tn):
            tl = true.variables[t].display_label(t)
            names = max(name_similarity(r, t), name_similarity(rl, tl))
            score[i, j] = 0.5 * names + 0.5 * jaccard(rv[r], tv[t])
    rows, cols = linear_sum_assignment(-score)
    return {
        rn[i]: tn[j] for i, j in zip(rows, cols, strict=True) if score[i, j] >= MIN_VARIABLE_SCORE
    }


def _feature_actions(model: ApplianceModel, name: str) -> set[str]:
    return {a for step in model.features[name] for a in step.actions}


def align_features(read: ApplianceModel, true: ApplianceModel) -> dict[str, str]:
    rn, tn = list(read.features), list(true.features)
    score = np.zeros((len(rn), len(tn)))
    for i, r in enumerate(rn):
        ra = _feature_actions(read, r)
        for j, t in enumerate(tn):
            jac = jaccard(ra, _feature_actions(true, t))
            score[i, j] = jac + 0.1 * name_similarity(r, t) if jac >= MIN_FEATURE_JACCARD else 0.0
    rows, cols = linear_sum_assignment(-score)
    return {rn[i]: tn[j] for i, j in zip(rows, cols, strict=True) if score[i, j] > 0}


@dataclass
class Counts:
    """Summable precision/recall counts: ``hit_p`` of ``read`` were right, ``hit_r`` of
    ``true`` were found (for numeric ranges the hits are per-variable fractions)."""

    hit_p: float = 0.0
    hit_r: float = 0.0
    read: float = 0.0
    true: float = 0.0

    def add(self, other: Counts) -> None:
        self.hit_p += other.hit_p
        self.hit_r += other.hit_r
        self.read += other.read
        self.true += other.true

    @property
    def precision(self) -> float:
        return self.hit_p / self.read if self.read else 0.0

    @property
    def recall(self) -> float:
        return self.hit_r / self.true if self.true else 0.0


@dataclass
class Score:
    variables: Counts = field(default_factory=Counts)
    discrete_values: Counts = field(default_factory=Counts)
    numeric_ranges: Counts = field(default_factory=Counts)  # sums of per-variable P and R
    placements: Counts = field(default_factory=Counts)
    features: Counts = field(default_factory=Counts)

    def add(self, other: Score) -> None:
        for key in ("variables", "discrete_values", "numeric_ranges", "placements", "features"):
            getattr(self, key).add(getattr(other, key))

    def table(self) -> dict[str, dict[str, float]]:
        out = {}
        for key in ("variables", "discrete_values", "numeric_ranges", "placements", "features"):
            c: Counts = getattr(self, key)
            out[key] = {"precision": round(c.precision, 3), "recall": round(c.recall, 3)}
        return out


def _placements(
    model: ApplianceModel, rename: dict[str, str] | None = None
) -> set[tuple[str, str, int]]:
    out = set()
    for name, steps in model.features.items():
        feature = rename.get(name, f"~{name}") if rename is not None else name
        for index, step in enumerate(steps):
            for action in step.actions:
                out.add((action, feature, index))
    return out


def score_reading(read: ApplianceModel, true: ApplianceModel) -> Score:
    """Compare one read model with its ground truth."""
    s = Score()
    va = align_variables(read, true)
    s.variables = Counts(len(va), len(va), len(read.variables), len(true.variables))
    back = {t: r for r, t in va.items()}
    # precision over the read variables of each kind, recall over the true ones
    for r, spec in read.variables.items():
        t = va.get(r)
        rv = value_set(read, r)
        hit = len(rv & value_set(true, t)) if t else 0
        if isinstance(spec, DiscreteVariable):
            s.discrete_values.read += len(rv)
            s.discrete_values.hit_p += hit
        else:
            s.numeric_ranges.read += 1
            s.numeric_ranges.hit_p += hit / len(rv) if rv else 0.0
    for t, spec in true.variables.items():
        found = back.get(t)
        tv = value_set(true, t)
        hit = len(tv & value_set(read, found)) if found else 0
        if isinstance(spec, DiscreteVariable):
            s.discrete_values.true += len(tv)
            s.discrete_values.hit_r += hit
        else:
            s.numeric_ranges.true += 1
            s.numeric_ranges.hit_r += hit / len(tv) if tv else 0.0
    fa = align_features(read, true)
    correct = sum(
        1
        for r, t in fa.items()
        if [set(st.actions) for st in read.features[r]]
        == [set(st.actions) for st in true.features[t]]
    )
    s.features = Counts(correct, correct, len(read.features), len(true.features))
    rp, tp = _placements(read, fa), _placements(true)
    hits = len(rp & tp)
    s.placements = Counts(hits, hits, len(rp), len(tp))
    return s


@dataclass
class SuiteScore:
    per_category: dict[str, Score]
    overall: Score
    seconds: float
    appliances: int

    def to_json(self) -> dict[str, Any]:
        return {
            "appliances": self.appliances,
            "seconds": round(self.seconds, 3),
            "overall": self.overall.table(),
            "per_category": {c: s.table() for c, s in sorted(self.per_category.items())},
        }


def evaluate(pairs: Iterable[tuple[str, str, list[str], ApplianceModel]]) -> SuiteScore:
    """Read every (category, manual, actions, truth) and score it; times the reading only."""
    import time

    from apbot.read.reader import read_manual

    per: dict[str, Score] = {}
    overall = Score()
    spent = 0.0
    count = 0
    for category, manual, actions, truth in pairs:
        start = time.perf_counter()
        reading = read_manual(manual, actions)
        spent += time.perf_counter() - start
        score = score_reading(reading.model, truth)
        per.setdefault(category, Score()).add(score)
        overall.add(score)
        count += 1
    return SuiteScore(per, overall, spent, count)


def translate_goal(
    read: ApplianceModel, true: ApplianceModel, goal: dict[str, Any]
) -> dict[str, Any]:
    """A true goal in the read model's names, through the variable alignment.

    PRIVILEGED: it uses the ground truth, so it serves only to *measure* the reader in the
    closed loop (the agent on a read belief, given the goal in the belief's own words); a
    method must never see it. A variable without a partner keeps its true name (the agent's
    finder looks for settings its belief lacks); a value is written the read variable's way
    when the read domain has it, else passed as the truth writes it.
    """
    from apbot.model.goal import parse_goal

    back = {t: r for r, t in align_variables(read, true).items()}
    canonical = parse_goal(true, goal)
    out: dict[str, Any] = {}
    for name, value in canonical.items():
        target = back.get(name, name)
        if target not in read.variables:
            out[target] = goal[name]
            continue
        spec = true.variables[name]
        keys = [next(iter(value_set_of(spec, value)))]
        if isinstance(spec, NumericVariable):  # a duration in hours read as a bare number
            keys.append(f"{float(value):g}")
        chosen: Any = goal[name]
        try:
            candidates = list(all_values(read.variables[target]))
        except Exception:  # a domain that cannot be listed: keep the truth's spelling
            candidates = []
        for key in keys:
            found = [c for c in candidates if key in value_set_of(read.variables[target], c)]
            if found:
                chosen = found[0]
                break
        else:
            if isinstance(spec, DiscreteVariable):  # "conv bake" for "convection bake"
                chosen = next((c for c in candidates if _abbreviates(str(c), str(value))), chosen)
            factor = TIME_UNITS.get(getattr(read.variables[target], "unit", "") or "")
            if factor and isinstance(spec, TimeVariable):  # 20 min on a belief counting hours
                chosen = round(parse_hms(str(value)) / factor, 4)
        out[target] = chosen
    return out


SHORT_WORDS = {
    "hi": "high",
    "lo": "low",
    "med": "medium",
    "mid": "medium",
    "std": "standard",
    "°c": "celsius",
    "°f": "fahrenheit",
    "quarter": "1 4",
    "half": "1 2",
}
"""Panel abbreviations and signs every manual uses for a word (after :func:`normalise_text`,
which writes "1/4" as "1 4")."""


def _spelled(text: str) -> str:
    """A value with the panel abbreviations every manual uses spelt out ("HI" is "high"), and
    no spaces round joining signs ("wash + dry" is "wash+dry")."""
    text = re.sub(r"\s*([+&/])\s*", r"\1", text)
    return " ".join(SHORT_WORDS.get(w, w) for w in text.split())


def _squeezed(text: str) -> str:
    """A value's name without the spaces one model writes and another leaves out ("HDMI 2" is
    "HDMI2", "USB-C" is "USBC"); a space between two figures stays ("1/4" is not 14)."""
    return re.sub(r"(?<!\d) | (?!\d)", "", text)


def _abbreviates(short: str, long: str) -> bool:
    """Whether ``short`` writes ``long`` with shortened words ("conv bake", "convection bake")."""
    sw = re.findall(r"[a-z0-9]+", normalise_text(short))
    lw = re.findall(r"[a-z0-9]+", normalise_text(long))
    return (
        len(sw) == len(lw)
        and sw != lw
        and all(w.startswith(s) and len(s) >= 3 for s, w in zip(sw, lw, strict=True))
    )


def value_set_of(spec: Any, value: Any) -> set[str]:
    """One value as :func:`value_set` would write it (for comparing across models)."""
    if isinstance(spec, TimeVariable):
        return {f"t{parse_hms(str(value))}"}
    if isinstance(spec, DiscreteVariable):
        text = _spelled(normalise_text(str(value)))
        number = re.fullmatch(r"(\d+(?:\.\d+)?)\s*[a-z%°]*", text)
        return {f"{float(number.group(1)):g}" if number else _squeezed(text)}
    factor = TIME_UNITS.get(getattr(spec, "unit", "") or "")
    if factor is not None:  # a duration counted in a unit compares with a time, in seconds
        return {f"t{round(float(value) * factor)}"}
    return {f"{float(value):g}"}
