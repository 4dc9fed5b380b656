"""One client for any OpenAI-compatible server: structured answers, cache, retries, budget.

>>> from apbot.llm import parse_spec
>>> parse_spec("openai:gpt-4o").model
'gpt-4o'
"""

from apbot.llm.client import Completion, LLMClient, LLMError
from apbot.llm.config import LLMConfig, LLMConfigError, configure_env, from_env, parse_spec
from apbot.llm.limits import Budget, BudgetSpent
from apbot.llm.structured import Answer, StructuredError, ask
from apbot.llm.usage import Usage

__all__ = [
    "Answer",
    "Budget",
    "BudgetSpent",
    "Completion",
    "LLMClient",
    "LLMConfig",
    "LLMConfigError",
    "LLMError",
    "StructuredError",
    "Usage",
    "ask",
    "configure_env",
    "from_env",
    "parse_spec",
]
