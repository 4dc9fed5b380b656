"""Programme tables with a yes/no column, a bare Range column, a step and a preset per row."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.model.values import parse_hms
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


# an ultrasonic cleaner: the soak time's table counts in minutes for one mode, seconds for another
SOAK_BATH = """
# Ultrasonic cleaner UC-2

## Panel
| Key | Use |
|---|---|
| **MODE** | Chooses the mode: GENTLE → NORMAL → JEWEL → GENTLE … |
| **SOAK −** | Shorter soaking. |
| **SOAK +** | Longer soaking. |
| **START** | Starts. |

## Soaking time
How long the parts soak depends on the mode:

| Mode | Range | Step per key | Start |
|---|---|---|---|
| GENTLE | 10 – 30 minutes | 5 minutes | 20 minutes |
| NORMAL | 20 – 90 seconds | 10 seconds | 30 seconds |
| JEWEL | fixed, 3 minutes | — | — |
"""

SOAK_ACTIONS = ["press_mode", "press_soak_minus", "press_soak_plus", "press_start"]


def _secs(x: object) -> int:
    """A time bound as the model keeps it ("00:10:00" or 600), in seconds."""
    return parse_hms(str(x)) if ":" in str(x) else int(float(str(x)))


def test_a_mode_table_counting_in_minutes_and_seconds_gives_each_mode_its_time() -> None:
    model = read_manual(SOAK_BATH, SOAK_ACTIONS).model
    soak = model.variables["soak"]
    assert soak.type == "time" and soak.depends_on == "mode", soak
    assert soak.cases is not None
    gentle, normal = soak.cases["gentle"], soak.cases["normal"]
    assert [_secs(x) for x in gentle.ranges[0]] == [600, 1800, 300], gentle
    assert [_secs(x) for x in normal.ranges[0]] == [20, 90, 10], normal
    assert "jewel" not in soak.cases


# a smoker whose chart gives each wood's smoking time with its step in one column
SMOKER = """
# Pellet smoker PS-5

## Panel
| Key | Use |
|---|---|
| **WOOD** | Chooses the wood: HICKORY → APPLE → CHERRY → MESQUITE → HICKORY … |
| **SMOKE −** / **SMOKE +** | Shorter / longer smoking. |
| **START** | Starts. |

## Wood chart
| Wood | Flavour | Smoking time (range, step) | Standard |
|---|---|---|---|
| HICKORY | strong | 1:00 – 3:00, 30 min | 2:00 |
| APPLE | mild | 0:30 – 2:00, 15 min | 1:00 |
| CHERRY | sweet | 0:30 – 1:30, 15 min | 0:45 |
| MESQUITE | very strong | 0:15 – 1:00, 15 min | 0:30 |
"""


def test_a_chart_column_naming_range_and_step_gives_each_row_its_range() -> None:
    actions = ["press_wood", "press_smoke_minus", "press_smoke_plus", "press_start"]
    model = read_manual(SMOKER, actions).model
    smoke = model.variables["smoke"]
    assert smoke.depends_on == "wood", smoke
    assert smoke.cases is not None
    assert _secs(smoke.cases["apple"].ranges[0][0]) == 1800, smoke.cases
    assert _secs(smoke.cases["hickory"].ranges[-1][1]) == 10800, smoke.cases


# a boot warmer whose chart gives each mode's fan levels as the FAN key steps through them
BOOT_WARMER = """
# Boot warmer BW-2

## Panel
| Key | Use |
|---|---|
| **MODE** | Next mode: HOT → MILD → AIR → HOT … |
| **FAN** | Next fan level of the mode: LOW, MID, HIGH or MAX (see the chart). |

## Fan levels per mode
| Mode | Fan levels, in the order FAN gives them | After MODE |
|---|---|---|
| HOT | LOW → MID → HIGH → LOW … | MID |
| MILD | LOW → MID → HIGH → MAX → LOW … | LOW |
| AIR | HIGH → MAX → HIGH … | MAX |
"""


def test_a_chart_cell_stepping_with_arrows_lists_each_value_once() -> None:
    model = read_manual(BOOT_WARMER, ["press_mode", "press_fan"]).model
    fan = model.variables["fan"]
    assert fan.depends_on == "mode" and fan.cases is not None, fan
    assert fan.cases["mild"].values == ["low", "mid", "high", "max"], fan.cases
