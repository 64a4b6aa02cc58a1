"""``make demo``, the README's first command, prints only its own lines: what it runs, the run
and the checks, the planted mistakes under a plain line of their own, and no warnings of the
build tools or make's "Error 1 (ignored)"."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


@pytest.mark.skipif(shutil.which("make") is None, reason="needs make")
def test_make_demo_shows_the_run_the_checks_and_the_planted_mistakes_without_noise() -> None:
    venv = Path(sys.prefix)
    if not (venv / "bin" / "cncmacro").exists():
        pytest.skip("the tests do not run in a virtual environment with cncmacro installed")
    installed = venv / ".installed"
    # -o: take the environment as set up, whatever its stamp says (this one runs the tests)
    r = subprocess.run(
        ["make", "--no-print-directory", "-o", str(installed), "demo", f"VENV={venv}"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=300,
    )
    out = r.stdout + r.stderr
    assert r.returncode == 0, out
    assert "status: completed after" in out
    assert "examples: no problems found" in out
    lines = out.splitlines()
    heading = next(i for i, line in enumerate(lines) if "a program with three planted mistakes" in line)
    assert sum("O0999_broken.nc:" in line and "error:" in line for line in lines[heading + 1 :]) == 3
    for noise in ("Error 1", "ignored", "Warning", "Deprecat", "Traceback", ".venv/bin/cncmacro"):
        assert noise not in out, noise
