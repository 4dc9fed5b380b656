"""What an effect does to a value, and how keypad digits read: model semantics, as functions.

The simulator compiles these into lookup tables (``apbot.sim.compiled``), the checker uses the
same functions to judge a model (``apbot.model.validate``), and the agent's repairs read a
step's effects through :func:`default_effect`: one definition, so none of them can drift.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

from apbot.model.domain import Domain
from apbot.model.schema import (
    Add,
    ApplianceModel,
    Conditional,
    Entry,
    GoTo,
    OtherThan,
    Skip,
    TimeVariable,
    time_step_seconds,
)
from apbot.model.values import parse_hms


def default_effect(step: Any, action: str, model: ApplianceModel) -> Any:
    """The effect of ``action`` in ``step``, with the defaults filled in.

    With no ``effect``: a step that adjusts a variable with keypad keys types digits; with a
    single action it steps to the next value; a step without a variable has no main effect.
    """
    if isinstance(step.effect, dict):
        return step.effect.get(action, "none")
    if step.effect is not None:
        return step.effect
    if step.variable is None:
        return "none"
    if model.actions[action].digit is not None:
        return "digit"
    return "next"


def value_index(domain: Domain, raw: Any) -> int | None:
    """Index of a model-written value (``to:``, ``set:``, guard values) in a domain.

    >>> from apbot.model.domain import build_domain
    >>> from apbot.model.schema import NumericVariable
    >>> domain = build_domain(NumericVariable(type="numeric", ranges=[(0, 10, 5)]))
    >>> value_index(domain, "5"), value_index(domain, 7)
    (1, None)
    """
    if domain.kind == "discrete":
        return domain.index.get(str(raw))
    if domain.kind == "time":
        try:
            seconds = parse_hms(str(raw))
        except ValueError:
            return None
        assert domain.magnitudes is not None
        return next((i for i, m in enumerate(domain.magnitudes) if m == seconds), None)
    try:
        number = float(raw)
    except (TypeError, ValueError):
        return None
    assert domain.magnitudes is not None
    return next((i for i, m in enumerate(domain.magnitudes) if abs(m - number) < 1e-9), None)


def condition_values(wanted: Any) -> list[Any]:
    """The values a condition names (``{other_than: ...}``: the ones it excludes)."""
    listed = wanted.other_than if isinstance(wanted, OtherThan) else wanted
    return list(listed) if isinstance(listed, list) else [listed]


def condition_indices(domain: Domain, wanted: Any) -> frozenset[int]:
    """The indices of ``domain`` a guard or effect condition accepts: one value, any of a
    list, or with ``{other_than: ...}`` every value but those.

    >>> from apbot.model.domain import build_domain
    >>> from apbot.model.schema import DiscreteVariable
    >>> dial = build_domain(DiscreteVariable(type="discrete", values=["off", "bake", "grill"]))
    >>> sorted(condition_indices(dial, OtherThan(other_than="off")))
    [1, 2]
    """
    named = {i for raw in condition_values(wanted) if (i := value_index(domain, raw)) is not None}
    if isinstance(wanted, OtherThan):
        return frozenset(range(len(domain))) - named
    return frozenset(named)


def leaf_effects(effect: Any) -> list[Any]:
    """The plain effects a (possibly conditional) effect may apply."""
    if isinstance(effect, Conditional):
        return [*leaf_effects(effect.then), *leaf_effects(effect.otherwise)]
    return [effect]


def constant_table(domain: Domain, target: int) -> tuple[int, ...]:
    """The table of an assignment: every value goes to ``target``."""
    return (target,) * len(domain)


def effect_table(effect: Any, domain: Domain, var: Any) -> tuple[int, ...] | None:
    """``new_index = table[index]`` for one value-changing effect on one domain (None: a go-to
    value outside this domain). ``digit`` and ``clear`` are not tables (see the simulator)."""
    n = len(domain)
    if effect == "next":
        return tuple(domain.next_index(i) for i in range(n))
    if effect == "prev":
        return tuple(domain.prev_index(i) for i in range(n))
    if effect == "toggle":
        return tuple((i + 1) % n for i in range(n))
    if effect == "reset":
        return constant_table(domain, domain.initial)
    if isinstance(effect, GoTo):
        target = value_index(domain, effect.to)
        return None if target is None else constant_table(domain, target)
    if isinstance(effect, Skip):
        move = domain.next_index if effect.skip > 0 else domain.prev_index
        table = []
        for i in range(n):
            for _ in range(abs(effect.skip)):
                i = move(i)
            table.append(i)
        return tuple(table)
    if isinstance(effect, Add):
        amount = add_amount(effect.add, var)
        assert domain.magnitudes is not None
        mags = domain.magnitudes
        return tuple(domain.snap_index(mags[i] + amount, down=amount < 0) for i in range(n))
    return tuple(range(n))


def add_amount(amount: Any, var: Any) -> float:
    """An ``add`` amount as a number (seconds for a time variable)."""
    if isinstance(var, TimeVariable):
        return float(time_step_seconds(amount) if isinstance(amount, str) else amount)
    return float(amount)


def parse_entry(buffer: str, entry: Entry) -> float | None:
    """The number a keypad buffer stands for (seconds for times), or None if it is not valid.

    >>> parse_entry("130", Entry(format="mm:ss")), parse_entry("190", Entry(format="mm:ss"))
    (90.0, None)
    """
    if not buffer:
        return None
    fmt = entry.format
    if fmt == "number":
        return float(int(buffer))
    if fmt == "minutes":
        return float(int(buffer) * 60)
    if fmt == "seconds":
        return float(int(buffer))
    padded = buffer.zfill(6 if fmt == "hh:mm:ss" else 4)
    if fmt == "hh:mm:ss":
        hours, minutes, secs = int(padded[:-4]), int(padded[-4:-2]), int(padded[-2:])
        if minutes >= 60 or secs >= 60:
            return None
        return float(hours * 3600 + minutes * 60 + secs)
    high, low = int(padded[:-2]), int(padded[-2:])
    if low >= 60:
        return None
    return float(high * 60 + low) if fmt == "mm:ss" else float(high * 3600 + low * 60)


def type_digit(buffer: str, digit: str, entry: Entry) -> str:
    """The buffer after typing one digit (shift out the oldest, or ignore, when full)."""
    if len(buffer) < entry.digits():
        return buffer + digit
    return (buffer + digit)[1:] if entry.overflow == "shift" else buffer


def entry_digits(magnitude: float, entry: Entry) -> str | None:
    """The shortest digit string whose entry parses to ``magnitude`` (None: not typeable).

    Digits are right-aligned and zero-padded, so leading zeros never help.

    >>> entry_digits(90, Entry(format="mm:ss")), entry_digits(5400, Entry(format="h:mm"))
    ('130', '130')
    """
    return _entry_text(magnitude, entry.format, entry.digits())


def typed_lengths(magnitudes: tuple[float, ...], entry: Entry) -> tuple[int | None, ...]:
    """Per magnitude, how many digits type it (None: not typeable).

    Cached by domain and entry: every repair rebuilds and re-checks the model, and the
    planner weighs keypad values on every plan, each time over the same long ranges.

    >>> typed_lengths((30.0, 90.0, 95.5), Entry(format="mm:ss"))
    (2, 3, None)
    """
    return _typed_lengths(magnitudes, entry.format, entry.digits())


@lru_cache(maxsize=64)  # a day in seconds keeps ~3.5 MB alive: few entries
def _typed_lengths(magnitudes: tuple[float, ...], fmt: str, width: int) -> tuple[int | None, ...]:
    return tuple(
        None if (text := _entry_text(m, fmt, width)) is None else len(text) for m in magnitudes
    )


def _entry_text(magnitude: float, fmt: str, width: int) -> str | None:
    if magnitude < 0 or abs(magnitude - round(magnitude)) > 1e-9:
        return None
    total = round(magnitude)
    if fmt in ("number", "seconds"):
        text = str(total)
    elif fmt == "minutes":
        if total % 60:
            return None
        text = str(total // 60)
    elif fmt == "mm:ss":
        text = str((total // 60) * 100 + total % 60)
    elif fmt in ("hh:mm", "h:mm"):
        if total % 60:
            return None
        text = str((total // 3600) * 100 + (total % 3600) // 60)
    else:
        hours, rest = divmod(total, 3600)
        text = str(hours * 10000 + (rest // 60) * 100 + rest % 60)
    return text if len(text) <= width else None
