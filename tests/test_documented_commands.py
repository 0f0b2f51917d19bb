"""Every command and script the README shows, and the docs' Python snippets, run as written.

From a clone (the package on the path, the README's folders made by ``relevance-plan examples``)
and after a regular install (a wheel installed into a folder of its own, run from elsewhere).
Each command must exit 0; the outputs that say something checkable are checked.
"""

from __future__ import annotations

import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest
from support import REPO

README = REPO / "README.md"
SET_UP = ("pip install",)


def code_blocks(path: Path, language: str) -> list[str]:
    return re.findall(rf"```{language}\n(.*?)```", path.read_text(encoding="utf-8"), flags=re.DOTALL)


def readme_commands() -> list[str]:
    """The README's shell commands, continuation lines joined; the set-up lines (pip) are CI's own."""
    joined = "\n".join(code_blocks(README, "bash")).replace("\\\n", " ")
    lines = [line.split("  #")[0].strip() for line in joined.splitlines()]
    return [line for line in lines if line and not line.startswith(SET_UP)]


def as_arguments(line: str) -> list[str]:
    words = shlex.split(line)
    if words[0] == "relevance-plan":
        return [sys.executable, "-m", "relevance_plan", *words[1:]]
    if words[0] == "python":
        return [sys.executable, *words[1:]]
    raise AssertionError(f"the README shows a command this test cannot run: {line}")


def run_in(folder: Path, arguments: list[str], env: dict[str, str]) -> subprocess.CompletedProcess[str]:
    return subprocess.run(arguments, cwd=folder, env=env, capture_output=True, text=True, timeout=600)


def check_readme_commands(folder: Path, env: dict[str, str]) -> None:
    made = run_in(folder, [sys.executable, "-m", "relevance_plan", "examples", "kitchen"], env)
    assert made.returncode == 0, made.stderr
    kitchen = folder / "kitchen"
    outputs = {}
    for line in readme_commands():
        done = run_in(kitchen, as_arguments(line), env)
        assert done.returncode == 0, f"{line}\n{done.stderr}"
        outputs[line.split()[1] if line.startswith("relevance-plan") else line] = done.stdout
    assert (kitchen / "small.pddl").is_file() and (kitchen / "sas_plan").is_file()
    assert "kept" in outputs["score"] and "relevance" in outputs["report"]
    watched = [line for line in outputs["watch"].splitlines() if line.startswith("{")]
    assert watched and '"plan"' in outputs["watch"]
    for snippet in code_blocks(README, "python"):
        done = run_in(kitchen, [sys.executable, "-c", snippet], env)
        assert done.returncode == 0, f"{snippet}\n{done.stderr}"


@pytest.mark.planner
def test_the_readme_commands_and_snippets_run_from_a_clone(tmp_path):
    env = {**os.environ, "PYTHONPATH": str(REPO)}
    check_readme_commands(tmp_path, env)


@pytest.mark.planner
def test_the_readme_commands_and_snippets_run_after_a_regular_install(installed_elsewhere):
    work, env = installed_elsewhere
    check_readme_commands(work, env)


@pytest.mark.planner
def test_the_unified_planning_guide_s_snippets_run_in_order(tmp_path):
    """The guide's snippets build on each other (the first defines the problem), as a reader runs them."""
    script = "\n\n".join(code_blocks(REPO / "docs" / "unified-planning.md", "python"))
    done = subprocess.run([sys.executable, "-c", script], cwd=tmp_path, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    assert "SOLVED" in done.stdout and "objects removed" in done.stdout
