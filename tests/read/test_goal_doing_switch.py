"""On a model with no running state, the one switch named for a doing (PRINTING) is it: checked
on a small model written for these tests."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

PRINTER = """
appliance: {id: printer_1, category: tag_printer, name: "Taggo T1 tag printer", brand: T}
controls:
  - {id: style_button, kind: button, label: "STYLE"}
  - {id: print_button, kind: button, label: "PRINT"}
variables:
  style:
    type: discrete
    values: [normal, bold]
  printing:
    type: discrete
    values: ["off", "on"]
actions:
  press_style: {control: style_button}
  press_print: {control: print_button}
features:
  style:
    - {actions: [press_style], variable: style, effect: next}
  print:
    - {actions: [press_print], variable: printing, effect: toggle}
display:
  idle: ""
"""


@pytest.fixture(scope="module")
def printer() -> ApplianceModel:
    return loads_model(PRINTER)


@pytest.mark.parametrize(
    ("text", "printing"),
    [
        ("Bold, and start printing.", "on"),
        ("Bold text, start now.", "on"),
        ("Bold text, and print.", "on"),
        ("Bold text, but don't print yet.", "off"),
        ("Bold text.", None),
    ],
)
def test_a_switch_named_for_a_doing_is_the_running_state(
    printer: ApplianceModel, text: str, printing: str | None
) -> None:
    assert parse_instruction(printer, text).get("printing") == printing
