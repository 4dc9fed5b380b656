"""The method registry: names are unique, and what a test registers it can remove."""

from __future__ import annotations

import pytest

from apbot.agent.environment import Environment
from apbot.agent.episode import Episode, TaskContext
from apbot.agent.registry import Method, get_method, methods, register, unregister


def _idle(context: TaskContext, env: Environment) -> Episode:
    return Episode()


def test_a_registered_method_can_be_removed_again() -> None:
    fake = Method("test-idle", _idle, "does nothing")
    assert register(fake) is fake
    try:
        assert get_method("test-idle") is fake
        with pytest.raises(ValueError, match="registered twice"):
            register(Method("test-idle", _idle, "again"))
    finally:
        assert unregister("test-idle") is fake
    assert "test-idle" not in methods()
    with pytest.raises(KeyError, match="unknown method 'test-idle'"):
        get_method("test-idle")
    with pytest.raises(KeyError, match="'test-idle' is not registered"):
        unregister("test-idle")


def test_the_built_in_methods_are_registered() -> None:
    assert {"apbot", "apbot-open-loop", "apbot-no-button-policy", "oracle"} <= set(methods())
