"""The package's shape: one attempt loop for every front end, options keyed by their fields, a working wheel."""

from __future__ import annotations

import dataclasses
import subprocess
import sys
import zipfile

import pytest
from support import REPO

from relevance_plan.batch.jobs import build_jobs, run_job
from relevance_plan.batch.keys import FINGERPRINT_RULES, config_fingerprint, config_hash
from relevance_plan.generators.padded import GRIPPER_DOMAIN, gripper_problem
from relevance_plan.planning.options import PLAN_OPTION_FIELDS, PlanOptions
from relevance_plan.planning.run import plan_task
from relevance_plan.relevance.selection.prune import Thresholds

# A value other than the default for every option (None where the default is set).
OTHER_VALUES = {
    "planner": "up:pyperplan",
    "planner_config": "astar-blind",
    "timeout": 7.0,
    "memory_limit_mb": 512,
    "thresholds": Thresholds(0.1, 0.3),
    "widen": False,
    "widen_factor": 0.25,
    "first_share": 0.75,
    "scorer": "goal",
    "goal_filter": False,
    "prefer_free": False,
    "economical": False,
    "objective": "drink",
    "activity": "hot",
    "human": "alice",
    "place_kinds": True,
    "seed": 3,
    "validators": ("up",),
    "planner_args": ("--translate-options", "--keep-unimportant-variables"),
    "race": True,
}


def test_every_option_has_a_fingerprint_decision():
    assert set(FINGERPRINT_RULES) == set(PLAN_OPTION_FIELDS)


@pytest.mark.parametrize("name", [n for n, rule in FINGERPRINT_RULES.items() if rule != "method" and n != "model_path"])
def test_changing_an_option_changes_the_job_key(name, coffee_domain_path):
    problem = REPO / "problems" / "coffee-simple.pddl"
    base = PlanOptions(method="relevance")
    changed = dataclasses.replace(base, **{name: OTHER_VALUES[name]})
    before = config_hash(config_fingerprint(base, str(coffee_domain_path), str(problem)))
    after = config_hash(config_fingerprint(changed, str(coffee_domain_path), str(problem)))
    assert before != after


def test_retraining_a_learned_model_at_the_same_path_changes_the_job_key(coffee_domain_path, tmp_path):
    problem = str(REPO / "problems" / "coffee-simple.pddl")
    model = tmp_path / "model.json"
    options = PlanOptions(scorer=f"learned:{model}")

    def key() -> str:
        return config_hash(config_fingerprint(options, str(coffee_domain_path), problem))

    model.write_text('{"threshold": 0.3}')
    first = key()
    assert key() == first  # the same file: the same key
    model.write_text('{"threshold": 0.4}')
    assert key() != first


@pytest.fixture
def hard_gripper(tmp_path):
    """A problem whose first pruning fails at these thresholds (the rooms and grippers are cut)."""
    domain = tmp_path / "domain.pddl"
    domain.write_text(GRIPPER_DOMAIN)
    problem = tmp_path / "p.pddl"
    problem.write_text(gripper_problem(extra=10))
    return domain, problem


@pytest.mark.planner
def test_plan_compare_and_the_up_engine_make_the_same_attempts(hard_gripper, tmp_path):
    from unified_planning.engines import PlanGenerationResultStatus as Status
    from unified_planning.io import PDDLReader
    from unified_planning.shortcuts import OneshotPlanner, get_environment

    from relevance_plan.integrations.up_engine import register_relevance_engine

    domain, problem = hard_gripper
    options = PlanOptions(thresholds=Thresholds(0.95, 0.95), timeout=120)
    planned = plan_task(domain, problem, options)
    assert len(planned.attempts) >= 2, "the first pruning should fail on this problem"
    assert planned.attempts[0].status.value != "solved" and planned.status.value == "solved"
    plan_attempts = [(a.objects_kept, a.outcome.status.value, a.status.value) for a in planned.attempts]

    (job,) = build_jobs([tmp_path], "relevance", (0,), options)
    row = run_job(job)
    import json

    stored = json.loads(row["result_json"])
    assert [(a["objects_kept"], a["planner_status"], a["status"]) for a in stored["attempt_log"]] == plan_attempts
    assert stored["status"] == planned.status.value

    get_environment().credits_stream = None
    register_relevance_engine()
    up_problem = PDDLReader().parse_problem(str(domain), str(problem))
    with OneshotPlanner(name="relevance[fast-downward]", params={"tau_class": 0.95, "tau_element": 0.95}) as planner:
        result = planner.solve(up_problem, timeout=120)
    assert result.status is Status.SOLVED_SATISFICING
    assert int(result.metrics["attempts"]) == len(planned.attempts)
    assert result.metrics["objects_kept_first_attempt"] == str(planned.attempts[0].objects_kept)
    assert result.metrics["objects_kept"] == str(planned.objects_kept)


# --------------------------------------------------------------------------- function lengths


def long_functions(*folders: str) -> list[str]:
    """What ``.ci/function_lengths.py`` (the check ``.ci/run`` makes) reports for ``folders``."""
    done = subprocess.run(
        [sys.executable, str(REPO / ".ci" / "function_lengths.py"), *folders],
        cwd=REPO,
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode in (0, 1), done.stderr
    return done.stdout.splitlines()


def test_no_function_of_the_package_is_over_80_lines():
    offenders = long_functions("relevance_plan")
    assert offenders == [], "functions over 80 lines:\n" + "\n".join(offenders)


def test_no_function_of_the_tests_or_the_benchmarks_is_over_80_lines():
    offenders = long_functions("tests", "benchmarks")
    assert offenders == [], "functions over 80 lines:\n" + "\n".join(offenders)


def test_the_length_check_finds_a_long_function(tmp_path):
    (tmp_path / "long.py").write_text("def long():\n" + "    x = 1\n" * 80 + "\n\ndef short():\n    pass\n")
    assert long_functions(str(tmp_path)) == [f"{tmp_path / 'long.py'}:1 long (81 lines)"]


# --------------------------------------------------------------------------- a regular install


def test_the_wheel_ships_the_worlds_and_no_stray_top_level_packages(wheel):
    names = zipfile.ZipFile(wheel).namelist()
    top = {name.split("/")[0] for name in names}
    assert {t for t in top if not t.endswith(".dist-info")} == {"relevance_plan"}
    for needed in (
        "relevance_plan/data/domains/coffee/domain.pddl",
        "relevance_plan/data/domains/coffee/relevance.yaml",
        "relevance_plan/data/domains/cereal/domain.pddl",
        "relevance_plan/data/problems/coffee-hard.pddl",
        "relevance_plan/generators/generate.py",
    ):
        assert needed in names


@pytest.mark.planner
def test_the_installed_tool_runs_without_the_source_tree(installed_elsewhere):
    work, env = installed_elsewhere

    def tool(*arguments):
        return subprocess.run(
            [sys.executable, "-m", "relevance_plan", *map(str, arguments)],
            cwd=work,
            env=env,
            capture_output=True,
            text=True,
            timeout=300,
        )

    generated = tool("generate", "coffee", "--count", "1", "--seed", "1", "--out", work / "suite")
    assert generated.returncode == 0, generated.stderr
    (problem,) = (work / "suite").glob("coffee-*.pddl")
    planned = tool("plan", work / "suite" / "domain.pddl", problem, "--json", "--plan-file", work / "plan.txt")
    assert planned.returncode == 0, planned.stderr
    assert '"valid": true' in planned.stdout and (work / "plan.txt").is_file()
    scored = tool("score", work / "suite" / "domain.pddl", problem)
    assert "scorer: model" in scored.stdout  # the shipped knowledge model was found
    demo = tool("demo", "--tiny", "--quiet", "--workdir", work / "demo")
    assert demo.returncode == 0, demo.stderr
    assert "coffee-simple" in demo.stdout


def _imports(path) -> set[str]:
    """The modules of the package a file imports: at its top, under TYPE_CHECKING, or inside functions."""
    import ast

    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("relevance_plan"):
            found |= {f"{node.module}.{alias.name}" for alias in node.names} | {node.module}
        elif isinstance(node, ast.Import):
            found |= {alias.name for alias in node.names if alias.name.startswith("relevance_plan")}
    return found


def test_no_module_imports_one_that_imports_it_back():
    package = REPO / "relevance_plan"
    modules = {}
    for path in package.rglob("*.py"):
        name = ".".join(path.relative_to(REPO).with_suffix("").parts).removesuffix(".__init__")
        modules[name] = path
    graph = {
        name: {target for target in _imports(path) if target in modules and target != name}
        for name, path in modules.items()
    }
    # every module that reaches itself again along the imports
    cycles = []
    for start in graph:
        seen, todo = set(), list(graph[start])
        while todo:
            name = todo.pop()
            if name not in seen:
                seen.add(name)
                todo += graph[name]
        if start in seen:
            cycles.append(start)
    assert not cycles


# --------------------------------------------------------------------------- classes and signatures


def _definitions(kinds):
    """(path, node) of every definition of ``kinds`` in the package."""
    import ast

    for path in sorted((REPO / "relevance_plan").rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, kinds):
                yield path.relative_to(REPO), node


def test_no_class_has_more_than_20_methods():
    import ast

    big = [
        f"{path}: {node.name} ({count} methods)"
        for path, node in _definitions(ast.ClassDef)
        if (count := sum(isinstance(item, (ast.FunctionDef, ast.AsyncFunctionDef)) for item in node.body)) > 20
    ]
    assert not big


def test_no_public_class_name_is_defined_twice():
    import ast
    from collections import defaultdict

    where = defaultdict(list)
    for path, node in _definitions(ast.ClassDef):
        if not node.name.startswith("_"):
            where[node.name].append(str(path))
    assert {name: paths for name, paths in where.items() if len(paths) > 1} == {}


def test_no_function_takes_more_than_8_parameters():
    import ast

    def count(arguments: ast.arguments) -> int:
        names = [a.arg for a in (*arguments.posonlyargs, *arguments.args, *arguments.kwonlyargs)]
        return len([n for n in names if n not in ("self", "cls")]) + bool(arguments.vararg) + bool(arguments.kwarg)

    found = list(_definitions((ast.FunctionDef, ast.AsyncFunctionDef)))
    wide = [f"{path}: {node.name} ({count(node.args)})" for path, node in found if count(node.args) > 8]
    assert found and not wide


def test_no_folder_of_the_package_holds_more_than_14_modules():
    folders = {path.parent for path in (REPO / "relevance_plan").rglob("*.py")}
    crowded = {
        str(folder.relative_to(REPO)): count
        for folder in folders
        if (count := sum(1 for module in folder.glob("*.py") if module.name != "__init__.py")) > 14
    }
    assert crowded == {}
