"""The README and docs/ say true things: commands that exist, links that resolve, the live exit table.

Nothing here starts a planner: the commands are checked by name and by ``--help``, not run.
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parent.parent
README = REPO / "README.md"
DOCUMENTS = [README, *sorted((REPO / "docs").glob("*.md"))]
TOOL = [sys.executable, "-m", "relevance_plan"]


def tool_output(*arguments: str) -> str:
    done = subprocess.run([*TOOL, *arguments], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    return done.stdout


def code_blocks(text: str, language: str = "bash") -> list[str]:
    return re.findall(rf"```{language}\n(.*?)```", text, flags=re.DOTALL)


def shell_lines(text: str) -> list[str]:
    """The commands of the bash blocks, continuation lines joined, comments dropped."""
    joined = "\n".join(code_blocks(text)).replace("\\\n", " ")
    return [line.split("  #")[0].strip() for line in joined.splitlines() if line.strip()]


@pytest.fixture(scope="module")
def commands() -> set[str]:
    listing = tool_output("--help").split("Commands:")[1]
    return {line.split()[0] for line in listing.splitlines() if line.strip()}


# --------------------------------------------------------------------------- set-up and first look


def test_the_two_set_up_commands_are_there_and_their_parts_exist(commands):
    text = README.read_text()
    assert "pip install -e . && relevance-plan demo\n" in text
    assert "pip install -e '.[test]' && python -m pytest -q\n" in text
    project = (REPO / "pyproject.toml").read_text()
    assert 'relevance-plan = "relevance_plan.cli.launch:main"' in project
    assert re.search(r"^test = \[", project, flags=re.MULTILINE)
    assert '"slow:' in project and '"planner:' in project  # the markers the README names
    assert "--runslow" in (REPO / "tests" / "conftest.py").read_text()
    assert "demo" in commands and "--tiny" in tool_output("demo", "--help")


def test_every_relevance_plan_command_in_the_docs_exists_and_its_shipped_files_too(commands):
    for document in DOCUMENTS:
        for line in shell_lines(document.read_text()):
            words = line.split()
            if words[0] == "relevance-plan":
                assert words[1] in commands, f"{document.name}: {line}"
            for word in words:
                if word.startswith(("domains/", "problems/", "examples/", "benchmarks/")):
                    assert (REPO / word).exists(), f"{document.name}: {word}"


def test_every_script_the_docs_name_exists():
    for document in DOCUMENTS:
        for script in re.findall(r"python ((?:benchmarks|examples)/[\w/-]+\.py)", document.read_text()):
            assert (REPO / script).is_file(), f"{document.name}: {script}"


def test_every_package_path_the_docs_name_exists():
    layers = "pddl|relevance|planning|session|batch|cli|integrations|generators|data"
    for document in DOCUMENTS:
        for path in re.findall(rf"`((?:{layers})/[\w/]*(?:\.py)?)`", document.read_text()):
            assert (REPO / "relevance_plan" / path).exists(), f"{document.name}: {path}"


BENCHMARK_SCRIPTS = sorted(
    path.name for path in (REPO / "benchmarks").glob("*.py") if 'if __name__ == "__main__"' in path.read_text()
)


def test_the_benchmarks_shared_module_is_the_only_one_that_is_not_a_script():
    assert set(BENCHMARK_SCRIPTS) == {path.name for path in (REPO / "benchmarks").glob("*.py")} - {"base.py"}


@pytest.mark.parametrize("script", BENCHMARK_SCRIPTS)
def test_every_benchmark_script_answers_help_without_running(script):
    done = subprocess.run(
        [sys.executable, str(REPO / "benchmarks" / script), "--help"],
        capture_output=True,
        text=True,
        timeout=60,
        cwd=REPO,
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith("usage:") and re.search(r"\btakes?\b", done.stdout, flags=re.IGNORECASE)


# --------------------------------------------------------------------------- the exit table


def test_the_readme_exit_table_is_the_tool_s_own():
    live = [re.match(r"\s*(\d+)\s+(\S+)\s+(.*)", line).groups() for line in tool_output("exit-codes").splitlines()]
    section = README.read_text().split("## Exit codes")[1].split("\n## ")[0]
    rows = [line.strip("|").split("|") for line in section.splitlines() if re.match(r"\| \d", line)]
    written = [tuple(cell.strip().replace("`", "") for cell in row) for row in rows]
    assert written == live


# --------------------------------------------------------------------------- links and names


def anchors(document: Path) -> set[str]:
    """GitHub's heading anchors: lower case, punctuation dropped, spaces as hyphens."""
    headings = re.findall(r"^#+ (.+)$", document.read_text(), flags=re.MULTILINE)
    return {re.sub(r"[^\w\- ]", "", heading.lower()).replace(" ", "-") for heading in headings}


def test_every_relative_link_in_the_readme_and_docs_resolves():
    for document in DOCUMENTS:
        text = re.sub(r"```.*?```", "", document.read_text(), flags=re.DOTALL)
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            if re.match(r"[a-z]+:", target):
                continue
            path, _, anchor = target.partition("#")
            resolved = (document.parent / path).resolve() if path else document
            assert resolved.exists(), f"{document.name}: {target}"
            if anchor:
                assert anchor in anchors(resolved), f"{document.name}: {target}"


def test_no_issue_numbers_in_the_documents_benchmarks_examples_or_their_file_names():
    places = [README, *(REPO / "docs").rglob("*"), *(REPO / "benchmarks").rglob("*"), *(REPO / "examples").rglob("*")]
    for path in places:
        assert "issue" not in path.name.lower(), path
        if path.is_file() and path.suffix in {".md", ".py", ".txt", ".csv", ".jsonl", ".pddl", ".example"}:
            assert not re.search(r"\bissues?\s*#?\d", path.read_text(), flags=re.IGNORECASE), path


def test_the_status_table_of_how_it_works_is_the_code_s():
    from relevance_plan.exitcodes import PLAN_STATUS_EXIT
    from relevance_plan.planning.planners.base import PlannerStatus
    from relevance_plan.planning.results import PLANNER_TO_PLAN_STATUS, AttemptStatus, PlanStatus

    text = (REPO / "docs" / "how-it-works.md").read_text()
    table = text.split("### Statuses, from the planner to the exit code")[1].split("\n\n")[2]
    attempt_cells = [line.strip("|").split("|")[1] for line in table.splitlines()[2:]]
    assert {re.findall(r"`([\w-]+)`", cell)[0] for cell in attempt_cells} == {s.value for s in AttemptStatus}
    rows = [line for line in table.splitlines() if line.startswith("| `")]
    assert len(rows) >= len(PlannerStatus)
    for row in rows:
        planner, attempt, problem, code = (cell.strip() for cell in row.strip("|").split("|"))
        planner_status = PlannerStatus(re.findall(r"`([\w-]+)`", planner)[0])
        AttemptStatus(re.findall(r"`([\w-]+)`", attempt)[0])
        plan_status = PlanStatus(re.findall(r"`([\w-]+)`", problem)[0])
        assert int(PLAN_STATUS_EXIT[plan_status.value]) == int(re.findall(r"\d+", code)[0]), row
        if planner_status in PLANNER_TO_PLAN_STATUS:
            assert PLANNER_TO_PLAN_STATUS[planner_status] is plan_status, row
    assert {re.findall(r"`([\w-]+)`", row)[0] for row in rows} == {status.value for status in PlannerStatus}
