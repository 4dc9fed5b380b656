"""The builder's ledger: the variables, features, notes and lamps a model is assembled into.

``Builder`` (build.py) reads numbers, the longest of its jobs; this base holds what every role
reader calls on it besides — where it writes a note, names a variable uniquely, adds a list or an
on/off setting and finds the lamp that shows it — so build.py keeps to reading ranges and steps.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.actions import ActionInfo
from apbot.read.evidence import EvidenceReader
from apbot.read.labels import Label
from apbot.read.named_starts import start_after_name
from apbot.read.report import Note
from apbot.read.shapes import (
    Evidence,
    _value_text,
)
from apbot.read.shapes_columns import (
    _dedupe,
)
from apbot.read.shown import shown_words
from apbot.read.symbol_lamps import lit_sign, sign_meaning, symbol_lamp, word_lamp
from apbot.read.text import Manual
from apbot.read.value_spans import expand_spans

_DISPLAY_RE = re.compile(
    r"\b(?:display|screen|indicators?|symbols?|icons?|lamps?|lights?|readouts?|signs?)\b", re.I
)
"""A section that explains what the panel shows."""


PLACEHOLDERS = "placeholders: the manual lists no choices"  # (the note on such a selector)


class BuilderBase(EvidenceReader):
    """Collects variables, features, guards and notes; ``data()`` gives the model as plain data."""

    def __init__(self, manual: Manual, infos: list[ActionInfo], labels: dict[str, Label]):
        self.manual = manual
        self.infos = infos
        self.labels = labels
        self.variables: dict[str, dict[str, Any]] = {}
        self.features: dict[str, list[dict[str, Any]]] = {}
        self.guards: list[dict[str, Any]] = []
        self.notes: list[Note] = []
        self.indicators: list[str] = []
        self._evidence: dict[tuple[str, ...], Evidence] = {}
        self.unread: set[str] = set()  # numbers whose range the manual never gave (guessed)

    # --- notes ------------------------------------------------------------------------------

    def note(self, subject: str, what: str, unit: int | None = None) -> None:
        if unit is None:
            self.notes.append(Note(subject, what, guess=True))
        else:
            line = self.manual.units[unit].line
            self.notes.append(Note(subject, what, line, self.manual.quote(line)))

    # --- evidence ---------------------------------------------------------------------------
    # --- variables --------------------------------------------------------------------------

    _fahrenheit: bool | None = None

    def fahrenheit(self) -> bool:
        """Whether the manual gives temperatures in °F more often than in °C."""
        if self._fahrenheit is None:
            text = "\n".join(u.text for u in self.manual.units)
            f = len(re.findall(r"°\s?F\b|\bdegrees F(?:ahrenheit)?\b", text))
            c = len(re.findall(r"°\s?C\b|\bdegrees C(?:elsius)?\b", text))
            self._fahrenheit = f > c
        return self._fahrenheit

    def unique(self, name: str, taken: dict[str, Any]) -> str:
        base = re.sub(r"[^a-z0-9_]+", "_", name.lower()).strip("_") or "setting"
        if not base[0].isalpha():
            base = "v_" + base
        out, k = base, 2
        while out in taken:
            out, k = f"{base}_{k}", k + 1
        return out

    def add_discrete(self, name: str, values: list[str], label: str, ev: Evidence | None) -> str:
        name = self.unique(name, self.variables)
        values = _dedupe([_value_text(v) for v in values if _value_text(v)])
        values = expand_spans(values)  # "OFF, WARM, 1-5, SEAR": five numbered positions
        initial = ev.initial if ev is not None else None
        if ev is not None and ev.initial_at is not None:  # "… call tone 1, VOX off, …"
            said = start_after_name(self.manual.units[ev.initial_at].text, label, values)
            initial = said if said is not None else initial
        if values in (["0", "i"], ["o", "i"]):  # a switch printed 0 / I: off and on
            values = ["off", "on"]
            initial = None  # ("position I" is as often the drawing's callout I)
        own = re.fullmatch(r"(.*?)\s+([A-Z0-9]{1,6}(?:/[A-Z0-9]{1,6})+)", label)
        if own and [p.lower() for p in own.group(2).split("/")] == values:
            label = own.group(1)  # the display names the setting, not the printed choices
        spec: dict[str, Any] = {"type": "discrete", "values": values, "label": label}
        if ev is not None and ev.shows and set(ev.shows) == set(values):
            spec["show"] = dict(ev.shows)  # "warm": "3000K", the figure its lamp prints
        if ev is not None and initial in values:
            spec["initial"] = initial
            self.note(f"variables.{name}.initial", f"starts at {initial}", ev.initial_at)
        self.variables[name] = spec
        return name

    def add_toggle(self, name: str, label: str, at: int | None, first: str = "off") -> str:
        name = self.unique(name, self.variables)
        self.variables[name] = {
            "type": "discrete",
            "values": ["off", "on"] if first == "off" else ["on", "off"],
            "label": label,
        }
        self.note(f"variables.{name}", "an on/off setting", at)
        shown = self._shown_on(name, label)
        if shown is not None:  # "FRESH ON appears": what the display prints while it is on
            self.variables[name]["show"] = {"off": "", "on": shown[0]}
            self.note(f"variables.{name}.show", f"the display shows {shown[0]} while on", shown[1])
            return name
        glyph = symbol_lamp(self.manual.units, label)
        if glyph is not None:  # "Mirror lamp ⇋ (lit when …)": the symbol lit while it is on
            self.variables[name]["show"] = {"off": "", "on": glyph[0]}
            self.note(f"variables.{name}.show", f"the {glyph[0]} lamp is lit while on", glyph[1])
            return name
        lit = word_lamp(self.manual.units, name.replace("_", " "))
        if lit is not None:  # "The PACER lamp is lit when the pacer is on (factory setting)"
            self.variables[name]["show"] = {"off": "", "on": lit[0]}
            self.note(f"variables.{name}.show", f"the {lit[0]} lamp is lit while on", lit[2])
            if lit[1]:
                self.variables[name]["initial"] = "on"
                self.note(f"variables.{name}.initial", "on as delivered", lit[2])
            return name
        near = self.manual.units[at].line if at is not None else None
        sign = lit_sign(self.manual.glyph_lines, name.replace("_", " "), near)
        if sign is not None:  # "◷ lit = zone timer on": the sign lit while it is on
            self.variables[name]["show"] = {"off": "", "on": sign[0]}
            what = f"the {sign[0]} lamp is lit while on"
            quote = self.manual.glyph_lines[sign[2] - 1].strip()[:160]
            self.notes.append(Note(f"variables.{name}.show", what, sign[2], quote))
            if sign[1]:
                self.variables[name]["initial"] = "on"
            return name
        means = sign_meaning(self.manual.glyph_lines, name.replace("_", " "))
        if means is not None:  # "♪ flag beep on (MUTE when off)": the sign, the word when off
            self.variables[name]["show"] = {"off": means[1], "on": means[0]}
            quote = self.manual.glyph_lines[means[2] - 1].strip()[:160]
            what = f"the display shows {means[0]} while on"
            self.notes.append(Note(f"variables.{name}.show", what, means[2], quote))
            self.indicators.append(name)
            return name
        lamp = self.lamp_unit(label)
        if lamp is not None:  # only a lamp the manual names: a wrong lamp misleads the reading
            self.indicators.append(name)
            self.note(f"display.indicators.{name}", "a lamp shows it", lamp)
        return name

    def _shown_on(self, name: str, label: str) -> tuple[str, int] | None:
        """A word of the key's name with ON after it that the display shows ("FRESH ON appears",
        a display legend's "FRESH ON   KEEP FRESH is on"): the sign the setting is on. A row
        counts only under a display heading ("POWER ON   two beeps" in a table of sounds is
        no display text), and never for the power switch, whose ON names the key's job."""
        if name == "power":
            return None
        names = [
            w
            for w in re.findall(r"[A-Z][A-Z0-9+-]{2,}", label)
            if w not in ("ON", "OFF", "POWER", "MAIN")
        ]
        if not names or label.upper() != label:
            return None
        phrase = re.compile(rf"(?<![\w/])((?:{'|'.join(map(re.escape, names))}) ON)(?![\w/])")
        for i, unit in enumerate(self.manual.units):
            for m in phrase.finditer(unit.text):
                legend = re.match(r"\s{2,}\S", unit.text[m.end() :])
                if legend and _DISPLAY_RE.search(self._section(unit.line) or unit.heading):
                    return m.group(1), i
                if m.group(1) in shown_words(unit.text):
                    return m.group(1), i
        return None

    def _section(self, line: int) -> str:
        """The nearest title above a line ("The display", "Sounds", "## Symbols"): a short line
        standing alone between blank lines, without a full stop — marked as a heading or not."""
        lines = self.manual.lines
        for k in range(min(line, len(lines)) - 2, max(line - 40, 0), -1):
            text = lines[k].strip()
            alone = not lines[k - 1].strip() and k + 1 < len(lines) and not lines[k + 1].strip()
            if text and alone and len(text.split()) <= 5 and not text.endswith((".", ":", ",")):
                return text
        return ""

    def lamp_unit(self, label: str) -> int | None:
        """A sentence saying the label lights up on the panel (a lamp, symbol or indicator)."""
        if not label:
            return None
        pattern = re.compile(rf"(?<![A-Za-z0-9]){re.escape(label)}(?![A-Za-z0-9])")
        cue = re.compile(
            r"\b(?:display|screen|appears?|shows?|shown)\b",  # text on the display, not a lamp
            re.IGNORECASE,
        )
        for i, unit in enumerate(self.manual.units):
            if pattern.search(unit.text) and cue.search(unit.text):
                return i
        return None

    # --- the whole model --------------------------------------------------------------------

    def feature(self, name: str, steps: list[dict[str, Any]]) -> None:
        self.features[self.unique(name, self.features)] = steps
