"""Selections as small as the task needs: where many objects share a role, one does."""

from __future__ import annotations

import random

from support import REPO

from relevance_plan.data import DOMAINS_DIR
from relevance_plan.io import load_domain
from relevance_plan.pddl.parser import read_problem
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.selection.prune import Widening, ranked_names, widen
from relevance_plan.relevance.setup import ScoringOptions, score_problem


def many_goal_logistics(seed: int, cities: int = 6, packages: int = 12, airplanes: int = 20) -> str:
    """Every package in the goal, each in another city than its destination; many airplanes."""
    rng = random.Random(seed)
    objects = []
    init = []
    for c in range(cities):
        objects += [f"city{c} - city", f"ap{c} - airport", f"post{c} - location", f"truck{c} - truck"]
        init += [f"(in-city ap{c} city{c})", f"(in-city post{c} city{c})", f"(at truck{c} post{c})"]
    for a in range(airplanes):
        objects.append(f"plane{a} - airplane")
        init.append(f"(at plane{a} ap{rng.randrange(cities)})")
    goal = []
    for p in range(packages):
        origin, target = rng.sample(range(cities), 2)
        objects.append(f"pkg{p} - package")
        init.append(f"(at pkg{p} post{origin})")
        goal.append(f"(at pkg{p} post{target})")
    return (
        f"(define (problem many-goals-{seed}) (:domain logistics-typed) (:objects {' '.join(objects)})"
        f" (:init {' '.join(init)}) (:goal (and {' '.join(goal)})))"
    )


def test_the_repair_picks_one_airplane_where_one_suffices():
    domain = load_domain(DOMAINS_DIR / "logistics-typed" / "domain.pddl")
    for seed in range(3):
        problem = read_problem(many_goal_logistics(seed), domain)
        selection = score_problem(PlanningTask(domain, problem), ScoringOptions(scorer="goal")).first_selection()
        airplanes = {n for n in selection.kept if problem.objects[n] == "airplane"}
        packages = {n for n in problem.objects if problem.objects[n] == "package"}
        assert packages <= selection.kept
        assert len(airplanes) == 1, (seed, sorted(airplanes))
        reasons = {r.name: r for r in selection.restored}
        assert reasons[next(iter(airplanes))].rule == "reachability"


def test_the_first_selection_keeps_one_of_many_nearby_airplanes():
    # generated many-goal logistics: every airport is near a goal object, so the goal scorer selects
    # nearly every airplane; the first selection keeps the one a relaxed plan needs
    from relevance_plan.generators import WORLDS, Settings

    for world in ("logistics-manygoals", "logistics-manygoals-typed"):
        generated = WORLDS[world].problem(2, 1, Settings(size=120))
        domain = load_domain(DOMAINS_DIR / generated.sidecar["domain"] / "domain.pddl")
        problem = read_problem(generated.pddl_text, domain)
        scoring = score_problem(PlanningTask(domain, problem), ScoringOptions())
        airplanes = {n for n in problem.objects if n.startswith("plane")}
        assert len(scoring.scores.alternatives & airplanes) > 10  # the scorer alone would keep them all
        selection = scoring.first_selection()
        assert len(selection.kept & airplanes) == 1, sorted(selection.kept & airplanes)
        assert len(selection.kept) <= len(generated.sidecar["necessary"]) + 5
        assert selection.set_aside  # what widening brings back last
        # the relevance method's later attempts and the other methods do not set alternatives aside
        assert len(scoring.first_selection(narrow=False).kept & airplanes) > 10


def test_a_second_truck_in_one_city_goes_when_the_first_can_stand_in_for_it(monkeypatch):
    """Trucks are needed one per city, so no truck stands in for most others; but when one round
    adds two trucks of one city and the relaxed plan uses both, the one the other can replace goes."""
    from relevance_plan.generators import WORLDS, Settings
    from relevance_plan.relevance.selection import repair

    pairwise = repair.PAIRWISE_UP_TO
    generated = WORLDS["logistics-manygoals"].problem(5, 1, Settings(size=200))
    domain = load_domain(WORLDS["logistics-manygoals"].domain_path)

    def trucks_of_city_eight(pairwise: int) -> set[str]:
        monkeypatch.setattr(repair, "PAIRWISE_UP_TO", pairwise)
        task = PlanningTask(domain, read_problem(generated.pddl_text, domain))
        selection = score_problem(task, ScoringOptions(), method="relevance").first_selection(narrow=True)
        return {name for name in selection.kept if name.startswith("truck8-")}

    assert trucks_of_city_eight(0) == {"truck8-1", "truck8-3"}  # both taken in one round, both used
    assert trucks_of_city_eight(pairwise) == {"truck8-1"}


def test_widening_keeps_set_aside_alternatives_aside_and_brings_them_back_last():
    # IPC driverlog with 30 spare trucks, drivers, packages and locations: the first selection sets
    # the trucks near the goal aside; a failed first attempt more likely lacks an object of another
    # role (the instance's own paths and driver) than thirty trucks
    from relevance_plan.generators.padded import padded_driverlog

    folder = REPO / "benchmarks" / "corpus" / "potassco" / "ipc-2002" / "driverlog-time-automatic"
    domain = load_domain(folder / "domain.pddl")
    instance = (folder / "instances" / "instance-3.pddl").read_text()
    task = PlanningTask(domain, read_problem(padded_driverlog(instance, 30), domain))
    scoring = score_problem(task, ScoringOptions())
    first = scoring.first_selection()
    aside = first.set_aside
    assert len(aside) > 10 and all(name.startswith("xtruck") for name in aside)
    instance_objects = {name for name in task.problem.objects if not name.startswith("x")}
    assert not instance_objects <= first.kept
    widened, _ = widen(first, Widening(0.5, goal_filter=True), frozenset(), scoring.knowledge_model)
    # the instance's own objects come back first, but for an idle twin of a kept one (package4,
    # at s1 like package3, is in no goal)
    profiles = task.object_profiles
    twins = {name for name in instance_objects - first.kept if any(profiles[name] == profiles[k] for k in first.kept)}
    assert twins == {"package4"}
    assert instance_objects - twins <= widened.kept
    assert not aside & widened.kept and widened.set_aside == aside
    assert len(widened.kept) < len(task.problem.objects) / 2


def test_widening_takes_one_of_each_set_of_interchangeable_objects_before_a_second():
    # IPC tpp-metric padded with 120 clones: only the five original markets have goods on sale,
    # and their clones (on no sale, all alike) sort between them by name
    from relevance_plan.generators.padded import pad_with_clones

    folder = REPO / "benchmarks" / "corpus" / "potassco" / "ipc-2006" / "tpp-metric"
    domain = load_domain(folder / "domain.pddl")
    problem = read_problem((folder / "instances" / "instance-1.pddl").read_text(), domain)
    task = PlanningTask(domain, pad_with_clones(domain, problem, 120, seed=1))
    first = score_problem(task, ScoringOptions()).first_selection()
    selling = {f"market{number}" for number in range(1, 6)}
    assert len(first.kept) == 4 and len(selling & first.kept) == 1
    ranked = ranked_names(task, first.scores, first.kept, first.set_aside)
    assert selling - first.kept <= set(ranked[:10])  # one clone of each market at most comes before
