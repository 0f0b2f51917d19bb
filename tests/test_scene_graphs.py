"""Scene graphs in (the hydra extra): Spark-DSG's apartment graph and Matterport3D house from the corpus,
and graphs built here with spark-dsg, imported, planned with goals as atoms and in words, and validated on
the imported problem; every PDDL object traced to its graph node."""

from __future__ import annotations

import json
import re

import pytest
from support import REPO, run

spark_dsg = pytest.importorskip("spark_dsg", reason="the hydra extra (spark-dsg) is not installed")

from relevance_plan.scene_graphs.importer import DOMAIN_FILE, ImportOptions, import_scene, read_graph  # noqa: E402

CORPUS = REPO / "benchmarks" / "corpus" / "spark-dsg" / "scene-graphs"
APARTMENT = CORPUS / "apartment_dsg.json"
HOUSE = CORPUS / "example_mp3d_scene.house"
APARTMENT_LABELS = REPO / "examples" / "scene-graphs" / "uhumans2_apartment_labels.yaml"
PDDL_NAME = re.compile(r"^[a-z][a-z0-9_-]*$")


def text_model_installed() -> bool:
    from relevance_plan.errors import MissingExtraError
    from relevance_plan.text import load_text_model

    try:
        load_text_model()
    except MissingExtraError:
        return False
    return True


needs_text = pytest.mark.skipif(not text_model_installed(), reason="the text extra's model is not installed")


def imported(tmp_path, graph, *goals, labels=None, start=None):
    arguments = ["scene-graph", "import", graph, "-o", tmp_path, "--json"]
    arguments += [a for goal in goals for a in ("--goal", goal)]
    arguments += ["--labels", labels] if labels else []
    arguments += ["--start", start] if start else []
    code, out, err = run(*arguments)
    return code, (json.loads(out) if out.strip() else None), err


# --------------------------------------------------------------------------- the import


def test_apartment_without_its_label_names_asks_about_each_label(tmp_path):
    code, report, err = imported(tmp_path / "out", APARTMENT, "(hand-free robot)")
    assert code == 12
    assert [q.split(" has")[0] for q in report["questions"]] == [f"objects label {n}" for n in (5, 11, 16)]
    assert not (tmp_path / "out" / "problem.pddl").exists()


def test_every_object_is_traced_to_its_graph_node_and_every_node_is_imported(tmp_path):
    code, report, err = imported(tmp_path, APARTMENT, "(hand-free robot)", labels=APARTMENT_LABELS)
    assert code == 0, err
    nodes = json.loads((tmp_path / "problem.json").read_text())["scene_graph"]["nodes"]
    from relevance_plan.io import load_domain, load_problem

    problem = load_problem(tmp_path / "problem.pddl", load_domain(DOMAIN_FILE))
    assert set(problem.objects) == set(nodes)
    assert all(PDDL_NAME.match(name) for name in problem.objects)
    graph = spark_dsg.DynamicSceneGraph.load(str(APARTMENT))
    layered = {n.id.value for n in graph.nodes if n.layer.layer in (2, 3, 4) and n.layer.partition == 0}
    traced = {entry["node"] for entry in nodes.values() if entry["layer"] in ("objects", "places", "rooms")}
    assert traced == layered
    for entry in nodes.values():
        if entry["node"] is not None:
            assert str(spark_dsg.NodeSymbol(entry["node"])) == entry["symbol"]
    assert nodes["robot"]["symbol"] == "a(101)"  # the agent's latest pose


def test_names_are_stable_across_spark_dsg_encodings(tmp_path):
    """The graph saved again by spark-dsg (its current encoding, without the mesh) imports to the same text."""
    resaved = tmp_path / "resaved.json"
    graph = spark_dsg.DynamicSceneGraph.load(str(APARTMENT))
    graph.save(str(resaved), include_mesh=False)
    options = ImportOptions(labels=str(APARTMENT_LABELS))
    first = import_scene(read_graph(str(APARTMENT), options), ["(hand-free robot)"], options, "apartment")
    again = import_scene(read_graph(str(resaved), options), ["(hand-free robot)"], options, "apartment")
    assert first.text.splitlines()[2:] == again.text.splitlines()[2:]


def test_house_labels_come_from_the_file_and_the_coarse_names(tmp_path):
    code, report, err = imported(tmp_path, HOUSE, "(hand-free robot)")
    assert code == 0, err
    how = {p["name"]: (p["class"], p["how"]) for p in report["placements"] if p["layer"] == "objects"}
    assert how["bottle"] == ("bottle", "vocabulary")
    assert how["bedside table"] == ("nightstand", "vocabulary")
    assert how["button"] == ("misc", "coarse name 'misc'")
    rooms = {p["name"]: p["class"] for p in report["placements"] if p["layer"] == "rooms"}
    assert rooms["kitchen"] == "kitchen" and rooms["bathroom"] == "bathroom"
    assert report["objects"] > 187 + 10  # every object and room, the places, the classes


@needs_text
def test_a_label_the_mapping_names_in_other_words_is_placed_by_meaning(tmp_path):
    labels = tmp_path / "labels.yaml"
    labels.write_text("objects: {5: seat, 11: lamp, 16: dinner table}\nrooms: {0: lounge area}\n")
    code, report, err = imported(tmp_path / "out", APARTMENT, "(hand-free robot)", labels=labels)
    assert code == 0, err
    placed = {p["name"]: p for p in report["placements"]}
    assert placed["seat"]["class"] == "chair" and placed["seat"]["how"] == "vocabulary"
    assert placed["dinner table"]["how"] == "text model" and placed["dinner table"]["class"] == "table"
    assert 0.55 <= placed["dinner table"]["similarity"] < 1.0
    assert placed["lounge area"]["how"] == "text model"


@needs_text
def test_a_label_like_no_class_is_a_question(tmp_path):
    labels = tmp_path / "labels.yaml"
    labels.write_text("objects: {5: chair, 11: quantum flux regulator, 16: table}\nrooms: {0: living room}\n")
    code, report, err = imported(tmp_path / "out", APARTMENT, "(hand-free robot)", labels=labels)
    assert code == 12
    assert len(report["questions"]) == 1 and "quantum flux regulator" in report["questions"][0]


# --------------------------------------------------------------------------- goals and plans


def plan_and_validate(folder):
    code, out, err = run(
        "plan", folder / "domain.pddl", folder / "problem.pddl", "--plan-file", folder / "plan", "--json"
    )
    assert code == 0, err
    result = json.loads(out)
    assert result["valid"] is True
    for validator in ("builtin", "val"):
        code, out, err = run(
            "validate", folder / "domain.pddl", folder / "problem.pddl", folder / "plan", "--validator", validator
        )
        assert code == 0, (validator, out, err)
    return result


@pytest.mark.planner
def test_apartment_planned_with_a_goal_as_atoms(tmp_path):
    code, report, err = imported(tmp_path, APARTMENT, "(on lamp_o84 table_o33)", labels=APARTMENT_LABELS)
    assert code == 0, err
    result = plan_and_validate(tmp_path)
    steps = result["plan_nodes"]
    assert steps[-1]["action"] == "put-on"
    assert [a["symbol"] for a in steps[-1]["args"][1:3]] == ["O(84)", "O(33)"]
    assert json.loads((tmp_path / "plan.nodes.json").read_text()) == steps


@pytest.mark.planner
def test_house_planned_with_a_goal_in_words(tmp_path):
    code, report, err = imported(tmp_path, HOUSE, "bring a towel to the kitchen")
    assert code == 0, err
    (goal,) = report["goals"]
    assert goal["atom"] == "(class-in-room towel kitchen)"
    assert [p["similarity"] for p in goal["parts"]] == [1.0, 1.0]
    result = plan_and_validate(tmp_path)
    assert result["objects_kept"] < result["objects_total"] / 4
    last = result["plan_nodes"][-1]
    assert last["args"][1]["symbol"].startswith("O(")  # the towel moved is a graph object


@needs_text
@pytest.mark.planner
def test_a_description_is_read_as_the_scene_class_it_resembles(tmp_path):
    code, report, err = imported(tmp_path, HOUSE, "put something to drink on the table")
    assert code == 0, err
    moved = report["goals"][0]["parts"][0]
    assert moved["class"] == "bottle" and 0.45 <= moved["similarity"] < 1.0
    plan_and_validate(tmp_path)


def test_a_class_the_scene_lacks_is_a_question(tmp_path):
    code, report, err = imported(tmp_path, APARTMENT, "bring a cup to the kitchen", labels=APARTMENT_LABELS)
    assert code == 12
    assert "no cup" in report["questions"][0]
    assert "question:" in err and not (tmp_path / "problem.pddl").exists()


def test_score_why_names_the_graph_nodes(tmp_path):
    code, report, err = imported(tmp_path, APARTMENT, "(on lamp_o84 table_o33)", labels=APARTMENT_LABELS)
    code, out, err = run("score", tmp_path / "domain.pddl", tmp_path / "problem.pddl", "--why", "lamp_o84")
    assert code == 0, err
    assert "graph node O(84) (id 5692549928996307028, objects)" in out


# --------------------------------------------------------------------------- graphs built here with spark-dsg

ROOM_NAMES = {0: "kitchen", 1: "bedroom", 2: "bathroom", 3: "office"}
OBJECT_NAMES = {0: "mug", 1: "book", 2: "table", 3: "fridge", 4: "shelf", 5: "bottle", 6: "cabinet"}


def built_graph(rooms: int, places_per_room: int, objects: list[tuple[int, int, int]]):
    """A spark-dsg graph: rooms in a row, each a chain of places joined to the next room's; objects as
    (object index, label, place number), with label spaces for objects and rooms."""
    graph = spark_dsg.DynamicSceneGraph()
    graph.set_labelspace(spark_dsg.Labelspace(OBJECT_NAMES), 2, 0)
    graph.set_labelspace(spark_dsg.Labelspace(ROOM_NAMES), 4, 0)
    for r in range(rooms):
        attributes = spark_dsg.RoomNodeAttributes()
        attributes.semantic_label = r % len(ROOM_NAMES)
        attributes.position = [10.0 * r, 0.0, 0.0]
        graph.add_node(spark_dsg.DsgLayers.ROOMS, spark_dsg.NodeSymbol("R", r).value, attributes)
        for k in range(places_per_room):
            number = r * places_per_room + k
            place = spark_dsg.PlaceNodeAttributes()
            place.position = [10.0 * r + k, 0.0, 0.0]
            graph.add_node(spark_dsg.DsgLayers.PLACES, spark_dsg.NodeSymbol("p", number).value, place)
            graph.insert_edge(spark_dsg.NodeSymbol("p", number).value, spark_dsg.NodeSymbol("R", r).value)
            if number:
                graph.insert_edge(spark_dsg.NodeSymbol("p", number - 1).value, spark_dsg.NodeSymbol("p", number).value)
    for index, label, place in objects:
        add_object(graph, index, label, place)
    return graph


def add_object(graph, index: int, label: int, place: int) -> None:
    attributes = spark_dsg.ObjectNodeAttributes()
    attributes.semantic_label = label
    attributes.position = graph.get_node(spark_dsg.NodeSymbol("p", place).value).attributes.position + [0.0, 3.0, 0.5]
    node = spark_dsg.NodeSymbol("O", index).value
    graph.add_node(spark_dsg.DsgLayers.OBJECTS, node, attributes)
    graph.insert_edge(spark_dsg.NodeSymbol("p", place).value, node)


def move_object(graph, index: int, place: int) -> None:
    node = spark_dsg.NodeSymbol("O", index).value
    label = graph.get_node(node).attributes.semantic_label
    graph.remove_node(node)
    add_object(graph, index, label, place)


@pytest.mark.planner
def test_a_graph_built_with_spark_dsg_plans_a_goal_in_words(tmp_path):
    objects = [(i, i % 7, (3 * i) % 24) for i in range(40)]
    built_graph(4, 6, objects).save(str(tmp_path / "g.json"), include_mesh=False)
    code, report, err = imported(tmp_path / "out", tmp_path / "g.json", "put a book on the shelf", start="p(0)")
    assert code == 0, err
    assert report["goals"][0]["atom"] == "(class-on book shelf)"
    plan_and_validate(tmp_path / "out")


# --------------------------------------------------------------------------- the live session


def snapshots(tmp_path) -> list:
    """A graph and four updates: an object moves, one appears, one goes, a place edge goes."""
    objects = [(i, i % 7, (5 * i) % 18) for i in range(24)]
    graph = built_graph(3, 6, objects)
    paths = []

    def save():
        path = tmp_path / f"g{len(paths)}.json"
        graph.save(str(path), include_mesh=False)
        paths.append(path)

    save()
    move_object(graph, 1, 17)
    save()
    add_object(graph, 99, 0, 4)
    save()
    graph.remove_node(spark_dsg.NodeSymbol("O", 2).value)
    save()
    graph.remove_edge(spark_dsg.NodeSymbol("p", 8).value, spark_dsg.NodeSymbol("p", 9).value)
    save()
    return paths


def prune_kept(path, goals, options) -> frozenset:
    from relevance_plan.io import load_domain
    from relevance_plan.pddl.parser import read_problem
    from relevance_plan.relevance.analysis.task import PlanningTask
    from relevance_plan.relevance.setup import ScoringOptions, score_problem

    result = import_scene(read_graph(str(path), options), goals, options, "live")
    domain = load_domain(DOMAIN_FILE)
    task = PlanningTask(domain, read_problem(result.text, domain))
    return score_problem(task, ScoringOptions()).first_selection().kept


def test_a_live_session_over_graph_updates_keeps_the_selection_prune_makes(tmp_path):
    from relevance_plan.relevance.setup import ScoringOptions
    from relevance_plan.scene_graphs.live import GraphSession, file_updates

    paths = snapshots(tmp_path)
    goals = ["(class-on cup table)"]
    options = ImportOptions(start="p(0)")
    live = GraphSession(goals, options, ScoringOptions())
    kinds = []
    for update, path in zip(file_updates([str(p) for p in paths]), paths):
        lines = live.apply(update)
        assert "error" not in lines[-1], lines[-1]
        assert all(not line.get("error") for line in lines), lines
        kinds += [line["event"] for line in lines[:-1]]
        assert live.session.kept == prune_kept(path, goals, options), update.number
    assert {"add", "remove", "set", "unset"} <= set(kinds)


def test_an_update_that_cannot_be_read_is_its_own_error_and_the_session_goes_on(tmp_path):
    from relevance_plan.relevance.setup import ScoringOptions
    from relevance_plan.scene_graphs.live import GraphSession, file_updates

    paths = snapshots(tmp_path)
    broken = tmp_path / "broken.json"
    broken.write_text(paths[1].read_text()[:5000])
    live = GraphSession(["(class-on cup table)"], ImportOptions(start="p(0)"), ScoringOptions())
    answers = [live.apply(update) for update in file_updates([str(paths[0]), str(broken), str(paths[1])])]
    assert (
        answers[1] == [{**answers[1][0], "error": answers[1][0]["error"]}] and "broken.json" in answers[1][0]["error"]
    )
    moved = {line["event"]: line["nodes"] for line in answers[2][:-1] if "book_o1" in line["nodes"]}
    assert moved["set"] == {
        "book_o1": spark_dsg.NodeSymbol("O", 1).value,
        "place_p_17": spark_dsg.NodeSymbol("p", 17).value,
    }
    assert moved["unset"] == {
        "book_o1": spark_dsg.NodeSymbol("O", 1).value,
        "place_p_5": spark_dsg.NodeSymbol("p", 5).value,
    }


def test_the_zmq_stream_of_a_local_publisher_feeds_the_session(tmp_path):
    import threading
    import time

    from spark_dsg.zmq import DsgSender

    from relevance_plan.relevance.setup import ScoringOptions
    from relevance_plan.scene_graphs.live import GraphSession, zmq_updates

    paths = snapshots(tmp_path)
    graphs = [spark_dsg.DynamicSceneGraph.load(str(p)) for p in paths[:3]]
    url = "tcp://127.0.0.1:18765"
    sender = DsgSender(url)

    def publish():
        for message in [graphs[0].to_binary()] * 10 + [b"not a graph"] + [g.to_binary() for g in graphs[1:]]:
            for _ in range(3):  # a subscriber that joins late still gets each; repeats are skipped
                sender._socket.send(message)
                time.sleep(0.15)

    publisher = threading.Thread(target=publish)
    publisher.start()
    live = GraphSession(["(class-on cup table)"], ImportOptions(start="p(0)"), ScoringOptions())
    answers = [live.apply(update) for update in zmq_updates(url, idle_timeout=2.0, max_bytes=2**26, first_timeout=10)]
    publisher.join()
    sender._socket.close(linger=0)
    assert answers[0][-1].get("started") is True
    errors = [a[-1] for a in answers if a[-1].get("error")]
    assert len(errors) == 1 and "binary update" in errors[0]["error"]
    assert live.session.kept == prune_kept(paths[2], ["(class-on cup table)"], ImportOptions(start="p(0)"))


# --------------------------------------------------------------------------- the documented commands


@pytest.mark.planner
def test_the_commands_of_the_scene_graph_page_run_as_written(tmp_path):
    import shlex
    import shutil
    import subprocess
    import sys

    from test_documented_commands import code_blocks

    shutil.copytree(CORPUS, tmp_path / "benchmarks" / "corpus" / "spark-dsg" / "scene-graphs")
    shutil.copytree(APARTMENT_LABELS.parent, tmp_path / "examples" / "scene-graphs")
    lines = "\n".join(code_blocks(REPO / "docs" / "scene-graphs.md", "bash")).replace("\\\n", " ").splitlines()
    outputs = {}
    for line in filter(None, map(str.strip, lines)):
        words = shlex.split(line)
        assert words[0] == "relevance-plan", line
        done = subprocess.run(
            [sys.executable, "-m", "relevance_plan", *words[1:]],
            cwd=tmp_path,
            capture_output=True,
            text=True,
            timeout=600,
        )
        assert done.returncode == 0, f"{line}\n{done.stderr}"
        outputs[" ".join(words[1:3])] = outputs.get(" ".join(words[1:3]), "") + done.stdout
    assert "-> (class-in-room towel kitchen)" in outputs["scene-graph import"]
    assert "graph node O(84)" in outputs["score out/apartment/domain.pddl"]
    updates = [json.loads(line) for line in outputs["scene-graph watch"].splitlines()]
    assert updates[0]["started"] is True and updates[-1]["events"] == 0
