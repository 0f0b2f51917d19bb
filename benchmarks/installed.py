"""How the benchmarks that time whole commands run the tool: as installed, or from this checkout.

``installed_tool`` builds this checkout as a wheel and installs it in a new
virtual environment whose other packages come from the running one (a
``.pth`` line, which adds that folder to the path but runs none of its
hooks), and returns its ``relevance-plan`` script: what a user has, without
an editable install's import hook (~15 ms on every start).
``compiled_checkout`` runs the checkout itself, its bytecode compiled first
(where ``PYTHONDONTWRITEBYTECODE`` is set, every start would otherwise
compile every module again, ~0.1 s that no installed copy pays).

Run alone, it builds the installed copy in FOLDER (which must not exist)
and prints the path of its script, to time by hand; it takes about 15 s.

    python benchmarks/installed.py /tmp/relevance-plan-installed
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import sysconfig
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent


def installed_environment() -> dict[str, str]:
    """The environment to run the installed copy in: this one without ``PYTHONPATH``, which
    would put a checkout's ``relevance_plan`` before the installed one."""
    return {name: value for name, value in os.environ.items() if name != "PYTHONPATH"}


def installed_tool(folder: Path) -> list[str]:
    """The checkout as a user installs it: a wheel in a new virtual environment whose other
    packages come from this one (a ``.pth`` line, which adds a folder but runs none of its hooks).
    Run its command with ``installed_environment()``."""
    env = installed_environment()  # with a checkout on PYTHONPATH, pip takes the wheel as installed already
    subprocess.run(
        [sys.executable, "-m", "pip", "wheel", "-q", "--no-deps", "-w", str(folder / "wheel"), str(REPO)],
        check=True, env=env,
    )  # fmt: skip
    venv = folder / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True, env=env)
    python = venv / "bin" / "python"
    wheel = next((folder / "wheel").glob("*.whl"))
    subprocess.run([str(python), "-m", "pip", "install", "-q", "--no-deps", str(wheel)], check=True, env=env)
    site = subprocess.run(
        [str(python), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
        check=True, capture_output=True, text=True, env=env,
    ).stdout.strip()  # fmt: skip
    Path(site, "zz-dependencies.pth").write_text(sysconfig.get_paths()["purelib"] + "\n")
    script = venv / "bin" / "relevance-plan"
    if not script.is_file():
        raise SystemExit(f"the wheel installed no relevance-plan script in {venv}")
    return [str(script)]


def compiled_checkout() -> tuple[list[str], dict[str, str]]:
    """(command, environment) that run ``relevance-plan`` from this checkout, bytecode compiled."""
    subprocess.run([sys.executable, "-m", "compileall", "-q", str(REPO / "relevance_plan")], check=True)
    pythonpath = os.pathsep.join(filter(None, [str(REPO), os.environ.get("PYTHONPATH")]))
    return [sys.executable, "-m", "relevance_plan"], {**os.environ, "PYTHONPATH": pythonpath}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folder", type=Path, help="where the wheel and the virtual environment go (new)")
    args = parser.parse_args(argv)
    if args.folder.exists():
        parser.error(f"{args.folder} exists already")
    args.folder.mkdir(parents=True)
    print(installed_tool(args.folder)[0])
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
