"""The ApBot closed loop: plan on the belief, execute one macro action, check, repair, re-plan.

After every macro action the agent compares what the appliance showed after each press with
what its belief predicted. On a mismatch it explores — repeats the step's key until a shown
value repeats (and the opposite key after an end) — infers the variable's true definition from
that walk by code, writes it into the belief and plans again from the observed state. A goal
value the belief does not even contain is treated the same way: the agent brings the setting
up, explores it, and learns whether the value exists. Faults in procedures are probed for
(``apbot.agent.procedures``).

Counting follows the paper: a reasoning step is one macro action (exploration excluded); every
physical action, exploration included, is an execution step.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from apbot.agent.budget import Budget
from apbot.agent.claims import starts_appliance
from apbot.agent.discovery import VariableFinder
from apbot.agent.displays import DisplayLearner
from apbot.agent.environment import Environment
from apbot.agent.episode import Episode, TaskContext
from apbot.agent.executed import GiveUp
from apbot.agent.explorer import Explorer
from apbot.agent.greedy import GreedyExecutor
from apbot.agent.guards import GuardLearner
from apbot.agent.guessed_choice import forget_guessed_choices
from apbot.agent.locks import is_lock_setting
from apbot.agent.loop_goal import GoalPlanning
from apbot.agent.merged import ProcedureSplitter
from apbot.agent.planning import BeliefPlans
from apbot.agent.procedures import ProcedureRepairer
from apbot.agent.quantities import summary
from apbot.agent.said_entries import said_entries
from apbot.agent.session import MISSING, AgentConfig, Executed, Session, Stop
from apbot.plan.plan import MacroAction, Unreachable

__all__ = ["AgentConfig", "run_agent"]


class ClosedLoop(GoalPlanning):
    """One episode of the agent: plans, executes, checks and dispatches repairs to its
    collaborators (the explorer, the procedure repairer, the greedy executor), which share one
    :class:`Session`. The check after each macro action, and the repairs it dispatches, are
    :class:`apbot.agent.checking.Checks`; the claim at the end,
    :class:`apbot.agent.claims.Claims`; the goal and the plan to it,
    :class:`apbot.agent.loop_goal.GoalPlanning`."""

    def __init__(self, config: AgentConfig, context: TaskContext, env: Environment) -> None:
        said: dict[str, Any] = {}
        if config.closed_loop and context.goal_read:
            # quantities the user said that the goal holds nowhere: look for them on the panel
            said = said_entries(context.belief, context.instruction, context.goal, context.manual)
            context = replace(context, goal={**context.goal, **said}) if said else context
        self.session = Session(config, context, env, Budget())
        if said:
            entries = ", ".join(f"{n}={v!r}" for n, v in said.items())
            self.session.episode.log("explore", f"said, held by no goal setting: {entries}")
        self.displays = DisplayLearner(self.session)
        self.explorer = Explorer(self.session, self.displays)
        self.guards = GuardLearner(self.session)
        self.procedures = ProcedureRepairer(self.session, self.guards)
        self.movers = self.procedures.movers
        self.side_effects = self.procedures.side_effects
        self.finder = VariableFinder(self.session, self.guards)
        self.splitter = ProcedureSplitter(self.session)
        self.greedy = GreedyExecutor(self.session)
        self.config = config
        self.context = context
        self.missing: dict[str, Any] = {}  # goal settings the belief lacks and has not found
        self.said = said
        self.unfound: dict[str, Any] = {}  # ... and looked for twice: the rest is set without
        self.set_aside: dict[str, str] = {}  # goal settings given up on: why (the rest is set)
        self.finding = 1  # the finder's attempt: once at the start, once with the rest set
        self.plans = BeliefPlans(self.session, config)
        self.pending: list[MacroAction] = []  # the rest of the plan, while it holds
        self.after_rest: set[str] = set()  # goal values a walk lacked: looked for again last
        self.values_before: dict[str, Any] = {}  # the belief before the current macro action

    def run(self) -> Episode:
        episode = self.session.episode
        try:
            self.session.start()
            if not self.config.closed_loop:
                self.open_loop()
            forget_guessed_choices(self.session, self.goal()[0])
            stalled = 0
            while True:
                mark = (episode.reasoning_steps, episode.execution_steps, len(episode.repairs))
                try:
                    self.reasoning_step()
                except GiveUp as stuck:
                    if not self.set_aside_for_the_rest(stuck):
                        raise
                progress = mark != (
                    episode.reasoning_steps,
                    episode.execution_steps,
                    len(episode.repairs),
                )
                stalled = 0 if progress else stalled + 1
                if stalled >= 2:
                    raise Stop("no progress: the belief offers no way to bring the goal closer")
        except Stop as stop:
            episode.claimed_success = stop.success
            episode.failure = "" if stop.success else stop.reason
            episode.log("stop", stop.reason)
        except Unreachable as exc:  # a repair left the belief with no plan: a declared failure
            episode.failure = f"no plan on the belief model: {exc.reason}"
            episode.log("stop", episode.failure)
        episode.belief = self.session.belief.model
        return episode

    def open_loop(self) -> None:
        """Plan once on the belief and press everything: no checks, no repairs."""
        inside, outside = self.goal()
        if outside:
            raise Stop(_outside_text(outside))
        for macro in self.make_plan(inside).macro_actions:
            self.start_macro(macro)
            self.execute(macro)
        holds = all(self.session.belief.value(n) == v for n, v in inside.items())
        raise Stop(
            "plan executed" if holds else "plan executed, but the belief no longer holds the goal",
            success=holds,
        )

    def reasoning_step(self) -> None:
        inside, outside = self.goal()
        if self.missing:  # set the rest first (the missing setting may need its programme),
            inside = {
                n: v for n, v in inside.items() if not starts_appliance(n)
            }  # but do not start
        for name in outside:
            if name in self.session.explored:
                if self._again_after_the_rest(name, inside):
                    continue
                raise Stop(
                    _outside_text({name: outside[name]}) + " (explored: "
                    f"{summary(self.session.domain_values(name))})"
                )
        if not self.pending:
            target = dict(inside)
            for name in outside:
                if name in self.after_rest and self._rest_pending(inside):
                    target = {n: v for n, v in target.items() if not starts_appliance(n)}
                    continue  # set the rest first (its programme), then walk this one again
                proxy = self.proxy(name, inside)
                if proxy is not MISSING:
                    target[name] = proxy
                elif name not in self.session.explored:
                    # the setting is to be looked for in its programme: starting first would
                    # lock it out
                    target = {n: v for n, v in target.items() if not starts_appliance(n)}
            found = self.make_plan(target)
            if not found.macro_actions:
                if self.missing:
                    self.finding += 1  # the rest is set: look for the missing settings again
                    return
                if outside:
                    pressed = self.session.episode.execution_steps
                    self.explore_outside(outside)
                    if self.session.episode.execution_steps == pressed:  # no value to go to first
                        any(self.inspect(name) for name in outside)
                    return
                if any(self.session.belief.value(n) != v for n, v in inside.items()):
                    raise Stop("the rest of the goal cannot be reached on the belief model")
                if self.settle_or_claim(inside):
                    return  # looked at the display (or settled what it showed): plan again
            self.pending = list(found.macro_actions)
            self.session.episode.log("plan", " → ".join(m.feature for m in found.macro_actions))
        if any(starts_appliance(n) or is_lock_setting(n) for n in self.pending[0].expect):
            # once it runs (or the lock is on), most keys are locked out: see what is
            # unconfirmed first
            settings = {n for n in inside if not (starts_appliance(n) or is_lock_setting(n))}
            unseen = self.session.unconfirmed(settings)
            # a setting the display cannot confirm (no look left) does not excuse leaving one
            # it never showed unlooked at before the start locks the panel
            if (unseen and self._look(unseen)) or self._glance(settings - set(unseen)):
                self.pending.clear()
                return
        macro = self.pending.pop(0)
        self.start_macro(macro)
        executed = self.execute(macro)
        if not self.check(macro, executed):
            self.pending.clear()  # the belief changed: plan again from what was observed
        elif self.take_marked():
            self.pending.clear()  # a choice only highlighted was looked at: plan again

    def set_aside_for_the_rest(self, stuck: GiveUp) -> bool:
        """Goal settings that keep going wrong are given up on, not the whole goal: the rest is
        still set (the run then ends with ``stuck``'s reason, never a claim). Otherwise which
        settings end up set would depend on whether the stuck one came first or last in the
        plan, an order that ties between equal-cost plans decide. False (stop now): the
        setting is no goal setting, was set aside already, or nothing else is left to set."""
        names = stuck.names
        goal = self.context.goal
        if not names or not names <= set(goal) or names & set(self.set_aside):
            return False
        for name in names:
            self.set_aside[name] = stuck.reason
        inside, outside = self.goal()
        rest = [n for n, v in inside.items() if self.session.belief.value(n) != v]
        if not rest and not outside:
            return False
        self.pending.clear()
        self.session.episode.log(
            "explore", f"{stuck.reason}: set aside ({', '.join(sorted(names))}), setting the rest"
        )
        return True

    def _again_after_the_rest(self, name: str, inside: dict[str, Any]) -> bool:
        """A goal value missing from what a walk showed, while the rest of the goal (a
        programme) is still to be set: the value may exist there. Walk it again once the rest
        holds (once per setting)."""
        pending = [n for n, v in inside.items() if self.session.belief.value(n) != v]
        if not [n for n in pending if not starts_appliance(n)]:
            return False
        if not self.session.budget.once("inspect", f"again:{name}"):
            return False
        self.session.explored.discard(name)
        self.after_rest.add(name)
        return True

    def _rest_pending(self, inside: dict[str, Any]) -> bool:
        """A goal setting other than a start is not yet what the goal asks."""
        return any(
            self.session.belief.value(n) != v for n, v in inside.items() if not starts_appliance(n)
        )

    def explore(self, name: str, last: Executed, history: list[Any] | None = None) -> None:
        """Walk ``name`` with ``last``'s key; a walk stuck on one value looks for the key
        that walks it, filed under another procedure."""
        self.explorer.explore(name, last, history)
        if self.explorer.stuck is not None:
            self.movers.find_sibling(*self.explorer.stuck)

    def start_macro(self, macro: MacroAction) -> None:
        self.session.count_reasoning_step()
        self.session.episode.log("macro", macro.feature, expected=dict(macro.expect))
        self.values_before = self.session.belief.values()

    def execute(self, macro: MacroAction) -> list[Executed]:
        if not self.config.button_policy:
            return self.greedy.execute_greedily(macro)
        executed = []
        actions = self.session.belief.model.actions
        for action, after in zip(macro.actions, (*macro.actions[1:], None), strict=True):
            # a digit the plan follows with another is on its way to the value: the entry
            # is judged at its last digit
            more = after is not None and getattr(actions.get(after.name), "digit", None) is not None
            executed.append(self.session.press(action, typing_on=more))
            if self.config.closed_loop and executed[-1].surprising:
                break  # not as predicted: pressing on would only make things worse
        return executed


def _outside_text(outside: dict[str, Any]) -> str:
    return "; ".join(
        f"{name}={raw!r} is not a value the model knows" for name, raw in outside.items()
    )


def run_agent(config: AgentConfig, context: TaskContext, env: Environment) -> Episode:
    """One episode of ApBot (or an ablation of it) on ``env``."""
    return ClosedLoop(config, context, env).run()
