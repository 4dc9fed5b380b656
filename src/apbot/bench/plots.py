"""The report's figures, drawn with matplotlib's object API and rendered to SVG (or PNG) bytes.

Figures are built on :class:`matplotlib.figure.Figure` directly (no ``pyplot``), so nothing
touches a display or global figure state: the canvases render them anywhere. The report uses
SVG with the text kept as text: smaller than a PNG of the same figure, and sharp at any zoom.
Metadata (and SVG's element ids) are fixed so the same inputs give byte-identical files.
"""

from __future__ import annotations

import io
import math
from collections.abc import Mapping, Sequence
from typing import Any

import matplotlib
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.backends.backend_svg import FigureCanvasSVG
from matplotlib.colors import LogNorm
from matplotlib.figure import Figure

P_FLOOR = 1e-6  # summary.json rounds p to 6 decimals: a 0 there means "below this"
SIGNIFICANT = 0.05
_DPI = 110


def png_bytes(figure: Figure) -> bytes:
    """The figure as a PNG, without the version/date metadata that would make it vary."""
    FigureCanvasAgg(figure)
    buffer = io.BytesIO()
    figure.savefig(
        buffer,
        format="png",
        dpi=_DPI,
        bbox_inches="tight",
        pad_inches=0.1,
        metadata={"Software": None},
    )
    return buffer.getvalue()


def svg_bytes(figure: Figure) -> bytes:
    """The figure as SVG: text as ``<text>`` (not paths), no date, ids from a fixed salt."""
    FigureCanvasSVG(figure)
    buffer = io.BytesIO()
    settings: dict[Any, Any] = {  # matplotlib's own font, named in the SVG before sans-serif
        "svg.fonttype": "none",
        "svg.hashsalt": "apbot-report",
        "font.sans-serif": ["DejaVu Sans"],
    }
    with matplotlib.rc_context(settings):
        figure.savefig(
            buffer,
            format="svg",
            bbox_inches="tight",
            pad_inches=0.1,
            metadata={"Date": None, "Creator": None},
        )
    return buffer.getvalue()


def format_p(p: float) -> str:
    """A p-value short enough for a table cell.

    >>> format_p(0.5), format_p(0.0123), format_p(0.00004), format_p(0.0)
    ('0.500', '0.012', '4.0e-05', '<1e-06')
    """
    if p < P_FLOOR:
        return f"<{P_FLOOR:.0e}"
    return f"{p:.3f}" if p >= 0.001 else f"{p:.1e}"


def overview_figure(methods: Sequence[str], overall: Mapping[str, Mapping[str, float]]) -> Figure:
    """SR, SPL and the two step counts per method: the paper's overall-performance panels."""
    figure = Figure(figsize=(10, 3.2), layout="constrained")
    panels = [
        ("sr", "Success rate", (0, 1.05)),
        ("spl", "SPL", (0, 1.05)),
        ("steps", "Average steps", None),
    ]
    axes = figure.subplots(1, len(panels))
    positions = list(range(len(methods)))
    for ax, (key, title, limits) in zip(axes, panels, strict=True):
        if key == "steps":
            width = 0.4
            for offset, field, label in (
                (-width / 2, "reasoning_steps", "reasoning"),
                (width / 2, "execution_steps", "execution"),
            ):
                ax.bar(
                    [p + offset for p in positions],
                    [overall[m].get(field, 0.0) for m in methods],
                    width,
                    label=label,
                )
            highest = max(
                (
                    overall[m].get(f, 0.0)
                    for m in methods
                    for f in ("reasoning_steps", "execution_steps")
                ),
                default=0.0,
            )
            ax.set_ylim(0, max(highest, 1.0) * 1.3)  # room for the legend above the bars
            ax.legend(fontsize=8, loc="upper left", ncol=2)
        else:
            ax.bar(
                positions,
                [overall[m].get(key, 0.0) for m in methods],
                0.6,
                color=[f"C{i % 10}" for i in positions],
            )
        ax.set_title(title, fontsize=10)
        _method_ticks(ax, methods)
        if limits:
            ax.set_ylim(*limits)
        ax.grid(axis="y", alpha=0.3)
    return figure


def pvalue_figure(methods: Sequence[str], pvalues: Mapping[str, Mapping[str, float]]) -> Figure:
    """The chi-square p-value matrix as a log-coloured heat map; p < 0.05 is starred and bold."""
    size = max(3.5, 1.0 + 0.9 * len(methods))
    figure = Figure(figsize=(size + 1.2, size), layout="constrained")
    ax = figure.subplots()
    norm = LogNorm(vmin=P_FLOOR, vmax=1.0)
    grid = [[_pvalue(pvalues, a, b) for b in methods] for a in methods]
    shown = [[math.nan if p is None else max(p, P_FLOOR) for p in row] for row in grid]
    image = ax.imshow(shown, cmap="viridis", norm=norm)
    colorbar = figure.colorbar(image, ax=ax, shrink=0.8)
    colorbar.set_label("p (log scale)")
    colorbar.ax.axhline(SIGNIFICANT, color="black", linewidth=1.5)
    for i, row in enumerate(grid):
        for j, p in enumerate(row):
            if i == j or p is None:
                text, weight, colour = "—", "normal", "grey"
            else:
                star = p < SIGNIFICANT
                text = format_p(p) + ("*" if star else "")
                weight = "bold" if star else "normal"
                colour = "white" if max(p, P_FLOOR) < 1e-3 else "black"
            ax.text(
                j, i, text, ha="center", va="center", fontsize=8, fontweight=weight, color=colour
            )
    ax.set_xticks(range(len(methods)), list(methods), rotation=30, ha="right", fontsize=8)
    ax.set_yticks(range(len(methods)), list(methods), fontsize=8)
    ax.set_title("χ² test p-values (* p < 0.05)", fontsize=10)
    return figure


def goal_variables_figure(
    methods: Sequence[str], by_count: Mapping[str, Mapping[str, Mapping[str, float]]]
) -> Figure:
    """Success rate against the number of variables a task sets: one small panel per method on
    shared axes, the other methods faint behind it. Methods with the same results (the oracle
    and ApBot on the true model) drew on top of each other in one panel; here none can hide."""
    columns = max(1, min(len(methods), 4))
    rows = max(1, math.ceil(len(methods) / columns))
    figure = Figure(figsize=(0.4 + 2.5 * columns, 0.5 + 2.2 * rows), layout="constrained")
    axes = figure.subplots(rows, columns, sharex=True, sharey=True, squeeze=False).flat
    counts = sorted({int(k) for m in methods for k in by_count.get(m, {})})

    def series(method: str) -> tuple[list[int], list[float]]:
        points = by_count.get(method, {})
        xs = [c for c in counts if str(c) in points]
        return xs, [points[str(c)]["sr"] for c in xs]

    for index, ax in enumerate(axes):
        if index >= len(methods):
            ax.set_visible(False)
            continue
        for other in methods:
            if other != methods[index]:
                ax.plot(*series(other), color="0.8", linewidth=1, zorder=1)
        ax.plot(*series(methods[index]), color=f"C{index % 10}", marker="o", markersize=5, zorder=3)
        ax.set_title(methods[index], fontsize=9)
        ax.set_xticks(counts)
        ax.set_ylim(-0.03, 1.05)
        ax.grid(alpha=0.3)
        ax.tick_params(labelsize=8)
    figure.supxlabel("goal variables per task", fontsize=9)
    figure.supylabel("success rate", fontsize=9)
    return figure


def fault_study_figure(
    rates: Sequence[float], methods: Mapping[str, Mapping[str, Sequence[float]]]
) -> Figure:
    """SR and SPL against the rate of injected model faults, one line per method."""
    figure = Figure(figsize=(9, 3.3), layout="constrained")
    axes = figure.subplots(1, 2)
    for ax, key, title in zip(axes, ("sr", "spl"), ("Success rate", "SPL"), strict=True):
        for index, (method, series) in enumerate(methods.items()):
            ax.plot(list(rates), list(series.get(key, [])), label=method, **_line_style(index))
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("fault rate")
        ax.set_ylim(-0.03, 1.05)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    return figure


def _line_style(index: int) -> dict[str, object]:
    """Distinct colour, marker, dash and shrinking marker size: methods with identical
    results draw on top of each other and must stay visible."""
    return {
        "color": f"C{index % 10}",
        "marker": "osD^v<>"[index % 7],
        "markersize": max(4.0, 10.0 - 1.5 * index),
        "linestyle": ("-", "--", "-.", ":")[index % 4],
    }


def _method_ticks(ax: Axes, methods: Sequence[str]) -> None:
    ax.set_xticks(range(len(methods)), list(methods), rotation=30, ha="right", fontsize=8)


def _pvalue(pvalues: Mapping[str, Mapping[str, float]], a: str, b: str) -> float | None:
    value = pvalues.get(a, {}).get(b)
    if value is None:
        value = pvalues.get(b, {}).get(a)
    return value
