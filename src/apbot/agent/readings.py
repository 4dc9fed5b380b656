"""What a display reading is: the screens a belief can show and the readings of a text.

Split from :mod:`apbot.agent.reader` so that the closed loop's modules (perception, checking)
can name a reading's parts without the machinery that produces them; the reader re-exports
them, so ``from apbot.agent.reader import Hypothesis`` keeps working.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Literal

ScreenKind = Literal["focus", "idle", "guard"]
_ABSENT = object()


@dataclass(frozen=True)
class Screen:
    """One thing the display can show: a variable being adjusted (``focus``), the idle screen,
    or a guard's text. ``fixed`` holds values the screen itself implies (the ``show`` entry of
    a value: ``RUN`` means running is on)."""

    kind: ScreenKind
    variable: str | None = None
    guard: int | None = None
    template: str = ""
    fixed: tuple[tuple[str, Any], ...] = ()

    @property
    def blank(self) -> bool:
        return not self.template.strip()

    def describe(self) -> str:
        if self.kind == "focus":
            return f"{self.variable} being adjusted"
        if self.kind == "idle":
            return "the idle screen"
        return f"guard {self.guard} ({self.template or 'dark'})"


@dataclass(frozen=True)
class Hypothesis:
    """One way the text fits the belief's display rules.

    ``values``: belief variable → canonical value in its (current) belief domain;
    ``outside``: variable → value of the right type that the belief's domain lacks;
    ``absent``: variables shown as ``--``; ``lamps``: indicator → the values its lamps allow
    (more than one when lamps cannot tell them apart); ``partial``: the screen was found inside
    a longer text.
    """

    screen: Screen
    values: dict[str, Any] = field(default_factory=dict)
    outside: dict[str, Any] = field(default_factory=dict)
    absent: frozenset[str] = frozenset()
    lamps: dict[str, frozenset[Any]] = field(default_factory=dict)
    partial: bool = False

    def shown(self) -> set[str]:
        """Every variable this reading says something about."""
        return set(self.values) | set(self.outside) | set(self.absent) | set(self.lamps)

    def value(self, name: str) -> Any:
        """The value read for ``name`` (``outside`` ones included); ``_ABSENT`` if none."""
        if name in self.values:
            return self.values[name]
        if name in self.outside:
            return self.outside[name]
        lamp = self.lamps.get(name)
        if lamp is not None and len(lamp) == 1:
            return next(iter(lamp))
        return None if name in self.absent else _ABSENT


@dataclass(frozen=True)
class Reading:
    """Everything the text could mean. No hypothesis at all: the text is unknown."""

    text: str
    hypotheses: tuple[Hypothesis, ...]

    @property
    def unknown(self) -> bool:
        return not self.hypotheses

    @property
    def blank(self) -> bool:
        return not self.text.strip()

    def candidates(self, name: str) -> set[Any]:
        """Every value some hypothesis reads for ``name`` (None for ``--``)."""
        found: set[Any] = set()
        for hypothesis in self.hypotheses:
            value = hypothesis.value(name)
            if value is not _ABSENT:
                found.add(value)
            elif name in hypothesis.lamps:
                found |= set(hypothesis.lamps[name])
        return found


def is_read(value: Any) -> bool:
    """Whether :meth:`Hypothesis.value` found a value (None included: shown as ``--``)."""
    return value is not _ABSENT
