"""Wrap a third-party appliance simulator as an :class:`Environment` in a line or two.

A simulator written without apbot in mind usually has one method per button and reports what
the appliance shows in its own words: a dict of its own variable names, a display string, or
both. :class:`ObjectEnvironment` turns such an object into an environment (state estimation
then maps its names onto the belief model's); :class:`FunctionEnvironment` does the same for
a single ``step(action)`` function.

>>> class Fan:
...     def reset(self):
...         self.on, self.speed = False, "Low"
...     def press_power(self):
...         self.on = not self.on
...         return {"Fan": "ON" if self.on else "OFF", "Spd": self.speed}
>>> env = ObjectEnvironment(Fan())
>>> env.actions, env.reset()
(('press_power',), Feedback(text='', values={}, accepted=True, reason='', image=None))
>>> env.step("press_power").text
'Fan: ON, Spd: Low'
"""

from __future__ import annotations

import inspect
from collections.abc import Callable, Mapping, Sequence
from typing import Any

from apbot.agent.environment import Feedback
from apbot.model.values import closest_matches
from apbot.sim.simulator import UnknownAction

Refusals = tuple[type[Exception], ...]


class _CallEnvironment:
    """The part both wrappers share: call something per action, read what it returns."""

    def __init__(
        self,
        owner: str,
        calls: dict[str, Callable[[float | None], Any]],
        reset: Callable[[], Any] | None,
        text: Callable[[], str] | None,
        refusals: Refusals,
    ) -> None:
        if not calls:
            raise ValueError(f"{owner} has no actions; list them with actions=[...]")
        if not all(isinstance(r, type) and issubclass(r, Exception) for r in refusals):
            raise TypeError(f"refusals must be exception classes, got {refusals!r}")
        self._owner = owner
        self._calls = calls
        self._actions = tuple(calls)
        self._reset = reset
        self._text = text
        self._refusals = refusals

    @property
    def actions(self) -> Sequence[str]:
        return self._actions

    def reset(self) -> Feedback:
        """Reset the wrapped simulator (if it can be) and report what it shows."""
        result = self._reset() if self._reset is not None else None
        return self._feedback(result, "reset")

    def step(self, action: str, seconds: float | None = None) -> Feedback:
        """Call the action; an exception listed in ``refusals`` is a refused action."""
        call = self._calls.get(action)
        if call is None:
            close = closest_matches(action, self._actions)
            hint = f"; did you mean {' or '.join(map(repr, close))}?" if close else ""
            raise UnknownAction(
                f"{self._owner} has no action {action!r}{hint} "
                f"(actions: {', '.join(self._actions)})"
            )
        try:
            result = call(seconds)
        except self._refusals as exc:
            return Feedback(
                self._text() if self._text else "", {}, False, str(exc) or type(exc).__name__
            )
        return self._feedback(result, action)

    def _feedback(self, result: Any, action: str) -> Feedback:
        if isinstance(result, Feedback):
            return result
        shown_text: str | None = None
        values: Mapping[Any, Any] = {}
        if isinstance(result, str):
            shown_text = result
        elif isinstance(result, Mapping):
            values = result
        elif (
            isinstance(result, tuple)
            and len(result) == 2
            and isinstance(result[0], str)
            and isinstance(result[1], Mapping)
        ):
            shown_text, values = result
        elif result is not None:
            raise TypeError(
                f"{self._owner}: {action} returned a {type(result).__name__}; "
                "return a dict of the values shown, the display text, a "
                "(text, dict) pair or None"
            )
        if shown_text is None:
            shown_text = self._text() if self._text else render(values)
        return Feedback(shown_text, {str(k): v for k, v in values.items()})


def render(values: Mapping[Any, Any]) -> str:
    """A readable display for an environment that reports only values: "Fan: ON, Spd: Low"."""
    return ", ".join(f"{name}: {value}" for name, value in values.items())


class ObjectEnvironment(_CallEnvironment):
    """An object with one method per action, as an :class:`Environment`.

    ``actions``: the method names that are actions (default: every public method of the
    object's class except ``reset``, in definition order — list them to leave out helpers
    such as ``display()``). ``reset``: the method that starts an episode (None: the object
    cannot be reset). A method that takes ``seconds`` receives how long a hold lasts.

    A method may return a dict of the values shown (its own names), the display text, a
    ``(text, dict)`` pair, a :class:`Feedback` or None. ``text(obj)`` reads the display when
    the method returns no text (default: the dict rendered as "name: value, ..."). An
    exception of a type listed in ``refusals`` means the appliance refused the action
    (``accepted=False``, the message as ``reason``); any other exception propagates.
    """

    def __init__(
        self,
        obj: Any,
        actions: Sequence[str] | None = None,
        reset: str | None = "reset",
        text: Callable[[Any], str] | None = None,
        refusals: Refusals = (),
    ) -> None:
        owner = type(obj).__name__
        if isinstance(actions, str):
            raise TypeError("actions is a list of method names, not one string")
        if reset is not None and not callable(getattr(obj, reset, None)):
            raise TypeError(
                f"{owner} has no method {reset!r} to start an episode; name its "
                "reset method with reset='...', or pass reset=None"
            )
        names = list(actions) if actions is not None else _public_methods(obj, reset)
        calls: dict[str, Callable[[float | None], Any]] = {}
        for name in names:
            method = getattr(obj, name, None) if not name.startswith("__") else None
            if name in calls:
                raise ValueError(f"action {name!r} is listed twice")
            if not callable(method):
                close = closest_matches(name, _public_methods(obj, None))
                hint = f"; did you mean {close[0]!r}?" if close else ""
                raise ValueError(f"{owner} has no method {name!r}{hint}")
            calls[name] = _timed(method)
        self.obj = obj
        super().__init__(
            owner,
            calls,
            getattr(obj, reset) if reset is not None else None,
            (lambda: text(obj)) if text is not None else None,
            tuple(refusals),
        )


class FunctionEnvironment(_CallEnvironment):
    """A ``step_fn(action)`` function (``step_fn(action, seconds=...)`` if it takes
    ``seconds``) as an :class:`Environment`; its results are read as
    :class:`ObjectEnvironment` reads a method's."""

    def __init__(
        self,
        step_fn: Callable[..., Any],
        actions: Sequence[str],
        reset_fn: Callable[[], Any] | None = None,
        refusals: Refusals = (),
    ) -> None:
        if isinstance(actions, str):
            raise TypeError("actions is a list of action names, not one string")
        if len(set(actions)) != len(actions):
            raise ValueError("an action is listed twice")
        timed = _takes_seconds(step_fn)

        def call(name: str) -> Callable[[float | None], Any]:
            def run(seconds: float | None) -> Any:
                if timed and seconds is not None:
                    return step_fn(name, seconds=seconds)
                return step_fn(name)

            return run

        owner = getattr(step_fn, "__name__", "step function")
        super().__init__(
            owner, {name: call(name) for name in actions}, reset_fn, None, tuple(refusals)
        )


def _public_methods(obj: Any, reset: str | None) -> list[str]:
    """Methods defined by the object's classes (not ``object``), in definition order."""
    names: dict[str, None] = {}
    for cls in type(obj).__mro__[:-1]:
        for name, attr in vars(cls).items():
            if (
                not name.startswith("_")
                and name != reset
                and name not in names
                and (inspect.isfunction(attr) or isinstance(attr, staticmethod | classmethod))
            ):
                names[name] = None
    return list(names)


def _takes_seconds(fn: Callable[..., Any]) -> bool:
    try:
        parameters = inspect.signature(fn).parameters.values()
    except (TypeError, ValueError):  # a builtin without a signature
        return False
    return any(p.name == "seconds" or p.kind is p.VAR_KEYWORD for p in parameters)


def _timed(method: Callable[..., Any]) -> Callable[[float | None], Any]:
    """Call ``method`` with the hold's ``seconds`` when it takes them, else with nothing."""
    if _takes_seconds(method):
        return lambda seconds: method() if seconds is None else method(seconds=seconds)
    return lambda seconds: method()
