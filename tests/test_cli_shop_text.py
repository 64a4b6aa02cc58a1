"""Text shops really write, through ``cncmacro check`` and ``cncmacro run`` (docs/semantics.md §1,
§2, §4; docs/cli.md): ``M30%`` on one line, a '(' inside a comment, a variable number with a
trailing point (``#504.``), ``M99O0810`` joining two programs of a dump file, Haas's IF before NC
words or before nothing, and ``--set`` when a shell has cut off the rest of the line."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from cli_capture import cli


def write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.write_text(text, encoding="utf-8")
    return path


def run(path: Path, *options: str) -> dict[str, Any]:
    """``cncmacro run --json`` of ``path``: the result object (the run exited 0)."""
    code, out, err = cli("run", "--json", "--no-save", *options, str(path))
    assert code == 0, err
    result: dict[str, Any] = json.loads(out)
    return result


def moves(result: dict[str, Any]) -> list[tuple[int, dict[str, float], dict[str, float]]]:
    """Each move as (line, from, to) with only the axes that changed."""
    out = []
    for m in result["moves"]:
        changed = [a for a in m["to"] if m["to"][a] != m["from"][a]]
        out.append((m["line"], {a: m["from"][a] for a in changed}, {a: m["to"][a] for a in changed}))
    return out


# ---- §1: the end code and the tape's end on one line


def test_1_end_code_and_tape_mark_on_one_line_runs_the_end_code(tmp_path: Path) -> None:
    path = write(tmp_path, "O1000.nc", "%\nO1000\nG00 X5.\nM30%\n")
    assert cli("check", str(path)) == (0, "", "")
    result = run(path)
    # two blocks run: G00 X5. and the M30 before the '%' (the header is no block)
    assert (result["status"], result["alarm"], result["blocks"]) == ("completed", None, 2)
    assert moves(result) == [(3, {"X": 0.0}, {"X": 5.0})]


def test_1_nothing_after_a_percent_that_follows_code_is_read(tmp_path: Path) -> None:
    path = write(tmp_path, "O1000.nc", "O1000\nG00 X5.\nM30% G00 X8.\nG01 X9. F100.\n")
    code, out, _ = cli("check", "--hints", str(path))
    assert code == 0 and out.startswith(f"{path}:3:1: hint: the tape ends at this '%': the line after it is")
    assert "[syntax]" not in out  # neither 'G00 X8.' after the '%' nor line 4 is read
    assert moves(run(path)) == [(2, {"X": 0.0}, {"X": 5.0})]


# ---- §1: a '(' inside a comment


def test_1_comment_ends_at_its_first_closing_parenthesis(tmp_path: Path) -> None:
    path = write(tmp_path, "O1001.nc", "O1001\n(CUT (ROUGH) PASS)\nG00 X5.\nM30\n")
    code, out, _ = cli("check", str(path))
    # "(CUT (ROUGH) " is 13 characters: the text read as code, "PASS)", starts at column 14
    assert code == 1 and out.count("\n") == 1
    assert out.startswith(f"{path}:2:14: error: 'PASS)' is read as program text: a comment ends at its first ')'")
    assert out.rstrip().endswith("[syntax]")
    code, out, _ = cli("run", "--json", "--no-save", str(path))
    result = json.loads(out)
    assert result["alarm"]["number"] == 125 and result["alarm"]["line"] == 2  # the control cannot read 'PASS)'


def test_1_open_parenthesis_inside_a_closed_comment_is_comment_text(tmp_path: Path) -> None:
    path = write(tmp_path, "O1001.nc", "O1001\n(DIA (50)\nG00 X50.\nM30\n")
    assert cli("check", str(path)) == (0, "", "")
    assert moves(run(path)) == [(3, {"X": 0.0}, {"X": 50.0})]


def test_1_closing_parenthesis_without_a_comment_says_so_in_chinese(tmp_path: Path) -> None:
    path = write(tmp_path, "O1001.nc", "O1001\nG00 X5.) (NOTE)\nM30\n")
    code, out, _ = cli("check", "--locale", "zh-CN", str(path))
    assert code == 1 and f"{path}:2:8:" in out and "')' 没有与之配对的 '('" in out


# ---- §2: a variable number with a trailing decimal point


def test_2_variable_number_with_a_trailing_point_is_that_variable(tmp_path: Path) -> None:
    text = "O1002\n#504.=#504.+1.\nIF[#504.EQ1]GOTO10\n#100=99\nN10 #101=#504.*2\nM30\n"
    path = write(tmp_path, "O1002.nc", text)
    assert cli("check", str(path)) == (0, "", "")
    result = run(path, "--set", "504=0")
    # #504 = 0 + 1 = 1; IF [1 EQ 1] jumps over #100=99 to N10; #101 = 1 * 2 = 2
    assert result["variables"] == {"504": 1.0, "101": 2.0}


def test_2_variable_number_with_decimals_names_the_rule_while_o_stays_whole(tmp_path: Path) -> None:
    path = write(tmp_path, "O1002.nc", "O1002\n#1=#2.5\nM30\nO1234.\nM99\n")
    code, out, _ = cli("check", str(path))
    assert code == 1
    assert f"{path}:2:6: error: a variable number is a whole number: '#2.5' names no variable" in out
    assert f"{path}:4:1: error: a program number must be a whole number written without a decimal point" in out


# ---- §1: one program's end and the next one's O number on one line (a dump file)


def test_1_end_and_next_program_number_on_one_line_start_that_program(tmp_path: Path) -> None:
    main = write(tmp_path, "MAIN.nc", "O1003\nM98 P0809\nM98 P0810\nM30\n")
    write(tmp_path, "DUMP.nc", "O0809\nG00 X9.\nM99O0810 (SECOND)\nG00 X1.\nM99\n")
    assert cli("check", str(main)) == (0, "", "")  # O0810 is found inside DUMP.nc
    assert cli("check", str(tmp_path)) == (0, "", "")
    result = run(main)
    # O0809 moves to X9 and returns at the M99 of line 3; O0810 starts after line 3, moves to X1, returns
    assert [(Path(m["file"]).name, m["line"]) for m in result["moves"]] == [("DUMP.nc", 2), ("DUMP.nc", 4)]
    assert moves(result) == [(2, {"X": 0.0}, {"X": 9.0}), (4, {"X": 9.0}, {"X": 1.0})]


def test_1_end_code_before_next_program_number_ends_a_main_program(tmp_path: Path) -> None:
    path = write(tmp_path, "PARTS.nc", "O0001\nG00 X1.\nM30O0002\nG00 X5.\nM30\n")
    result = run(path)
    # O0001 runs G00 X1. and ends at its M30; O0002's G00 X5. is not run
    assert (result["status"], result["blocks"]) == ("completed", 2)
    assert moves(result) == [(2, {"X": 0.0}, {"X": 1.0})]


# ---- §4: Haas's IF governs the rest of its block


HAAS_IF = "O01004\n#1=1\nIF [#1 GT 0] G01 X1. F10.\nIF [#1 LT 0] G01 X7. F10.\nIF [#1 GE 1] #101=5 G00 Y2.\nM30\n"


def test_4_haas_if_runs_the_words_after_it_only_when_the_condition_holds(tmp_path: Path) -> None:
    path = write(tmp_path, "O01004.nc", HAAS_IF)
    assert cli("check", "--dialect", "haas", str(path)) == (0, "", "")
    result = run(path, "--dialect", "haas")
    # #1 = 1: [1 GT 0] holds (X1.), [1 LT 0] does not (no X7.), [1 GE 1] holds (#101 = 5, then Y2.)
    assert moves(result) == [(3, {"X": 0.0}, {"X": 1.0}), (5, {"Y": 0.0}, {"Y": 2.0})]
    assert result["variables"] == {"1": 1.0, "101": 5.0}


def test_4_haas_if_with_nothing_after_it_warns_that_it_governs_nothing(tmp_path: Path) -> None:
    path = write(tmp_path, "O01005.nc", "O01005\n#1=1\nIF [#1 GT 0]\nG00 X5.\nM30\n")
    code, out, _ = cli("check", "--dialect", "haas", str(path))
    assert code == 0 and out.startswith(f"{path}:3:1: warning: IF [...] with nothing after it") and "[empty-if]" in out
    assert moves(run(path, "--dialect", "haas")) == [(4, {"X": 0.0}, {"X": 5.0})]


@pytest.mark.parametrize("dialect", ["fanuc-0i", "fanuc-30i", "gsk980tdi"])
def test_4_if_before_nc_words_is_alarm_114_where_the_if_governs_no_block(tmp_path: Path, dialect: str) -> None:
    path = write(tmp_path, "O1004.nc", "O1004\n#1=1\nIF [#1 GT 0] G01 X1. F10.\nIF [#1 GT 0]\nM30\n")
    code, out, _ = cli("check", "--dialect", dialect, str(path))
    assert code == 1
    assert "3:1: error: IF [...] followed by NC words:" in out and "alarm 114" in out
    assert "4:1: error: IF [...] with nothing after it:" in out and "[dialect-feature]" in out
    code, out, _ = cli("run", "--json", "--no-save", "--dialect", dialect, str(path))
    alarm = json.loads(out)["alarm"]
    assert (alarm["number"], alarm["line"]) == (114, 3)


# ---- docs/cli.md: --set when a shell cut off the rest of the line


@pytest.mark.parametrize(
    ("locale", "said"), [("en", "quote it (--set '#3026=1')"), ("zh-CN", "加引号（--set '#3026=1'）")]
)
def test_set_cut_off_by_a_shell_comment_says_to_leave_out_or_quote_the_hash(
    tmp_path: Path, locale: str, said: str
) -> None:
    path = write(tmp_path, "O1000.nc", "O1000\nM30\n")
    # ``cncmacro run FILE --set #3026=1`` in a shell: the shell drops '#3026=1' as a comment
    code, _, err = cli("run", "--locale", locale, str(path), "--set")
    assert code == 2 and "--set: expected one argument" in err and said in err
