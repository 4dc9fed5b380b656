"""The end-to-end failure classifier files each failure under the first cause, in its order."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from apbot.model.schema import ApplianceModel
from benchmarks.e2e_failures import claim_causes, classify, first_cause, wrong_settings
from tests.helpers import model_from

NEWCATS = Path(__file__).resolve().parents[2] / "benchmarks" / "data" / "newcats"


def _model(modes: str, with_fan: bool = True) -> ApplianceModel:
    fan = (
        """
          fan: {type: discrete, values: [low, high]}"""
        if with_fan
        else ""
    )
    fan_feature = (
        """
          fan:
            - {actions: [press_fan], variable: fan, effect: next}"""
        if with_fan
        else ""
    )
    fan_action = "\n          press_fan: {control: fan_key}" if with_fan else ""
    fan_control = "\n          - {id: fan_key, kind: touch, label: FAN}" if with_fan else ""
    return model_from(
        f"""
        controls:
          - {{id: mode_key, kind: touch, label: MODE}}{fan_control}
        variables:
          mode: {{type: discrete, values: [{modes}]}}{fan}
        actions:
          press_mode: {{control: mode_key}}{fan_action}
        features:
          mode:
            - {{actions: [press_mode], variable: mode, effect: next}}{fan_feature}
        """
    )


TRUTH = _model("auto, dry, sleep")


def test_a_right_goal_blames_the_agent() -> None:
    belief = _model("auto, dry, sleep")
    causes = classify(belief, TRUTH, {"mode": "dry"}, {"mode": "dry"})
    assert causes == [] and first_cause(causes) == "agent"


def test_a_value_the_belief_lacks_comes_before_what_the_parser_did() -> None:
    belief = _model("auto, sleep")
    causes = classify(belief, TRUTH, {"mode": "dry", "fan": "high"}, {"fan": "low"})
    assert [c.kind for c in causes] == ["lacks value", "wrong value"]
    assert causes[0].setting == "mode" and "auto, sleep" in causes[0].detail


def test_a_setting_the_belief_lacks_is_named_with_the_truths_name() -> None:
    belief = _model("auto, dry, sleep", with_fan=False)
    causes = classify(belief, TRUTH, {"fan": "high", "mode": "dry"}, {"mode": "dry"})
    assert first_cause(causes) == "lacks setting" and causes[0].setting == "fan"


def test_parser_faults_dropped_refused_and_extra() -> None:
    belief = _model("auto, dry, sleep")
    dropped = classify(belief, TRUTH, {"mode": "dry", "fan": "high"}, {"mode": "dry"})
    assert [c.kind for c in dropped] == ["parser dropped"]
    refused = classify(belief, TRUTH, {"mode": "dry"}, None)
    assert [c.kind for c in refused] == ["parser refused"]
    extra = classify(belief, TRUTH, {"mode": "dry"}, {"mode": "dry", "fan": "low"})
    assert [(c.kind, c.setting) for c in extra] == [("extra setting", "fan")]


def test_the_run_names_its_suite_and_another_suite_judges_every_category(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    from benchmarks.e2e_failures import main, run_suite

    assert run_suite(tmp_path) == "bundled"  # no run.json: the bundled suite
    (tmp_path / "run.json").write_text(json.dumps({"suite": str(NEWCATS)}), encoding="utf-8")
    assert run_suite(tmp_path) == str(NEWCATS)
    assert run_suite(tmp_path / "results.jsonl") == str(NEWCATS)
    record = {"method": "apbot", "category": "steam_iron", "appliance": "steam_iron_1"}
    (tmp_path / "results.jsonl").write_text(
        json.dumps({**record, "task": "t01", "success": True}) + "\n", encoding="utf-8"
    )
    main([str(tmp_path)])  # a new category counts: the nine are the bundled suite's default
    assert "failed 0 of 1 records" in capsys.readouterr().out
    with pytest.raises(SystemExit, match="no apbot records"):
        main([str(tmp_path), "--suite", "bundled"])


def test_a_false_claim_is_judged_on_the_settings_it_got_wrong() -> None:
    # the parser dropped the fan, but the claim went wrong on the mode it was given right:
    # the agent's own false claim, whatever else the parser missed
    belief = _model("auto, dry, sleep")
    stored = {"mode": "dry", "fan": "high"}
    causes = classify(belief, TRUTH, stored, {"mode": "dry"})
    wrong = wrong_settings(belief, TRUTH, stored, {"mode": "auto", "fan": "high"})
    assert wrong == {"mode"}
    assert first_cause(claim_causes(causes, wrong)) == "agent"


def test_a_claim_wrong_only_where_the_parser_was_wrong_is_the_parsers() -> None:
    belief = _model("auto, dry, sleep")
    stored = {"mode": "dry", "fan": "high"}
    causes = classify(belief, TRUTH, stored, {"mode": "dry"})
    wrong = wrong_settings(belief, TRUTH, stored, {"mode": "dry", "fan": "low"})
    assert first_cause(claim_causes(causes, wrong)) == "parser dropped"


def test_a_dropped_setting_the_task_reached_anyway_is_no_cause_of_its_failure() -> None:
    # the parse left out the fan, which ended as asked all the same; the mode it was given
    # right ended wrong: the failure is the agent's, not the parser's
    from benchmarks.e2e_failures import failure_causes

    belief = _model("auto, dry, sleep")
    stored = {"mode": "dry", "fan": "high"}
    causes = classify(belief, TRUTH, stored, {"mode": "dry"})
    assert first_cause(causes) == "parser dropped"
    reached = wrong_settings(belief, TRUTH, stored, {"mode": "auto", "fan": "high"})
    assert first_cause(failure_causes(causes, reached)) == "agent"
    missed = wrong_settings(belief, TRUTH, stored, {"mode": "dry", "fan": "low"})
    assert first_cause(failure_causes(causes, missed)) == "parser dropped"
    extra = classify(belief, TRUTH, {"mode": "dry"}, {"mode": "dry", "fan": "low"})
    assert first_cause(failure_causes(extra, set())) == "extra setting"
