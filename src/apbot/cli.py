"""``apbot`` on the command line: check models, plan, drive a simulator, inspect the suite.

The commands are thin: each calls library functions that the tests use too. They live in
one module per group (``cli_model``, ``cli_suite``, ``cli_goal``,
``cli_bench``, ``cli_run``, ``cli_read``, ``cli_vision``, ``cli_llm``); this module only builds
the app and registers them, in the order ``apbot --help`` lists them.
"""

from __future__ import annotations

import typer

from apbot.cli_bench import bench, report_command
from apbot.cli_goal import eval_goals, goal_command
from apbot.cli_llm import llm_app
from apbot.cli_model import check, plan_command, sim
from apbot.cli_read import eval_reader, read_command
from apbot.cli_run import run_command
from apbot.cli_suite import suite_app
from apbot.cli_vision import ground_command, render_command

app = typer.Typer(
    add_completion=False,
    no_args_is_help=True,
    help="Operate home appliances by reading their manuals.",
)
app.add_typer(suite_app, name="suite")
app.add_typer(llm_app, name="llm")
app.command()(check)
app.command("plan")(plan_command)
app.command()(sim)
app.command("goal")(goal_command)
app.command("eval-goals")(eval_goals)
app.command()(bench)
app.command("report")(report_command)
app.command("run")(run_command)
app.command("read")(read_command)
app.command("eval-reader")(eval_reader)
app.command("render")(render_command)
app.command("ground")(ground_command)


def main() -> None:
    """Console entry point."""
    app()


if __name__ == "__main__":
    main()
