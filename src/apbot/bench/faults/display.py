"""Faults in how a value is shown and typed: the display text copied wrong, a keypad format
misread.

A reader writes ``P{value}`` for what the panel prints as ``PL7``, calls a setting "TEMP" where
the display says "TEMPERATURE", spells out a programme the display abbreviates, or takes a
timer typed as ``mm:ss`` for one typed in minutes.
"""

from __future__ import annotations

import random
import re
from collections.abc import Iterator

from apbot.bench.faults.common import Candidates, Data, Fault, by_mode, copied, dump
from apbot.model.schema import TEMPLATE_FIELD, ApplianceModel

# The confusions a reader plausibly makes, each one reading some short entry differently
# (``h:mm`` and ``hh:mm`` parse alike, and ``hh:mm:ss`` reads every short entry as ``mm:ss``
# does, so those pairs would change nothing a plan types).
ENTRY_CONFUSIONS: dict[str, tuple[str, ...]] = {
    "mm:ss": ("minutes", "seconds", "hh:mm"),
    "hh:mm": ("mm:ss", "minutes"),
    "h:mm": ("mm:ss", "minutes"),
    "hh:mm:ss": ("hh:mm", "minutes"),
    "minutes": ("mm:ss", "hh:mm", "seconds"),
    "seconds": ("mm:ss", "minutes"),
}


def entry_format(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """A keypad entry read in the wrong format: typing 5 believed to give 5 min, not ``00:05``
    (``minutes`` for ``mm:ss``). Only time variables: a number is typed as a number."""
    data = dump(model)
    var = data["variables"][name]
    entry = var.get("entry")
    if entry is None or entry["format"] not in ENTRY_CONFUSIONS:
        return
    true_format = entry["format"]
    for wrong in rng.sample(ENTRY_CONFUSIONS[true_format], len(ENTRY_CONFUSIONS[true_format])):
        candidate = copied(data)
        candidate["variables"][name]["entry"]["format"] = wrong
        yield (
            candidate,
            Fault("entry_format", name, f"typed as {wrong} instead of {true_format}"),
        )


# --- the display --------------------------------------------------------------------------------

_WORD = re.compile(r"[A-Za-z][A-Za-z0-9]*")


def _literal_runs(template: str) -> list[tuple[int, int]]:
    """Where the template's own words are (outside ``{fields}``): (start, end) of each."""
    fields = [m.span() for m in TEMPLATE_FIELD.finditer(template)]
    return [
        m.span() for m in _WORD.finditer(template) if not any(a <= m.start() < b for a, b in fields)
    ]


def _tidy(text: str) -> str:
    return re.sub(r"\s{2,}", " ", text).strip()


def _template_misreadings(template: str) -> Iterator[str]:
    """Plausible wrong copies of a display template: a letter dropped from a printed prefix
    (``PL{value}`` → ``P{value}``), a one-letter prefix or a unit missed, the setting's name
    added where the display prints the bare value."""
    for start, end in _literal_runs(template):
        word = template[start:end]
        if len(word) >= 2:
            yield template[: end - 1] + template[end:]
        else:
            yield _tidy(template[:start] + template[end:])
    suffix = re.search(r"\}([^A-Za-z{}\s][^{}]*)$", template)  # "{value}°C": the unit missed
    if suffix:
        yield template[: suffix.start(1)]
    if template.strip() == "{value}":
        yield "{label} {value}"


def _label_misreadings(label: str, name: str) -> Iterator[str]:
    """Plausible wrong labels: the setting's name for a printed abbreviation ("HUMIDITY" for
    "RH"), a word of a longer label left out, a long word shortened ("TEMP")."""
    spelled = name.replace("_", " ").upper()
    if spelled != label.upper():
        yield spelled
    words = label.split()
    if len(words) >= 2:
        for i in range(len(words)):
            yield " ".join(words[:i] + words[i + 1 :])
    elif len(label) > 4:
        yield label[:4]


def _word_misreadings(text: str, value: str) -> Iterator[str]:
    """Plausible wrong words for one value's display text: the value spelled out where the
    display abbreviates it ("STERILISE + DRY" for "STER+DRY"), a word left out, a long word
    shortened."""
    runs = _literal_runs(text)
    if not runs:
        return
    spelled = value.upper()
    literal = _tidy(TEMPLATE_FIELD.sub("", text))
    if literal.upper() != spelled and not TEMPLATE_FIELD.search(text):
        yield spelled
    if len(runs) >= 2:
        for start, end in runs:
            yield _tidy(text[:start] + text[end:])
    for start, end in runs:
        if end - start > 4:
            yield text[: start + 4] + text[end:]


def _shown_variables(model: ApplianceModel) -> set[str]:
    """Variables whose own display rules the panel uses: adjusted by a step (shown while it is
    being set) or an indicator lamp."""
    stepped = {s.variable for steps in model.features.values() for s in steps if s.variable}
    return (stepped | set(model.display.indicators)) & {
        n for n, v in model.variables.items() if v.visible
    }


def display(model: ApplianceModel, name: str, rng: random.Random) -> Candidates:
    """The display text of a setting copied wrong: ``show: "P{value}"`` for what the panel
    prints ``PL{value}``, the label "TEMP" for "TEMPERATURE", or a per-value ``show`` map with
    a wrong word ("STERILISE + DRY" where the display says "STER+DRY")."""
    if name not in _shown_variables(model):
        return
    original = dump(model)
    show = original["variables"][name].get("show")
    shows: list[tuple[Data, Fault]] = []
    labels: list[tuple[Data, Fault]] = []
    if isinstance(show, dict):
        for value, text in show.items():
            for wrong in _word_misreadings(text, value):
                data = copied(original)
                data["variables"][name]["show"][value] = wrong
                detail = f"shows {wrong!r} for {value!r} instead of {text!r}"
                shows.append((data, Fault("display", name, detail)))
    elif isinstance(show, str):
        for wrong in _template_misreadings(show):
            data = copied(original)
            data["variables"][name]["show"] = wrong
            shows.append((data, Fault("display", name, f"shows {wrong!r} instead of {show!r}")))
    texts = show.values() if isinstance(show, dict) else [show or ""]
    if show is None or any("{label}" in text for text in texts):
        label = model.variables[name].display_label(name)
        for wrong in _label_misreadings(label, name):
            data = copied(original)
            data["variables"][name]["label"] = wrong
            detail = f"labelled {wrong!r} instead of {label!r}"
            labels.append((data, Fault("display", name, detail)))
    yield from by_mode([shows, labels], rng)
