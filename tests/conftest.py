import os
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parent.parent
DOMAINS = REPO / "domains"
PROBLEMS = REPO / "problems"


def pytest_addoption(parser):
    parser.addoption("--runslow", action="store_true", default=False, help="run tests marked slow")


def pytest_collection_modifyitems(config, items):
    if config.getoption("--runslow") or os.environ.get("RELEVANCE_PLAN_SLOW") == "1":
        return
    skip = pytest.mark.skip(reason="slow: run with --runslow")
    for item in items:
        if "slow" in item.keywords:
            item.add_marker(skip)


@pytest.fixture
def coffee_domain_path():
    return DOMAINS / "coffee" / "domain.pddl"


@pytest.fixture
def cereal_domain_path():
    return DOMAINS / "cereal" / "domain.pddl"
