"""The reader does not depend on how an environment spells its action names.

Our suites say ``press_menu``; other environments (and the issue that asked for the reader) say
``press_menu_button``, ``press_and_hold_lock_button``, ``turn_timer_dial_clockwise``. The same
manual with the same panel must read into the same model whichever spelling the actions use.
"""

from __future__ import annotations

from typing import Any

import pytest
import yaml

from apbot.bench.runner import cached_suite
from apbot.read import read_manual
from apbot.read.actions import action_info, parse_actions
from benchmarks.renamed_actions import rename_map, renamed_model


@pytest.mark.parametrize(
    ("name", "skill", "controls", "digit"),
    [
        ("press_menu_button", "press", ("menu",), None),
        ("press_and_hold_lock_button", "hold", ("lock",), None),
        ("long_press_timer_key", "hold", ("timer",), None),
        ("turn_timer_dial_clockwise", "turn_cw", ("timer",), None),
        ("turn_timer_dial_counterclockwise", "turn_ccw", ("timer",), None),
        ("rotate_temp_knob_left", "turn_ccw", ("temp",), None),
        ("turn_dial_counter_clockwise", "turn_ccw", ("dial",), None),
        ("turn_timer_knob_anti_clockwise", "turn_ccw", ("timer",), None),
        ("turn_dial_clockwise", "turn_cw", ("dial",), None),
        ("press_7_button", "press", ("key_7",), 7),
        ("press_button", "press", ("button",), None),  # nothing but the kind: it stays
        ("push_start_stop_key", "press", ("start_stop",), None),
    ],
)
def test_an_action_name_without_its_kind_of_control(
    name: str, skill: str, controls: tuple[str, ...], digit: int | None
) -> None:
    info = action_info(name)
    assert (info.skill, info.controls, info.digit) == (skill, controls, digit)


def test_a_two_key_hold_spelt_with_buttons_finds_both_keys() -> None:
    infos = parse_actions(
        ["press_minus_button", "press_plus_button", "press_and_hold_minus_and_plus_buttons"]
    )
    assert infos[-1].skill == "hold" and infos[-1].controls == ("minus", "plus")


def _plain(model: Any, back: dict[str, str]) -> dict[str, Any]:
    """Variables and procedures of a read model, its action names mapped back."""
    data = model.model_dump(mode="json", exclude_none=True)

    def swap(node: Any) -> Any:
        if isinstance(node, dict):
            return {back.get(k, k): swap(v) for k, v in node.items()}
        if isinstance(node, list):
            return [swap(v) for v in node]
        return back.get(node, node) if isinstance(node, str) else node

    return {"variables": data["variables"], "features": swap(data["features"])}


@pytest.mark.parametrize("style", ["button", "key"])
@pytest.mark.parametrize("appliance_id", ["kettle_1", "microwave_1", "air_fryer_3"])
def test_the_same_manual_reads_the_same_under_other_action_names(
    appliance_id: str, style: str
) -> None:
    appliance = next(a for a in cached_suite("bundled").appliances if a.id == appliance_id)
    data = yaml.safe_load((appliance.directory / "model.yaml").read_text(encoding="utf-8"))
    mapping = rename_map(data, style)
    renamed = list(renamed_model(data, style)["actions"])
    assert renamed != list(data["actions"])
    original = read_manual(appliance.manual, list(data["actions"])).model
    other = read_manual(appliance.manual, renamed).model
    back = {new: old for old, new in mapping.items()}
    assert _plain(other, back) == _plain(original, {})
