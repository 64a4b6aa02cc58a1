"""Run the tests again under the oldest and the newest Python on this machine (``make test``).

cncmacro promises Python 3.10 to the newest. The main suite runs under the interpreter that made
``.venv``; this script finds the oldest and the newest supported interpreter (``tests/pythons.py``),
gives each its own ``.venv-<version>`` with the test dependencies (``--setup``: ``make setup`` makes
them, so that the tests need no network), and runs the Python suite there
(with ``--quick``: the part that covers each layer, parse, check, run, the machine file, an LSP
session and a DAP session) and the DAP client's tests. An interpreter the main suite already ran
under is not run twice; one that is missing is named with the reason, and the run goes on.
Exit status 1 when any run failed.
"""

from __future__ import annotations

import argparse
import hashlib
import os
import subprocess
import sys
import time
from pathlib import Path

from pythons import Interpreter, oldest_and_newest

ROOT = Path(__file__).resolve().parent.parent

# Each layer once: syntax, the dialects' tables, the machine file (tomllib or tomli), the
# interpreter, `check` and `run`, an LSP session over stdio, the debug adapter in Python and the
# MCP server through the SDK's client (the optional cncmacro[mcp], whose packages are compiled).
# What is the same on every Python stays in the main suite only: the language server's position
# encodings (arithmetic on str, which every version does alike) cost ten sessions here, the 1,500
# generated lines of the fast path's comparison with the grammar (its real lines and the 3.10 one
# stay) and the MCP tools one by one (one session lists them, one runs a program); of the language
# server's diagnostics, a session in each language (the rest is what every Python does alike); of
# the shared persistent file, runs started together (the locks). The debug adapter through the DAP
# client runs under the oldest Python only: the newest runs its protocol and history in Python.
QUICK = [
    "tests/test_seed_examples_parse.py",
    "tests/test_fast_path_equals_grammar.py::test_real_lines",
    "tests/test_fast_path_equals_grammar.py::test_lines_the_fast_path_leaves_to_the_grammar",
    "tests/test_fast_path_equals_grammar.py::test_python_3_10_reads_the_same_plain_lines_as_3_11",
    "tests/test_dialect_tables.py",
    "tests/test_machine_file_profile.py",
    "tests/test_run_4_control_flow.py",
    "tests/test_run_5_calls.py",
    "tests/test_cli_check.py",
    "tests/test_cli_run.py",
    "tests/test_dap_protocol_and_history.py",
    "tests/lsp/test_lsp_diagnostics.py::test_open_publishes_syntax_errors_with_the_version",
    "tests/lsp/test_lsp_diagnostics.py::test_incremental_edits_fix_the_error_and_only_the_newest_version_counts",
    "tests/lsp/test_lsp_diagnostics.py::test_severity_setting_changes_a_code_in_chinese_session",
    "tests/hardening/test_shared_state.py::test_runs_started_together_each_add_their_one",
    "tests/test_mcp_server.py::test_the_server_offers_four_read_only_tools",
    "tests/test_mcp_server.py::test_run_returns_a_10_mm_feed_move_at_600_mm_min_taking_1_s",
]
DAP_QUICK = ["tests/dap/debugger.test.js"]


def _say(text: str) -> None:
    print(f"[other pythons] {text}", flush=True)


def _venv(interpreter: Interpreter) -> Path:
    """``.venv-<major.minor>`` with cncmacro and its test dependencies, made again only when
    pyproject.toml changed."""
    venv = ROOT / f".venv-{interpreter.version[0]}.{interpreter.version[1]}"
    python = venv / "bin" / "python"
    stamp = venv / ".installed"
    wanted = hashlib.sha256((ROOT / "pyproject.toml").read_bytes()).hexdigest()
    if python.exists() and stamp.exists() and stamp.read_text(encoding="utf-8") == wanted:
        return venv
    _say(f"setting up {venv.name} for {interpreter.name}")
    subprocess.run([interpreter.executable, "-m", "venv", "--clear", str(venv)], check=True)
    pip = [str(python), "-m", "pip", "install", "--quiet", "--disable-pip-version-check"]
    subprocess.run([*pip, "-e", f"{ROOT}[test]"], check=True, cwd=ROOT)
    stamp.write_text(wanted, encoding="utf-8")
    return venv


def _run(interpreter: Interpreter, quick: bool, dap_client: bool = True) -> bool:
    venv = _venv(interpreter)
    python = str(venv / "bin" / "python")
    start = time.monotonic()
    tests = QUICK if quick else []
    env = dict(os.environ, CNCMACRO_TEST_PYTHON=python)
    ok = subprocess.run([python, "-m", "pytest", "-p", "no:cacheprovider", *tests], cwd=ROOT, env=env).returncode == 0
    if dap_client or not quick:
        ok = subprocess.run(["node", "--test", *DAP_QUICK], cwd=ROOT, env=env).returncode == 0 and ok
    _say(f"{interpreter.name}: {'passed' if ok else 'FAILED'} in {time.monotonic() - start:.0f} s")
    return ok


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="run the part of the suite that covers each layer")
    parser.add_argument(
        "--setup", action="store_true", help="only make (or bring up to date) each interpreter's .venv-3.N: make setup"
    )
    args = parser.parse_args(argv)
    main_version = sys.version_info[:2]
    found = oldest_and_newest()
    if not found:
        _say("skipped: no Python 3.10 or newer found besides the main one (looked in pyenv's versions and the PATH)")
        return 0
    if len(found) == 1:
        _say(f"only one supported Python here, {found[0].name}: there is no older or newer one to run under")
    roles = ["oldest", "newest"] if len(found) == 2 else ["only"]
    results = []
    for role, interpreter in zip(roles, found, strict=True):
        if interpreter.version[:2] == main_version:
            _say(f"{role}: {interpreter.name} is the main suite's interpreter, which ran everything above")
            continue
        _say(f"{role}: {interpreter.name} ({interpreter.executable})")
        if args.setup:
            venv = _venv(interpreter)  # and the package compiled for it, as make setup does for the main one
            subprocess.run([str(venv / "bin" / "python"), "-m", "compileall", "-q", "server"], cwd=ROOT, check=True)
            continue
        results.append(_run(interpreter, args.quick, dap_client=role != "newest"))
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
