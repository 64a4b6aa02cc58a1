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
