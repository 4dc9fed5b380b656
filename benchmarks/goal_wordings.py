"""The goal parser on the same orders worded other ways: polite, unpunctuated, lower case.

    python benchmarks/goal_wordings.py [--categories kettle,microwave] [--show WORDING]

People do not type the sentences of our tasks: they ask ("Could you please …?"), speak to a
phone that leaves out commas and full stops, type in lower case or with typographic
apostrophes. The order is the same, so the goal should be. For each task of the chosen
categories (default: the nine development categories; the six held-out ones stay the test) this
rewords the instruction each way, parses it against the true model, and prints the exact goal
accuracy per wording beside the sentence as written. ``--show WORDING`` lists the tasks that
wording loses (instruction, and each setting stored vs parsed).
"""

from __future__ import annotations

import argparse
from collections.abc import Callable

from apbot.bench.goal_eval import GoalScore, evaluate_goals
from apbot.bench.runner import cached_suite
from apbot.bench.suite import READER_DEVELOPMENT_CATEGORIES
from apbot.read.goal import parse_instruction


def _low(text: str) -> str:
    return text[:1].lower() + text[1:]


WORDINGS: dict[str, Callable[[str], str]] = {
    "as written": lambda t: t,
    "Could you please …?": lambda t: f"Could you please {_low(t).rstrip('.!')}?",
    "Can you …": lambda t: f"Can you {_low(t)}",
    "I'd like you to …": lambda t: f"I'd like you to {_low(t)}",
    "Hey, go ahead and …": lambda t: f"Hey, go ahead and {_low(t)}",
    "lower case": str.lower,
    "typographic apostrophes": lambda t: t.replace("'", "\u2019"),
    "no commas or full stop": lambda t: t.rstrip(".!?").replace(",", ""),
}


def score(wording: str, categories: list[str]) -> GoalScore:
    """Exact goal accuracy with every instruction reworded."""
    change = WORDINGS[wording]
    return evaluate_goals(
        cached_suite("bundled"),
        categories=categories,
        parser=lambda model, text, manual: parse_instruction(model, change(text), manual),
    )


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--categories", default=",".join(READER_DEVELOPMENT_CATEGORIES))
    parser.add_argument("--show", default="", choices=["", *WORDINGS], help="list its losses")
    args = parser.parse_args(argv)
    categories = [c for c in args.categories.split(",") if c]
    written = score("as written", categories)
    missed = {(m.appliance, m.task) for m in written.misses}
    print(f"{'wording':<26}{'exact goals':>12}{'lost':>6}  ({written.n} instructions)")
    for wording in WORDINGS:
        result = written if wording == "as written" else score(wording, categories)
        lost = [m for m in result.misses if (m.appliance, m.task) not in missed]
        print(f"{wording:<26}{result.accuracy:>12.3f}{len(lost):>6}")
        if wording == args.show:
            for m in lost:
                parsed = m.parsed or {}
                keys = sorted({*m.expected, *parsed})
                diff = {k: (m.expected.get(k), parsed.get(k)) for k in keys}
                diff = {k: v for k, v in diff.items() if v[0] != v[1]}
                print(f"    {m.appliance} {m.task}: {WORDINGS[wording](m.instruction)!r} {diff}")


if __name__ == "__main__":
    main()
