"""The worlds shipped with the package: kitchen domains, knowledge models, base scenes.

Files are found relative to this package, so an installed wheel never reads
the source tree (the top-level ``domains/``, ``problems/`` and ``examples/`` of
a checkout are links to these folders).
"""

from __future__ import annotations

from pathlib import Path

DATA_DIR = Path(__file__).resolve().parent
DOMAINS_DIR = DATA_DIR / "domains"
PROBLEMS_DIR = DATA_DIR / "problems"
EXAMPLES_DIR = DATA_DIR / "examples"
