"""The command line called in-process for the tests of ``cncmacro run``: ``cli(*args)`` gives the
exit status, standard output and standard error a user would see (the ``examples`` fixture, a
copy of the bundled examples to run them in, is in conftest.py)."""

from __future__ import annotations

import io
import json
import sys
from pathlib import Path
from typing import Any

from cncmacro.cli.main import main


def cli(*args: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    old = sys.stdout, sys.stderr
    sys.stdout, sys.stderr = out, err
    try:
        code = main(list(args))
    except SystemExit as e:  # argparse usage errors
        code = int(e.code or 0)
    finally:
        sys.stdout, sys.stderr = old
    return code, out.getvalue(), err.getvalue()


def run_json(folder: Path, text: str, name: str = "MAIN.nc", machine_file: str | None = None) -> dict[str, Any]:
    """``cncmacro run --json`` of ``text`` saved as ``name`` in ``folder`` (with ``machine_file`` as its
    ``.cncmacro.toml``): the result object, the run having exited 0."""
    if machine_file is not None:
        (folder / ".cncmacro.toml").write_text(machine_file, encoding="utf-8")
    path = folder / name
    path.write_text(text, encoding="utf-8")
    code, out, err = cli("run", "--json", "--no-save", str(path))
    assert code == 0, err
    result: dict[str, Any] = json.loads(out)
    return result


def check_findings(folder: Path, text: str, machine_file: str | None = None, *extra: str) -> tuple[int, list[str]]:
    """``cncmacro check --hints`` of ``text`` saved as ``O0100.nc`` in ``folder`` (with
    ``machine_file`` as its ``.cncmacro.toml``): the exit status and the findings as
    ``line:column: severity: ... [code]`` without the file name."""
    (folder / "O0100.nc").write_text(text, encoding="utf-8")
    if machine_file is not None:
        (folder / ".cncmacro.toml").write_text(machine_file, encoding="utf-8")
    code, out, err = cli("check", "--hints", *extra, str(folder / "O0100.nc"))
    assert err == ""
    return code, [line.split(":", 1)[1] for line in out.splitlines()]
