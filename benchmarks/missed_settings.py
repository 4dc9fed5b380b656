"""Which goal settings the offline reader misses, by the panel mechanism that sets them.

    python benchmarks/missed_settings.py [--suite bundled|DIR] [--held-out] [--list] [--why]

MEASURING ONLY — this script uses privileged inputs: the ground-truth model (to say how each
setting is reached on the panel) and the tasks' stored goals (which settings matter). No method
ever sees what it computes.

Each manual is read with its appliance's action names; every setting a stored goal names counts
once per task that names it, and is *missed* when no read variable aligns with it under the
reader's evaluation alignment (:func:`apbot.read.evaluate.align_variables`). Settings are tagged
by how the truth's procedures reach them:

- ``own-key``: the keys that set it set nothing else;
- ``shared-adjuster``: a key that sets it also sets another setting (▲ / ▼ shared by fields);
- ``after-entry-step``: a step that sets nothing comes first (press SET, hold CLOCK);
- ``walk-after-other-var``: another setting is set earlier in the same procedure (a walk of
  fields: hour, then minutes);
- ``hold``, ``dial``, ``digits``: a held key, a turned dial, a keypad;
- ``type:…``: the setting's type.

A mechanism missed far more often than the rest is where the reader's rules are thinnest: on 6
December (late) walks of fields were missed 41 % of the time on the newcats against 4 % for a
setting with a key of its own. On the bundled suite the nine development categories are judged
by default; ``--held-out`` judges the six held out instead and prints only the aggregate table
(never a line per appliance), so they stay a test set.

``--why`` adds a second aggregate table: for each missed setting, what the reader made of the
keys that set it in the truth — nothing (``keys-unread``), a variable already aligned with
another setting (``keys-set-other``: two settings conflated), or a variable of its own that did
not align, tagged by the two kinds (``onoff`` for a two-valued switch, ``levels`` for bare numbers,
``names``, ``range``, ``time``) and whether any value is shared; and whether the truth's value
names occur in the manual's text at all (``values-in-manual:none`` means the manual words them
differently from the stored model, which no reader can fix). Aggregate, so it may be run on the
held out: it says *which kind* of rule the unseen manuals need without showing any of them.

``--why`` also prints where the wrong variable came from (``--origin`` table): for a setting whose
keys the reader gave a variable of the wrong kind or to another setting, the reader module whose
note first made that variable (``from:…``, taken from the call site of the report's note) and the
SHAPE of the note's manual line (``src:…``) and of the line naming the true values (``vals:…``):
a table row (and its number of cells), a list item, a heading; digits with a time unit, a range
"a–b", parentheses, "or" or a slash, commas, arrows, "and", spaced dashes, dots, semicolons,
quotes (:func:`line_shape`); for the values' line also whether a key's word stands on it, near
it or far (:func:`key_place`), how many of the values it names ("2of5") and how it prints them
(:func:`written_case`). The note's kind is the reader's own phrasing (:func:`note_kind`), never
the manual's words, so held-out value names are not printed. With ``--held-out`` the values
table's build marks (:func:`table_detail`) are left out too: they describe one unseen table.
``--beside DIR`` prints the same counts for a second suite (the newcats, development) in a
column beside, so a shape frequent in one stands out. ``--top N`` rows per table.

The shapes (line, values' line, key place, case) are named in :mod:`benchmarks.missed_shapes`;
this module reads each appliance and counts.
"""

from __future__ import annotations

import argparse
import re
import sys
from collections import Counter, defaultdict
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from apbot.bench.suite import HELD_OUT_CATEGORIES, load_suite
from apbot.model.domain import all_values
from apbot.model.schema import ApplianceModel, DiscreteVariable, TimeVariable
from apbot.read.build_base import BuilderBase
from apbot.read.evaluate import align_variables, value_set
from apbot.read.reader import Reading, read_manual
from apbot.read.report import Note

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))  # run as a script
from benchmarks.missed_shapes import (
    key_place,
    line_shape,
    note_kind,
    table_detail,
    value_shape,
    values_line,
    written_case,
)


def mechanisms(model: ApplianceModel, variable: str) -> set[str]:
    """How the truth's procedures reach ``variable`` (the tags above)."""
    adjusts: defaultdict[str, set[str]] = defaultdict(set)
    for steps in model.features.values():
        for step in steps:
            if step.variable:
                for action in step.actions:
                    adjusts[action].add(step.variable)
    tags: set[str] = set()
    for steps in model.features.values():
        for k, step in enumerate(steps):
            if step.variable != variable:
                continue
            if any(s.variable is None for s in steps[:k]):
                tags.add("after-entry-step")
            if any(s.variable and s.variable != variable for s in steps[:k]):
                tags.add("walk-after-other-var")
            shared = any(len(adjusts[a]) > 1 for a in step.actions)
            tags.add("shared-adjuster" if shared else "own-key")
            skills = {model.actions[a].skill for a in step.actions if a in model.actions}
            tags |= {"hold"} & skills | ({"dial"} if "turn" in skills else set())
            if any(ch.isdigit() for a in step.actions for ch in a):
                tags.add("digits")
    kind = type(model.variables[variable]).__name__.removesuffix("Variable").lower()
    return tags | {f"type:{kind}"}


def kind(model: ApplianceModel, variable: str) -> str:
    """A coarse kind for the ``--why`` table."""
    var = model.variables[variable]
    if isinstance(var, TimeVariable):
        return "time"
    if not isinstance(var, DiscreteVariable):
        return "range"
    values = [str(v).lower() for v in all_values(var)]
    if len(values) == 2:
        return "onoff"
    if all(re.fullmatch(r"[a-z]?\d+", v) for v in values):
        return "levels"
    return "names"


def setters(model: ApplianceModel) -> defaultdict[str, set[str]]:
    """action → the variables a procedure step with that action sets."""
    out: defaultdict[str, set[str]] = defaultdict(set)
    for steps in model.features.values():
        for step in steps:
            if step.variable:
                for action in step.actions:
                    out[action].add(step.variable)
    return out


def why_missed(
    read: ApplianceModel,
    truth: ApplianceModel,
    variable: str,
    aligned: dict[str, str],
    manual: str,
) -> list[str]:
    """Reasons (``--why`` tags) the reader missed ``variable``."""
    keys = {a for a, vs in setters(truth).items() if variable in vs}
    read_setters = setters(read)
    candidates = {v for a in keys for v in read_setters.get(a, set())}
    tags: list[str] = []
    if not candidates:
        tags.append("keys-unread")
    elif all(c in aligned for c in candidates):
        tags.append("keys-set-other")
    else:
        mine = sorted(c for c in candidates if c not in aligned)[0]
        shared = value_set(read, mine) & value_set(truth, variable)
        tags.append(
            f"keys-set-own read:{kind(read, mine)} true:{kind(truth, variable)}"
            f" {'some' if shared else 'no'}-value-shared"
        )
    var = truth.variables[variable]
    if isinstance(var, DiscreteVariable):
        text = manual.lower()
        names = [str(v).lower().replace("_", " ") for v in all_values(var)]
        found = [name in text for name in names]
        share = "all" if all(found) else "some" if any(found) else "none"
        tags.append(f"values-in-manual:{share}")
        if any(found):
            tags.append(f"values-written-in:{value_shape(manual, names)}")
    return tags


NOTE_ORIGINS: dict[int, str] = {}


@contextmanager
def note_origins() -> Iterator[None]:
    """Record, for each note the builder writes, the reader module that wrote it (measuring only:
    the report says which manual line a variable came from, not which rule read it)."""
    plain = BuilderBase.note

    def tagged(self: BuilderBase, subject: str, what: str, unit: int | None = None) -> None:
        plain(self, subject, what, unit)
        frame = sys._getframe(1)
        # (build.py's add_number / add_discrete note for the rule that called them: skip both)
        while frame.f_back and frame.f_code.co_filename.endswith(("build_base.py", "build.py")):
            frame = frame.f_back
        module = frame.f_globals.get("__name__", "?").rsplit(".", 1)[-1]
        NOTE_ORIGINS[id(self.notes[-1])] = module

    BuilderBase.note = tagged  # type: ignore[method-assign]
    try:
        yield
    finally:
        BuilderBase.note = plain  # type: ignore[method-assign]


def origin(reading: Reading, variable: str) -> str:
    """Which module first wrote ``variable`` and the shape of that note's manual line."""
    subject = f"variables.{variable}"
    notes = [n for n in reading.report.notes if n.subject == subject]
    notes = notes or [n for n in reading.report.notes if n.subject.startswith(subject + ".")]
    if not notes:
        return "from:? src:none"
    first: Note = next((n for n in notes if not n.guess), notes[0])
    module = NOTE_ORIGINS.get(id(first), "direct")
    said = note_kind(first.what)
    return f"from:{module}:{said} src:{line_shape(first.quote) if not first.guess else 'guess'}"


def origin_tags(
    reading: Reading,
    truth: ApplianceModel,
    variable: str,
    aligned: dict[str, str],
    manual: str,
    detail: bool = True,
) -> list[str]:
    """``--origin`` rows for a missed ``variable`` whose keys the reader used: per read variable
    on those keys, its kind, the module and source-line shape that made it, and the values' line.
    ``detail``: also how the values' table is built (:func:`table_detail`) — left out on the held
    out, where even masked marks of one table's build would describe an unseen manual's line."""
    read = reading.model
    keys = {a for a, vs in setters(truth).items() if variable in vs}
    candidates = sorted({v for a in keys for v in setters(read).get(a, set())})
    var = truth.variables[variable]
    vals = "vals:n/a"
    if isinstance(var, DiscreteVariable):
        names = [str(v).lower().replace("_", " ") for v in all_values(var)]
        line = values_line(manual, names)
        low = line.lower()
        hits = sum(1 for n in names if re.search(rf"(?<![a-z]){re.escape(n)}(?![a-z])", low))
        count = f"{hits}of{len(names)}"
        count += f"/{written_case(line, names)}"
        place = key_place(manual, line, keys) if line else ""
        vals = f"vals:{line_shape(line)}/{place}/{count}" if line else "vals:unwritten"
        if detail:
            vals += " " + table_detail(manual, line, keys, names)
    tags = []
    for candidate in candidates:
        how = "other" if candidate in aligned else "own"
        what = f"{how} read:{kind(read, candidate)} true:{kind(truth, variable)}"
        tags.append(f"{what} {origin(reading, candidate)} {vals}")
    return tags


def tally(
    suite_name: str, held_out: bool, why: bool
) -> tuple[Counter[str], Counter[str], Counter[str], Counter[str], list[str]]:
    """Totals and misses per mechanism, ``--why`` reasons and ``--origin`` rows, and (for the
    development data only) the per-setting lines."""
    suite = load_suite(suite_name)
    total: Counter[str] = Counter()
    missed: Counter[str] = Counter()
    reasons: Counter[str] = Counter()
    origins: Counter[str] = Counter()
    lines: list[str] = []
    for appliance in suite.appliances:
        if (appliance.category in HELD_OUT_CATEGORIES) != held_out:
            continue
        truth = appliance.model
        with note_origins():
            reading = read_manual(appliance.manual, list(truth.actions))
        read = reading.model
        aligned = align_variables(read, truth)
        found = set(aligned.values())
        uses = Counter(v for task in appliance.tasks for v in task.goal or {})
        for variable, n in sorted(uses.items()):
            if variable not in truth.variables:
                continue
            tags = mechanisms(truth, variable) | {"ALL"}
            for tag in tags:
                total[tag] += n
                missed[tag] += 0 if variable in found else n
            if variable not in found and why:
                why_tags = why_missed(read, truth, variable, aligned, appliance.manual)
                for reason in why_tags:
                    reasons[reason] += n
                shapes = [w.split(":", 1)[1] for w in why_tags if w.startswith("values-written-in")]
                reasons[f"{why_tags[0]} + {shapes[0] if shapes else 'values-not-named'}"] += n
                manual = appliance.manual
                for row in origin_tags(reading, truth, variable, aligned, manual, not held_out):
                    origins[row] += n
            if variable not in found and not held_out:
                lines.append(
                    f"  {appliance.id} {variable} ×{n}: {', '.join(sorted(tags - {'ALL'}))}"
                )
        NOTE_ORIGINS.clear()
    return total, missed, reasons, origins, lines


def _table(title: str, main: Counter[str], beside: Counter[str] | None, top: int) -> None:
    """Counts, largest first, with the second suite's count in a column beside."""
    head = f"{title:96s} {'n':>5s}" + (f" {'beside':>7s}" if beside is not None else "")
    print("\n" + head)
    keys = sorted(
        set(main) | set(beside or {}), key=lambda k: (-main[k], -(beside or {}).get(k, 0), k)
    )
    for key in keys[:top]:
        extra = f" {(beside or Counter())[key]:7d}" if beside is not None else ""
        print(f"{key:96s} {main[key]:5d}{extra}")


def _split(origins: Counter[str], field: int) -> Counter[str]:
    """One column of the ``--origin`` rows (0 kinds, 3 module, 4 source shape, 5 values shape,
    6 values table detail)."""
    out: Counter[str] = Counter()
    for row, n in origins.items():
        parts = row.split(" ")
        out[" ".join(parts[:3]) if field == 0 else parts[field] if field < len(parts) else "-"] += n
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--suite", default="bundled")
    parser.add_argument("--held-out", action="store_true", help="the six held out, aggregate only")
    parser.add_argument("--list", action="store_true", help="each missed setting (development)")
    parser.add_argument("--why", action="store_true", help="what the reader made of missed keys")
    parser.add_argument("--beside", help="a second (development) suite counted in a column beside")
    parser.add_argument("--top", type=int, default=40, help="rows of each --why table")
    args = parser.parse_args()
    total, missed, reasons, origins, lines = tally(args.suite, args.held_out, args.why)
    print(f"{'mechanism':24s} {'missed':>7s} {'of':>6s}  share")
    for tag in sorted(total, key=lambda t: (-missed[t] / total[t], t)):
        print(f"{tag:24s} {missed[tag]:7d} {total[tag]:6d}  {missed[tag] / total[tag]:.2f}")
    if args.why:
        other: tuple[Counter[str], Counter[str]] | None = None
        if args.beside:
            _, _, b_reasons, b_origins, _ = tally(args.beside, False, True)
            other = (b_reasons, b_origins)
        _table("why missed (task uses)", reasons, other[0] if other else None, args.top)
        _table(
            "origin: own/other read-kind true-kind",
            _split(origins, 0),
            _split(other[1], 0) if other else None,
            args.top,
        )
        for field, title in (
            (3, "origin: module"),
            (4, "origin: source line shape"),
            (5, "origin: values line shape"),
            *([] if args.held_out else [(6, "origin: values table detail")]),
        ):
            _table(
                title, _split(origins, field), _split(other[1], field) if other else None, args.top
            )
        _table("origin (whole rows)", origins, other[1] if other else None, args.top)
    if args.list and not args.held_out:
        print(
            "\n".join(["", "missed settings (appliance, setting, task uses, mechanisms):", *lines])
        )


if __name__ == "__main__":
    main()
