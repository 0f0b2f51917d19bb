"""The hostile sweep's fixture: ``hostile(scenario)`` runs one scenario of the calling module and judges it."""

import pytest

from hostile.harness import check, measure_startup


@pytest.fixture(scope="session")
def tool_startup() -> float:
    """The tool's start-up, which every deadline allows for (measured once)."""
    return measure_startup()


@pytest.fixture
def hostile(request, tool_startup):
    return lambda scenario: check(request.module.__name__, scenario, tool_startup)
