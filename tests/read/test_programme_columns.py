"""Programme tables with a yes/no column, a bare Range column, a step and a preset per row."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.read import read_manual

STEAM_POT = """
IMPORTANT SAFEGUARDS
Do not open the lid while steam escapes. Keep the cord away from the edge of the worktop. Do
not use the pot outdoors. Children must be supervised.

## 2. Panel

| Key | Use |
|---|---|
| **MENU** | Chooses the menu. |
| **TIME** | Opens the cooking time (STEW, JAM, BROTH only). |
| **+** / **–** | Change the time. |
| **START** | Starts. |

## 3. Menus
Press MENU once for each step to the next menu.
The menus come in the order of the table below.

| Menu | Good for | Time adjustable? | Range | Each + / – press | Preset time |
|---|---|---|---|---|---|
| RICE | white rice | no | — | — | automatic |
| GRAIN | quinoa, barley | no | — | — | automatic |
| STEW | meat, beans | yes | 1:00 – 4:00 | 30 min | 2:00 |
| JAM | fruit | yes | 0:20 – 1:00 | 10 min | 0:40 |
| BROTH | stock | yes | 2:00 – 6:00 | 60 min | 3:00 |

## 4. Cooking grains (RICE, GRAIN)
Rinse, add water to the mark, close the lid.
"""

ACTIONS = ["press_menu", "press_time", "press_plus", "press_minus", "press_start"]


def test_the_table_below_gives_the_menu_key_all_its_rows() -> None:
    model = read_manual(STEAM_POT, ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    assert model.variables["menu"].values == ["rice", "grain", "stew", "jam", "broth"]


def test_a_yes_no_column_names_the_setting_whose_values_stand_in_the_range_column() -> None:
    model = read_manual(STEAM_POT, ACTIONS).model
    time = model.variables["time"]
    assert time.depends_on == "menu"
    assert set(time.cases) == {"stew", "jam", "broth"}
    assert time.cases["stew"].ranges == [("01:00:00", "04:00:00", 1800)]
    assert time.cases["jam"].ranges == [("00:20:00", "01:00:00", 600)]
    assert time.cases["broth"].initial == "03:00:00"


def test_the_time_key_is_opened_then_stepped_by_the_pair() -> None:
    model = read_manual(STEAM_POT, ACTIONS).model
    steps = next(f for f in model.features.values() if f[0].actions == ["press_time"])
    assert len(steps) == 2 and set(steps[1].actions) == {"press_plus", "press_minus"}
