"""``llm-policy-image``: the LLM as policy looking at the panel photo (the paper's baseline).

Each reasoning step a vision LLM sees the manual, the user's request, what it did so far and
the latest panel photo with numbered boxes drawn on it (the control candidates the detector
found: shapes, dials and printed labels that sit on no shape). It answers with a skill and a
box number; the robot touches the centre of that box. Nothing is grounded by name, so a
wrong box costs what a wrong touch costs. The answer is data (validated JSON), never code.

The method runs only when named, with an LLM configured, on ``--feedback image``. A model
that reads no images (the local Qwen 1.5B, a text-only server) is refused with that reason.
"""

from __future__ import annotations

import base64
import io
from typing import Any, Literal

import numpy as np
from PIL import Image, ImageDraw
from pydantic import BaseModel, Field, create_model

from apbot.agent.environment import Environment, Feedback
from apbot.agent.episode import Episode, TaskContext
from apbot.agent.registry import Method, register
from apbot.llm.client import LLMClient, LLMError, configured_client
from apbot.llm.structured import StructuredError, ask
from apbot.llm.usage import add_records

BoxT = tuple[float, float, float, float]
DONE = "done"
SKILLS = ("press", "hold", "turn_cw", "turn_ccw")
MAX_BOXES = 60
MAX_SIDE = 1024  # the photo sent is scaled down to this (tokens, not accuracy, are the limit)
MAX_MANUAL_CHARS = 16_000
HOLD_SECONDS = 3.0  # a hold with no duration given lasts this long

SYSTEM = (
    "You operate a home appliance for a user by touching its control panel, following its "
    "user manual. You see a photo of the panel with numbered boxes on the things that may be "
    "controls. Each step choose one skill and one box (two boxes for a two-finger hold), or "
    "answer done when the appliance does what the user asked."
)


class NoVision(RuntimeError):
    """The configured LLM cannot look at the panel photo (or the run is not in image mode)."""


def panel_boxes(image: np.ndarray) -> list[BoxT]:
    """The boxes offered to the LLM, in reading order (top to bottom, left to right): control
    shapes and dials off the display, and printed labels that lie on none of them."""
    from apbot.vision.detect import detect
    from apbot.vision.labels import _controls
    from apbot.vision.locate import find_window

    detection = detect(image)
    window = find_window(image)
    shapes = [c.box for c in _controls(detection, window)]
    labels = [
        c.box
        for c in detection.candidates
        if c.kind == "text"
        and not (window is not None and _inside(c.centre, window.box))
        and not any(_inside(c.centre, s) for s in shapes)
    ]
    boxes = sorted(shapes + labels, key=lambda b: -_area(b))[:MAX_BOXES]
    rows = max(1.0, float(np.median([b[3] - b[1] for b in boxes]))) if boxes else 1.0
    return sorted(boxes, key=lambda b: (round((b[1] + b[3]) / 2 / rows), (b[0] + b[2]) / 2))


def _inside(point: tuple[float, float], box: BoxT) -> bool:
    return box[0] <= point[0] <= box[2] and box[1] <= point[1] <= box[3]


def _area(box: BoxT) -> float:
    return max(0.0, box[2] - box[0]) * max(0.0, box[3] - box[1])


def centre(box: BoxT) -> tuple[float, float]:
    return ((box[0] + box[2]) / 2, (box[1] + box[3]) / 2)


def draw_boxes(image: Image.Image, boxes: list[BoxT]) -> Image.Image:
    """The photo with box k outlined and numbered k (1-based), as the LLM sees it."""
    out = image.convert("RGB").copy()
    draw = ImageDraw.Draw(out)
    for k, box in enumerate(boxes, 1):
        draw.rectangle(box, outline=(255, 40, 40), width=2)
        tag = str(k)
        x, y = box[0] + 1, box[1] + 1
        draw.rectangle((x, y, x + 7 * len(tag) + 3, y + 12), fill=(255, 40, 40))
        draw.text((x + 2, y), tag, fill=(255, 255, 255))
    return out


def data_url(image: Image.Image) -> str:
    """A JPEG data URL of ``image``, its longer side at most :data:`MAX_SIDE` pixels."""
    scaled = image.copy()
    scaled.thumbnail((MAX_SIDE, MAX_SIDE))
    buffer = io.BytesIO()
    scaled.save(buffer, format="JPEG", quality=85)
    return "data:image/jpeg;base64," + base64.b64encode(buffer.getvalue()).decode()


def choice_schema(count: int) -> type[BaseModel]:
    """What an answer may be: a skill (or done), box numbers in 1..count, hold seconds."""
    skills = Literal[(*SKILLS, DONE)]  # type: ignore[valid-type]
    return create_model(
        "PanelChoice",
        action=(skills, ...),
        box=(int, Field(default=1, ge=1, le=max(1, count))),
        second_box=(int | None, Field(default=None, ge=1, le=max(1, count))),
        seconds=(float | None, Field(default=None, gt=0, le=60)),
    )


def policy_messages(
    context: TaskContext, count: int, history: list[str], photo_url: str
) -> list[dict[str, Any]]:
    """Manual first (the same every step, for a server's prompt cache), then the photo, then
    the request and the history."""
    steps = "\n".join(history) if history else "(nothing yet)"
    return [
        {"role": "system", "content": SYSTEM},
        {"role": "user", "content": f"User manual:\n{context.manual[:MAX_MANUAL_CHARS]}"},
        {
            "role": "user",
            "content": [
                {"type": "text", "text": f"The panel now, boxes numbered 1 to {count}:"},
                {"type": "image_url", "image_url": {"url": photo_url}},
            ],
        },
        {
            "role": "user",
            "content": f"User's request: {context.instruction}\n\n"
            f"What you did so far:\n{steps}\n\n"
            "Choose the skill (press, hold, turn_cw, turn_ccw) and the box, or done.",
        },
    ]


def _client() -> LLMClient:
    client = configured_client()
    if client is None:
        raise NoVision(
            "llm-policy-image needs a vision LLM: give --llm (openai:MODEL or "
            "http://HOST:PORT/v1:MODEL) or set APBOT_LLM"
        )
    if client.config.provider == "local":
        raise NoVision(
            "llm-policy-image needs an LLM that reads images; the local model (Qwen 1.5B) is "
            "text-only: name a vision model with --llm"
        )
    return client


def run_llm_policy_image(
    context: TaskContext, env: Environment, client: LLMClient | None = None
) -> Episode:
    """Ask the LLM for a skill and a box each step until it says done or the steps run out."""
    from apbot.vision.environment import ImageEnvironment

    if not isinstance(env, ImageEnvironment):
        raise NoVision("llm-policy-image looks at the panel photo: run it with --feedback image")
    llm = client or _client()
    episode = context.episode()
    history: list[str] = []
    env.reset()
    photo = env.panel.latest.image
    boxes = panel_boxes(np.asarray(photo))  # the panel does not move: found once
    if not boxes:
        episode.failure = "no control candidates found on the panel photo"
        episode.log("stop", episode.failure)
        return episode
    schema = choice_schema(len(boxes))
    while episode.reasoning_steps < context.max_reasoning_steps:
        url = data_url(draw_boxes(photo, boxes))
        try:
            answer = ask(llm, policy_messages(context, len(boxes), history, url), schema,
                         max_tokens=60)  # fmt: skip
        except StructuredError as exc:
            add_records(episode.llm_usage, exc.usage)
            episode.failure = f"no valid choice from the LLM: {exc}"
            episode.log("stop", episode.failure)
            return episode
        except LLMError as exc:
            raise NoVision(
                f"the LLM did not take the panel photo ({exc}); llm-policy-image needs a model "
                "that reads images"
            ) from None
        add_records(episode.llm_usage, answer.usage)
        choice: Any = answer.value
        if choice.action == DONE:
            episode.claimed_success = True
            episode.log("stop", "the LLM says the request is done")
            return episode
        numbers = [choice.box] + ([choice.second_box] if choice.second_box else [])
        points = [centre(boxes[k - 1]) for k in numbers]
        skill = "hold" if len(points) > 1 else str(choice.action)
        seconds = choice.seconds or (HOLD_SECONDS if skill == "hold" else None)
        said = f"{skill} box {' + '.join(map(str, numbers))}"
        if skill == "hold":
            said += f" for {seconds:g} s"
        episode.reasoning_steps += 1
        episode.log("macro", said)
        feedback = env.touch(points, skill, seconds)
        episode.execution_steps += 1
        episode.log("action", action=said, display=feedback.text, accepted=feedback.accepted)
        history.append(f"{len(history) + 1}. {said}{_heard(feedback)}")
        photo = env.panel.latest.image
    episode.failure = f"no done after {context.max_reasoning_steps} reasoning steps"
    episode.log("stop", episode.failure)
    return episode


def _heard(feedback: Feedback) -> str:
    return "" if feedback.accepted else " (it beeped)"


register(
    Method(
        "llm-policy-image",
        run_llm_policy_image,
        "LLM as policy with the panel image: manual, instruction and the photo with numbered "
        "boxes in, a skill and a box (or done) out, each step (needs a vision LLM and "
        "--feedback image)",
        needs_llm=True,
    )
)
