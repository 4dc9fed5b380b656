"""Display codes of named values (``value_codes``), a programme chart numbered by knob
position (``evidence_tables``) and a key's on/off said only for holding it together with
another key (``roles._hold_row``), each on a small manual written in our own words."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.goal import parse_instruction
from tests.helpers import model_from

# a chart pairing each named mode with the code the display shows, and a chain of names
# with their codes in brackets
LAMP = """GLOWMAX GARDEN LAMP GL-2
Operating instructions

KEYS
  MODE     next mode
  SOUND    next beeper volume

MODES

  Press MODE to move to the next mode:

     STEADY  →  FLICKER  →  FADE  →  STEADY ...

  Mode        Code   Lamp   What it does
  ----------  -----  -----  ------------------------------
  STEADY      St     ☼      even light all night
  FLICKER     FL     ☾      like a candle flame
  FADE        Fd     ☾☾     slowly brighter and darker
  ----------  -----  -----  ------------------------------

BEEPER

  Press SOUND. Each press moves to the next volume:

     QUIET  →  SOFT (VOL 1)  →  LOUD (VOL 2)  →  QUIET ...
"""
LAMP_ACTIONS = ["press_mode", "press_sound"]


def test_a_chart_s_code_column_gives_each_named_value_its_display_code() -> None:
    model = read_manual(LAMP, LAMP_ACTIONS).model
    (spec,) = [
        v for v in model.variables.values() if "flicker" in (getattr(v, "values", None) or [])
    ]
    assert spec.show == {"steady": "St", "flicker": "FL", "fade": "Fd"}


def test_codes_in_brackets_after_the_names_are_what_the_display_shows() -> None:
    model = read_manual(LAMP, LAMP_ACTIONS).model
    (spec,) = [v for v in model.variables.values() if "loud" in (getattr(v, "values", None) or [])]
    assert spec.show == {"quiet": "QUIET", "soft": "VOL 1", "loud": "VOL 2"}


# a gloss in brackets is no code: the names keep no show
GLOSSED = LAMP.replace("SOFT (VOL 1)", "SOFT (half volume)").replace(
    "LOUD (VOL 2)", "LOUD (full volume)"
)


def test_a_gloss_in_brackets_is_no_display_code() -> None:
    model = read_manual(GLOSSED, LAMP_ACTIONS).model
    (spec,) = [v for v in model.variables.values() if "loud" in (getattr(v, "values", None) or [])]
    assert not spec.show


# a programme chart whose first column counts the knob positions, headed "Dial pos."
CROCK = """BRINEMASTER FC-1 FERMENTER
Operating instructions

  PROG knob    turn to choose the programme; it stops at both ends
  TEMP − / +   temperature 1 °C lower / higher

PROGRAMME CHART

  Dial pos.  Programme     Range (°C)  Factory
  ---------  ------------  ----------  -------
  1          YOGHURT       35 – 45     40 °C
  2          TEMPEH        25 – 32     30 °C
  3          KOMBUCHA      20 – 28     24 °C
  ---------  ------------  ----------  -------

Each press of TEMP − or TEMP + changes the temperature by 1 °C, within the range of the
programme.
"""
CROCK_ACTIONS = ["turn_prog_cw", "turn_prog_ccw", "press_temp_minus", "press_temp_plus"]


def test_a_chart_numbered_by_knob_position_lists_the_programmes() -> None:
    model = read_manual(CROCK, CROCK_ACTIONS).model
    (spec,) = [
        v for v in model.variables.values() if "tempeh" in (getattr(v, "values", None) or [])
    ]
    assert list(spec.values or []) == ["yoghurt", "tempeh", "kombucha"]


# a key whose legend row says on / off only in the column for holding it with another key
DIFFUSER = """AIRLY AD-1 DIFFUSER
Operating instructions

  No.   Key      Touch briefly                     Touch and hold
  ----  -------  --------------------------------  -----------------------------------
  ①     ⏻        Switch on / switch off            –
  ②     MIST     Next mist mode                    together with TIMER for 3 s:
                                                    key lock on / off
  ③     TIMER    Next run time                     together with MIST for 3 s:
                                                    key lock on / off
  ----  -------  --------------------------------  -----------------------------------

MIST MODES

  Touch MIST to change the mist mode. Each touch moves to the next mode, in this
  order:

      STRONG  →  GENTLE  →  PULSE  →  STRONG ...

TIMER

  Touch TIMER; each touch moves to the next run time: 1 h → 3 h → 6 h → 1 h ...
"""
DIFFUSER_ACTIONS = ["press_power", "press_mist", "press_timer", "hold_mist_timer"]


def test_an_on_off_said_for_holding_two_keys_together_is_not_the_press_s() -> None:
    model = read_manual(DIFFUSER, DIFFUSER_ACTIONS).model
    assert list(getattr(model.variables["mist"], "values", None) or []) == [
        "strong",
        "gentle",
        "pulse",
    ]


# a mode whose display code is spelled as a switch's word
ZAPPER = model_from(
    """
    controls: [{id: mode}, {id: lure}]
    variables:
      mode:
        type: discrete
        values: [always on, dusk to dawn, dusk timer]
        show: {always on: "On", dusk to dawn: "dd", dusk timer: "dt"}
        label: MODE
      lure: {type: discrete, values: ["off", "on"], label: LURE}
    actions:
      press_mode: {control: mode}
      press_lure: {control: lure}
    features:
      mode:
        - {actions: [press_mode], variable: mode, effect: next}
      lure:
        - {actions: [press_lure], variable: lure, effect: toggle}
    """
)


def test_a_code_spelled_as_a_switch_word_names_no_value_in_a_request() -> None:
    goal = parse_instruction(ZAPPER, "Keep the lure on, please.")
    assert "mode" not in goal


# amounts in brackets or in a Display column, and a fault chart's Code column, name no code
WASHER = """AQUAWASH COMPACT WASHER
Operating instructions

KEYS
  PROG     next programme
  START    start or pause

PROGRAMMES

  Press PROG to move to the next programme:

     COTTON  →  SYNTHETIC  →  WOOL  →  COTTON ...

{extra}
"""
WASHER_EXTRAS = [
    "  The wash temperatures are COTTON (60 °C), SYNTHETIC (40 °C) and WOOL (30 °C).",
    "  Typical run times: COTTON (2 h), SYNTHETIC (90 min), WOOL (45 min).",
    """SPECIFICATIONS

  Programme   Display   Max load
  ----------  --------  --------
  COTTON      1:59      6 kg
  SYNTHETIC   1:30      3 kg
  WOOL        0:45      2 kg
""",
    """WHEN SOMETHING GOES WRONG

  Programme   Code   Cause
  ----------  -----  ------------------------------
  COTTON      E1     door not closed when cotton starts
  SYNTHETIC   E2     water tap closed
  WOOL        E3     drain blocked
  ----------  -----  ------------------------------
""",
]


def test_amounts_and_a_fault_chart_s_codes_are_no_display_codes_of_the_names() -> None:
    for extra in WASHER_EXTRAS:
        model = read_manual(WASHER.format(extra=extra), ["press_prog", "press_start"]).model
        (spec,) = [
            v for v in model.variables.values() if "wool" in (getattr(v, "values", None) or [])
        ]
        assert spec.show is None, extra


# a numbered table of steps to do, before the chart, lists no programmes
DESCALE_STEPS = """DESCALING

  Step  Programme use         What to do
  ----  --------------------  ------------------------------
  1     Empty the crock       pour out the brine
  2     Fill with vinegar     half a litre
  3     Rinse twice           with warm water
  ----  --------------------  ------------------------------

"""


def test_a_numbered_table_of_steps_to_do_is_no_programme_chart() -> None:
    at = CROCK.index("PROGRAMME CHART")
    model = read_manual(CROCK[:at] + DESCALE_STEPS + CROCK[at:], CROCK_ACTIONS).model
    (spec,) = [
        v for v in model.variables.values() if "tempeh" in (getattr(v, "values", None) or [])
    ]
    assert list(spec.values or []) == ["yoghurt", "tempeh", "kombucha"]
