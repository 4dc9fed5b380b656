"""``apbot run``: one instruction live, printing every macro action, press, check and
repair as the agent makes them."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Any

import typer

from apbot.cli_common import bundled_appliance, console, fail, feedback_mode
from apbot.cli_llm import CacheOption, LLMOption
from apbot.cli_llm import setup as llm_setup
from apbot.model.goal import GoalError

if TYPE_CHECKING:
    from apbot.agent.environment import FeedbackMode
    from apbot.agent.episode import TraceEvent
    from apbot.bench.suite import SuiteAppliance, Task


def run_command(
    appliance: Annotated[str, typer.Argument(help="A bundled appliance id.")],
    instruction: Annotated[
        str,
        typer.Argument(help="What to do, in any words — or a task id (t01…) of the appliance."),
    ],
    goal: Annotated[
        list[str] | None,
        typer.Option(
            "--goal",
            "-g",
            help="Give the goal as NAME=VALUE (repeatable) instead of reading it from the "
            "instruction; names and values are the true appliance's.",
        ),
    ] = None,
    method: Annotated[str, typer.Option(help="The method to run.")] = "apbot",
    belief: Annotated[
        str | None,
        typer.Option(
            help="The model the method works from: read (from the manual, by the LLM with "
            "--llm, else offline; the default), true (the default with -g, whose names are the "
            "truth's), faulty:RATE or faulty:RATE:KIND,..."
        ),
    ] = None,
    seed: Annotated[int, typer.Option(help="Seed for fault injection.")] = 0,
    feedback: Annotated[
        str, typer.Option(help="What the method perceives: display, values or image.")
    ] = "display",
    show_exploration: Annotated[
        bool, typer.Option(help="Print every exploring press, not only a count.")
    ] = False,
    parse_goal_text: Annotated[
        bool, typer.Option("--parse-goal", hidden=True, help="The default now; ignored.")
    ] = False,
    llm: LLMOption = None,
    cache: CacheOption = None,
) -> None:
    """Run one instruction live: every macro action, press, display, check and repair.

    The goal is read from the instruction against the method's belief (the offline goal
    parser) unless -g gives it. A task of the appliance (its id or its instruction) is judged
    on the true simulator against the task's stored goal; any other instruction has no stored
    goal, so the verdict is the agent's own.
    """
    from apbot.agent.registry import get_method
    from apbot.bench.beliefs import BeliefError
    from apbot.bench.runner import run_task
    from apbot.bench.suite import Task
    from apbot.cli_llm import describe
    from apbot.model.goal import parse_goal, split_assignments

    try:  # before any work: a free instruction's run has no other place that would say it
        get_method(method)
    except KeyError as exc:
        raise fail(str(exc.args[0]), 2) from None
    config = llm_setup(llm, cache)
    found = bundled_appliance(appliance, 2)
    task = _task_for(found, instruction)
    mode = feedback_mode(feedback)
    belief = belief if belief is not None else ("true" if goal else "read")
    if belief.strip() == "read" or not goal:
        console.print(f"[dim]{describe(config)}[/dim]")
    if goal:
        try:
            goal_values = split_assignments(goal)
            parse_goal(found.model, goal_values)
        except GoalError as exc:
            raise fail(str(exc), 2) from None
        # a live task is not a line of tasks.yaml: the instruction is the user's own words
        # (any length), and the goal was just checked against the appliance
        task = Task.model_construct(
            id=task.id if task else "live",
            instruction=task.instruction if task else instruction,
            goal=goal_values,
            optimal_steps=None,
        )
    printer = _LivePrinter(show_exploration)
    if task is None:
        _run_free(found, instruction, method, belief, seed, mode, printer)
        return
    console.print(f"[bold]{found.id}[/bold] · {task.instruction}")
    console.print(f"stored goal: {', '.join(f'{k}={v}' for k, v in task.goal.items())}")
    try:
        record = run_task(
            found,
            task,
            method,
            belief,
            seed,
            observer=printer,
            feedback=mode,
            goal="given" if goal else "read",
        )
    except BeliefError as exc:
        raise fail(str(exc), 2) from None
    except (KeyError, ValueError) as exc:
        raise fail(str(exc.args[0] if isinstance(exc, KeyError) else exc), 2) from None
    printer.flush()
    if record.parsed_goal is not None:
        console.print(f"read goal: {', '.join(f'{k}={v}' for k, v in record.parsed_goal.items())}")
    verdict = "[green]success[/green]" if record.success else "[red]failure[/red]"
    console.print(
        f"{verdict}: {record.reasoning_steps} reasoning steps, "
        f"{record.execution_steps} actions (optimal {record.optimal_steps}), "
        f"SPL {record.spl:.2f}"
    )
    if record.failure:
        console.print(f"[red]{record.failure}[/red]")
    raise typer.Exit(0 if record.success else 1)


def _run_free(
    found: SuiteAppliance,
    instruction: str,
    method: str,
    belief: str,
    seed: int,
    mode: FeedbackMode,
    printer: _LivePrinter,
) -> None:
    """An instruction that is none of the tasks: read its goal against the belief and run it;
    there is no stored goal, so the agent's verdict is all there is (said so)."""
    from apbot.agent.environment import SimulatorEnvironment
    from apbot.bench.beliefs import BeliefError, belief_model
    from apbot.operate import operate

    try:
        model, _faults = belief_model(found, belief, seed)
    except (BeliefError, ValueError) as exc:
        raise fail(str(exc), 2) from None
    if mode == "image":  # the rendered panel, grounded from its photo, as `bench` does
        from apbot.bench.runner import image_environment

        try:
            env: Any = image_environment(found, found.model.actions, seed)
        except ImportError as exc:
            raise fail(f"--feedback image needs the vision extra ({exc})", 2) from None
    else:
        env = SimulatorEnvironment(found.model, mode)
    console.print(f"[bold]{found.id}[/bold] · {instruction}")
    done = operate(
        found.manual,
        list(env.actions),
        instruction,
        env,
        method=method,
        observer=printer,
        model=model,
    )
    printer.flush()
    if done.goal_error:
        raise fail(f"cannot read the instruction: {done.goal_error}", 2)
    console.print(f"read goal: {', '.join(f'{k}={v}' for k, v in done.goal.items())}")
    verdict = "[green]done[/green]" if done.success else "[red]not done[/red]"
    console.print(
        f"{verdict} (the agent's verdict: a free instruction has no stored goal to judge by): "
        f"{done.episode.reasoning_steps} reasoning steps, {env.steps} actions"
    )
    if done.episode.failure:
        console.print(f"[red]{done.episode.failure}[/red]")
    raise typer.Exit(0 if done.success else 1)


def _task_for(appliance: SuiteAppliance, text: str) -> Task | None:
    """The appliance's task with this id or instruction (or one very close to it)."""
    import difflib

    wanted = text.strip().casefold()
    for task in appliance.tasks:
        if wanted in (task.id, task.instruction.strip().casefold()):
            return task
    scores = [
        (difflib.SequenceMatcher(None, wanted, t.instruction.casefold()).ratio(), t)
        for t in appliance.tasks
    ]
    best = max(scores, key=lambda pair: pair[0], default=None)
    return best[1] if best is not None and best[0] >= 0.85 else None


class _LivePrinter:
    """Prints trace events as the agent produces them; runs of exploration are summarised."""

    def __init__(self, show_exploration: bool) -> None:
        self.show_exploration = show_exploration
        self.exploring = 0

    def flush(self) -> None:
        if self.exploring:
            console.print(f"    [dim]… explored with {self.exploring} presses[/dim]")
            self.exploring = 0

    def __call__(self, event: TraceEvent) -> None:
        if event.kind == "action" and event.exploring and not self.show_exploration:
            self.exploring += 1
            return
        self.flush()
        if event.kind == "macro":
            target = ", ".join(f"{k}={v}" for k, v in event.expected.items())
            console.print(f"[bold]{event.step:>2}. {event.text}[/bold] [dim]→ {target}[/dim]")
        elif event.kind == "action":
            mark = "[yellow]explore[/yellow] " if event.exploring else ""
            refused = " [red](refused)[/red]" if not event.accepted else ""
            console.print(
                f"    {mark}{event.action}: [cyan]{event.display or '(dark)'}[/cyan]{refused}"
            )
        elif event.kind == "check":
            if event.text == "ok":
                console.print("    [green]✓ as expected[/green]")
            else:
                seen = ", ".join(f"{k}={v}" for k, v in event.values.items())
                console.print(f"    [red]✗ mismatch[/red] {seen}")
        elif event.kind in ("explore", "repair"):
            colour = "magenta" if event.kind == "repair" else "yellow"
            console.print(f"    [{colour}]{event.kind}: {event.text}[/{colour}]")
        elif event.kind == "stop":
            console.print(f"[dim]stop: {event.text}[/dim]")
