"""Drawing a panel's controls: buttons, round keys, keypad keys, dials with ticks, sliders and
icon-only soft-touch pads, each with its printed label.

Labels are printed with DejaVu Sans Bold (shipped with matplotlib). The few symbols that font
lacks (⏻ 🔒 🔓 💡 ⏱ ⏲ ⌚ 🔑) are drawn as simple vector icons in the usual IEC style.
"""

from __future__ import annotations

import math
from functools import cache
from pathlib import Path

from PIL import ImageDraw, ImageFont

RGB = tuple[int, int, int]
Box = tuple[float, float, float, float]

VECTOR_SYMBOLS = frozenset("⏻🔒🔓💡⏱⏲⌚🔑")
_SKIP = "\ufe0e\ufe0f"


@cache
def font(size: int) -> ImageFont.FreeTypeFont:
    """DejaVu Sans Bold at ``size`` pixels (the font matplotlib ships: no download)."""
    import matplotlib

    path = Path(matplotlib.__file__).parent / "mpl-data" / "fonts" / "ttf" / "DejaVuSans-Bold.ttf"
    return ImageFont.truetype(str(path), max(6, size))


def hex_rgb(colour: str) -> RGB:
    """``#rrggbb`` → (r, g, b)."""
    text = colour.lstrip("#")
    return (int(text[0:2], 16), int(text[2:4], 16), int(text[4:6], 16))


def luminance(rgb: RGB) -> float:
    return 0.299 * rgb[0] + 0.587 * rgb[1] + 0.114 * rgb[2]


def shade(rgb: RGB, amount: float) -> RGB:
    """Lighter (``amount`` > 0) or darker (< 0) by a fraction of the way to white or black."""
    if amount >= 0:
        return (
            round(rgb[0] + (255 - rgb[0]) * amount),
            round(rgb[1] + (255 - rgb[1]) * amount),
            round(rgb[2] + (255 - rgb[2]) * amount),
        )
    return (
        round(rgb[0] * (1 + amount)),
        round(rgb[1] * (1 + amount)),
        round(rgb[2] * (1 + amount)),
    )


# --- text with symbols -------------------------------------------------------------------------


def _runs(text: str) -> list[tuple[bool, str]]:
    """``text`` cut into (is a vector symbol, run) pieces."""
    runs: list[tuple[bool, str]] = []
    for char in text:
        if char in _SKIP:
            continue
        vector = char in VECTOR_SYMBOLS
        if runs and not vector and not runs[-1][0]:
            runs[-1] = (False, runs[-1][1] + char)
        else:
            runs.append((vector, char))
    return runs


def text_size(text: str, size: int) -> tuple[float, float]:
    """Width and height of one line of ``text`` at ``size``."""
    width = 0.0
    for vector, run in _runs(text):
        width += size * 1.05 if vector else font(size).getlength(run)
    return width, float(size)


def draw_text(draw: ImageDraw.ImageDraw, centre: tuple[float, float], text: str, size: int,
              colour: RGB) -> None:  # fmt: skip
    """One line of ``text`` centred on ``centre``."""
    width, _ = text_size(text, size)
    x = centre[0] - width / 2
    y = centre[1]
    for vector, run in _runs(text):
        if vector:
            draw_symbol(draw, run, (x + size * 0.52, y), size * 0.9, colour)
            x += size * 1.05
        else:
            draw.text((x, y), run, font=font(size), fill=colour, anchor="lm")
            x += font(size).getlength(run)


def fit_lines(text: str, width: float, height: float, largest: int) -> tuple[list[str], int]:
    """``text`` in one or two lines and the largest size (≤ ``largest``) that fits the box."""
    options = [[text]]
    words = text.split(" ")
    if len(words) > 1:
        best = min(
            range(1, len(words)),
            key=lambda i: abs(len(" ".join(words[:i])) - len(" ".join(words[i:]))),
        )
        options.append([" ".join(words[:best]), " ".join(words[best:])])
    chosen, chosen_size = options[0], 6
    for lines in options:
        size = min(largest, int(height / (1.25 * len(lines))))
        while size > 6 and max(text_size(line, size)[0] for line in lines) > width:
            size -= 1
        if size > chosen_size:
            chosen, chosen_size = lines, size
    return chosen, chosen_size


def draw_label(draw: ImageDraw.ImageDraw, box: Box, text: str, colour: RGB, largest: int) -> None:
    """``text`` fitted into ``box`` (one or two lines), centred."""
    x0, y0, x1, y1 = box
    lines, size = fit_lines(text, x1 - x0, y1 - y0, largest)
    cy = (y0 + y1) / 2 - (len(lines) - 1) * size * 0.62
    for line in lines:
        draw_text(draw, ((x0 + x1) / 2, cy), line, size, colour)
        cy += size * 1.25


# --- vector symbols ----------------------------------------------------------------------------


def draw_symbol(draw: ImageDraw.ImageDraw, symbol: str, centre: tuple[float, float],
                size: float, colour: RGB) -> None:  # fmt: skip
    """One of :data:`VECTOR_SYMBOLS` drawn in a ``size`` square around ``centre``."""
    cx, cy = centre
    r = size * 0.42
    w = max(1, round(size * 0.11))
    if symbol == "⏻":  # IEC 60417-5009: a broken circle and a bar
        draw.arc((cx - r, cy - r, cx + r, cy + r), -60, 240, fill=colour, width=w)
        draw.line((cx, cy - r * 1.15, cx, cy + r * 0.05), fill=colour, width=w)
    elif symbol in "🔒🔓":
        body = (cx - r * 0.8, cy - r * 0.1, cx + r * 0.8, cy + r)
        draw.rectangle(body, fill=colour)
        shift = r * 0.55 if symbol == "🔓" else 0.0
        draw.arc((cx - r * 0.5 + shift, cy - r * 0.95, cx + r * 0.5 + shift, cy + r * 0.15),
                 180, 360, fill=colour, width=w)  # fmt: skip
        draw.line((cx - r * 0.5 + shift, cy - r * 0.4, cx - r * 0.5 + shift, cy - r * 0.1),
                  fill=colour, width=w)  # fmt: skip
        if symbol == "🔒":
            draw.line((cx + r * 0.5, cy - r * 0.4, cx + r * 0.5, cy - r * 0.1), fill=colour,
                      width=w)  # fmt: skip
    elif symbol == "💡":
        draw.ellipse((cx - r * 0.7, cy - r, cx + r * 0.7, cy + r * 0.4), outline=colour, width=w)
        draw.rectangle((cx - r * 0.35, cy + r * 0.45, cx + r * 0.35, cy + r), fill=colour)
    elif symbol in "⏱⏲⌚":
        draw.ellipse((cx - r * 0.85, cy - r * 0.75, cx + r * 0.85, cy + r * 0.95), outline=colour,
                     width=w)  # fmt: skip
        draw.line((cx, cy + r * 0.1, cx, cy - r * 0.45), fill=colour, width=w)
        draw.line((cx, cy + r * 0.1, cx + r * 0.4, cy + r * 0.1), fill=colour, width=w)
        if symbol == "⏱":
            draw.line((cx - r * 0.3, cy - r, cx + r * 0.3, cy - r), fill=colour, width=w)
        elif symbol == "⌚":
            draw.rectangle((cx - r * 0.4, cy - r * 1.1, cx + r * 0.4, cy - r * 0.75), fill=colour)
            draw.rectangle((cx - r * 0.4, cy + r * 0.95, cx + r * 0.4, cy + r * 1.2), fill=colour)
    elif symbol == "🔑":
        draw.ellipse((cx - r, cy - r * 0.45, cx - r * 0.1, cy + r * 0.45), outline=colour, width=w)
        draw.line((cx - r * 0.1, cy, cx + r, cy), fill=colour, width=w)
        draw.line((cx + r * 0.7, cy, cx + r * 0.7, cy + r * 0.4), fill=colour, width=w)


# --- controls ----------------------------------------------------------------------------------


def draw_button(draw: ImageDraw.ImageDraw, box: Box, label: str, face: RGB, ink: RGB,
                radius: float) -> None:  # fmt: skip
    """A rectangular button or pad with its label printed on it."""
    x0, y0, x1, y1 = box
    draw.rounded_rectangle(box, radius=radius, fill=face, outline=shade(face, -0.35), width=2)
    pad = 0.1 * min(x1 - x0, y1 - y0)
    draw_label(draw, (x0 + pad, y0 + pad, x1 - pad, y1 - pad), label, ink, int(0.42 * (y1 - y0)))


def draw_round(draw: ImageDraw.ImageDraw, box: Box, label: str, face: RGB, ink: RGB) -> None:
    """A round key: an ellipse filling the box with its label inside."""
    x0, y0, x1, y1 = box
    draw.ellipse(box, fill=face, outline=shade(face, -0.35), width=2)
    w, h = x1 - x0, y1 - y0
    inner = (x0 + 0.16 * w, y0 + 0.18 * h, x1 - 0.16 * w, y1 - 0.18 * h)
    draw_label(draw, inner, label, ink, int(0.36 * min(w, h)))


def draw_knob(draw: ImageDraw.ImageDraw, box: Box, name: str, ticks: list[str], face: RGB,
              ink: RGB, pointer: float) -> None:  # fmt: skip
    """A dial: a disc with a pointer, tick marks and tick labels around, its name below."""
    x0, y0, x1, y1 = box
    w, h = x1 - x0, y1 - y0
    name_height = 0.16 * h if name else 0.0
    cx, cy = (x0 + x1) / 2, y0 + (h - name_height) / 2
    outer = min(w, h - name_height) / 2
    r = outer * (0.58 if ticks else 0.85)
    draw.ellipse((cx - r, cy - r, cx + r, cy + r), fill=shade(face, -0.15), outline=ink, width=2)
    draw.ellipse((cx - r * 0.8, cy - r * 0.8, cx + r * 0.8, cy + r * 0.8), fill=face)
    angle = math.radians(pointer)
    draw.line((cx + 0.2 * r * math.sin(angle), cy - 0.2 * r * math.cos(angle),
               cx + 0.75 * r * math.sin(angle), cy - 0.75 * r * math.cos(angle)),
              fill=ink, width=max(2, round(r * 0.1)))  # fmt: skip
    if ticks:
        span = 270.0 if len(ticks) > 1 else 0.0
        size = max(7, int(outer * 0.16))
        for i, tick in enumerate(ticks):
            a = math.radians(-135 + span * i / max(1, len(ticks) - 1))
            sx, sy = math.sin(a), -math.cos(a)
            draw.line((cx + sx * r * 1.05, cy + sy * r * 1.05, cx + sx * r * 1.18,
                       cy + sy * r * 1.18), fill=ink, width=2)  # fmt: skip
            tx, ty = cx + sx * outer * 0.82, cy + sy * outer * 0.82
            draw_text(draw, (tx, ty), tick, size, ink)
    if name:
        draw_label(draw, (x0, y1 - name_height, x1, y1), name, ink, int(name_height * 0.8))


def draw_slider(draw: ImageDraw.ImageDraw, box: Box, label: str, face: RGB, ink: RGB,
                on: bool) -> None:  # fmt: skip
    """A slide or rocker switch: a track with its thumb, the label above it."""
    x0, y0, x1, y1 = box
    h = y1 - y0
    track = (x0 + 0.1 * (x1 - x0), y0 + 0.55 * h, x1 - 0.1 * (x1 - x0), y1 - 0.08 * h)
    draw.rounded_rectangle(track, radius=(track[3] - track[1]) / 2, fill=shade(face, -0.3))
    tw = (track[2] - track[0]) * 0.45
    tx = track[2] - tw if on else track[0]
    draw.rounded_rectangle((tx, track[1], tx + tw, track[3]), radius=(track[3] - track[1]) / 2,
                           fill=shade(face, 0.4), outline=ink, width=1)  # fmt: skip
    draw_label(draw, (x0, y0, x1, y0 + 0.5 * h), label, ink, int(0.4 * h))


def draw_icon_pad(draw: ImageDraw.ImageDraw, box: Box, label: str, ink: RGB) -> None:
    """An icon-only soft-touch pad: a printed pictogram, its word (if any) printed below it."""
    x0, y0, x1, y1 = box
    w, h = x1 - x0, y1 - y0
    words = "".join(c for c in label if c.isalnum() or c in " +-/")
    symbolic = not any(c.isalpha() for c in label)
    if symbolic:
        draw_label(draw, (x0 + 0.15 * w, y0 + 0.15 * h, x1 - 0.15 * w, y1 - 0.15 * h), label, ink,
                   int(0.6 * h))  # fmt: skip
        return
    # a pictogram made of the word's initial in a ring, the word below
    cx, cy = (x0 + x1) / 2, y0 + 0.33 * h
    r = min(0.3 * h, 0.3 * w)
    draw.ellipse((cx - r, cy - r, cx + r, cy + r), outline=ink, width=max(1, round(r * 0.12)))
    draw.ellipse((cx - r * 0.3, cy - r * 0.3, cx + r * 0.3, cy + r * 0.3), fill=ink)
    draw_label(draw, (x0, y0 + 0.66 * h, x1, y1), words.strip(), ink, int(0.26 * h))
