"""Seeded benchmark problems and suites for the coffee and cereal worlds.

``generate_problem`` is pure: (world, difficulty, seed, index, distractors)
always gives the same ``GeneratedProblem``.  It starts from the base scene,
adds distractors drawn from the 200-kind catalog, placed on random surfaces
or inside random containers, and, in the coffee world, random spatial
constraints (one item stacked on another).  The random stream is seeded from
a SHA-256 of (seed, world, difficulty, index), never from ``hash()``.

``generate_suite`` writes a directory atomically: ``domain.pddl`` (a byte
copy of ``domains/<world>/domain.pddl``), ``<world>-<difficulty>-<NNN>.pddl``
with a ``.json`` sidecar per problem, and a ``suite.json`` manifest.
``write_base_scenes`` writes the four base scenes into ``problems/``.
"""

from __future__ import annotations

import functools
import hashlib
import json
import os
import random
import shutil
import tempfile
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Protocol

from relevance_plan.data import DOMAINS_DIR
from relevance_plan.errors import InputFileError, UsageError
from relevance_plan.generators.catalog import CATALOG
from relevance_plan.generators.problem import choose_roles, format_scene, necessary_objects, relevant_objects
from relevance_plan.generators.scenes import DIFFICULTIES, KITCHENS, SCENES, Item, SceneLayout, name_key
from relevance_plan.io import new_directory_mode
from relevance_plan.limits import MAX_COUNT, MAX_DISTRACTORS
from relevance_plan.progress import ProgressCallback, ProgressEvent

GENERATOR = "relevance_plan.generators"
GENERATOR_VERSION = "1"


DISTRACTOR_RANGES: dict[tuple[str, str], tuple[int, int]] = {
    ("coffee", "simple"): (10, 30),
    ("coffee", "hard"): (20, 50),
    ("cereal", "simple"): (10, 45),
    ("cereal", "hard"): (30, 60),
}
"""Inclusive range the number of distractors is drawn from (paper, Sec. V.A)."""

CONSTRAINT_COUNTS: dict[tuple[str, str], int] = {
    ("coffee", "simple"): 3,
    ("coffee", "hard"): 8,
    ("cereal", "simple"): 0,
    ("cereal", "hard"): 0,
}
"""Random on-top constraints added per problem (cereal adds none)."""


@dataclass(frozen=True)
class GeneratedProblem:
    name: str
    pddl_text: str
    sidecar: dict[str, Any]
    scene: SceneLayout = field(repr=False, compare=False)

    @property
    def sidecar_text(self) -> str:
        return sidecar_json(self.sidecar)


def sidecar_json(data: dict[str, Any]) -> str:
    return json.dumps(data, sort_keys=True, indent=2) + "\n"


# --- arguments ---------------------------------------------------------------


def _check_world(world: object, difficulty: object) -> None:
    if world not in KITCHENS:
        raise UsageError(f"unknown world {world!r}: choose one of {', '.join(KITCHENS)}")
    if difficulty not in DIFFICULTIES:
        raise UsageError(f"unknown difficulty {difficulty!r}: choose one of {', '.join(DIFFICULTIES)}")


def _check_int(label: str, value: object, minimum: int | None = None) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        raise UsageError(f"{label} must be an integer, not {value!r}")
    if minimum is not None and value < minimum:
        raise UsageError(f"{label} must be at least {minimum}, not {value}")
    return value


def _check_arguments(world: object, difficulty: object, seed: object, distractors: object) -> None:
    _check_world(world, difficulty)
    _check_int("seed", seed)
    if distractors is not None:
        if _check_int("distractors", distractors, 0) > MAX_DISTRACTORS:
            raise UsageError(f"distractors must be at most {MAX_DISTRACTORS}, not {distractors}")


def check_suite_arguments(world: object, difficulty: object, count: object, seed: object, distractors: object) -> None:
    """Raise ``UsageError`` for a bad kitchen world, difficulty, count, seed or distractor count."""
    _check_arguments(world, difficulty, seed, distractors)
    _check_int("count", count, 1)
    if count > MAX_COUNT:  # type: ignore[operator]
        raise UsageError(f"count must be at most {MAX_COUNT}, not {count}")


def problem_rng(seed: int, world: str, difficulty: str, index: int) -> random.Random:
    """The random stream of one problem (stable across processes and Pythons)."""
    key = f"{GENERATOR}/{GENERATOR_VERSION}/{seed}/{world}/{difficulty}/{index}".encode()
    return random.Random(int.from_bytes(hashlib.sha256(key).digest()[:16], "big"))


# --- one problem -------------------------------------------------------------


def problem_name(world: str, difficulty: str, index: int) -> str:
    return f"{world}-{difficulty}-{index:03d}"


def generate_problem(
    world: str,
    difficulty: str,
    seed: int,
    index: int,
    distractors: int | None = None,
) -> GeneratedProblem:
    """Build problem ``index`` of the suite (world, difficulty, seed).

    ``distractors`` overrides the number of distractors drawn from
    ``DISTRACTOR_RANGES`` (the paper's count is still drawn first, so the
    stream is consumed the same way up to the distractors themselves).
    """
    _check_arguments(world, difficulty, seed, distractors)
    _check_int("index", index, 0)
    base = SCENES[f"{world}-{difficulty}"]
    rng = problem_rng(seed, world, difficulty, index)

    low, high = DISTRACTOR_RANGES[(world, difficulty)]
    drawn = rng.randint(low, high)
    count = drawn if distractors is None else distractors
    added = _draw_distractors(base, count, rng)
    items, constraints = _add_constraints(base, list(base.items) + added, CONSTRAINT_COUNTS[(world, difficulty)], rng)
    scene = SceneLayout(
        world=world,
        difficulty=difficulty,
        places=base.places,
        items=tuple(items),
        humans=base.humans,
        robot_start=base.robot_start,
    )
    name = problem_name(world, difficulty, index)
    comment = (
        f"{name}: base scene {base.name} + {count} distractors, {len(constraints)} added constraints\n"
        f"generated by {GENERATOR} version {GENERATOR_VERSION}, seed {seed}, index {index}"
    )
    sidecar = build_sidecar(
        scene,
        base_scene=base.name,
        seed=seed,
        index=index,
        distractors=[item.name for item in added],
        constraints=constraints,
    )
    return GeneratedProblem(name, format_scene(scene, name, comment), sidecar, scene)


def _draw_distractors(base: SceneLayout, count: int, rng: random.Random) -> list[Item]:
    """``count`` distractors: distinct kinds per pass over the catalog, each on
    the base of a random place; indices continue after the scene's own."""
    next_index: dict[str, int] = {}
    for name in base.object_names():
        kind, number = name_key(name)
        next_index[kind] = max(next_index.get(kind, 0), number)
    places = [p.name for p in base.places]
    added: list[Item] = []
    while len(added) < count:
        for kind, type_name in rng.sample(CATALOG, min(len(CATALOG), count - len(added))):
            next_index[kind] = next_index.get(kind, 0) + 1
            added.append(Item(f"{kind}_{next_index[kind]}", type_name, rng.choice(places)))
    return added


def _add_constraints(
    base: SceneLayout, items: list[Item], count: int, rng: random.Random
) -> tuple[list[Item], list[list[str]]]:
    """Add ``count`` on-top constraints [top, bottom].

    The bottom is a task item with nothing on it (so every constraint is a task
    dependency); the top is the base item of any other pile, which moves with
    everything on it onto the bottom, at the bottom's place.  Piles may chain;
    task items may stand on task items; the items' order is kept.
    """
    if count == 0:
        return items, []
    relevant = set(base.world_spec.relevant_types)
    order = [item.name for item in items]
    type_of = {item.name: item.type for item in items}
    place_of = {item.name: item.place for item in items}
    below = {item.name: item.on for item in items}
    above = {item.on: item.name for item in items if item.on is not None}

    def pile(name: str) -> list[str]:
        while (lower := below[name]) is not None:
            name = lower
        result = [name]
        while result[-1] in above:
            result.append(above[result[-1]])
        return result

    constraints: list[list[str]] = []
    for _ in range(count):
        bottoms = [n for n in order if type_of[n] in relevant and n not in above]
        bottom = rng.choice(bottoms)
        bottom_pile = set(pile(bottom))
        tops = [n for n in order if below[n] is None and n not in bottom_pile]
        top = rng.choice(tops)
        for moved in pile(top):
            place_of[moved] = place_of[bottom]
        below[top] = bottom
        above[bottom] = top
        constraints.append([top, bottom])
    return [Item(n, type_of[n], place_of[n], below[n]) for n in order], constraints


def build_sidecar(
    scene: SceneLayout,
    *,
    base_scene: str,
    seed: int | None,
    index: int | None,
    distractors: list[str],
    constraints: list[list[str]],
) -> dict[str, Any]:
    roles = choose_roles(scene)
    return {
        "seed": seed,
        "index": index,
        "world": scene.world,
        "difficulty": scene.difficulty,
        "base_scene": base_scene,
        "distractor_count": len(distractors),
        "distractors": list(distractors),
        "constraints": [list(pair) for pair in constraints],
        "dependencies": [d.as_dict() for d in scene.dependencies],
        "objects_total": scene.objects_total,
        "relevant": relevant_objects(scene),
        "necessary": necessary_objects(scene, roles),
        "roles": roles,
    }


def base_scene_problem(scene_name: str) -> GeneratedProblem:
    """A base scene as a problem (no distractors, no added constraints)."""
    if scene_name not in SCENES:
        raise UsageError(f"unknown base scene {scene_name!r}: choose one of {', '.join(SCENES)}")
    scene = SCENES[scene_name]
    comment = (
        f"{scene.name}: base scene of the {scene.world} world, {scene.objects_total} objects, "
        f"{len(scene.dependencies)} natural task dependencies\n"
        f"generated by {GENERATOR} version {GENERATOR_VERSION}"
    )
    sidecar = build_sidecar(scene, base_scene=scene.name, seed=None, index=None, distractors=[], constraints=[])
    return GeneratedProblem(scene.name, format_scene(scene, scene.name, comment), sidecar, scene)


# --- files -------------------------------------------------------------------


def _write_text(path: Path, text: str) -> None:
    with open(path, "w", encoding="utf-8", newline="\n") as handle:
        handle.write(text)


def _own_files(directory: Path) -> set[str] | None:
    """Names of the files a previous run of this generator wrote into
    ``directory`` (from its ``suite.json``), or None if it holds no suite of ours.

    Only plain file names count: a manifest can never make us touch a file
    elsewhere.
    """
    try:
        manifest = json.loads((directory / "suite.json").read_text(encoding="utf-8"))
    except (OSError, ValueError, RecursionError):
        return None
    if not isinstance(manifest, dict) or manifest.get("generator") != GENERATOR:
        return None
    names = {"suite.json"}
    if isinstance(manifest.get("domain"), str):
        names.add(manifest["domain"])
    entries = manifest.get("problems")
    for entry in entries if isinstance(entries, list) else ():
        if isinstance(entry, dict):
            names.update(value for key in ("problem", "sidecar") if isinstance(value := entry.get(key), str))
    return {name for name in names if name and name == Path(name).name and name not in (".", "..")}


def _check_out_dir(out_dir: Path, planned: list[str], force: bool) -> set[str]:
    """The generator's files already in ``out_dir`` (to replace); refuses to
    overwrite anything else unless ``force``."""
    if not (out_dir.exists() or out_dir.is_symlink()):
        return set()
    if not out_dir.is_dir() or out_dir.is_symlink():
        raise InputFileError("output path exists and is not a plain directory", path=str(out_dir))
    try:
        present = {entry.name for entry in out_dir.iterdir()}
    except OSError as error:
        raise InputFileError(f"cannot read the output directory: {error.strerror}", path=str(out_dir)) from None
    if not present:
        return set()
    own = _own_files(out_dir)
    if own is None and not force:
        raise UsageError(
            f"output directory {out_dir} is not empty and holds no suite of ours;"
            " choose another or give --force (files of yours are never deleted)"
        )
    own = own or set()
    clashes = sorted(name for name in planned if name in present and name not in own)
    if clashes and not force:
        raise UsageError(
            f"output directory {out_dir} holds {clashes[0]}, which this generator did not write;"
            " move it or give --force to overwrite it"
        )
    return own & present


def generate_suite(
    world: str,
    difficulty: str,
    count: int,
    seed: int,
    out_dir: Path,
    distractors: int | None = None,
    progress: ProgressCallback | None = None,
    force: bool = False,
) -> list[Path]:
    """Write ``count`` problems (indices 1..count) into ``out_dir`` as ``write_suite``
    does; return the ``.pddl`` paths.  Raises ``UsageError`` for bad arguments,
    ``InputFileError`` when the directory cannot be written."""
    check_suite_arguments(world, difficulty, count, seed, distractors)
    make = functools.partial(generate_problem, world, difficulty, seed, distractors=distractors)
    manifest = suite_manifest(GENERATOR_VERSION, world, difficulty, count, seed, distractors=distractors)
    return write_kitchen_suite(manifest, make, out_dir, progress, force)


def write_kitchen_suite(
    manifest: dict[str, Any],
    make_problem: Callable[[int], GeneratedProblem],
    out_dir: Path,
    progress: ProgressCallback | None = None,
    force: bool = False,
) -> list[Path]:
    """A suite of a kitchen world or variant (``write_suite``'s layout) of the world, difficulty and
    count ``manifest`` names (``suite_manifest``); problem ``i`` is ``make_problem(i)``."""
    world, difficulty, count = manifest["world"], manifest["difficulty"], manifest["count"]
    names = [problem_name(world, difficulty, index) for index in range(1, count + 1)]
    domain = DOMAINS_DIR / world / "domain.pddl"
    return write_suite(out_dir, domain, names, make_problem, manifest, "distractor_count", progress, force)


def suite_manifest(
    version: str, world: str, difficulty: str | None, count: int, seed: int, **settings: object
) -> dict[str, object]:
    """What a suite's ``suite.json`` says of how it was made (``settings``: the generator's own)."""
    return {
        "generator": GENERATOR,
        "generator_version": version,
        "world": world,
        "difficulty": difficulty,
        "count": count,
        "seed": seed,
        **settings,
    }


class Generated(Protocol):
    """A generated problem as a suite stores it: its name, its text and its sidecar."""

    @property
    def name(self) -> str: ...

    @property
    def pddl_text(self) -> str: ...

    @property
    def sidecar(self) -> dict[str, Any]: ...


def write_suite(
    out_dir: Path,
    domain_path: Path,
    names: list[str],
    make_problem: Callable[[int], Generated],
    manifest: dict[str, object],
    entry_field: str,
    progress: ProgressCallback | None = None,
    force: bool = False,
) -> list[Path]:
    """Write a suite (every generator's layout): ``domain.pddl``, ``NAME.pddl`` and
    ``NAME.json`` for each of ``names`` (problem ``i`` made by ``make_problem(i)``, 1-based),
    and ``suite.json`` (``manifest`` plus the file list, each problem's entry with its
    sidecar's ``entry_field``); return the ``.pddl`` paths.

    The suite is built in a temporary sibling directory, so a failure leaves
    no partial suite.  Into an existing directory only the generator's own
    files (those its ``suite.json`` lists) are replaced or removed; any other
    file stays.  A non-empty directory without a suite of ours, or a file of
    the user's with a name the generator would write, is refused unless
    ``force`` (which overwrites same-named files, and still deletes nothing).
    """
    out_dir = Path(os.path.abspath(os.fspath(out_dir)))
    planned = ["domain.pddl", "suite.json"] + [f"{name}{suffix}" for name in names for suffix in (".pddl", ".json")]
    previous = _check_out_dir(out_dir, planned, force)
    try:
        domain_bytes = domain_path.read_bytes()
    except OSError as error:
        raise InputFileError(f"cannot read the domain: {error.strerror or error}", path=str(domain_path)) from None

    parent = out_dir.parent
    try:
        parent.mkdir(parents=True, exist_ok=True)
        staging = Path(tempfile.mkdtemp(prefix=f".{out_dir.name}.", suffix=".tmp", dir=parent))
        # mkdtemp makes it 0700; the suite gets the mode mkdir would give it.
        os.chmod(staging, new_directory_mode())
    except OSError as error:
        raise InputFileError(f"cannot write the suite: {error.strerror or error}", path=str(out_dir)) from None

    try:
        (staging / "domain.pddl").write_bytes(domain_bytes)
        entries = []
        for index, name in enumerate(names, start=1):
            problem = make_problem(index)
            assert problem.name == name, (problem.name, name)
            _write_text(staging / f"{name}.pddl", problem.pddl_text)
            _write_text(staging / f"{name}.json", sidecar_json(problem.sidecar))
            entry = {"name": name, "problem": f"{name}.pddl", "sidecar": f"{name}.json"}
            entries.append({**entry, entry_field: problem.sidecar[entry_field]})
            if progress is not None:
                progress(ProgressEvent(done=index, total=len(names)))
        full_manifest = {**manifest, "domain": "domain.pddl", "problems": entries}
        _write_text(staging / "suite.json", sidecar_json(full_manifest))
        _move_into_place(staging, out_dir, planned, previous)
    except OSError as error:
        shutil.rmtree(staging, ignore_errors=True)
        raise InputFileError(f"cannot write the suite: {error.strerror or error}", path=str(out_dir)) from None
    except BaseException:
        shutil.rmtree(staging, ignore_errors=True)
        raise
    return [out_dir / entry["problem"] for entry in entries]


def _move_into_place(staging: Path, out_dir: Path, planned: list[str], previous: set[str]) -> None:
    """Rename ``staging`` to ``out_dir`` when there is nothing there yet;
    otherwise move each new file in (the manifest last) and remove the
    previous run's files that the new suite does not have.  Files the
    generator did not write are never touched."""
    if not out_dir.exists():
        os.rename(staging, out_dir)
        return
    if not any(out_dir.iterdir()):
        os.rmdir(out_dir)
        os.rename(staging, out_dir)
        return
    # The new manifest first: if we are stopped half-way, every file of ours
    # in the directory is still listed by it or by nothing (then left alone).
    for name in ["suite.json"] + [n for n in planned if n != "suite.json"]:
        os.replace(staging / name, out_dir / name)
    for name in sorted(set(previous) - set(planned)):
        old = out_dir / name
        if old.is_file() and not old.is_symlink():
            old.unlink()
    staging.rmdir()


def write_base_scenes(problems_dir: Path) -> list[Path]:
    """Write the four base scenes (``<world>-<difficulty>.pddl`` + ``.json``)."""
    problems_dir = Path(problems_dir)
    written: list[Path] = []
    try:
        problems_dir.mkdir(parents=True, exist_ok=True)
        for scene_name in SCENES:
            problem = base_scene_problem(scene_name)
            for suffix, text in ((".pddl", problem.pddl_text), (".json", problem.sidecar_text)):
                target = problems_dir / f"{scene_name}{suffix}"
                temporary = problems_dir / f".{scene_name}{suffix}.tmp"
                _write_text(temporary, text)
                os.replace(temporary, target)
            written.append(problems_dir / f"{scene_name}.pddl")
    except OSError as error:
        raise InputFileError(
            f"cannot write the base scenes: {error.strerror or error}", path=str(problems_dir)
        ) from None
    return written
