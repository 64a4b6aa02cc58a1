"""What real shop programs (FANUC 0i/30i, Haas and GSK controls) taught: forms that a control
runs and that must not be reported, and mistakes that a control alarms on and that must be.

Each test names the docs/semantics.md section whose rule it proves.
"""

from __future__ import annotations

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
