"""The benchmark corpus in ``benchmarks/corpus``: whole against its manifest, and readable by the project.

No planner runs; reading every folder's domain and first problem takes a few seconds.  The
script is run as a user runs it; the folders are read from its manifest.
"""

from __future__ import annotations

import json
import subprocess
import sys

import pytest
from support import REPO

from relevance_plan.batch.suites import find_suite_problems
from relevance_plan.errors import RelevancePlanError
from relevance_plan.io import load_domain, load_problem

SCRIPT = REPO / "benchmarks" / "corpus.py"
CORPUS = REPO / "benchmarks" / "corpus"


def manifest() -> dict:
    return json.loads((CORPUS / "MANIFEST.json").read_text(encoding="utf-8"))


def folders(track: str | None = None):
    return [CORPUS / entry["path"] for entry in manifest()["folders"] if track is None or entry["track"] == track]


def corpus_script(*arguments: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, str(SCRIPT), *arguments], capture_output=True, text=True, timeout=60)


def test_verify_finds_the_corpus_whole_and_covers_the_tracks():
    result = corpus_script("verify", "--json")
    assert result.returncode == 0, result.stderr
    counts = json.loads(result.stdout)
    assert counts["domains"] >= 150
    assert counts["tracks"].get("temporal", 0) >= 10
    assert counts["tracks"].get("numeric", 0) >= 10
    assert counts["tracks"].get("scene-graph", 0) >= 1
    assert counts["files"] == len(manifest()["files"])


def test_verify_names_each_mismatch_on_its_own_line(tmp_path):
    root = tmp_path / "corpus"
    (root / "a").mkdir(parents=True)
    (root / "a" / "domain.pddl").write_text("(define (domain a))\n")
    (root / "a" / "p1.pddl").write_text("(define (problem p) (:domain a))\n")
    (root / "stray.pddl").write_text("\n")
    files = [
        {"path": "a/domain.pddl", "folder": "a", "role": "domain", "sha256": "0" * 64, "size": 1},
        {"path": "a/p1.pddl", "folder": "a", "role": "problem", "sha256": "0" * 64, "size": 1},
        {"path": "a/p3.pddl", "folder": "a", "role": "problem", "sha256": "0" * 64, "size": 1},
    ]
    (root / "MANIFEST.json").write_text(json.dumps({"folders": [{"path": "a", "track": "classical"}], "files": files}))
    result = corpus_script("verify", "--root", str(root))
    assert result.returncode == 1
    assert result.stderr.splitlines() == [
        "a/domain.pddl: sha256 differs from the manifest (size 20, manifest says 1)",
        "a/p1.pddl: sha256 differs from the manifest (size 33, manifest says 1)",
        "a/p3.pddl: missing",
        "stray.pddl: not in the manifest",
    ]


def test_every_folder_pairs_each_problem_with_a_domain():
    data = manifest()
    expected = {entry["path"]: entry["problems"] for entry in data["folders"]}
    for folder in folders():
        entries = find_suite_problems(folder)
        relative = folder.relative_to(CORPUS).as_posix()
        assert len(entries) == expected[relative], relative
        for entry in entries:
            assert entry.error is None and entry.domain is not None, (relative, entry)


@pytest.mark.parametrize("track", ["temporal", "numeric", "classical", "scene-graph"])
def test_list_shows_a_track_s_folders_and_only_them(track):
    result = corpus_script("list", "--track", track)
    assert result.returncode == 0, result.stderr
    listed = {line.split()[0] for line in result.stdout.splitlines()[1:]}
    assert listed == {entry["path"] for entry in manifest()["folders"] if entry["track"] == track}


def test_each_domain_and_first_problem_reads_or_is_a_known_unreadable_one():
    unreadable = {entry["folder"]: entry["error"] for entry in manifest().get("known_unreadable", [])}
    refused = {}
    for folder in folders():
        relative = folder.relative_to(CORPUS).as_posix()
        first = find_suite_problems(folder)[0]
        try:
            load_problem(first.problem, load_domain(first.domain))
        except RelevancePlanError as error:
            refused[relative] = str(error).splitlines()[0]
    surprises = sorted(set(refused) - set(unreadable))
    assert not surprises, "\n".join(f"{name}: {refused[name]}" for name in surprises)
    assert set(unreadable) <= {entry["path"] for entry in manifest()["folders"]}


def test_training_problems_pair_with_their_test_folders_domain():
    data = manifest()
    training = [entry for entry in data["folders"] + data["sets"] if "training" in entry]
    assert training, "the Taskography training problems are in the manifest"
    for entry in training:
        folder = CORPUS / entry["training"]["path"]
        listed = [f for f in data["files"] if f["role"] == "training-problem" and f["folder"] == entry["path"]]
        entries = find_suite_problems(folder)
        assert len(entries) == len(listed) == entry["training"]["problems"]
        (test_domain,) = {e.domain for e in find_suite_problems(CORPUS / entry["path"])}
        assert {e.domain for e in entries} == {test_domain}
        load_problem(entries[0].problem, load_domain(test_domain))


def problem_folders(entry: dict) -> list[dict]:
    """A set's folders of test problems: its cells of role test, or the set's own folder."""
    return [cell for cell in entry.get("cells", [entry]) if cell.get("role", "test") == "test"]


def test_benchmark_sets_pair_their_problems_with_the_domain_and_stay_out_of_the_domain_folders():
    data = manifest()
    sets = data["sets"]
    assert {entry["path"].rsplit("/", 1)[1] for entry in sets} >= {
        "taskographyv4medium5_test",
        "taskographyv5medium5bagslots5_test",
        "mazenamo_problems",
        "rovers-large-simple",
    }
    domain_folders = {entry["path"] for entry in data["folders"]}
    for entry in sets:
        assert entry["path"] not in domain_folders
        folders = problem_folders(entry)
        assert sum(folder["problems"] for folder in folders) == entry["problems"] <= entry["problems_in_source"]
        for folder in folders:
            entries = find_suite_problems(CORPUS / folder["path"])
            assert len(entries) == folder["problems"] <= folder["problems_in_source"]
            assert all(e.error is None and e.domain is not None for e in entries)
            load_problem(entries[-1].problem, load_domain(entries[-1].domain))


def test_a_set_s_cells_hold_the_files_the_manifest_gives_them_and_each_pairs_with_one_domain():
    data = manifest()
    celled = [entry for entry in data["sets"] if "cells" in entry]
    assert {entry["name"] for entry in celled} >= {"mazenamo", "sokomindplus", "difficultlogistics"}
    role_of_files = {"test": "problem", "training": "training-problem"}
    for entry in celled:
        for cell in entry["cells"]:
            listed = [f for f in data["files"] if f.get("cell") == cell["path"] and f["role"] != "domain"]
            assert {f["role"] for f in listed} == {role_of_files[cell["role"]]}, cell["path"]
            assert all(f["folder"] == entry["path"] for f in listed)
            entries = find_suite_problems(CORPUS / cell["path"])
            found = sorted(e.problem.relative_to(CORPUS).as_posix() for e in entries)
            assert found == sorted(f["path"] for f in listed)
            assert len(entries) == cell["problems"] <= cell["problems_in_source"]
            (domain,) = {e.domain for e in entries}
            load_problem(entries[0].problem, load_domain(domain))
    gnad = next(entry for entry in celled if entry["name"] == "gnad-et-al-aaai19-large-instances")
    assert "satellite-large" in {cell["name"] for cell in gnad["cells"]}


def test_benchmark_sets_finds_each_set_by_name_with_its_cells_at_their_paths():
    from corpus import benchmark_sets

    sets = benchmark_sets()
    assert {"taskographyv4medium5", "mazenamo", "difficultlogistics", "blocksworld-large-simple"} <= set(sets)
    mazenamo = sets["mazenamo"]
    assert len([cell for cell in mazenamo["cells"] if cell["role"] == "test"]) == 12
    assert all(cell["path"].is_dir() and cell["path"].parent == mazenamo["path"] for cell in mazenamo["cells"])
    assert sets["taskographyv4medium5"]["training"]["path"].is_dir() and sets["taskographyv4medium5"]["cells"] == []
