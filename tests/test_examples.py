"""`relevance-plan examples DIR`: the shipped worlds copied out, never over a user's file."""

from __future__ import annotations

from support import run

from relevance_plan.exitcodes import ExitCode


def test_examples_makes_the_readme_first_look_work_outside_the_clone(tmp_path):
    code, out, err = run("examples", tmp_path / "kitchen")
    assert code == 0, err
    kitchen = tmp_path / "kitchen"
    domain, problem = kitchen / "domains/coffee/domain.pddl", kitchen / "problems/coffee-hard.pddl"
    assert domain.is_file() and problem.is_file() and (kitchen / "domains/coffee/relevance.yaml").is_file()
    code, out, err = run("prune", domain, problem, "-o", tmp_path / "small.pddl")
    assert code == 0, err
    assert not list(tmp_path.glob(".relevance-plan-examples-*"))  # no staging folder left


def test_examples_into_a_folder_with_a_clashing_file_writes_nothing(tmp_path):
    mine = tmp_path / "problems" / "coffee-hard.pddl"
    mine.parent.mkdir()
    mine.write_text("my own problem")
    code, _, err = run("examples", tmp_path)
    assert code == ExitCode.USAGE and "coffee-hard.pddl exists" in err
    assert mine.read_text() == "my own problem"
    assert sorted(p.name for p in tmp_path.rglob("*")) == ["coffee-hard.pddl", "problems"]


def test_examples_into_an_existing_folder_keeps_the_users_other_files(tmp_path):
    (tmp_path / "notes.txt").write_text("mine")
    code, _, err = run("examples", tmp_path)
    assert code == 0, err
    assert (tmp_path / "notes.txt").read_text() == "mine"
    assert (tmp_path / "domains/cereal/domain.pddl").is_file()


def test_examples_refuses_an_empty_path_and_a_missing_parent_in_one_line(tmp_path):
    code, _, err = run("examples", "")
    assert code == ExitCode.USAGE and len(err.splitlines()) == 1
    code, _, err = run("examples", tmp_path / "absent" / "kitchen")
    assert code == ExitCode.INPUT_FILE and "absent is not a folder" in err and len(err.splitlines()) == 1
    assert not (tmp_path / "absent").exists()
