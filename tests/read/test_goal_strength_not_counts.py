"""A strength superlative with no setting named ("as strong as it goes", "the gentlest
cycle") picks a numbered level only when it is the one strength there: not a count of things
(cups, rinses), not when the word after it names a programme, and not beside a LOW/HIGH
strength in words. Checked on small models written for these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction


def _model(variables: dict[str, str]) -> str:
    head = 'appliance: {id: t_1, category: tester, name: "T T-1", brand: T}\ncontrols:\n'
    controls = "".join(
        f'  - {{id: {n}_b, kind: button, label: "{n.upper()}"}}\n' for n in variables
    )
    body = "".join(f"  {n}:\n    {spec}\n" for n, spec in variables.items())
    actions = "".join(f"  press_{n}: {{control: {n}_b}}\n" for n in variables)
    features = "".join(
        f"  {n}:\n    - {{actions: [press_{n}], variable: {n}, effect: next}}\n" for n in variables
    )
    return f"{head}{controls}variables:\n{body}actions:\n{actions}features:\n{features}"


POWER = 'type: discrete\n    values: ["off", "on"]'
BREWER = _model({"power": POWER, "cups": "type: numeric\n    ranges: [[1, 12, 1]]"})
WASHER = _model(
    {
        "power": POWER,
        "program": "type: discrete\n    values: [cottons, delicates, wool, quick]",
        "rinse": "type: numeric\n    ranges: [[1, 3, 1]]",
    }
)
RUBBER = _model(
    {
        "power": POWER,
        "intensity": "type: discrete\n    values: [low, medium, high]",
        "speed": "type: numeric\n    ranges: [[1, 3, 1]]",
    }
)


def test_a_count_of_cups_is_no_strength() -> None:
    goal = parse_instruction(loads_model(BREWER), "Make it as strong as it goes.")
    assert "cups" not in goal


def test_the_gentlest_cycle_is_no_rinse_count() -> None:
    model = loads_model(WASHER)
    for sentence in ("As gentle as it goes on the jumpers.", "Use the softest cycle, please."):
        try:
            goal = parse_instruction(model, sentence)
        except ValueError:
            continue  # asking which programme is fine; a rinse count is not
        assert "rinse" not in goal


def test_a_worded_strength_beside_numbers_is_not_passed_over() -> None:
    goal = parse_instruction(loads_model(RUBBER), "As strong as it goes.")
    assert goal.get("speed") != 3
