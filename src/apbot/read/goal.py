"""The offline goal parser: a user's instruction to a partial assignment over a model's variables.

It reads only the *belief* model — variable names, labels, values, units, show texts, and the
labels of the controls that set them — and the instruction. It never invents a setting the
instruction does not mention, and an instruction the model cannot satisfy (a value outside a
domain, a named value the model lacks) raises :class:`GoalParseError` naming the words and why.

How it works, in order:

1. *value names*: every discrete value (and every labelled key that sets one value, such as a
   GREEN TEA key) is matched as a phrase against the instruction's stemmed words;
2. *quantities*: durations, clock times and numbers with units (``apbot.read.numbers``) are
   given to the variable whose type, unit and domain fit, and whose names are nearest in the
   text; a relative time ("ready in 8 hours") prefers a delay, a clock time a clock;
3. *superlatives and scales*: "the lowest", "full power", "a dark crust" on a numeric setting;
4. *switches*: an on/off setting named in the text is on unless negated ("no prewash");
5. *power and start*: "switch it on" sets the power variable; "start it", "get it going" or an
   instruction that opens with a cooking verb sets the running variable to what the model's
   START key sets (in the programme that was asked for); "don't start" sets it off.

Before step 1, ``goal_remarks`` drops the clauses that ask nothing of the appliance ("…, I'll be
back in an hour", "…, we are 4 at the table"). The steps live in their own modules:
``goal_spelling`` (rewrites before tokenising),
``goal_names`` (1), ``goal_fractions`` (parts of a cup, before 2), ``goal_assign`` and
``goal_fit`` (2), ``goal_scales`` and ``goal_ladders`` (3), ``goal_switches`` and ``goal_offs``
(4), ``goal_start`` and ``goal_held`` (5), ``goal_twins`` (zones and sides), ``goal_cases``
(the mode a setting's value implies); ``goal_view`` is the model as the parser sees it.
"""

from __future__ import annotations

from apbot.model.domain import ValueProblem, normalise
from apbot.model.schema import ApplianceModel, DiscreteVariable
from apbot.model.values import closest_matches, preview
from apbot.read.goal_acronyms import said_acronyms
from apbot.read.goal_ages import said_ages
from apbot.read.goal_amount_words import said_amounts
from apbot.read.goal_assign import assign_mentions
from apbot.read.goal_both import both_values
from apbot.read.goal_cases import entry_modes, implied_cases, set_by_hand
from apbot.read.goal_charted_levels import charted_levels, charted_superlatives
from apbot.read.goal_code_rows import coded_rows
from apbot.read.goal_copies import confirmed_choices
from apbot.read.goal_count_words import counted_times
from apbot.read.goal_counted_ends import counted_ends
from apbot.read.goal_dates import said_dates
from apbot.read.goal_digits import spelled_codes
from apbot.read.goal_electric import said_milliamps
from apbot.read.goal_error import GoalParseError
from apbot.read.goal_every import every_periods
from apbot.read.goal_fractions import fractions
from apbot.read.goal_from_start import said_from_start
from apbot.read.goal_gates import closing_switches, entry_switches, gated_switches
from apbot.read.goal_glued_values import said_glued_values
from apbot.read.goal_halfway import halfway_levels
from apbot.read.goal_headings import said_headings
from apbot.read.goal_hourly import hourly_periods
from apbot.read.goal_hundreds import said_hundreds
from apbot.read.goal_hyphen_counts import said_hyphen_counts
from apbot.read.goal_joined_ends import joined_ends
from apbot.read.goal_kelvin import kelvin_words
from apbot.read.goal_kinds import kind_numbers
from apbot.read.goal_last import said_last
from apbot.read.goal_left_to_it import left_to_it
from apbot.read.goal_limits import limit_numbers
from apbot.read.goal_listed import listed_outside
from apbot.read.goal_listed_days import listed_in_days, weeks_elsewhere
from apbot.read.goal_marked_ends import marked_ends
from apbot.read.goal_meters import said_meters
from apbot.read.goal_microlitres import said_microlitres
from apbot.read.goal_minutes_seconds import said_minutes_seconds
from apbot.read.goal_mode_cut import said_mode_cuts
from apbot.read.goal_mute import muted_volume, silenced_sounds
from apbot.read.goal_names import pronoun_ones, restated_codes, value_matches
from apbot.read.goal_numbered_times import numbered_times
from apbot.read.goal_offs import (
    boil,
    no_values,
    off_levels,
    self_switching_off,
    switched_off_numbers,
    switched_off_values,
    zero_settings,
)
from apbot.read.goal_on_values import on_values
from apbot.read.goal_open import open_entries
from apbot.read.goal_ordinals import ordinal_numbers
from apbot.read.goal_outside import kept_outside
from apbot.read.goal_own_switch import own_switch_states
from apbot.read.goal_owner_words import owner_words
from apbot.read.goal_part_of_top import said_parts_of_top
from apbot.read.goal_periods import distinct, in_weeks
from apbot.read.goal_preset_rows import charted_presets
from apbot.read.goal_presets import lift_presets, preset_companions, restore_presets
from apbot.read.goal_quantity_values import quantity_values
from apbot.read.goal_rates import said_rates, said_road_speeds
from apbot.read.goal_readings import frozen_readings
from apbot.read.goal_remarks import without_remarks
from apbot.read.goal_said import per_period
from apbot.read.goal_scales import superlatives
from apbot.read.goal_scheduled_states import scheduled_states
from apbot.read.goal_selector import on_auto_off
from apbot.read.goal_shown_levels import shown_levels
from apbot.read.goal_signed import signed_changes
from apbot.read.goal_spans import time_spans
from apbot.read.goal_spelling import joined_compounds
from apbot.read.goal_spoken_numbers import (
    a_number_for_a_name,
    numbers_owning,
    said_hundreds_past_ten,
    said_hyphenated,
    said_points,
    said_steps,
)
from apbot.read.goal_start import power_and_running
from apbot.read.goal_stopped import said_stopped
from apbot.read.goal_stops import said_power_parts, said_stops
from apbot.read.goal_switch_values import switch_named_values
from apbot.read.goal_switches import switches
from apbot.read.goal_table_quantities import said_table_quantities
from apbot.read.goal_text import Text
from apbot.read.goal_thousands import said_thousands
from apbot.read.goal_times_a_day import said_times_a_day
from apbot.read.goal_turns import said_turns
from apbot.read.goal_twins import place_twins, twin_numbers
from apbot.read.goal_unit_cases import named_units, said_units, unit_cases
from apbot.read.goal_values import in_days
from apbot.read.goal_view import Goal, Model, model_view
from apbot.read.goal_vocab import STOP_WORDS, stem
from apbot.read.goal_wording import plain_order
from apbot.read.numbers import find_mentions

__all__ = ["MAX_INSTRUCTION", "GoalParseError", "parse_instruction"]

MAX_INSTRUCTION = 5_000
"""Characters of one instruction; a longer text is not something a user said to an appliance."""


_REWRITES = (
    without_remarks,
    said_table_quantities,
    said_meters,
    said_from_start,
    said_parts_of_top,
    said_last,
    said_headings,
    said_microlitres,
    said_glued_values,
    said_hyphen_counts,
    said_mode_cuts,
    said_stopped,
    said_minutes_seconds,
    said_power_parts,
    said_stops,
    counted_ends,
    said_acronyms,
    said_hyphenated,
    said_hundreds_past_ten,
    said_points,
    said_steps,
    said_road_speeds,
    said_rates,
    said_amounts,
    numbers_owning,
    said_milliamps,
    said_hundreds,
    said_thousands,
    said_times_a_day,
    said_turns,
    said_dates,
    spelled_codes,
    said_ages,
    joined_compounds,
    hourly_periods,
    every_periods,
    ordinal_numbers,
)
"""Rewrites of the instruction before it is read, in order (innermost first)."""


def parse_instruction(
    model: ApplianceModel,
    instruction: str,
    manual: str = "",
    outside: list[str] | None = None,
) -> Goal:
    """The goal an instruction asks for, over ``model``'s variables, values canonical.

    ``manual``, when given, names the values the panel shows only as codes ("2" is the French
    loaf; :mod:`apbot.read.goal_manual`). Raises :class:`GoalParseError` when the instruction
    asks for a value the model lacks — unless ``outside`` is given: then a quantity the model
    has no value for is still given to the setting of its kind the words name, as said (a
    belief read from a manual may lack the value the appliance has, and the closed loop looks
    for it), and the reason it would have been refused is appended to ``outside``.

    >>> from apbot.examples import load_example
    >>> goal = parse_instruction(load_example("washing_machine"), "Wool at 30 degrees, no prewash")
    >>> sorted(goal.items())[:2]
    [('programme', 'wool'), ('temperature', '30')]
    """
    if len(str(instruction)) > MAX_INSTRUCTION:
        raise GoalParseError(
            str(instruction)[:40] + "…",
            f"the instruction has {len(str(instruction)):,} characters; at most "
            f"{MAX_INSTRUCTION:,} are read",
        )
    view = model_view(model, manual or "")
    said = plain_order(str(instruction))
    for rewrite in _REWRITES:  # each writes a way of saying things as the parser reads it
        said = rewrite(view, said)
    text = Text.of(said)
    goal: Goal = {}
    claimed: set[int] = set()
    where: dict[str, int] = {}  # the token each setting was read from
    shown_levels(view, text, goal, claimed, where)  # before a looser name: "clean" for PURIFIED
    found = owner_words(view, text, counted_times(text, value_matches(view, text)))
    matches, naming = switch_named_values(view, text, found)
    claimed.update(naming)  # "the beep as the click": the sound, no CLICK switch
    for match in matches:
        if match.var in goal or any(k in claimed for k in range(match.start, match.end)):
            continue
        if a_number_for_a_name(text, match.start, match.end, match.value):
            continue  # "ten seconds" is no TENS
        goal[match.var] = match.value
        where[match.var] = match.start
        claimed.update(range(match.start, match.end))
    lifted = lift_presets(view, text, goal, where)  # "Movie scene, but thirty percent"
    confirmed_choices(view, goal, where)
    both_values(view, text, matches, goal, claimed, where)
    restated_codes(view, text, goal, claimed)
    pronoun_ones(text, claimed)
    fractions(view, text, goal, claimed, where)
    quantity_values(view, text, goal, claimed, where)
    charted_levels(view, text, goal, claimed, where)  # "a hundred lumens": MEDIUM  100 lm
    coded_rows(view, text, goal, claimed, where)  # "dusk till dawn": its code chart row
    unit_cases(view, text, goal, claimed, where)
    counted = [info for info in view.infos.values() if info.role == "setting"]
    days = any(in_days(info.var) for info in counted)
    listed = not days and any(listed_in_days(info) for info in counted)
    mentions = distinct(in_weeks(text, find_mentions(text.tokens, skip=claimed), days or listed))
    mentions = [m for m in mentions if not per_period(text, m)]  # "three doses a day"
    mentions = time_spans(view, text, mentions, goal, claimed, where)
    mentions = kind_numbers(view, text, mentions, goal, claimed, where)
    mentions = limit_numbers(view, text, mentions, goal, claimed, where)
    counting = assign_mentions(view, text, mentions, goal, claimed, where, outside)
    if listed:  # weeks read as days for a list of days ("28 d") go to that list only
        mentions = weeks_elsewhere(view, text, mentions, goal, claimed, where, outside)
    twin_numbers(view, text, mentions, goal, claimed, where)
    numbered_times(view, text, mentions, goal, claimed, where)
    signed_changes(view, text, goal, where)
    charted_presets(view, said, goal)  # "the TV position": its row of the manual's chart
    if outside is not None:  # a read belief: a number its setting's name stands beside
        kept_outside(view, text, mentions, goal, claimed, where, outside)
        listed_outside(view, text, goal, claimed, where, outside, manual or "")
    kelvin_words(view, text, goal, claimed, where)
    joined_ends(view, text, goal, claimed, where)  # before one end is read as a tie
    halfway_levels(view, text, goal, claimed, where)
    left_to_it(view, text, goal, claimed)
    marked_ends(view, text, goal, claimed, where)
    superlatives(view, text, goal, claimed, where)
    charted_superlatives(view, text, goal, claimed, where)
    named_units(view, text, goal, claimed, where)
    said_units(view, goal)
    zero_settings(view, text, goal, claimed, where)
    switched_off_numbers(view, text, goal, claimed, where)
    off_levels(view, text, goal, claimed)
    switched_off_values(view, text, goal, where)
    no_values(view, text, goal, claimed)
    silenced_sounds(view, text, goal, claimed)
    switches(view, text, goal, claimed, where)
    frozen_readings(view, text, goal, where)
    on_values(view, text, goal, claimed, where)
    self_switching_off(view, text, goal, claimed)
    muted_volume(view, text, goal, claimed)
    place_twins(view, text, goal, where)
    own_switch_states(view, text, goal, where)
    scheduled_states(view, text, goal, where)
    entry_switches(view, goal)
    closing_switches(view, text, goal)
    gated_switches(view, text, goal)
    restore_presets(goal, where, lifted)
    preset_companions(view, text, goal, where, lifted)
    set_by_hand(view, text, goal)
    implied_cases(view, goal, start_known=outside is None)  # (a read belief guesses its start)
    entry_modes(view, goal, start_known=outside is None)
    boil(view, text, goal)
    power_and_running(view, text, goal, counting)
    on_auto_off(view, text, goal)
    opened = (
        {}
        if outside is None
        else open_entries(view, text, mentions, goal, claimed, where, manual or "")
    )
    try:
        _unknown_values(view, text, goal, claimed)
    except GoalParseError as exc:
        if outside is None:
            raise
        outside.append(str(exc))
    return {**_checked(view, goal, outside), **opened}


_KIND_WORDS = frozenset(
    stem(w) for w in ("programme", "program", "mode", "cycle", "menu", "course", "function")
)


def _unknown_values(view: Model, text: Text, goal: Goal, claimed: set[int]) -> None:
    """ "the turbo programme" on a model without TURBO: a value name the model lacks is an
    error, not a silent omission. Only the word right before a programme-kind word counts,
    and only when no value of that kind was found."""
    for k in range(1, len(text.tokens)):
        if text.stems[k] not in _KIND_WORDS or k - 1 in claimed:
            continue
        word = text.word(k - 1)
        if not word.isalpha() or word in STOP_WORDS or word in _ORDINARY:
            continue
        key = text.concepts[k]
        kinds = [
            info
            for info in view.infos.values()
            if isinstance(info.var, DiscreteVariable)
            and info.role == "setting"
            and info.vocab.get(key, 0.0) >= 0.8
        ]
        if not kinds or any(info.name in goal for info in kinds):
            continue
        here = text.stems[k - 1]
        if any(
            text.concepts[k - 1] in info.vocab
            or any(
                len(key) >= 3 and (here.startswith(key) or key.startswith(here))
                for key in info.vocab
            )
            for info in view.infos.values()
        ):
            continue  # "temperature mode", "automatic programme": a setting's own word
        info = kinds[0]
        names = [str(v) for v in info.values]
        close = closest_matches(word, names, limit=1)
        hint = f"; did you mean {close[0]!r}?" if close else ""
        raise GoalParseError(
            text.span(k - 1, k + 1),
            f"{info.name} has no {word!r}; it can be {preview(names, quote=False)}{hint}",
        )


_ORDINARY = frozenset(
    {
        "this",
        "that",
        "my",
        "your",
        "its",
        "their",
        "same",
        "usual",
        "whole",
        "full",
        "any",
        "normal",
        "standard",
        "default",
        "next",
        "other",
        "another",
        "each",
        "every",
        "one",
        "first",
        "second",
        "last",
        "right",
        "correct",
        "wrong",
        "entire",
        "complete",
        "new",
    }
)


def _checked(view: Model, goal: Goal, outside: list[str] | None = None) -> Goal:
    """Normalise every value against its variable (the programme's case for a setting); with
    ``outside``, a value the variable lacks is kept as said and noted."""
    out: Goal = {}
    for name, value in goal.items():
        info = view.infos[name]
        try:
            out[name] = normalise(info.var, value)
        except ValueProblem as exc:
            problem = GoalParseError(str(value), f"not a value of {name}: {exc}")
            if outside is None:
                raise problem from None
            out[name] = value
            if not any(f" {name} can be" in note for note in outside):
                outside.append(str(problem))
    return out
