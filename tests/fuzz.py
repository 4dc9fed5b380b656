"""Shared pieces of the fuzzers: budgets, a hang guard, and mutations of bundled files.

Budgets fit CI (a few seconds per fuzzer). ``pytest --hypothesis-profile=long`` (or
``APBOT_FUZZ=long``) multiplies every fuzzer's examples by :data:`LONG_FACTOR` for a longer
hunt; ``--hypothesis-show-statistics`` prints how many inputs each one tried.
"""

from __future__ import annotations

import copy
import os
import signal
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from functools import lru_cache
from typing import Any

import yaml
from hypothesis import HealthCheck, settings
from hypothesis import strategies as st

LONG_FACTOR = 40
LONG = os.environ.get("APBOT_FUZZ") == "long" or settings.get_current_profile_name() == "long"
HANG_SECONDS = 20.0  # far beyond any input's honest cost; past it the input hangs the code


def fuzz_settings(examples: int) -> settings:
    """Settings for a fuzzer that tries ``examples`` inputs in CI (more with the long profile).

    Hypothesis's own deadline is off: on a shared 2-core machine it would report noise as
    flakiness. :func:`no_hang` stops an input that runs away instead.
    """
    return settings(
        max_examples=examples * LONG_FACTOR if LONG else examples,
        deadline=None,
        suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
        print_blob=True,
    )


class Hang(BaseException):
    """An input ran past :data:`HANG_SECONDS` (a BaseException: no ``except Exception`` in the
    code under test can swallow it)."""


@contextmanager
def no_hang(what: str, seconds: float = HANG_SECONDS) -> Iterator[None]:
    """Fail the example with :class:`Hang` if the body runs longer than ``seconds``."""
    if (
        not hasattr(signal, "setitimer")
        or threading.current_thread() is not threading.main_thread()
    ):
        yield
        return

    def alarm(signum: int, frame: Any) -> None:
        raise Hang(f"{what} ran for more than {seconds:g} s")

    previous = signal.signal(signal.SIGALRM, alarm)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


# --- mutations -----------------------------------------------------------------------------

HOSTILE_TOKENS = [
    "",
    "-1",
    "0",
    "1e308",
    "1e-300",
    "-0.0",
    ".inf",
    "-.inf",
    ".nan",
    "null",
    "~",
    "yes",
    "off",
    "[]",
    "{}",
    "[[]]",
    "'",
    '"',
    ":",
    "- ",
    "? ",
    "&a",
    "*a",
    "&a [*a]",
    "<<: *a",
    "!!binary aGk=",
    "!!set {a, b}",
    "!!python/object/apply:os.system ['true']",
    "2024-01-01",
    "00:99:00",
    "99:59:59",
    "-00:00:30",
    "\t",
    "\x00",
    "\x85",
    "é",
    "🙂",
    "a" * 300,
    "9" * 40,
    "%YAML 1.1",
    "---",
    "...",
]

# JSON-ish values, from plain scalars to small nested collections
json_values = st.recursive(
    st.none()
    | st.booleans()
    | st.integers(min_value=-(10**20), max_value=10**20)
    | st.floats(allow_nan=True, allow_infinity=True)
    | st.text(max_size=12),
    lambda children: (
        st.lists(children, max_size=4) | st.dictionaries(st.text(max_size=8), children, max_size=4)
    ),
    max_leaves=8,
)


@st.composite
def mutated_text(draw: st.DrawFn, base: str) -> str:
    """``base`` with a few line- and character-level edits, hostile tokens among them."""
    lines = base.splitlines()
    for _ in range(draw(st.integers(min_value=1, max_value=4))):
        if not lines:
            lines = [""]
        i = draw(st.integers(min_value=0, max_value=len(lines) - 1))
        operation = draw(
            st.sampled_from(["delete", "duplicate", "swap", "token", "insert", "cut", "indent"])
        )
        if operation == "delete":
            del lines[i]
        elif operation == "duplicate":
            lines.insert(i, lines[i])
        elif operation == "swap":
            j = draw(st.integers(min_value=0, max_value=len(lines) - 1))
            lines[i], lines[j] = lines[j], lines[i]
        elif operation == "token":
            line = lines[i]
            at = draw(st.integers(min_value=0, max_value=len(line)))
            end = draw(st.integers(min_value=at, max_value=len(line)))
            lines[i] = line[:at] + draw(st.sampled_from(HOSTILE_TOKENS)) + line[end:]
        elif operation == "insert":
            lines.insert(i, draw(st.text(max_size=30)))
        elif operation == "cut":
            lines = lines[: i + 1]
        else:
            lines[i] = draw(st.sampled_from(["", " ", "  ", "\t"])) + lines[i]
    return "\n".join(lines) + draw(st.sampled_from(["\n", "", "\n\n"]))


def _paths(data: Any, prefix: tuple[Any, ...] = ()) -> Iterator[tuple[Any, ...]]:
    yield prefix
    if isinstance(data, dict):
        for key, value in data.items():
            yield from _paths(value, (*prefix, key))
    elif isinstance(data, list):
        for i, value in enumerate(data):
            yield from _paths(value, (*prefix, i))


def _strings(data: Any) -> Iterator[Any]:
    if isinstance(data, dict):
        for key, value in data.items():
            yield key
            yield from _strings(value)
    elif isinstance(data, list):
        for value in data:
            yield from _strings(value)
    else:
        yield data


@lru_cache(maxsize=64)
def _parsed(base: str) -> tuple[Any, tuple[Any, ...]]:
    data = yaml.safe_load(base)
    return data, tuple(s for s in _strings(data) if s is not None)


@st.composite
def mutated_data_text(draw: st.DrawFn, base: str) -> str:
    """``base`` parsed, one to three nodes replaced, deleted or duplicated, and dumped again.

    Replacements are often names and values the document already uses, so a mutant gets past
    the schema and reaches the semantic checks, the simulator and the planner.
    """
    original, known = _parsed(base)
    data = copy.deepcopy(original)
    for _ in range(draw(st.integers(min_value=1, max_value=3))):
        paths = [p for p in _paths(data) if p]
        if not paths:
            break
        path = paths[draw(st.integers(min_value=0, max_value=len(paths) - 1))]
        parent = data
        for part in path[:-1]:
            parent = parent[part]
        key = path[-1]
        operation = draw(st.sampled_from(["known", "value", "delete", "duplicate"]))
        if operation == "delete":
            del parent[key]
        elif operation == "duplicate" and isinstance(parent, list):
            parent.insert(key, parent[key])
        elif operation == "known" and known:
            parent[key] = known[draw(st.integers(min_value=0, max_value=len(known) - 1))]
        else:
            parent[key] = draw(json_values)
    return yaml.safe_dump(data, allow_unicode=True, sort_keys=False)
