"""What real shop programs (FANUC 0i/30i, Haas and GSK controls) taught: forms that a control
runs and that must not be reported, and mistakes that a control alarms on and that must be.

Each test names the docs/semantics.md section whose rule it proves.
"""

from __future__ import annotations

from cncmacro.analysis.workspace import WorkspaceAnalysis
from cncmacro.dap.breakpoints import Breakpoints
from running import alarm, final
from static_helpers import at, check, coded, lines

# ---------------------------------------------------------------- §3 bracket depth

# five nested pairs: the condition's, ABS's, two plain ones and the indirection's
FIVE_DEEP = "IF[ABS[#5061-[#31-[#[#111+2]]*#129]]GE#123]GOTO14"
SIX_DEEP = "IF[ABS[#5061-[#31-[#[[#111]+2]]*#129]]GE#123]GOTO14"


def test_3_expressions_bracket_depth_counts_indirection_once():
    text = lines("O1000", FIVE_DEEP, "N14 M30")
    assert coded(check(text), "bracket-depth") == []
    assert final(text) is not None


def test_3_expressions_six_real_bracket_levels_are_still_alarm_118():
    text = lines("O1000", SIX_DEEP, "N14 M30")
    found = coded(check(text), "bracket-depth")
    assert [at(d) for d in found] == [(2, 2, 45, "error")]
    assert "nested 6 deep" in found[0].message
    assert alarm(text) == (118, 2)


def test_3_expressions_indirection_inside_an_assignment_counts_once():
    assert check(lines("O1000", "#1=#[#[#[#[#[1]]]]]", "M30")) == []
    text = lines("O1000", "#1=#[#[#[#[#[#[1]]]]]]", "M30")
    assert [d.code for d in check(text)] == ["bracket-depth"]
    assert alarm(text) == (118, 2)


# ---------------------------------------------------------------- §3 long expressions

CHAIN = "#1=1" + "+1" * 500  # a generated line: 500 operators in a row
SIGNS = "#1=" + "-" * 1000 + "1"  # 1,000 unary minus signs


def test_3_expressions_500_chained_operators_evaluate_without_recursion():
    text = lines("O1000", CHAIN, "#2=2*3-1/2*4+7-3*2+1" + "-1+2" * 40, "M30")
    assert check(text) == []
    got = final(text)
    assert got[1] == 501 and got[2] == 2 * 3 - 1 / 2 * 4 + 7 - 3 * 2 + 1 + 40


def test_3_expressions_1000_unary_signs_evaluate_without_recursion():
    text = lines("O1000", SIGNS, "#2=" + "-" * 999 + "#0", "#3=" + "-+" * 300 + "2", "M30")
    assert check(text) == []
    got = final(text)
    assert got[1] == 1 and got[2] == 0 and got[3] == 2


def test_3_expressions_a_long_chain_still_divides_by_zero_as_alarm_112():
    assert alarm(lines("O1000", "#1=1" + "+1" * 40 + "/#5", "M30")) == (112, 2)


# ---------------------------------------------------------------- §1 the end of the tape


def test_1_text_and_blocks_a_dos_end_of_file_byte_after_the_closing_percent_is_not_read():
    text = "%\nO1000\n#1=1\nM30\n%\n\x1a"
    assert [(d.code, *at(d)) for d in check(text)] == [("after-tape-end", 5, 0, 1, "hint")]
    assert final(text)[1] == 1


def test_1_text_and_blocks_junk_after_the_closing_percent_is_only_a_hint():
    text = lines("O1000", "#1=1", "N10 M30", "%", "this is no program [[[", "GOTO 99", "O2000", "#1=#50")
    [d] = check(text)
    assert (d.code, *at(d)) == ("after-tape-end", 4, 0, 1, "hint")
    assert "the 4 lines after it (to line 8)" in d.message
    assert final(text)[1] == 1


def test_1_text_and_blocks_a_leading_percent_starts_the_tape_and_the_second_ends_it():
    text = lines("", "(TAPE START)", "%", "O1000", "#1=1", "%", "#1=5", "#2=[", "M30")
    assert [(d.code, d.line + 1) for d in check(text)] == [("after-tape-end", 6)]
    got = final(text)
    assert got[1] == 1 and 2 not in got  # the run ends at the closing '%'


def test_1_text_and_blocks_running_into_the_closing_percent_ends_the_program():
    text = lines("O1000", "#1=1", "%", "#1=2", "M30")
    assert final(text)[1] == 1


def test_1_text_and_blocks_a_dos_end_of_file_byte_without_percent_ends_the_file():
    assert check("O1000\n#1=1\nM30\n\x1a") == []
    assert check("O1000\n#1=1\nM30\n\x1a\n#1=[\n")[0].code == "after-tape-end"


def test_1_text_and_blocks_a_breakpoint_after_the_tape_end_is_never_reached(tmp_path):
    path = tmp_path / "O9100.nc"
    path.write_text("%\nO9100\n#100=1\nM99\n%\n#100=2\nM99\n", encoding="utf-8")
    made = Breakpoints().set_lines(str(path), [{"line": 3}, {"line": 6}])
    assert [(b.verified, b.line) for b in made] == [(True, 2), (False, None)]


def test_1_text_and_blocks_the_checker_passes_over_what_follows_the_tape(tmp_path):
    path = tmp_path / "O1000.nc"
    path.write_text("%\nO1000\nG65 P2000\nM30\n%\nO2000\n#1=1/0\nM99\nGOTO 5\n\x1a", encoding="utf-8")
    ws = WorkspaceAnalysis()
    ws.open(str(path), path.read_text(encoding="utf-8"), 1)
    result = ws.analyze(str(path))
    assert result is not None
    assert [(d.code, d.line + 1) for d in result.diagnostics[str(path)]] == [
        ("program-not-found", 3),  # O2000 after the end of the tape is not a program of the file
        ("not-executed", 4),
        ("after-tape-end", 5),
    ]
