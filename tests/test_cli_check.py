"""``cncmacro check``: DESIGN.md's command-line contract (formats and exit status)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def run(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "cncmacro", *args], capture_output=True, text=True, cwd=cwd, timeout=120
    )


def test_examples_have_no_diagnostics():
    r = run("check", str(ROOT / "examples"))
    assert r.returncode == 0, r.stdout + r.stderr
    assert r.stdout == ""


def test_broken_line_is_reported_at_its_line_and_column(tmp_path):
    f = tmp_path / "O0001.nc"
    f.write_text("O0001\nG00 X0 Y0\n#1=[#2+3\nM30\n", encoding="utf-8")
    r = run("check", str(f))
    assert r.returncode == 1
    assert r.stdout == f"{f}:3:9: error: expected ']' to close the '[' at column 4 [syntax]\n"


def test_json_format(tmp_path):
    f = tmp_path / "bad.nc"
    f.write_text("G01 X\n", encoding="utf-8")
    r = run("check", "--format", "json", str(f))
    assert r.returncode == 1
    [d] = json.loads(r.stdout)
    assert d == {
        "file": str(f),
        "line": 1,
        "column": 5,
        "endLine": 1,
        "endColumn": 6,
        "severity": "error",
        "code": "syntax",
        "message": "the block ends too early; expected a value (a number, #variable or [expression])",
    }


def test_warnings_alone_exit_zero(tmp_path):
    f = tmp_path / "w.nc"
    f.write_text("G00 X0 (UNCLOSED\n", encoding="utf-8")
    r = run("check", str(f))
    assert r.returncode == 0 and ": warning: comment not closed" in r.stdout


def test_missing_path_and_binary_file_exit_two(tmp_path):
    assert run("check", str(tmp_path / "nope.nc")).returncode == 2
    b = tmp_path / "bin.nc"
    b.write_bytes(b"\x00\x01\x02G00")
    r = run("check", str(b))
    assert r.returncode == 2 and "binary file" in r.stderr


def test_bad_usage_exits_two():
    assert run("check").returncode == 2
    assert run("check", "--format", "xml", "x.nc").returncode == 2


def test_gbk_file_is_checked(tmp_path):
    f = tmp_path / "O0100.nc"
    f.write_bytes("O0100 (刀具)\nIF[#100<100]GOTO10\nN10 M30\n".encode("gbk"))
    r = run("check", str(f))
    assert r.returncode == 0, r.stdout + r.stderr
