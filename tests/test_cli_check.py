"""``cncmacro check``: docs/design.md's command-line contract (formats and exit status)."""

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
    f.write_bytes("O0100 (刀具)\nIF[#100 LT 100]GOTO10\nN10 M30\n".encode("gbk"))  # fanuc spells LT
    r = run("check", str(f))
    assert r.returncode == 0, r.stdout + r.stderr


def test_run_found_error_in_a_called_macro_is_reported_in_its_file(tmp_path):
    (tmp_path / "MAIN.nc").write_text("O0001\nG65 P9001 A0\nM30\n", encoding="utf-8")
    (tmp_path / "O9001.nc").write_text("O9001\n#2=1/#1\nM99\n", encoding="utf-8")
    r = run("check", "--format", "json", str(tmp_path))
    assert r.returncode == 1, r.stdout + r.stderr
    found = [(Path(d["file"]).name, d["line"], d["code"]) for d in json.loads(r.stdout)]
    assert found == [("O9001.nc", 2, "division-by-zero")]


def test_max_blocks_and_hints(tmp_path):
    f = tmp_path / "O0001.nc"
    f.write_text("O0001\nN1 #1=#1+1\nGOTO1\nM30\n", encoding="utf-8")
    r = run("check", "--max-blocks", "50", "--hints", str(f))
    assert r.returncode == 0, r.stdout + r.stderr
    assert "[run-limit]" in r.stdout and "after 50 blocks" in r.stdout
    assert f"{f}:4:1: hint:" in r.stdout and "[not-executed]" in r.stdout
    assert "[not-executed]" not in run("check", "--max-blocks", "50", str(f)).stdout
    assert run("check", "--max-blocks", "0", str(f)).returncode == 2


def test_dialect_option_takes_effect(tmp_path):
    f = tmp_path / "O0001.nc"
    f.write_text("O0001\n#1=10000\nG65 P9001 L#1\nM30\nO9001\nM99\n", encoding="utf-8")
    fanuc = json.loads(run("check", "--format", "json", str(f)).stdout)
    gsk = json.loads(run("check", "--format", "json", "--dialect", "gsk980tdi", str(f)).stdout)
    assert [(d["line"], d["severity"]) for d in fanuc if d["code"] == "repeat-count-range"] == [(3, "error")]
    assert [(d["line"], d["severity"]) for d in gsk if d["code"] == "repeat-count-range"] == [(3, "warning")]


def test_path_option_finds_called_programs(tmp_path):
    lib = tmp_path / "lib"
    lib.mkdir()
    (lib / "O8001.nc").write_text("O8001\n#2=SQRT[-1]\nM99\n", encoding="utf-8")
    main = tmp_path / "main"
    main.mkdir()
    f = main / "MAIN.nc"
    f.write_text("O0001\n#1=8001\nG65 P#1\nM30\n", encoding="utf-8")
    without = json.loads(run("check", "--format", "json", str(f)).stdout)
    assert [d["code"] for d in without] == ["program-not-found"]
    found = json.loads(run("check", "--format", "json", "--path", str(lib), str(f)).stdout)
    assert [(Path(d["file"]).name, d["line"], d["code"]) for d in found] == [("O8001.nc", 2, "argument-range")]


def test_locale_and_sarif(tmp_path):
    f = tmp_path / "O0001.nc"
    f.write_text("O0001\n#1=0\n#2=5/#1\nM30\n", encoding="utf-8")
    r = run("check", "--locale", "zh-CN", str(f))
    assert r.returncode == 1 and "除数为零" in r.stdout
    sarif = json.loads(run("check", "--format", "sarif", str(f)).stdout)
    [result] = sarif["runs"][0]["results"]
    assert result["ruleId"] == "division-by-zero"


def test_each_file_is_checked_with_its_nearest_machine_file(tmp_path):
    for name, calls in (("mill", "M60 = 9020"), ("lathe", "M31 = 9020")):
        folder = tmp_path / name
        folder.mkdir()
        (folder / ".cncmacro.toml").write_text(f"[variables]\n100 = 4\n[calls]\n{calls}\n", encoding="utf-8")
        code = calls.split()[0]
        (folder / "MAIN.nc").write_text(f"O0001\n{code}\n#1=1/#100\nM30\n", encoding="utf-8")
        (folder / "O9020.nc").write_text("O9020\n#2=5/[#100-4]\nM99\n", encoding="utf-8")
    r = run("check", "--format", "json", str(tmp_path / "mill"), str(tmp_path / "lathe"))
    found = sorted((Path(d["file"]).parent.name, Path(d["file"]).name, d["line"], d["code"])
                   for d in json.loads(r.stdout))  # fmt: skip
    assert found == [("lathe", "O9020.nc", 2, "division-by-zero"), ("mill", "O9020.nc", 2, "division-by-zero")]
    assert r.returncode == 1


def test_a_print_whose_text_has_no_closing_bracket_says_so_not_expected_what_it_got(tmp_path):
    # "unexpected '['; expected '[' with the text to print" named the very character it refused
    f = tmp_path / "O0001.nc"
    f.write_text("O0001\nBPRNT[X#1[53]\nDPRNT[RATE*50%]\nM30\n", encoding="utf-8")  # the '%' ends the tape
    r = run("check", str(f))
    said = "error: the text to print has no closing ']' on this line (nor can it hold a '%', which ends the tape)"
    assert r.stdout == f"{f}:2:6: {said} [syntax]\n{f}:3:6: {said} [syntax]\n"
