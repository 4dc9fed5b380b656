"""The styled development set and its script: honest membership, the same scoring as eval-reader."""

from __future__ import annotations

from pathlib import Path

import pytest

from apbot.bench.suite import load_suite
from apbot.read import read_manual
from apbot.read.evaluate import score_reading
from benchmarks.styled_reader import (
    HELD_OUT,
    STYLED_DIR,
    StyledSetError,
    main,
    pick,
    styled_manuals,
)


def test_the_set_is_of_the_nine_categories_and_has_its_readme() -> None:
    chosen = pick(styled_manuals(), None)
    categories = {a.category for a, _ in chosen}
    assert len(chosen) >= 6 and len(categories) >= 6
    assert not categories & set(HELD_OUT)
    assert (STYLED_DIR / "README.md").is_file()
    for appliance, text in chosen:
        # real-manual length, and not the original manual copied
        assert 1900 <= len(text.split()) <= 5000, appliance.id
        assert text.strip() != appliance.manual.strip()


def test_a_held_out_category_or_an_unknown_id_is_refused_by_name() -> None:
    with pytest.raises(StyledSetError, match="held-out"):
        pick({"blender_1": "BLENDER\n"}, None)
    with pytest.raises(StyledSetError, match="kettle_99"):
        pick({"kettle_99": "KETTLE\n"}, None)
    with pytest.raises(StyledSetError, match="no styled manual for 'kettle_1'"):
        pick({"bread_maker_4": "x"}, ["kettle_1"])


def test_the_script_on_one_appliance_scores_as_eval_reader(
    capsys: pytest.CaptureFixture[str],
) -> None:
    result = main(["--appliances", "bottle_washer_4", "--json"])
    assert '"bottle_washer_4"' in capsys.readouterr().out
    row = result["appliances"]["bottle_washer_4"]
    appliance = load_suite().get("bottle_washer_4")
    actions = list(appliance.model.actions)
    styled_text = (STYLED_DIR / "bottle_washer_4.md").read_text(encoding="utf-8")
    for label, text in (("styled", styled_text), ("original", appliance.manual)):
        expected = score_reading(read_manual(text, actions).model, appliance.model).table()
        assert row[label] == expected
    assert result["overall"]["styled"] == row["styled"]
    assert row["words"]["original"] == appliance.manual_words


def test_an_unknown_appliance_exits_with_a_message(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as stop:
        main(["--appliances", "toaster"])
    assert stop.value.code == 2
    assert "no styled manual for 'toaster'" in capsys.readouterr().err


def test_end_to_end_runs_styled_and_original_from_their_own_manuals(tmp_path: Path) -> None:
    result = main(
        ["--appliances", "bottle_washer_4", "--e2e", "--sample", "1", "--out", str(tmp_path)]
    )
    rows = result["e2e"]["apbot"]
    assert rows["bottle_washer_4"]["styled"]["n"] == 1
    assert rows["bottle_washer_4"]["original"]["n"] == 1
    copied = tmp_path / "suite-styled" / "bottle_washer_4" / "manual.md"
    assert copied.read_text(encoding="utf-8") == (STYLED_DIR / "bottle_washer_4.md").read_text(
        encoding="utf-8"
    )
    records = (tmp_path / "styled").rglob("*.jsonl")
    assert any("bottle_washer_4" in p.read_text(encoding="utf-8") for p in records)
