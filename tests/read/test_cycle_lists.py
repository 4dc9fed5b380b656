"""Lists that come back round to their first item (``shapes.comes_round``,
``value_lists._triangle_arrows``) and a column of times given to an amount before an on/off
switch (``cases._switch``): each rule on a small manual of our own words."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.shapes import _keyish, comes_round
from apbot.read.value_lists import find_list

# a plate warmer whose MODE cycles modes sharing names with two keys
PLATES = """
HotStack PW-6 plate warmer

  Keys: ⏻  MODE  WARM  DRY  START

  MODE      next mode
  WARM      choose the warming time, then + or −
  DRY       choose the drying time, then + or −
  +         longer
  −         shorter

Touch MODE to go through the modes in this order: EASY → WARM+DRY → WARM → DRY → EASY
"""


def test_a_list_coming_back_round_is_values_even_with_key_names() -> None:
    items = ["EASY", "WARM+DRY", "WARM", "DRY"]
    text = "in this order: EASY → WARM+DRY → WARM → DRY → EASY"
    assert comes_round(items, text)
    assert not _keyish(items, {"warm", "dry"}, {"MODE"}, text)
    assert _keyish(["WARM", "DRY", "then +"], {"warm", "dry"}, {"MODE"}, "WARM, DRY, then +")
    model = read_manual(
        PLATES,
        ["press_power", "press_mode", "press_warm", "press_dry", "press_plus", "press_minus"],
    ).model
    assert model.variables["mode"].values == ["easy", "warm+dry", "warm", "dry"]


def test_the_next_keys_triangles_drawn_between_names_are_arrows() -> None:
    found = find_list("L1 ► L2 ► L3 ► L4 ► L1 …  L1 ◄ L4 ◄ L3 … (from L1, ◄ goes to L4)")
    assert found == (["L1", "L2", "L3", "L4"], "arrows")
    assert find_list("Press ► to go on, then ► again.") is None


def test_a_path_through_a_menu_drawn_with_triangles_is_no_list() -> None:
    # a path never comes back round to its first name: not a key stepping its values
    assert find_list("To change the format go to MENU ▶ Clock ▶ Format and press OK.") is None


# the plate warmer's modes with a time chart; holding DRY switches low heat on and off
PLATES_CHART = (
    PLATES.replace(
        "  DRY       choose the drying time, then + or −",
        "  DRY       choose the drying time, then + or − (hold 3 s: low heat on / off)",
    )
    + """
MODE CHART

  Mode        Warming time      Drying time
  ----------  ----------------  ----------------
  EASY        fixed             fixed
  WARM+DRY    10 - 30 min       20 - 60 min
  WARM        10 - 30 min       none
  DRY         none              20 - 60 min
"""
)


def test_a_chart_of_times_goes_to_the_amount_not_the_held_switch() -> None:
    actions = ["press_power", "press_mode", "press_warm", "press_dry", "hold_dry"]
    model = read_manual(PLATES_CHART, [*actions, "press_plus", "press_minus"]).model
    switches = [
        n for n, v in model.variables.items() if getattr(v, "values", None) == ["off", "on"]
    ]
    timed = [n for n, v in model.variables.items() if v.depends_on == "mode"]
    assert "dry" in timed and not set(switches) & set(timed)
