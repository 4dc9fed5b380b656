"""Fuzz the command line: random arguments to check, plan, run and suite show end in a result,
a one-line error or a usage message (exit 0, 1 or 2) — never a traceback, never a hang."""

from __future__ import annotations

import shutil
import tempfile
from pathlib import Path

from hypothesis import event, given
from hypothesis import strategies as st
from typer.testing import CliRunner

from apbot.bench.suite import bundled_suite_dir
from apbot.cli import app
from apbot.examples import example_dir
from tests.fuzz import HOSTILE_TOKENS, fuzz_settings, mutated_text, no_hang

runner = CliRunner()
EXAMPLE = (example_dir() / "washing_machine.yaml").read_text(encoding="utf-8")

MODELS = [
    "kettle_1",
    "dehumidifier_1",
    "microwave_1",
    "washing_machine",
    "microwave_keypad",
    "toaster_oven_dial",
    "nosuch",
    "kettle_11",
    "",
    ".",
    "/",
    "/dev/null",
    "../kettle_1",
    "<file>",
    "<dir>",
    "<appliance>",
]
APPLIANCES = ["kettle_1", "dehumidifier_1", "microwave_1", "air_fryer_2", "kettle_11", "", "x/y"]
GOALS = [
    "power=on",
    "power=off",
    "temperature=80",
    "temperature=81",
    "temperature=1e308",
    "temperature=nan",
    "programme=wool",
    "programme=wol",
    "humidity=45",
    "humidity=-5",
    "cook_time=00:75:00",
    "cook_time=2 h",
    "running=on",
    "keep_warm=on",
    "=",
    "a=",
    "=b",
    "x",
    "power=on=off",
    "🙂=🙂",
]
OPTIONS = ["-g", "--goal", "--json", "--lines", "--method", "--belief", "--seed", "--help"]
tokens = st.one_of(
    st.sampled_from(OPTIONS),
    st.sampled_from(GOALS),
    st.sampled_from(HOSTILE_TOKENS),
    st.text(max_size=12),
)
METHODS = ["apbot", "oracle", "apbot-open-loop", "apbot-no-button-policy", "nosuch", ""]
BELIEFS = ["true", "faulty:0.3", "faulty:1", "faulty:2", "faulty:x", "read", "", "truth"]
NUMBERS = ["0", "1", "-1", "3", "25", "99999999999999999999", "x", "1.5", ""]
INSTRUCTIONS = ["t01", "t03", "t10", "t99", "make tea", "x", "", "Heat the water to 80 degrees"]


def maybe(draw: st.DrawFn, option: str, values: list[str]) -> list[str]:
    return [option, draw(st.sampled_from(values))] if draw(st.booleans()) else []


@st.composite
def well_formed(draw: st.DrawFn) -> list[str]:
    """A command line shaped as the help says, with odd values in every slot."""
    command = draw(st.sampled_from(["check", "plan", "run", "suite show"]))
    model = draw(st.sampled_from(APPLIANCES if command in ("run", "suite show") else MODELS))
    goals = [p for g in draw(st.lists(st.sampled_from(GOALS), max_size=3)) for p in ("-g", g)]
    if command == "check":
        return ["check", model, *goals]
    if command == "plan":
        return ["plan", model, *goals, *(["--json"] if draw(st.booleans()) else [])]
    if command == "run":
        return [
            "run",
            model,
            draw(st.sampled_from(INSTRUCTIONS)),
            *goals,
            *maybe(draw, "--method", METHODS),
            *maybe(draw, "--belief", BELIEFS),
            *maybe(draw, "--seed", NUMBERS),
            *maybe(draw, "--feedback", ["display", "values", "image", "", "Display"]),
        ]
    return ["suite", "show", model, *maybe(draw, "--lines", NUMBERS)]


@st.composite
def argv(draw: st.DrawFn) -> list[str]:
    """Mostly well-formed command lines; some with a random token inserted anywhere."""
    args = draw(well_formed())
    for _ in range(draw(st.integers(min_value=0, max_value=2)) if draw(st.booleans()) else 0):
        at = draw(st.integers(min_value=1, max_value=len(args)))
        args.insert(at, draw(tokens))
    return args


@fuzz_settings(60)
@given(argv(), mutated_text(EXAMPLE))
def test_random_command_lines_end_in_a_result_or_a_clear_error(args: list[str], text: str) -> None:
    with tempfile.TemporaryDirectory() as scratch:
        root = Path(scratch)
        (root / "model.yaml").write_text(text, encoding="utf-8")
        shutil.copytree(bundled_suite_dir() / "kettle_1", root / "kettle_1")
        real = {"<file>": str(root / "model.yaml"), "<dir>": scratch}
        real["<appliance>"] = str(root / "kettle_1")
        args = [real.get(a, a) for a in args]
        with no_hang(f"apbot {' '.join(args)}"):
            result = runner.invoke(app, args)
    event(f"{'suite show' if args[0] == 'suite' else args[0]}: exit {result.exit_code}")
    assert result.exception is None or isinstance(result.exception, SystemExit), (
        args,
        result.exception,
    )
    assert result.exit_code in (0, 1, 2), (args, result.exit_code, result.output)
    assert "Traceback" not in result.output, (args, result.output)
