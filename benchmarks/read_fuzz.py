"""Fuzzing the offline reader: how often it reads a model, refuses with ReaderError, or fails.

    python benchmarks/read_fuzz.py [--cases 200] [--seed 0]

Six kinds of input, ``--cases`` of each, drawn with a seeded generator: random text, binary
garbage (decoded as Latin-1), truncated manuals, a manual read with another appliance's action
names, shuffled manual lines with junk spliced in, and two manuals run together. Every result
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

    kinds: dict[str, Callable[[], tuple[str, list[str]]]] = {
        "random text": random_text,
        "binary garbage": garbage,
        "truncated manual": truncated,
        "another appliance's manual": other_appliance,
        "shuffled lines + junk": shuffled,
        "two manuals together": two_manuals,
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
