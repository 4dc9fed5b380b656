"""Drawing an appliance display: seven-segment or dot-matrix cells with the unlit ones faint.

A display is a dark window behind a bezel. Its top row shows the main display text; a smaller
dot-matrix status row under it shows the lit indicator lamps (annunciators), two blank cells
apart. Every cell of every row is drawn, unlit segments and dots faintly, as on a real LCD or
VFD: that is also what lets a reader find the cell grid when little is lit.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from PIL import ImageDraw

from apbot.vision.glyphs import INVISIBLE, SEG_EXTRAS, SEGMENTS, dot_pattern

DisplayStyle = Literal["seg", "dot"]
RGB = tuple[int, int, int]


@dataclass(frozen=True)
class Palette:
    """Colours of one display: the window, a lit element, an unlit one, the bezel."""

    window: RGB
    lit: RGB
    unlit: RGB
    bezel: RGB


PALETTES: tuple[tuple[RGB, RGB], ...] = (
    ((8, 10, 9), (80, 255, 170)),  # green VFD
    ((10, 8, 6), (255, 176, 60)),  # amber
    ((6, 8, 14), (110, 200, 255)),  # blue-white
    ((12, 6, 6), (255, 80, 70)),  # red LED
    ((9, 9, 9), (235, 235, 225)),  # white
)


def palette(index: int, faint: float = 0.2) -> Palette:
    """Palette ``index`` (cycled); ``faint`` is how bright an unlit element is (0..1)."""
    window, lit = PALETTES[index % len(PALETTES)]
    unlit = tuple(round(w + (c - w) * faint) for w, c in zip(window, lit, strict=True))
    return Palette(window, lit, (unlit[0], unlit[1], unlit[2]), (120, 122, 125))


@dataclass(frozen=True)
class DisplayLook:
    """How one appliance's display is built: style of the main row, columns per row."""

    style: DisplayStyle
    main_columns: int
    status_columns: int
    palette: Palette
    status_lines: int = 1


def wrap_lamps(lamps: list[str], columns: int) -> list[str]:
    """Lit lamps packed into status lines of ``columns`` cells, two blank cells apart; a lamp
    is never split (a line break stands for the two-space gap)."""
    lines: list[str] = []
    for lamp in lamps:
        if lines and len(lines[-1]) + 2 + len(lamp) <= columns:
            lines[-1] += "  " + lamp
        else:
            lines.append(lamp)
    return lines


def status_layout(lamp_sets: list[list[str]]) -> tuple[int, int]:
    """(columns per line, lines) for the status rows: the fewest cells per line such that
    every seen set of lit lamps fits in at most three lines, preferring one line."""
    longest = max([0, *(len(lamp) for lamps in lamp_sets for lamp in lamps)])
    total = max([0, *(len("  ".join(lamps)) for lamps in lamp_sets)])
    if total == 0:
        return 0, 0
    for lines in (1, 2, 3):
        columns = max(longest, -(-total // lines))
        while any(len(wrap_lamps(lamps, columns)) > lines for lamps in lamp_sets):
            columns += 1
        if columns <= 20 or lines == 3:
            return columns, lines
    return total, 1


def visible(text: str) -> str:
    """``text`` as cells: without marks a display cannot show (variation selectors)."""
    return "".join(c for c in text if c not in INVISIBLE)


Box = tuple[float, float, float, float]


def draw_display(
    draw: ImageDraw.ImageDraw, box: Box, look: DisplayLook, main: str, lamps: list[str]
) -> None:
    """Draw the display window into ``box`` (pixels) showing ``main`` and the lit ``lamps``."""
    x0, y0, x1, y1 = box
    w, h = x1 - x0, y1 - y0
    bezel = max(2.0, 0.04 * min(w, h))
    draw.rectangle((x0, y0, x1, y1), fill=look.palette.bezel)
    ix0, iy0, ix1, iy1 = x0 + bezel, y0 + bezel, x1 - bezel, y1 - bezel
    draw.rectangle((ix0, iy0, ix1, iy1), fill=look.palette.window)
    iw, ih = ix1 - ix0, iy1 - iy0
    pad = 0.06 * min(iw, ih)
    main = visible(main)
    if look.status_columns:
        lines = wrap_lamps([visible(lamp) for lamp in lamps if visible(lamp)], look.status_columns)
        count = max(look.status_lines, len(lines))
        split = MAIN_SHARE[min(count, 3)]
        main_box = (ix0 + pad, iy0 + pad, ix1 - pad, iy0 + split * ih)
        top = iy0 + (split + 0.06) * ih
        step = (iy1 - pad - top) / count
        columns = max([look.status_columns, *(len(line) for line in lines)])
        for i in range(count):
            line = lines[i] if i < len(lines) else ""
            row_box = (ix0 + pad, top + i * step, ix1 - pad, top + (i + 0.82) * step)
            _dot_row(draw, row_box, columns, line, look.palette)
    else:
        main_box = (ix0 + pad, iy0 + pad, ix1 - pad, iy1 - pad)
    columns = max(look.main_columns, len(main))
    if look.style == "seg":
        _seg_row(draw, main_box, columns, main, look.palette)
    else:
        _dot_row(draw, main_box, columns, main, look.palette)


MAIN_SHARE = {1: 0.6, 2: 0.5, 3: 0.42}
"""Share of the window's height above the status rows, by their number."""


def dot_geometry(box: Box, columns: int) -> tuple[float, float, float]:
    """(pitch, x of the first dot's centre, y of the first row's centre) of a dot row."""
    x0, y0, x1, y1 = box
    pitch = min((y1 - y0) / 7.0, (x1 - x0) / (6 * columns - 1))
    width, height = (6 * columns - 1) * pitch, 7 * pitch
    left = x0 + ((x1 - x0) - width) / 2 + pitch / 2
    top = y0 + ((y1 - y0) - height) / 2 + pitch / 2
    return pitch, left, top


def _dot_row(draw: ImageDraw.ImageDraw, box: Box, columns: int, text: str, pal: Palette) -> None:
    pitch, left, top = dot_geometry(box, columns)
    radius = 0.4 * pitch
    for k in range(columns):
        pattern = dot_pattern(text[k] if k < len(text) else " ")
        for row in range(7):
            for col in range(5):
                cx, cy = left + (6 * k + col) * pitch, top + row * pitch
                colour = pal.lit if pattern[row, col] else pal.unlit
                draw.ellipse((cx - radius, cy - radius, cx + radius, cy + radius), fill=colour)


def seg_geometry(box: Box, columns: int) -> tuple[float, float, float, float]:
    """(cell width, cell height, x of the first cell, y of its top) of a seven-segment row."""
    x0, y0, x1, y1 = box
    width = min((x1 - x0) / (columns * 1.3 - 0.3), (y1 - y0) / 1.7)
    height = 1.7 * width
    total = columns * 1.3 * width - 0.3 * width
    return width, height, x0 + ((x1 - x0) - total) / 2, y0 + ((y1 - y0) - height) / 2


# segment polygons in cell units (x from 0 to 1 of the width, y from 0 to 1 of the height)
_T = 0.09  # half the thickness, in heights
SEGMENT_LINES: dict[str, tuple[float, float, float, float]] = {
    "a": (0.2, 0.06, 0.8, 0.06),
    "b": (0.88, 0.1, 0.88, 0.46),
    "c": (0.88, 0.54, 0.88, 0.9),
    "d": (0.2, 0.94, 0.8, 0.94),
    "e": (0.12, 0.54, 0.12, 0.9),
    "f": (0.12, 0.1, 0.12, 0.46),
    "g": (0.2, 0.5, 0.8, 0.5),
}
EXTRA_DOTS: dict[str, tuple[tuple[float, float], ...]] = {
    "colon": ((0.5, 0.3), (0.5, 0.7)),
    "point": ((1.04, 0.94),),
}


def _seg_row(draw: ImageDraw.ImageDraw, box: Box, columns: int, text: str, pal: Palette) -> None:
    width, height, left, top = seg_geometry(box, columns)
    thick = _T * height
    for k in range(columns):
        char = text[k] if k < len(text) else " "
        lit = SEGMENTS.get(char, frozenset())
        extra = SEG_EXTRAS.get(char)
        cx0 = left + k * 1.3 * width
        for name, (ax, ay, bx, by) in SEGMENT_LINES.items():
            p = (cx0 + ax * width, top + ay * height)
            q = (cx0 + bx * width, top + by * height)
            colour = pal.lit if name in lit else pal.unlit
            draw.line((p, q), fill=colour, width=max(1, round(thick)))
            for x, y in (p, q):  # rounded ends
                r = thick / 2
                draw.ellipse((x - r, y - r, x + r, y + r), fill=colour)
        for name, dots in EXTRA_DOTS.items():
            colour = pal.lit if name == extra else pal.unlit
            for ux, uy in dots:
                x, y, r = cx0 + ux * width, top + uy * height, 0.55 * thick
                draw.ellipse((x - r, y - r, x + r, y + r), fill=colour)
