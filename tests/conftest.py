"""Fixtures shared by the test modules; plain helpers are in ``support.py``."""

import os
import subprocess
import sys

import pytest
from support import COFFEE_DOMAIN, DOMAINS, REPO

# The benchmarks' shared module and scripts are run from their folder; the tests that import them find
# them here (the one place that puts benchmarks/ on the path).
sys.path.insert(0, str(REPO / "benchmarks"))


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
    return COFFEE_DOMAIN


@pytest.fixture
def cereal_domain_path():
    return DOMAINS / "cereal" / "domain.pddl"


@pytest.fixture
def coffee_extra_plates():
    """The extra plates of ``coffee_files``' problem; a module overrides this fixture to change it."""
    return 6


@pytest.fixture
def coffee_files(tmp_path, coffee_domain_path, coffee_extra_plates):
    """The shipped coffee domain and a tiny coffee problem in ``tmp_path / "coffee.pddl"``."""
    from support import coffee_problem

    problem = tmp_path / "coffee.pddl"
    problem.write_text(coffee_problem(extra_plates=coffee_extra_plates))
    return coffee_domain_path, problem


@pytest.fixture
def copied_coffee_files(tmp_path):
    """A copy of the coffee domain (a test may change it) and a problem with two extra plates, in ``tmp_path``."""
    from support import coffee_problem

    domain = tmp_path / "domain.pddl"
    domain.write_bytes(COFFEE_DOMAIN.read_bytes())
    problem = tmp_path / "problem.pddl"
    problem.write_text(coffee_problem(extra_plates=2))
    return domain, problem


@pytest.fixture(scope="session")
def wheel(tmp_path_factory):
    """A wheel of the checkout, as ``pip wheel .`` makes it for a regular install."""
    out = tmp_path_factory.mktemp("wheel")
    subprocess.run(
        [sys.executable, "-m", "pip", "wheel", "--no-deps", "-q", "-w", str(out), str(REPO)],
        check=True,
        capture_output=True,
    )
    (found,) = out.glob("relevance_plan-*.whl")
    return found


@pytest.fixture
def installed_elsewhere(wheel, tmp_path):
    """(a folder outside the clone, the environment that runs the wheel installed into a folder of its own)."""
    site = tmp_path / "site"
    subprocess.run(
        [sys.executable, "-m", "pip", "install", "--no-deps", "-q", "--target", str(site), str(wheel)],
        check=True,
        capture_output=True,
    )
    work = tmp_path / "elsewhere"
    work.mkdir()
    env = {**os.environ, "PYTHONPATH": str(site)}
    where = subprocess.run(
        [sys.executable, "-c", "import relevance_plan; print(relevance_plan.__file__)"],
        cwd=work,
        env=env,
        capture_output=True,
        text=True,
    )
    assert where.stdout.startswith(str(site)), "the installed package, not the clone's"
    return work, env
