"""Hostile inputs, each a file a user may really open: a 10 MB line, 1,000-deep brackets, a
binary file, NUL bytes, a GBK file with Chinese comments and program names, mixed line
breaks, an endless loop and recursion by M98 and G65. Each gets a clean diagnostic (or a
clean error from the command line) and never a crash, a RecursionError or a hang."""

from __future__ import annotations

import json
import os
import random
import subprocess
import sys
from pathlib import Path

import pytest

from cncmacro.analysis import Diagnostic
from cncmacro.analysis.workspace import WorkspaceAnalysis
from fuzzing import LspTarget, check_run, run_case

DEEP = 1000


def analyse(text: str, tmp_path: Path, name: str = "O0001.nc", max_blocks: int = 20_000) -> list[Diagnostic]:
    """The diagnostics of ``text`` as the checker finds them, hints included."""
    path = str(tmp_path / name)
    ws = WorkspaceAnalysis(max_blocks=max_blocks)
    ws.open(path, text, 1)
    result = ws.analyze(path)
    assert result is not None
    return result.diagnostics.get(path, [])


def codes(diags: list[Diagnostic]) -> list[str]:
    return [d.code for d in diags if d.code != "not-executed"]


def cli(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "cncmacro", *args], capture_output=True, text=True, timeout=120)


def test_a_10_mb_line_is_one_clean_diagnostic(ten_mb_line: str, tmp_path: Path, lsp_target: LspTarget) -> None:
    diags = analyse(ten_mb_line + "\nM30\n", tmp_path)
    [d] = [d for d in diags if d.code == "syntax"]
    assert d.line == 0 and "too long" in d.message
    assert d.end_column <= len(ten_mb_line)
    run_case(ten_mb_line, "fanuc", lsp_target, random.Random(1))  # every handler on it too


@pytest.mark.parametrize(
    "template",
    [
        "#1={open}1{close}",
        "IF[{open}#1 EQ 1{close}]GOTO10",
        "WHILE[{open}#1 LT 1{close}]DO1",
        "G01 X{open}#1{close}",
        "#1=#{open}1{close}",
        "#1=SIN{open}1{close}",
        "#1={open}1",  # never closed
    ],
)
def test_1000_deep_brackets_are_a_clean_diagnostic_not_a_recursion_error(template: str, tmp_path: Path) -> None:
    text = template.format(open="[" * DEEP, close="]" * DEEP)
    diags = analyse(f"O0001\n{text}\nM30\n", tmp_path)
    errors = [d for d in diags if d.severity == "error" and d.line == 1]
    assert errors, diags
    assert {d.code for d in errors} <= {"bracket-depth", "syntax"}
    assert check_run(f"O0001\n{text}\nM30\n", "fanuc", str(tmp_path / "O0001.nc")) in ("alarm", "completed")


def test_a_binary_file_is_named_and_skipped_while_the_others_are_checked(tmp_path: Path) -> None:
    (tmp_path / "O0002.nc").write_bytes(bytes(range(256)) * 64)
    (tmp_path / "O0003.nc").write_text("O0003\n#1=[1\nM30\n", encoding="utf-8")
    r = cli("check", str(tmp_path))
    assert r.returncode == 2
    assert "O0002.nc: binary file" in r.stderr
    assert "O0003.nc:2:" in r.stdout and "[syntax]" in r.stdout


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs named pipes")
@pytest.mark.parametrize("command", ["check", "run"])
def test_a_pipe_or_a_device_named_on_the_command_line_is_refused_at_once(tmp_path: Path, command: str) -> None:
    pipe = tmp_path / "O0004.nc"
    os.mkfifo(pipe)
    for path in (str(pipe), os.devnull):
        r = subprocess.run([sys.executable, "-m", "cncmacro", command, path], capture_output=True, text=True,
                           timeout=20)  # fmt: skip
        assert r.returncode == 2, r
        assert f"{path}: a " in r.stderr and "not a file: not read" in r.stderr


def test_nul_bytes_in_an_open_document_are_syntax_errors_on_their_lines(tmp_path: Path, lsp_target: LspTarget) -> None:
    text = "O0001\nG01 X1\0Y2\n#1=\0\nM30\n"
    diags = analyse(text, tmp_path)
    assert sorted({d.line for d in diags if d.code == "syntax"}) == [1, 2]
    assert any("U+0000" in d.message for d in diags)
    run_case(text, "fanuc", lsp_target, random.Random(2))


def test_a_gbk_file_with_chinese_comments_and_program_names_is_checked_and_run(tmp_path: Path) -> None:
    main = "(cncmacro: dialect=gsk980tdi)\r\nO0001 (主程序 粗车)\r\n#100=0 (计数器)\r\nG65 P[切削] A2\r\nM30\r\n"
    sub = "(cncmacro: dialect=gsk980tdi)\n(切削程序)\n#101=#1*2 (两倍)\nM99\n"
    (tmp_path / "O0001.CNC").write_bytes(main.encode("gbk"))
    (tmp_path / "切削.CNC").write_bytes(sub.encode("gbk"))
    r = cli("check", str(tmp_path))
    assert (r.returncode, r.stdout, r.stderr) == (0, "", "")
    r = cli("run", "--no-save", "--json", str(tmp_path / "O0001.CNC"))
    assert r.returncode == 0, r.stderr
    assert json.loads(r.stdout)["variables"] == {"100": 0.0, "101": 4.0}


def test_mixed_line_breaks_keep_every_line_and_column(tmp_path: Path, lsp_target: LspTarget) -> None:
    text = "O0001\r\nG00 X0\r#1=[#2+3\n\r\nG01 X#1\r\n#2=#1/0\rM30\r\n"
    diags = analyse(text, tmp_path)
    [syntax] = [d for d in diags if d.code == "syntax"]
    assert (syntax.line, syntax.column) == (2, 8)  # '#1=[#2+3' is the third line, whatever ends it
    run_case(text, "fanuc", lsp_target, random.Random(3))


def test_an_endless_loop_ends_at_the_block_budget_with_run_limit(tmp_path: Path) -> None:
    for body in ("N1 #100=#100+1\nGOTO1", "WHILE[1 EQ 1]DO1\n#100=#100+1\nEND1"):
        diags = analyse(f"O0001\n{body}\nM30\n", tmp_path, max_blocks=5_000)
        assert codes(diags) == ["run-limit"], body
        assert "5000 blocks" in diags[0].message or "5000 blocks" in diags[-1].message
    # a loop that changes nothing stops sooner, as an endless loop (tests/test_diagnostics_run_endless_loop.py)
    diags = analyse("O0001\nDO1\nEND1\nM30\n", tmp_path, max_blocks=5_000)
    assert codes(diags) == ["run-limit"] and diags[0].message.startswith("an endless loop")


def test_a_self_recursive_m98_is_a_nesting_depth_error(tmp_path: Path) -> None:
    diags = analyse("O0001\nM98 P0002\nM30\nO0002\nM98 P0002\nM99\n", tmp_path)
    assert codes(diags) == ["nesting-depth"]
    assert "alarm 77" in diags[0].message or any("alarm 77" in d.message for d in diags)


def test_g65_recursion_is_a_nesting_depth_error_and_so_is_recursion_through_two_macros(tmp_path: Path) -> None:
    diags = analyse("O0001\nG65 P0002 A1\nM30\nO0002\nG65 P0002 A[#1+1]\nM99\n", tmp_path)
    assert codes(diags) == ["nesting-depth"]
    diags = analyse("O0001\nG65 P0002 A1\nM30\nO0002\nG65 P0003 A1\nM99\nO0003\nG65 P0002 A1\nM99\n", tmp_path)
    assert codes(diags) == ["nesting-depth"]
    assert any("122" in d.message for d in diags)


def test_recursion_in_cncmacro_run_stops_with_its_alarm(tmp_path: Path) -> None:
    f = tmp_path / "O0001.nc"
    f.write_text("O0001\nM98 P0002\nM30\nO0002\nM98 P0002\nM99\n", encoding="utf-8")
    r = cli("run", "--no-save", "--json", str(f))
    assert r.returncode == 1
    assert json.loads(r.stdout)["alarm"]["number"] == 77


def test_a_constant_address_in_1000_brackets_runs_without_a_recursion_error(tmp_path: Path) -> None:
    """A literal in brackets in an NC address is taken as the literal (no alarm 118, as
    docs/semantics.md's constant addresses); 1,000 of them used to overflow the interpreter."""
    text = f"O0001\nG01 X{'[' * DEEP}1.5{']' * DEEP} F100\nM30\n"
    assert check_run(text, "fanuc", str(tmp_path / "O0001.nc")) == "completed"
    assert codes(analyse(text, tmp_path)) == []


def test_an_endless_loop_of_pauses_stops_at_exactly_its_budget(tmp_path: Path) -> None:
    """Found by the fuzzer: a pause (M00, #3006) on the budget's last block let ``cncmacro
    run`` go on one block at a time past ``--max-blocks``."""
    f = tmp_path / "O0001.nc"
    f.write_text("O0001\nN1 M00\nGOTO1\nM30\n", encoding="utf-8")
    for budget in (10, 11, 1000):
        r = cli("run", "--no-save", "--json", "--max-blocks", str(budget), str(f))
        assert r.returncode == 3, r.stderr
        assert json.loads(r.stdout)["blocks"] == budget
        assert check_run("O0001\nN1 M00\nGOTO1\nM30\n", "fanuc", str(f), budget) == "limit"
