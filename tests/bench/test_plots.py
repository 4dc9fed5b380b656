"""The report's figures: every method's line visible, deterministic SVG with text as text."""

from __future__ import annotations

import numpy as np
from matplotlib.colors import to_rgb
from matplotlib.figure import Figure

from apbot.bench import plots

SAME = {"1": {"sr": 1.0, "n": 10}, "2": {"sr": 1.0, "n": 10}, "3": {"sr": 0.5, "n": 10}}
METHODS = ["oracle", "apbot", "apbot-open-loop", "apbot-no-button-policy", "other"]


def _goal_figure() -> Figure:
    by_count = {m: SAME for m in METHODS[:3]}
    by_count |= {m: {"1": {"sr": 0.5, "n": 4}, "3": {"sr": 0.0, "n": 4}} for m in METHODS[3:]}
    return plots.goal_variables_figure(METHODS, by_count)


def test_goal_size_plot_shows_every_method_even_with_identical_results() -> None:
    """The oracle, ApBot and open loop score the same: each still has its own coloured line."""
    figure = _goal_figure()
    panels = [ax for ax in figure.axes if ax.get_visible()]
    assert [ax.get_title() for ax in panels] == METHODS
    grey = to_rgb("0.8")
    for index, ax in enumerate(panels):
        own = [line for line in ax.get_lines() if to_rgb(line.get_color()) != grey]
        assert len(own) == 1 and len(ax.get_lines()) == len(METHODS)
        assert to_rgb(own[0].get_color()) == to_rgb(f"C{index}")
        assert own[0].get_zorder() > max(
            line.get_zorder() for line in ax.get_lines() if line is not own[0]
        )
        expected = SAME if index < 3 else {"1": {"sr": 0.5}, "3": {"sr": 0.0}}
        assert np.asarray(own[0].get_xdata()).tolist() == [int(k) for k in expected]
        assert np.asarray(own[0].get_ydata()).tolist() == [p["sr"] for p in expected.values()]
    assert len([ax for ax in figure.axes if not ax.get_visible()]) == 3  # 5 panels on a 4×2 grid


def test_svg_is_deterministic_and_keeps_text_as_text() -> None:
    def figure() -> Figure:
        return plots.goal_variables_figure(
            ["apbot", "apbot-open-loop"], dict.fromkeys(METHODS, SAME)
        )

    first, second = plots.svg_bytes(figure()), plots.svg_bytes(figure())
    assert first == second
    text = first.decode("utf-8")
    assert text.startswith("<?xml") and ">apbot-open-loop</text>" in text
    assert "<dc:date>" not in text
