"""Rules read from manuals written again by another writer (styled round 11): a manual of a
range marking one model's own paragraphs with its type in brackets, a chart of what the
display reads after so many presses or clicks, a list of where a setting cannot be used, a
setting's longest value given as a field ("Longest: 9:00")."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.count_tables import count_charts
from apbot.read.evidence_checks import excluded_list
from apbot.read.text import parse_manual
from apbot.read.values import Range
from apbot.read.values_labels import clock_tops

RANGE_MANUAL = """\
Models YG-20 · YG-30

The YG-20 and the YG-30 share everything below unless a paragraph is marked with the type.

THE KEYS

JAR    Steps through the jar sizes: 150 ml → 250 ml → 500 ml → 150 ml …

[YG-30] The YG-30 has no JAR key; its jar switch is on or off.

HOURS  Sets the fermenting time from 4 to 12 hours in steps of 1 hour.
"""


def test_a_paragraph_marked_with_a_sister_type_is_not_read() -> None:
    texts = [u.text for u in parse_manual(RANGE_MANUAL).units]
    assert not any("no JAR key" in t for t in texts), texts
    model = read_manual(RANGE_MANUAL, ["press_jar", "press_hours"]).model
    jar = model.variables["jar"].model_dump(mode="json")
    assert jar.get("unit") == "ml", jar  # (read as the sister's on/off switch without the rule)
    assert (jar["ranges"][0][0], jar["ranges"][-1][1]) == (150, 500), jar


def test_a_bracketed_code_that_names_no_model_of_the_range_stays() -> None:
    text = "ERRORS\n\n[EH-01] The tank is empty. Fill it and press START.\n"
    texts = [u.text for u in parse_manual(text).units]
    assert any("tank is empty" in t for t in texts), texts


HEATER_CHART = """\
Table 4 – Water temperature (start: 35 °C)

 Touches of UP   Display   Good for
 -------------   -------   ------------------
 1               38 °C     a warm rinse
 2               41 °C     hand washing
 4               47 °C     dishes
 5               50 °C     greasy pans
 6               52 °C     soaking
 7 or more       54 °C     (hottest, no further change)
"""


def test_a_chart_of_touches_and_readings_is_the_range_with_its_steps() -> None:
    charts = count_charts(parse_manual(HEATER_CHART).units)
    assert len(charts) == 1, charts
    assert charts[0].pieces == [Range(35, 50, "°C", 3), Range(50, 54, "°C", 2)], charts


TIMER_CHART = """\
How the delay moves – clicks clockwise from DELAY 0:00

  Clicks   Display        Clicks   Display
  1        DELAY 0:15     6        DELAY 1:30
  2        DELAY 0:30     8        DELAY 2:30
  4        DELAY 1:00     9 or more   DELAY 3:00
"""


def test_a_clicks_chart_with_labelled_readings_in_two_halves_is_read_as_one() -> None:
    charts = count_charts(parse_manual(TIMER_CHART).units)
    assert len(charts) == 1 and charts[0].label == "DELAY", charts
    assert charts[0].pieces == [Range(0, 5400, "s", 900), Range(5400, 10800, "s", 1800)], charts


def test_a_list_of_where_a_setting_cannot_be_used_is_no_list_of_its_values() -> None:
    said = "The delay cannot be used on ROAST, GRILL or DEFROST."
    assert excluded_list(["roast", "grill", "defrost"], said)
    assert not excluded_list(["low", "high"], "FAN selects LOW or HIGH; it is not used on GRILL.")


def test_a_longest_value_given_as_a_field_is_the_top_of_the_range() -> None:
    assert [top for top, _, _ in clock_tops("Longest: 9:00. Further presses do nothing.")] == [
        9 * 3600
    ]


SIDEWAYS = """\
Steaming by weight

Touch STEAM once for every 50 g of vegetables. Above 300 g each touch adds 100 g:

   touches   1     2     3    …   6       7       8
   weight    50 g  100 g 150 g …  300 g   400 g   500 g

Touch START.
"""


def test_a_sideways_chart_of_touches_is_the_keys_range_with_its_steps() -> None:
    model = read_manual(SIDEWAYS, ["press_steam", "press_start"]).model
    steam = model.variables["steam"].model_dump(mode="json")
    assert steam["ranges"] == [[50, 300, 50], [300, 500, 100]], steam


# review: a range's manual read for the tagged model's own panel, and a list of fault codes
FLAVOUR_RANGE = """\
Models YG-20 · YG-30

THE KEYS

JAR    Steps through the jar sizes: 150 ml, 250 ml, 500 ml.

[YG-30] The YG-30 also has a FLAVOUR key. FLAVOUR steps through PLAIN, GREEK and SKYR.

HOURS  Sets the fermenting time from 4 to 12 hours in steps of 1 hour.
"""


def test_the_tagged_paragraphs_of_the_model_whose_key_only_they_name_stay() -> None:
    model = read_manual(FLAVOUR_RANGE, ["press_jar", "press_hours", "press_flavour"]).model
    flavour = model.variables["flavour"].model_dump(mode="json")
    assert flavour.get("values") == ["plain", "greek", "skyr"], flavour  # (off/on without)
    texts = [u.text for u in parse_manual(FLAVOUR_RANGE).units]
    assert not any("FLAVOUR" in t for t in texts), texts  # (a panel without it: left out)


def test_bracketed_fault_codes_listed_together_far_from_the_cover_stay() -> None:
    intro = "\n\n".join(f"Step {n}. Fill the tank and close the lid." for n in range(1, 14))
    codes = "Codes EH-01, EH-02 and EH-03 may appear.\n\n[EH-01] The tank is empty.\n"
    text = f"{intro}\n\nERRORS\n\n{codes}"
    texts = [u.text for u in parse_manual(text).units]
    assert any("tank is empty" in t for t in texts), texts


def test_a_paragraph_after_a_tagged_one_without_a_blank_line_stays() -> None:
    text = (
        "Models BM-10 · BM-12 · BM-14\n\nTHE TIMER\n\n"
        "[BM-14] The BM-14 timer goes up to 15 hours.\n"
        "The TIMER key sets the delay from 1 to 13 hours in steps of 10 minutes.\n"
    )
    texts = [u.text for u in parse_manual(text).units]
    assert any(t.startswith("The TIMER key") for t in texts), texts  # (a flattened PDF's layout)
    assert not any("15 hours" in t for t in texts), texts
