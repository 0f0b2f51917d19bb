"""The field's benchmark corpus in ``benchmarks/corpus/``: check it against its manifest, list it.

The corpus holds PDDL files of the International Planning Competitions
(1998-2023), of Taskography, of Flax and of the hard-to-ground collection,
copied unchanged from public repositories;
``corpus/MANIFEST.json`` names each file's source, commit, path there,
sha256, size and track (``corpus/README.md`` says more).

    python benchmarks/corpus.py verify            # exit 1 naming each mismatch
    python benchmarks/corpus.py verify --json     # {"files": N, "domains": N, "tracks": {...}}
    python benchmarks/corpus.py list --track temporal

Other benchmarks import ``corpus_root()``, ``folders(track)`` and
``newest_of_each_family``: a folder is a path
``relevance_plan.io.find_suite_problems`` reads as it is.  Standard library
only.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import sys
from pathlib import Path

MANIFEST = "MANIFEST.json"
# Files of the corpus folder that are not corpus data and so not in the manifest.
OWN_FILES = {MANIFEST, "README.md", ".gitattributes"}


class CorpusError(Exception):
    """The manifest is missing or unreadable (``verify`` exits 1 with its one line)."""


def corpus_root() -> Path:
    """The corpus folder, ``benchmarks/corpus`` beside this file."""
    return Path(__file__).resolve().parent / "corpus"


def manifest(root: Path | None = None) -> dict:
    """The parsed manifest of the corpus at ``root`` (default: ``corpus_root()``)."""
    path = (root or corpus_root()) / MANIFEST
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise CorpusError(f"{path}: manifest not found") from None
    except (OSError, UnicodeDecodeError) as error:
        raise CorpusError(f"{path}: cannot read the manifest ({error})") from None
    except json.JSONDecodeError as error:
        raise CorpusError(f"{path}: not valid JSON (line {error.lineno}: {error.msg})") from None
    if (
        not isinstance(data, dict)
        or not isinstance(data.get("files"), list)
        or not isinstance(data.get("folders"), list)
    ):
        raise CorpusError(f"{path}: the manifest needs the lists 'files' and 'folders'")
    return data


def folders(track: str | None = None, root: Path | None = None) -> list[Path]:
    """The domain folders of the corpus (of ``track`` when given), in manifest order."""
    root = root or corpus_root()
    return [root / entry["path"] for entry in manifest(root)["folders"] if track is None or entry["track"] == track]


def benchmark_sets(root: Path | None = None) -> dict[str, dict]:
    """The benchmark sets (a set's name, e.g. ``taskographyv4medium5`` or ``mazenamo`` -> its manifest
    entry, paths made absolute): test problems of one benchmark, with their training problems, kept
    apart from the domain folders so that the field's sweeps do not plan them.

    A set is one folder of test problems (its ``training`` the folder of its training problems), or,
    when it has ``cells``, a folder of cells: each a folder of test or training problems (``role``)."""
    root = root or corpus_root()
    found = {}
    for entry in manifest(root).get("sets", []):
        folder = root / entry["path"]
        training = dict(entry.get("training", {}))
        if training:
            training["path"] = root / training["path"]
        cells = [{**cell, "path": root / cell["path"]} for cell in entry.get("cells", [])]
        name = entry.get("name", folder.name.removesuffix("_test"))
        found[name] = {**entry, "path": folder, "training": training, "cells": cells}
    return found


# Words that begin the part of a folder's name that names a form of its domain (the competition's
# variants: durations, numbers, STRIPS or ADL, compiled time windows).
FORM_WORDS = frozenset(
    {
        "time",
        "temporal",
        "metric",
        "numeric",
        "complex",
        "strips",
        "adl",
        "fluents",
        "automatic",
        "hand",
        "satisficing",
        "constraints",
        "compiled",
    }
)


def family_of(folder: Path) -> str:
    """The domain a folder holds a form of: its name up to the first form word, hyphens and a
    plural 's' dropped (``driver-log-temporal-satisficing`` and ``driverlog-time-automatic`` are
    both ``driverlog``)."""
    words = []
    for word in folder.name.split("-"):
        if word in FORM_WORDS:
            break
        words.append(word)
    return "".join(words).rstrip("s") or folder.name


def newest_of_each_family(chosen: list[tuple[str, Path]]) -> list[tuple[str, Path]]:
    """Of (track, folder) pairs in manifest order (oldest competition first), the last of each
    track and family: the newest competition's form."""
    newest = {(track, family_of(folder)): (track, folder) for track, folder in chosen}
    kept = set(newest.values())
    return [pair for pair in chosen if pair in kept]


def tracks(root: Path | None = None) -> dict[Path, str]:
    """Folder (resolved) -> its track, for every domain folder of the manifest."""
    root = root or corpus_root()
    return {(root / entry["path"]).resolve(): entry["track"] for entry in manifest(root)["folders"]}


def known_unreadable(root: Path | None = None) -> dict[str, str]:
    """Folder (relative to the corpus) -> the one-line error the project's reader gave for it."""
    return {entry["folder"]: entry["error"] for entry in manifest(root).get("known_unreadable", [])}


def scene_graph_files(root: Path | None = None) -> dict[str, Path]:
    """The scene graphs of the corpus (the manifest's ``scene_graphs`` section, not PDDL): file name -> path."""
    root = root or corpus_root()
    section = manifest(root).get("scene_graphs", {})
    return {Path(e["path"]).name: root / e["path"] for e in section.get("files", []) if e.get("role") == "scene-graph"}


def _sha256(path: Path) -> str:
    digest = hashlib.sha256()
    with open(path, "rb") as stream:
        for chunk in iter(lambda: stream.read(1 << 16), b""):
            digest.update(chunk)
    return digest.hexdigest()


def mismatches(root: Path | None = None) -> list[str]:
    """One line per difference between the corpus folder and its manifest; empty when they agree."""
    root = root or corpus_root()
    data = manifest(root)
    problems: list[str] = []
    listed: set[str] = set()
    scene_graphs = data.get("scene_graphs", {})
    for entry in data["files"] + scene_graphs.get("files", []):
        relative = entry.get("path", "")
        listed.add(relative)
        path = root / relative
        if not path.is_file():
            problems.append(f"{relative}: missing")
            continue
        if _sha256(path) != entry.get("sha256"):
            size = path.stat().st_size
            than = "" if size == entry.get("size") else f" (size {size}, manifest says {entry.get('size')})"
            problems.append(f"{relative}: sha256 differs from the manifest{than}")
    folder_paths = {entry["path"] for entry in data["folders"] + data.get("sets", [])}
    for relative in sorted({entry.get("folder") for entry in data["files"]} - folder_paths):
        problems.append(f"{relative}: files name this folder, but it is not in the manifest's folders")
    for relative in sorted(folder_paths):
        roles = {entry.get("role") for entry in data["files"] if entry.get("folder") == relative}
        if not {"domain", "problem"} <= roles:
            problems.append(f"{relative}: the manifest gives this folder no domain or no problem")
    graph_sets = {entry["path"] for entry in scene_graphs.get("sets", [])}
    for entry in scene_graphs.get("files", []):
        if entry.get("role") == "scene-graph" and entry.get("folder") not in graph_sets:
            problems.append(f"{entry.get('path')}: its folder is not among the manifest's scene-graph sets")
    for path in sorted(p for p in root.rglob("*") if p.is_file() or p.is_symlink()):
        relative = path.relative_to(root).as_posix()
        if relative not in listed and relative not in OWN_FILES:
            problems.append(f"{relative}: not in the manifest")
    return problems


def summary(root: Path | None = None) -> dict:
    """Files, domain folders and domain folders per track."""
    data = manifest(root)
    tracks: dict[str, int] = {}
    for entry in data["folders"]:
        tracks[entry["track"]] = tracks.get(entry["track"], 0) + 1
    counts = {"files": len(data["files"]), "domains": len(data["folders"]), "tracks": dict(sorted(tracks.items()))}
    graphs = data.get("scene_graphs", {})
    return {
        **counts,
        "sets": len(data.get("sets", [])),
        "scene_graph_sets": len(graphs.get("sets", [])),
        "scene_graph_files": len(graphs.get("files", [])),
    }


def _verify(args: argparse.Namespace) -> int:
    problems = mismatches(args.root)
    for line in problems:
        print(line, file=sys.stderr)
    if args.json:
        print(json.dumps(summary(args.root)))
    elif not problems:
        counts = summary(args.root)
        print(f"corpus ok: {counts['files']} files, {counts['domains']} domain folders")
    return 1 if problems else 0


def _list(args: argparse.Namespace) -> int:
    data = manifest(args.root)
    tracks = sorted({entry["track"] for entry in data["folders"]})
    if args.track is not None and args.track not in tracks:
        print(f"error: no track {args.track!r} in the corpus (tracks: {', '.join(tracks)})", file=sys.stderr)
        return 2
    problems: dict[str, int] = {}
    for entry in data["files"]:
        if entry.get("role") == "problem":
            problems[entry["folder"]] = problems.get(entry["folder"], 0) + 1
    for track in tracks if args.track is None else [args.track]:
        entries = [entry for entry in data["folders"] if entry["track"] == track]
        print(f"{track} ({len(entries)} folders)")
        for entry in entries:
            count = problems.get(entry["path"], 0)
            print(f"  {entry['path']}  {count} problem{'s' if count != 1 else ''}")
    return 0


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description="The benchmark corpus: check it against its manifest, list it. Takes under a second."
    )
    commands = parser.add_subparsers(dest="command", required=True)
    verify = commands.add_parser("verify", help="check every file against the manifest (exit 1 on a mismatch)")
    verify.add_argument("--json", action="store_true", help="print the counts of files, domains and tracks as JSON")
    listing = commands.add_parser("list", help="the domain folders by track, with their number of problems")
    listing.add_argument("--track", help="only this track (classical, adl, numeric, temporal, ...)")
    for command in (verify, listing):
        command.add_argument("--root", type=Path, default=None, help="the corpus folder (default: benchmarks/corpus)")
    args = parser.parse_args(argv)
    try:
        return _verify(args) if args.command == "verify" else _list(args)
    except CorpusError as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    except (KeyError, TypeError, AttributeError) as error:
        print(f"error: the manifest has an entry of the wrong form ({type(error).__name__}: {error})", file=sys.stderr)
        return 1
    except BrokenPipeError:  # the reader stopped early (``| head``): not an error
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except OSError as error:
        print(f"error: {error}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
