"""Fuzzing the offline reader: how often it reads a model, refuses with ReaderError, or fails.

    python benchmarks/read_fuzz.py [--cases 200] [--seed 0]

Seven kinds of input, ``--cases`` of each, drawn with a seeded generator: random text, binary
garbage (decoded as Latin-1), truncated manuals, a manual read with another appliance's action
names, shuffled manual lines with junk spliced in, two manuals run together, and short manuals
of counted, ranged and stepped phrases with odd numbers in them ("zero positions", "0 to 0 min
in steps of 0 min"). Every result
must be a model the checker accepts that uses exactly the given action names, or a
``ReaderError`` with a message; anything else is counted as a failure and printed.
"""

from __future__ import annotations

import argparse
import random
import string
import time
from collections import Counter
from collections.abc import Callable

from apbot.bench.suite import load_suite
from apbot.model.validate import check_model
from apbot.read import ReaderError, read_manual

_COUNTS = ("zero", "0", "one", "1", "two", "seven", "12", "99", "eleven", "nineteen", "no", "a")
_AMOUNTS = ("0", "0.5", "1", "1.5", "zero", "ten", "half", "12", "24", "99", "1000", "1,5", "00")
_UNITS = ("min", "minutes", "h", "hours", "s", "°C", "%", "kg", "g", "W", "rpm", "L", "")
_PHRASE_ACTIONS = (
    ["turn_mode_knob_clockwise", "press_start_button", "press_timer_button"],
    ["press_hour_button", "press_min_button", "press_start_button", "press_clock_button"],
    ["press_temp_up_button", "press_temp_down_button", "press_power_button"],
    ["press_1", "press_2", "press_0", "press_start_button", "press_weight_button"],
)
_TEMPLATES = (
    "The MODE knob has {c} positions.",
    "The {K} button has {c} settings:",
    "{a} {u} · {b} {u} · {c} {u}",
    "Set the time from {a} to {b} {u} in steps of {s} {u}.",
    "Each press of {K} adds {s} {u}, up to {b} {u}.",
    "The {K} can be set between {a}{u} and {b}{u}.",
    "The timer goes up to {b} {u}; in the first {c} minutes every minute has its own mark.",
    "Weight ranges from {a} kg to {b} g.",
    "The clock uses the {c}-hour format (AM/PM); press CLOCK to switch to {a}-hour.",
    "Press HOUR and MIN to set {a}:{b}.",
    "{K} can be set only for {N} and {N}.",
    "| Programme | Time ({u}) | Temperature |",
    "| --- | --- | --- |",
    "| {N} | {a}–{b} | {a} |",
    "| {N} | {b} | – |",
    "The delay is {a} to {b} h; hold {K} of the {N} for {s} seconds.",
    "Printed round the knob:",
    "{N} · {N} · {N}",
)


def phrase_manual(rng: random.Random) -> str:
    """A short manual of the reader's counted, ranged and stepped phrases, with odd numbers."""
    lines = ["# Appliance", ""]
    for _ in range(rng.randint(1, 12)):
        line = rng.choice(_TEMPLATES)
        lines.append(
            line.format(
                c=rng.choice(_COUNTS),
                a=rng.choice(_AMOUNTS),
                b=rng.choice(_AMOUNTS),
                s=rng.choice(_AMOUNTS),
                u=rng.choice(_UNITS),
                K=rng.choice(("MODE", "TIMER", "HOUR", "MIN", "TEMP", "WEIGHT", "CLOCK")),
                N=rng.choice(("BAKE", "Grill", "Rice", "Eco", "OFF")),
            )
        )
        if rng.random() < 0.5:  # (else the next line goes on the paragraph or the table)
            lines.append("")
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--cases", type=int, default=200, help="cases of each kind")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    suite = load_suite("bundled")
    manuals = [a.manual for a in suite.appliances]
    actions = [list(a.model.actions) for a in suite.appliances]

    def any_actions() -> list[str]:
        return rng.choice(actions)

    def random_text() -> tuple[str, list[str]]:
        alphabet = string.printable + "▲▼°⏻·–—½✓❄🔒é"
        return "".join(rng.choice(alphabet) for _ in range(rng.randint(0, 3000))), any_actions()

    def garbage() -> tuple[str, list[str]]:
        data = bytes(rng.randrange(256) for _ in range(rng.randint(0, 4000)))
        return data.decode("latin-1"), any_actions()

    def truncated() -> tuple[str, list[str]]:
        i = rng.randrange(len(manuals))
        return manuals[i][: rng.randint(0, len(manuals[i]))], actions[i]

    def other_appliance() -> tuple[str, list[str]]:
        return rng.choice(manuals), any_actions()

    def shuffled() -> tuple[str, list[str]]:
        i = rng.randrange(len(manuals))
        lines = manuals[i].splitlines()
        picked = [rng.choice(lines) for _ in range(rng.randint(1, len(lines)))]
        junk = bytes(rng.randrange(256) for _ in range(rng.randint(1, 300)))
        picked.insert(rng.randrange(len(picked)), junk.decode("utf-8", errors="replace"))
        return "\n".join(picked), actions[i]

    def two_manuals() -> tuple[str, list[str]]:
        return rng.choice(manuals) + "\n\n" + rng.choice(manuals), any_actions()

    def phrases() -> tuple[str, list[str]]:
        return phrase_manual(rng), rng.choice(_PHRASE_ACTIONS)

    kinds: dict[str, Callable[[], tuple[str, list[str]]]] = {
        "random text": random_text,
        "binary garbage": garbage,
        "truncated manual": truncated,
        "another appliance's manual": other_appliance,
        "shuffled lines + junk": shuffled,
        "two manuals together": two_manuals,
        "counted and ranged phrases": phrases,
    }
    print(f"{'kind':<28}{'model':>8}{'ReaderError':>13}{'failures':>10}{'ms/case':>9}")
    total: Counter[str] = Counter()
    for kind, make in kinds.items():
        counts: Counter[str] = Counter()
        started = time.process_time()
        for _ in range(args.cases):
            text, names = make()
            try:
                reading = read_manual(text, names)
            except ReaderError as error:
                counts["error" if str(error).strip() else "failure"] += 1
                continue
            except Exception as error:
                counts["failure"] += 1
                print(f"  {kind}: {type(error).__name__}: {error}")
                continue
            bad = [p for p in check_model(reading.model) if p.severity == "error"]
            if bad or set(reading.model.actions) != set(names):
                counts["failure"] += 1
                print(f"  {kind}: model rejected: {bad[:1]}")
            else:
                counts["model"] += 1
        ms = (time.process_time() - started) * 1000 / args.cases
        total += counts
        print(
            f"{kind:<28}{counts['model']:>8}{counts['error']:>13}{counts['failure']:>10}{ms:>9.1f}"
        )
    print(f"{'all':<28}{total['model']:>8}{total['error']:>13}{total['failure']:>10}")


if __name__ == "__main__":
    main()
