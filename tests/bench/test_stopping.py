"""Stopping early: SIGTERM is handled like Ctrl-C, a second signal abandons, exit codes."""

from __future__ import annotations

import os
import signal

import pytest

from apbot.bench.stopping import WORKER_DIED, Stop, handling_signals


def test_the_first_signal_finishes_the_running_tasks_and_the_second_abandons_them() -> None:
    said: list[str] = []
    stop = Stop(in_process=False)
    stop.notice = said.append
    stop(signal.SIGTERM, None)
    assert (stop.requested, stop.reason, stop.hard, stop.exit_code) == (True, "SIGTERM", False, 143)
    assert said == [
        "stopping (SIGTERM): finishing the running tasks (SIGTERM again to abandon them)"
    ]
    stop(signal.SIGINT, None)
    assert stop.hard and stop.reason == "SIGTERM" and len(said) == 1


def test_in_this_process_the_second_signal_interrupts_the_running_task() -> None:
    stop = Stop(in_process=True)
    stop(signal.SIGINT, None)
    assert stop.exit_code == 130
    with pytest.raises(KeyboardInterrupt):
        stop(signal.SIGINT, None)


def test_a_signal_right_after_a_worker_died_is_the_reason_not_a_second_signal() -> None:
    stop = Stop(in_process=False)
    stop.request(WORKER_DIED)
    assert stop.exit_code == 1
    stop(signal.SIGTERM, None)  # the same `kill` that killed the worker
    assert (stop.reason, stop.hard, stop.exit_code) == ("SIGTERM", False, 143)


def test_signals_reach_the_handler_only_while_it_is_installed() -> None:
    before = signal.getsignal(signal.SIGINT), signal.getsignal(signal.SIGTERM)
    stop = Stop(in_process=False)
    with handling_signals(stop):
        os.kill(os.getpid(), signal.SIGTERM)
    assert stop.reason == "SIGTERM"
    assert (signal.getsignal(signal.SIGINT), signal.getsignal(signal.SIGTERM)) == before
