"""The methods the benchmark can run, by name.

A method turns a :class:`TaskContext` and an :class:`Environment` into an :class:`Episode`.
LLM-based baselines register here too, so the runner, the metrics and the report treat every
method alike.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from apbot.agent.environment import Environment
from apbot.agent.episode import Episode, TaskContext

RunFunction = Callable[[TaskContext, Environment], Episode]


@dataclass(frozen=True)
class Method:
    """A named way of operating an appliance.

    ``uses_truth``: the method is given the ground-truth model whatever belief the run asks
    for (the oracle). ``needs_llm``: it asks an LLM (``apbot.llm``); it runs only when named,
    never as part of a default method list, so no run spends tokens unasked.
    """

    name: str
    run: RunFunction
    description: str
    uses_truth: bool = False
    needs_llm: bool = False


_METHODS: dict[str, Method] = {}


def register(method: Method) -> Method:
    if method.name in _METHODS:
        raise ValueError(f"method {method.name!r} is registered twice")
    _METHODS[method.name] = method
    return method


def unregister(name: str) -> Method:
    """Remove a method registered with :func:`register` (tests that add fakes clean up, so
    no other test, nor a default ``--methods``, ever runs them)."""
    if name not in _METHODS:
        raise KeyError(f"method {name!r} is not registered")
    return _METHODS.pop(name)


def methods() -> dict[str, Method]:
    """Every registered method, by name (importing the built-in ones first)."""
    import apbot.agent.llm_methods
    import apbot.agent.methods  # noqa: F401  (registers the built-in methods)

    return dict(_METHODS)


def default_methods() -> list[str]:
    """What a run with no ``--methods`` runs: every method that needs no LLM."""
    return [name for name, method in methods().items() if not method.needs_llm]


def get_method(name: str) -> Method:
    known = methods()
    if name not in known:
        raise KeyError(f"unknown method {name!r}; known: {', '.join(known)}")
    return known[name]
