"""Rules of the values30 session, each on a small manual of our own words: a key that steps
through "the levels" takes the table column headed Level (``noun_columns``); a bare-figure
choice keys no chart of codes; its start is the value printed after its name in a list of
start settings (``named_starts``); a hold opening a setting takes the run of codes the pair's
next step gives ("SG 1 … SG 6", ``code_spans``); a span in brackets after the setting's noun on
the line leading its steps is its range; a legend run's on/off is the item's that says it; a
key's own "each press adds" range beats a list near it; and a stepping pair keeps its own
amount beside a key that borrows it (``pair_own_ranges``)."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.code_spans import code_span, named_span
from apbot.read.noun_columns import numbered_choice

# a nursery intercom: a night light stepped through levels, a lullaby picked by a hold
INTERCOM = """
Brisa N-4 nursery intercom

CONTROLS

  ▲ — next room channel; in a setting view, next value.
  ▼ — previous room channel; in a setting view, previous value.
  GLOW — night light brightness.
  TUNE — hold 2 s: pick the lullaby.

NIGHT LIGHT AND LULLABY

Night light
Press GLOW to step through the levels; after level 4 the light is off again.

| Screen | Level | Light  |
|--------|-------|--------|
| (none) | off   | dark   |
| L1     | 1     | faint  |
| L2     | 2     | soft   |
| L3     | 3     | medium |
| L4     | 4     | bright |

Lullaby
To pick the lullaby:
 1. Hold TUNE for 2 seconds. The screen shows SG 1 (or the tune now chosen).
 2. Press ▲ / ▼: SG 1 … SG 6, going round from 6 to 1.
 3. Wait 4 seconds; the screen goes back to the channel.

ROOM CHANNELS

Press ▲ or ▼ to change the room channel, 1 to 9.

| Channel | Hz   |
|---------|------|
| 1       | 88.5 |
| 2       | 91.5 |
| 3       | 94.8 |
| 4       | 97.4 |

New units start on channel 1, lullaby 1, GLOW off.
"""

INTERCOM_KEYS = ["press_up", "press_down", "press_glow", "hold_tune"]

# a haze machine: a legend run, a key's own stepped range, a pair that an address key borrows
HAZER = """
Vapora H-3 haze machine

CONTROLS

  [1] SHOW – the display  [2] HAZE – continuous haze on / off  [3] PUFF – length of each puff
  [4] CHAN – console start channel  [5][6] ▲ ▼ – haze output; after CHAN, the channel

HAZE OUTPUT

▲ and ▼ set the haze output in steps of 5 %: from 20 % to 100 %. Factory setting: 60 %.

PUFF AND PAUSE (INTERVAL AND PUFF)

Pause between puffs
  The pause is fixed in this list:

      15 s → 30 s → 60 s → 120 s → 15 s …

Length of a puff — PUFF key
  Each further press of PUFF adds one second, from 1 to 8 s; after 8 s it starts again at 1 s.

CONSOLE CHANNEL

Setting the console channel (1 … 256):
  1. Press CHAN. The display shows the channel, e.g.
     CH 1.
  2. Press ▲ or ▼ to change the channel by 1.
"""

HAZER_KEYS = ["press_haze", "press_puff", "press_chan", "press_up", "press_down"]


def test_a_key_stepping_through_levels_takes_the_level_column() -> None:
    model = read_manual(INTERCOM, INTERCOM_KEYS).model
    glow = model.variables["glow"]
    assert glow.values == ["off", "1", "2", "3", "4"]  # not the Screen column, not on / off


def test_a_choice_of_bare_figures_keys_no_chart_of_codes() -> None:
    assert numbered_choice(["off", "1", "2", "3"])
    assert not numbered_choice(["low", "high", "1"])
    model = read_manual(INTERCOM, INTERCOM_KEYS).model
    # the frequency chart's rows start 1, 2, 3: no setting depends on the night light
    assert not any(v.depends_on == "glow" for v in model.variables.values())


def test_a_start_said_after_the_setting_name() -> None:
    model = read_manual(INTERCOM, INTERCOM_KEYS).model
    assert model.variables["glow"].initial == "off"  # "GLOW off", not the "1" said before it


def test_a_run_of_codes_said_by_its_ends() -> None:
    assert code_span("Press ▲ / ▼: SG 1 … SG 6, going round from 6 to 1.").high == 6
    assert code_span("P1 to P8") is not None
    assert code_span("CH 01 … VOL 8") is None  # two labels: no one run
    model = read_manual(INTERCOM, INTERCOM_KEYS).model
    tune = next(v for v in model.variables.values() if v.type == "numeric" and v.label == "TUNE")
    assert list(tune.ranges[0][:2]) == [1, 6]


def test_a_span_in_brackets_after_the_setting_noun() -> None:
    assert named_span("Setting the console channel (1 … 256):", {"chan"}).high == 256
    assert named_span("Setting the console channel (1 … 256):", {"puff"}) is None
    model = read_manual(HAZER, HAZER_KEYS).model
    chan = model.variables["chan"]
    assert list(chan.ranges[0][:2]) == [1, 256]


def test_the_pair_step_after_a_step_cut_by_an_example() -> None:
    # "1. Press CHAN. The display shows the channel, e.g. / CH 1." "2. Press ▲ or ▼ …": the
    # pair sets what CHAN opened, though the example cut step 1 into three units
    model = read_manual(HAZER, HAZER_KEYS).model
    steps = model.features["set_chan"]
    assert steps[0].actions == ["press_chan"]
    assert set(steps[1].actions) == {"press_up", "press_down"}


def test_a_legend_run_on_off_is_the_item_that_says_it() -> None:
    model = read_manual(HAZER, HAZER_KEYS).model
    assert model.variables["haze"].values == ["off", "on"]
    assert model.variables["puff"].type != "discrete"  # not HAZE's on / off


def test_a_key_own_stepped_range_beats_a_list_near_it() -> None:
    model = read_manual(HAZER, HAZER_KEYS).model
    puff = model.variables["puff"]
    assert puff.type == "time"
    assert puff.ranges[0][0] == "00:00:01" and puff.ranges[-1][1] == "00:00:08"


def test_a_pair_keeps_its_own_amount_beside_a_borrowing_key() -> None:
    model = read_manual(HAZER, HAZER_KEYS).model
    percents = [v for v in model.variables.values() if getattr(v, "unit", None) == "%"]
    assert percents and list(percents[0].ranges[0][:2]) == [20, 100]


def test_a_first_figure_in_lower_case_leads_an_arrow_list() -> None:
    from apbot.read.value_lists import find_list

    said = "Press CUPS to step through 1x → 2x → 3x → 1x … The display shows the count."
    assert find_list(said) == (["1x", "2x", "3x"], "arrows")


# a heat pad whose timer has a letter for "no time limit"
HEAT_PAD = """
Calda H-1 heat pad

KEYS

  TIMER ... each press: 30MIN → 60MIN → 90MIN → C → 30MIN …

TIMER

The timer switches the pad off after the time chosen, or C for continuous: the pad then
stays warm until you switch it off.
"""


def test_a_letter_value_is_named_by_its_gloss() -> None:
    model = read_manual(HEAT_PAD, ["press_timer"]).model
    timer = model.variables["timer"]
    assert "continuous" in timer.values  # the user says "continuous", the display prints C
    assert timer.show["continuous"] == "C"
