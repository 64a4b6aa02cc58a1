"""``cncmacro --version``: the version a user sees is the one the package, its metadata and the
editor extension carry."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

if sys.version_info >= (3, 11):
    import tomllib
else:  # the same reader the package uses on 3.10 (library/machine_file.py)
    import tomli as tomllib

import cncmacro

ROOT = Path(__file__).resolve().parents[2]


def test_version_is_printed_and_agrees_everywhere():
    done = subprocess.run([sys.executable, "-m", "cncmacro", "--version"], capture_output=True, text=True, timeout=60)
    assert (done.returncode, done.stdout.strip(), done.stderr) == (0, f"cncmacro {cncmacro.__version__}", "")
    project = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]["version"]
    extension = json.loads((ROOT / "package.json").read_text(encoding="utf-8"))["version"]
    assert cncmacro.__version__ == project == extension
