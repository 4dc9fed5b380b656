"""The package's layers: nothing lower imports anything higher, checked on the source (ast).

llm < model < sim < plan < read < agent < vision < bench < cli (``envs`` beside the cli,
``examples`` with the model).
``apbot.testing`` (the random model generator, brute-force BFS) may use model, sim and plan,
and no product module may import it: test tooling never decides a result. Every import counts,
also one inside a function, since a lazy import is a dependency all the same.
"""

from __future__ import annotations

import ast
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[1] / "src" / "apbot"
ORDER = ("llm", "model", "sim", "plan", "read", "agent", "vision", "bench", "cli")
CLI_MODULES = ("bench", "common", "goal", "llm", "model", "read", "run", "suite", "vision")
SAME_AS = {
    "examples": "model",
    "envs": "cli",
    "cli": "cli",
    "operate": "agent",
    **{f"cli_{name}": "cli" for name in CLI_MODULES},
}
TESTING_MAY_USE = {"model", "sim", "plan", "testing"}


def layer_of(module: str) -> str:
    """The layer of ``apbot.X...`` (or of a file path relative to the package, dotted)."""
    top = module.split(".")[0].removesuffix(".py")
    return SAME_AS.get(top, top)


def imported_modules(source: str) -> list[tuple[int, str]]:
    """(line, module) of every absolute import of ``apbot.*`` in ``source``."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.ImportFrom):
            assert node.level == 0, f"line {node.lineno}: relative import; write apbot.…"
            names = [node.module or ""]
        elif isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        else:
            continue
        found.extend((node.lineno, n) for n in names if n.startswith("apbot."))
    return found


def violations(layer: str, source: str, where: str = "<source>") -> list[str]:
    """Imports in ``source`` (code of ``layer``) that reach a higher layer or the test tooling."""
    found = []
    for line, module in imported_modules(source):
        target = layer_of(module.removeprefix("apbot."))
        if layer == "testing":
            bad = target not in TESTING_MAY_USE
        elif target == "testing":
            bad = True
        else:
            bad = target in ORDER and layer in ORDER and ORDER.index(target) > ORDER.index(layer)
        if bad:
            found.append(f"{where}:{line}: {layer} imports {module} ({target})")
    return found


def test_no_module_imports_a_higher_layer() -> None:
    found = []
    files = sorted(PACKAGE.rglob("*.py"))
    assert len(files) > 50
    for path in files:
        relative = path.relative_to(PACKAGE)
        if relative.parts == ("__init__.py",):
            continue
        layer = layer_of(relative.parts[0])
        assert layer in (*ORDER, "testing"), f"{relative}: in no layer; add it to ORDER/SAME_AS"
        found += violations(layer, path.read_text(encoding="utf-8"), str(relative))
    assert found == [], "\n".join(found)


def test_the_check_catches_an_upward_import() -> None:
    assert violations("model", "def f():\n    from apbot.sim.compiled import State\n") == [
        "<source>:2: model imports apbot.sim.compiled (sim)"
    ]
    assert violations("bench", "import apbot.testing.bfs\n") != []
    assert violations("testing", "from apbot.agent.loop import run_agent\n") != []
    assert violations("plan", "from apbot.model.schema import Step\n") == []
