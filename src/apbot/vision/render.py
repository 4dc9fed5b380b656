"""Rendering a bundled appliance's panel from its layout, its display showing a state.

This is the *world* side of image mode (it may use the ground truth: it stands for the
physical appliance). A :class:`PanelScene` holds what does not change while the appliance is
used — the layout, the display's style and size, dial ticks, colours — and draws the panel
for any display text. Together with a :class:`~apbot.vision.photo.Camera` it gives a
:class:`Photo`: the image and the mapping from layout coordinates to photo pixels (used only
to score grounding and to resolve where a robot's finger landed).

>>> from apbot.bench.suite import load_suite  # doctest only: vision sits below bench
>>> scene = PanelScene.of(load_suite().get("kettle_1"))
>>> photo = scene.photograph("SET 80°C", ())
>>> photo.image.size == (round(scene.width), round(scene.height))
True
"""

from __future__ import annotations

import random
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol

import numpy as np
from PIL import Image, ImageDraw

from apbot.model.schema import ApplianceModel, DiscreteVariable, NumericVariable
from apbot.sim.compiled import compiled_model
from apbot.sim.simulator import Simulator
from apbot.vision.display_art import (
    MAIN_SHARE,
    DisplayLook,
    DisplayStyle,
    draw_display,
    palette,
    status_layout,
    visible,
)
from apbot.vision.glyphs import seven_segment_ok
from apbot.vision.panel_art import (
    draw_button,
    draw_icon_pad,
    draw_knob,
    draw_round,
    draw_slider,
    hex_rgb,
    luminance,
    shade,
)
from apbot.vision.photo import Camera, apply


class ControlLike(Protocol):
    """A control as the layout draws it (``apbot.bench.suite.PanelControl``)."""

    @property
    def id(self) -> str: ...
    @property
    def label(self) -> str: ...
    @property
    def box(self) -> tuple[float, float, float, float]: ...
    @property
    def shape(self) -> str: ...


class PanelLayout(Protocol):
    """A panel layout (``apbot.bench.suite.PanelLayout``): canvas, display box, controls."""

    @property
    def canvas(self) -> tuple[int, int]: ...
    @property
    def display(self) -> tuple[float, float, float, float]: ...
    @property
    def controls(self) -> Sequence[ControlLike]: ...
    @property
    def colour(self) -> str: ...


class SuiteAppliance(Protocol):
    """What rendering needs of a suite appliance (``apbot.bench.suite.SuiteAppliance``)."""

    @property
    def id(self) -> str: ...
    @property
    def model(self) -> ApplianceModel: ...
    @property
    def layout(self) -> PanelLayout: ...


MIN_PITCH = 6.0
"""Smallest dot pitch (pixels) the rendering scale allows on the display."""


@dataclass
class Photo:
    """A rendered panel photo and the map from layout coordinates to its pixels."""

    image: Image.Image
    to_photo: np.ndarray  # 3×3 homography: layout units → photo pixels

    def layout_point(self, x: float, y: float) -> tuple[float, float]:
        """Where photo pixel (x, y) lies in layout units."""
        px, py = apply(np.linalg.inv(self.to_photo), np.array([[x, y]]))[0]
        return float(px), float(py)

    def photo_box(self, box: Sequence[float]) -> tuple[float, float, float, float]:
        """The axis-aligned photo box around a layout box."""
        x0, y0, x1, y1 = box
        pts = apply(self.to_photo, np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]]))
        return (
            float(pts[:, 0].min()),
            float(pts[:, 1].min()),
            float(pts[:, 0].max()),
            float(pts[:, 1].max()),
        )


def sample_texts(model: ApplianceModel, seed: str, episodes: int = 20, steps: int = 50
                 ) -> tuple[set[str], set[tuple[str, ...]]]:  # fmt: skip
    """Main display texts and sets of lit lamps seen on random walks (sizes the display)."""
    sim = Simulator(compiled_model(model))
    rng = random.Random(seed)
    actions = list(sim.actions)
    mains: set[str] = set()
    lamps: set[tuple[str, ...]] = set()
    for _ in range(episodes):
        seen = [sim.reset()]
        for _ in range(steps):
            name = rng.choice(actions)
            seen.append(sim.step(name, model.actions[name].seconds))
        for obs in seen:
            mains.add(obs.display)
            lamps.add(tuple(visible(lamp) for lamp in obs.lamps if visible(lamp)))
    return mains, lamps


def knob_ticks(model: ApplianceModel, control: str, limit: int = 8) -> list[str]:
    """Tick labels of a dial: the values of the setting its turns change (at most ``limit``)."""
    turns = {n for n, a in model.actions.items() if a.control == control and "turn" in a.skill}
    for steps in model.features.values():
        for step in steps:
            if step.variable and set(step.actions) & turns:
                spec = model.variables[step.variable]
                if isinstance(spec, DiscreteVariable) and spec.values:
                    values = [str(v) for v in spec.values]
                elif isinstance(spec, NumericVariable) and spec.ranges:
                    values = [str(spec.ranges[0][0]), str(spec.ranges[-1][1])]
                else:
                    continue
                if len(values) > limit:
                    index = np.linspace(0, len(values) - 1, limit).round().astype(int)
                    values = [values[i] for i in index]
                return [v.upper() if len(v) <= 3 else v[:8] for v in values]
    return []


@dataclass
class PanelScene:
    """What stays the same while one appliance is used: layout, display look, dial ticks."""

    appliance_id: str
    layout: PanelLayout
    look: DisplayLook
    ticks: dict[str, list[str]]
    scale: float
    margin: float
    seed: int = 0
    _bases: dict[float, Image.Image] = field(default_factory=dict, repr=False)
    _photos: dict[Camera, tuple[Photo, tuple[int, int, int, int]]] = field(
        default_factory=dict, repr=False
    )

    @classmethod
    def of(cls, appliance: SuiteAppliance, seed: int = 0, style: DisplayStyle | None = None,
           force: bool = False) -> PanelScene:  # fmt: skip
        """The scene of a bundled appliance; ``style`` asks for a display style (one the
        texts cannot all use falls back to dot matrix unless ``force``: then the texts it
        cannot show are drawn as far as they go, and only the others should be read)."""
        mains, lamps = sample_texts(appliance.model, f"{appliance.id}/{seed}")
        rng = random.Random(f"scene/{appliance.id}/{seed}")
        segment_ok = all(seven_segment_ok(t) for t in mains)
        chosen: DisplayStyle = style or ("seg" if segment_ok else "dot")
        if chosen == "seg" and not segment_ok and not force:
            chosen = "dot"
        main_columns = max([4, *(len(visible(t)) for t in mains)])
        status_columns, status_lines = status_layout([list(t) for t in lamps])
        if status_columns == 0 and appliance.model.display.indicators:
            status_columns, status_lines = 8, 1
        look = DisplayLook(
            chosen, main_columns, status_columns, palette(rng.randrange(5)), status_lines
        )
        ticks = {
            c.id: knob_ticks(appliance.model, c.id)
            for c in appliance.layout.controls
            if c.shape == "knob"
        }
        scale = _scale_for(appliance.layout, look)
        return cls(appliance.id, appliance.layout, look, ticks, scale, 0.04, seed)

    @property
    def width(self) -> float:
        return self.layout.canvas[0] * self.scale * (1 + 2 * self.margin)

    @property
    def height(self) -> float:
        return self.layout.canvas[1] * self.scale + self.layout.canvas[0] * self.scale * (
            2 * self.margin
        )

    def clean(self, main: str, lamps: Sequence[str], zoom: float = 1.0) -> Image.Image:
        """The panel as drawn, without any camera effect (``zoom`` scales it)."""
        image = self._base(zoom).copy()
        self._draw_display(image, main, lamps, zoom)
        return image

    def _draw_display(self, image: Image.Image, main: str, lamps: Sequence[str], zoom: float,
                      offset: tuple[float, float] = (0.0, 0.0)) -> None:  # fmt: skip
        s = self.scale * zoom
        pad = self.layout.canvas[0] * self.scale * self.margin * zoom
        x0, y0, x1, y1 = self.layout.display
        box = (pad + x0 * s - offset[0], pad + y0 * s - offset[1], pad + x1 * s - offset[0],
               pad + y1 * s - offset[1])  # fmt: skip
        draw_display(ImageDraw.Draw(image), box, self.look, main, list(lamps))

    def _base(self, zoom: float) -> Image.Image:
        """The panel without its display (cached per zoom: it never changes)."""
        cached = self._bases.get(zoom)
        if cached is not None:
            return cached
        s = self.scale * zoom
        pad = self.layout.canvas[0] * self.scale * self.margin * zoom
        size = (round(self.width * zoom), round(self.height * zoom))
        image = Image.new("RGB", size, (70, 68, 64))
        draw = ImageDraw.Draw(image)
        base = hex_rgb(self.layout.colour)
        cw, ch = self.layout.canvas

        def px(box: Sequence[float]) -> tuple[float, float, float, float]:
            return (pad + box[0] * s, pad + box[1] * s, pad + box[2] * s, pad + box[3] * s)

        draw.rounded_rectangle(px((0, 0, cw, ch)), radius=12 * s, fill=base)
        dark = luminance(base) < 110
        ink = (238, 238, 232) if dark else (30, 30, 32)
        face = shade(base, 0.18) if dark else shade(base, -0.1)
        rng = random.Random(f"controls/{self.appliance_id}/{self.seed}")
        for control in self.layout.controls:
            box = px(control.box)
            if control.shape == "knob":
                ticks = self.ticks.get(control.id, [])
                named = "·" not in control.label
                if not named:
                    ticks = [t.strip() for t in control.label.split("·")][:8]
                draw_knob(draw, box, control.label if named else "", ticks, face, ink,
                          rng.uniform(-120, 120))  # fmt: skip
            elif control.shape == "round":
                draw_round(draw, box, control.label, face, ink)
            elif control.shape == "slider":
                draw_slider(draw, box, control.label, face, ink, rng.random() < 0.5)
            elif control.shape == "icon":
                draw_icon_pad(draw, box, control.label, ink)
            else:
                radius = 0.12 * min(box[2] - box[0], box[3] - box[1])
                if control.shape == "key":
                    radius *= 2
                draw_button(draw, box, control.label, face, ink, radius)
        if len(self._bases) > 4:
            self._bases.clear()
        self._bases[zoom] = image
        return image

    def layout_to_clean(self, zoom: float = 1.0) -> np.ndarray:
        """Homography (a scaling and shift) from layout units to clean-image pixels."""
        s = self.scale * zoom
        pad = self.layout.canvas[0] * self.scale * self.margin * zoom
        return np.array([[s, 0, pad], [0, s, pad], [0, 0, 1]], dtype=float)

    def photograph(self, main: str, lamps: Sequence[str], camera: Camera | None = None,
                   frame: int = 0) -> Photo:  # fmt: skip
        """The panel showing ``main`` and ``lamps`` as ``camera`` sees it (clean by default).

        A pure function of its arguments: with a camera, the panel is photographed once with
        its display blank (frame 0, cached per camera) and each call draws and photographs
        only the display region again on top of that (the rest of a still panel in front
        of a still camera does not change)."""
        camera = camera or Camera()
        if camera.level == "clean":
            clean = self.clean(main, lamps, camera.zoom)
            to_photo = camera.homography(*clean.size) @ self.layout_to_clean(camera.zoom)
            return Photo(camera.photograph(clean, frame), to_photo / to_photo[2, 2])
        reference = self._photos.get(camera)
        if reference is None:
            blank = self.clean("", (), camera.zoom)
            to_photo = camera.homography(*blank.size) @ self.layout_to_clean(camera.zoom)
            photo = Photo(camera.photograph(blank, 0), to_photo / to_photo[2, 2])
            if len(self._photos) > 4:
                self._photos.clear()
            reference = (photo, self._display_region(camera.zoom, blank.size))
            self._photos[camera] = reference
        return self._rephotograph(reference, main, lamps, camera, frame)

    def _display_region(self, zoom: float, size: tuple[int, int]) -> tuple[int, int, int, int]:
        """Clean-image pixels around the display (with a margin for blur and perspective)."""
        m = self.layout_to_clean(zoom)
        x0, y0, x1, y1 = self.layout.display
        margin = 0.05 * max(x1 - x0, y1 - y0) * m[0, 0] + 6
        return (
            max(0, int(m[0, 2] + x0 * m[0, 0] - margin)),
            max(0, int(m[1, 2] + y0 * m[1, 1] - margin)),
            min(size[0], int(m[0, 2] + x1 * m[0, 0] + margin) + 1),
            min(size[1], int(m[1, 2] + y1 * m[1, 1] + margin) + 1),
        )

    def _rephotograph(self, cached: tuple[Photo, tuple[int, int, int, int]], main: str,
                      lamps: Sequence[str], camera: Camera, frame: int) -> Photo:  # fmt: skip
        """The blank-display reference photo with the display region drawn showing ``main``
        and ``lamps`` and photographed again (its own frame's noise); the reference is not
        changed."""
        photo, region = cached
        base = self._base(camera.zoom)
        crop = base.crop(region)
        self._draw_display(crop, main, lamps, camera.zoom, (region[0], region[1]))
        image = camera.photograph_region(photo.image, crop, region, base.size, frame)
        return Photo(image, photo.to_photo)


def _scale_for(layout: PanelLayout, look: DisplayLook) -> float:
    """A drawing scale at which the display's dots are at least :data:`MIN_PITCH` apart."""
    x0, y0, x1, y1 = layout.display
    w, h = x1 - x0, y1 - y0
    lines = min(3, look.status_lines) if look.status_columns else 0
    main_h = h * (MAIN_SHARE[lines] - 0.06 if lines else 0.85)
    pitch = min(main_h / 9, w / (6 * look.main_columns + 2))
    if lines:
        status_h = h * (1 - MAIN_SHARE[lines] - 0.1) / lines
        pitch = min(pitch, status_h / 9, w / (6 * look.status_columns + 2))
    wanted = max(1.5, MIN_PITCH / max(pitch, 0.1))
    cw, ch = layout.canvas
    return float(min(wanted, 5000 / max(cw, ch), (6e6 / (cw * ch)) ** 0.5))


def render_state(appliance: SuiteAppliance, state: dict[str, str], out: Any, level: str = "clean",
                 seed: int = 0, style: DisplayStyle | None = None) -> str:  # fmt: skip
    """Render ``appliance`` showing ``state`` (VAR → VALUE, reached by the planner's presses
    from the start) to the PNG file ``out``; returns the display text shown."""
    from apbot.model.goal import parse_goal
    from apbot.plan.plan import plan

    sim = Simulator(compiled_model(appliance.model))
    seen = sim.reset()
    if state:
        goal = parse_goal(appliance.model, dict(state))
        for action in plan(appliance.model, None, goal).actions:
            seen = sim.step(action.name, action.seconds)
    scene = PanelScene.of(appliance, style=style)
    photo = scene.photograph(seen.display, seen.lamps, Camera.sample(seed, level))
    photo.image.save(out)
    return seen.text
