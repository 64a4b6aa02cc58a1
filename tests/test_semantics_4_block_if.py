"""docs/semantics.md §4 "Block IF": ``IF [cond] THEN`` … ``ELSE`` … ``ENDIF`` on lines of their own,
behind ``Dialect.block_if`` (the ``mitsubishi-m70`` profile; docs/profiles.md "mitsubishi-m70").

Where the profile has it, the blocks after ``IF [cond] THEN`` run when the condition holds, those
after ``ELSE`` when it does not, and the run goes on after ``ENDIF``; blocks nest. An IF without its
ENDIF, an ELSE or ENDIF without its IF and a second ELSE are ``if-mismatch``, a jump into a branch
from outside it ``jump-into-if``; the run stops there with the format alarm. Elsewhere each of the
three lines is a ``dialect-feature`` error and the run stops at the IF with alarm 114. Every test
runs the same text under ``fanuc-0i`` too, where the behaviour differs.
"""

from __future__ import annotations

import pytest

from cncmacro.syntax.block_parser import parse_block
from cncmacro.syntax.document import ParsedDocument
from cncmacro.syntax.nodes import Else, EndIf, If
from running import lines, run
from static_helpers import at, check, coded

M70 = "mitsubishi-m70"
FANUC = "fanuc-0i"


def outcome(text: str, dialect: str) -> tuple[str, dict[int, float], int | None]:
    """(status, variables, 1-based line of the alarm or None) of a run."""
    m = run(text, dialect)
    return m.status, m.variables(), None if m.alarm is None else m.alarm.line + 1


# #1 = 7: 7 GT 5 holds, so #2 = 10; the ELSE branch (#2 = 20) is passed over; #3 = 10 + 1 = 11
CHOOSE = lines("O1000", "#1=7", "IF [#1 GT 5] THEN", "#2=10", "ELSE", "#2=20", "ENDIF", "#3=#2+1", "M30")


# ---------------------------------------------------------------------------------------------
# reading the lines


def test_4_block_if_reads_if_then_alone_else_and_endif_as_markers() -> None:
    [s] = parse_block("IF [#1 GT 5] THEN").statements
    assert isinstance(s, If) and s.opens_block and s.then is None and s.goto is None
    assert isinstance(parse_block("ELSE").statements[0], Else)
    assert isinstance(parse_block("N20 endif").statements[0], EndIf)
    assert not parse_block("IF [#1 GT 5] THEN #2=1").statements[0].opens_block  # the one-line form is as before
    assert parse_block("END1").statements[0].__class__.__name__ == "End"  # ENDIF is not END then IF


def test_4_block_if_pairs_nested_blocks_within_the_program() -> None:
    text = lines("IF [#1 GT 0] THEN", "IF [#2 GT 0] THEN", "#3=1", "ENDIF", "ELSE", "#3=2", "ENDIF", "M30")
    program = ParsedDocument(text).program
    assert [(f.if_line, f.else_line, f.endif_line) for f in program.if_blocks] == [(0, 4, 6), (1, None, 3)]
    assert program.if_problems == []


# ---------------------------------------------------------------------------------------------
# running it


def test_4_block_if_runs_the_then_branch_when_the_condition_holds() -> None:
    assert outcome(CHOOSE, M70) == ("completed", {1: 7, 2: 10, 3: 11}, None)
    assert outcome(CHOOSE, FANUC) == ("alarm", {1: 7}, 3)  # alarm 114 at the IF


def test_4_block_if_runs_the_else_branch_when_the_condition_fails() -> None:
    # #1 = 3: 3 GT 5 fails, so #2 = 20 and #3 = 20 + 1 = 21
    text = CHOOSE.replace("#1=7", "#1=3")
    assert outcome(text, M70) == ("completed", {1: 3, 2: 20, 3: 21}, None)
    assert outcome(text, FANUC)[0] == "alarm"


def test_4_block_if_without_else_passes_over_its_blocks_when_the_condition_fails() -> None:
    # #1 vacant: vacant GT 0 fails (vacant reads 0), so #2 stays vacant and #3 = 1
    text = lines("IF [#1 GT 0] THEN", "#2=5", "ENDIF", "#3=1", "M30")
    assert outcome(text, M70) == ("completed", {3: 1}, None)
    m = run(text, FANUC)
    assert m.status == "alarm" and m.alarm is not None and m.alarm.number == 114


def test_4_block_if_nests_three_deep_and_each_else_belongs_to_its_own_if() -> None:
    # #1 = 2: the outer IF (2 GT 0) holds; the middle (2 GT 1) holds; the inner (2 GT 3) fails, so its
    # ELSE sets #5 = 3; the outer ELSE (#5 = 9) is passed over. #6 = #5 * 10 = 30
    text = lines(
        "#1=2",
        "IF [#1 GT 0] THEN",
        "  IF [#1 GT 1] THEN",
        "    IF [#1 GT 3] THEN",
        "      #5=1",
        "    ELSE",
        "      #5=3",
        "    ENDIF",
        "  ELSE",
        "    #5=2",
        "  ENDIF",
        "ELSE",
        "  #5=9",
        "ENDIF",
        "#6=#5*10",
        "M30",
    )
    assert outcome(text, M70) == ("completed", {1: 2, 5: 3, 6: 30}, None)
    assert outcome(text, FANUC) == ("alarm", {1: 2}, 2)


def test_4_block_if_inside_a_while_loop_chooses_anew_each_pass() -> None:
    # #1 = 1..4: odd passes add 1 to #10, even passes add 100 to #20 -> #10 = 2 (passes 1, 3), #20 = 200
    text = lines(
        "#1=1",
        "WHILE [#1 LE 4] DO1",
        "IF [[#1 AND 1] EQ 1] THEN",
        "#10=#10+1",
        "ELSE",
        "#20=#20+100",
        "ENDIF",
        "#1=#1+1",
        "END1",
        "M30",
    )
    assert outcome(text, M70) == ("completed", {1: 5, 10: 2, 20: 200}, None)
    assert outcome(text, FANUC)[0] == "alarm"


def test_4_block_if_branches_move_the_tool() -> None:
    # #1 = 1 holds: X10. ; the ELSE branch's X20. is never cut; then Y5.
    text = lines("#1=1", "G90 G00 X0 Y0", "IF [#1 EQ 1] THEN", "G01 X10. F100", "ELSE", "G01 X20. F100", "ENDIF",
                 "G01 Y5.", "M30")  # fmt: skip
    m = run(text, M70)
    ends = [(mv.end[0], mv.end[1]) for mv in m.planner.moves]
    assert m.status == "completed" and ends[-2:] == [(10.0, 0.0), (10.0, 5.0)]
    assert run(text, FANUC).status == "alarm"


def test_4_block_if_a_goto_may_leave_a_branch() -> None:
    # #1 = 1 holds; the GOTO leaves the branch to N50: #2 = 1 and #3 (after ENDIF) never set, #4 = 4
    text = lines("#1=1", "IF [#1 EQ 1] THEN", "#2=1", "GOTO 50", "ENDIF", "#3=3", "N50 #4=4", "M30")
    assert outcome(text, M70) == ("completed", {1: 1, 2: 1, 4: 4}, None)
    assert check(text, M70) == []
    assert outcome(text, FANUC)[0] == "alarm"


# ---------------------------------------------------------------------------------------------
# what does not pair, and jumps into a branch


@pytest.mark.parametrize(
    ("text", "line", "said"),
    [
        (lines("#1=1", "IF [#1 EQ 1] THEN", "#2=1", "M30"), 2, "IF [...] THEN has no ENDIF in its program"),
        (lines("#1=1", "ELSE", "#2=1", "M30"), 2, "ELSE has no IF [...] THEN before it"),
        (lines("#1=1", "ENDIF", "M30"), 2, "ENDIF has no IF [...] THEN before it"),
    ],
)
def test_4_block_if_unmatched_markers_are_if_mismatch_and_stop_the_run(text: str, line: int, said: str) -> None:
    [d] = check(text, M70)
    assert (d.code, d.line + 1, d.severity) == ("if-mismatch", line, "error")
    assert d.message.startswith(said)
    m = run(text, M70)
    assert m.status == "alarm" and m.alarm is not None and m.alarm.line + 1 == line
    assert [d.code for d in check(text, FANUC)] == ["dialect-feature"]  # the FANUC finding, not a mismatch


def test_4_block_if_second_else_is_if_mismatch() -> None:
    text = lines("IF [#1 EQ 1] THEN", "#2=1", "ELSE", "#2=2", "ELSE", "#2=3", "ENDIF", "M30")
    [d] = check(text, M70)
    assert (d.code, *at(d)) == ("if-mismatch", 5, 0, 4, "error")
    assert d.message.startswith("a second ELSE for the IF [...] THEN whose ELSE is on line 3")
    assert d.related[0].line + 1 == 3


@pytest.mark.parametrize(
    "text",
    [
        # the loop starts inside the THEN branch and ends after the ENDIF
        lines("#1=0", "IF [#1 EQ 0] THEN", "WHILE [#1 LT 2] DO1", "#1=#1+1", "ENDIF", "END1", "M30"),
        # the loop starts before the IF and ends inside its branch
        lines("#1=0", "WHILE [#1 LT 2] DO1", "IF [#1 EQ 0] THEN", "#1=#1+1", "END1", "ENDIF", "M30"),
    ],
)
def test_4_block_if_crossing_a_loop_is_if_mismatch_and_stops_the_run(text: str) -> None:
    [d] = check(text, M70)
    assert (d.code, d.severity) == ("if-mismatch", "error")
    assert "a block IF and a loop may not cross" in d.message
    m = run(text, M70)
    assert m.status == "alarm" and m.alarm is not None
    assert str(m.alarm.message) == "a block IF [...] THEN and a WHILE/DO loop cross"
    assert "if-mismatch" not in [d.code for d in check(text, FANUC)]


def test_4_block_if_a_jump_into_a_branch_is_jump_into_if() -> None:
    text = lines("#1=0", "GOTO 10", "IF [#1 EQ 1] THEN", "N10 #2=1", "ENDIF", "M30")
    [d] = check(text, M70)
    assert (d.code, *at(d)) == ("jump-into-if", 2, 5, 7, "error")
    assert d.message.startswith("GOTO 10 jumps into a branch of the IF [...] THEN block (lines 3–5) from outside it")
    m = run(text, M70)
    assert m.status == "alarm" and m.alarm is not None and m.alarm.line + 1 == 2
    assert str(m.alarm.message) == "GOTO 10 jumps into a branch of an IF [...] THEN block from outside it"
    assert "jump-into-if" not in [d.code for d in check(text, FANUC)]


def test_4_block_if_then_followed_by_nc_words_is_nc_and_macro() -> None:
    text = lines("IF [#1 EQ 1] THEN G01 X5.", "ENDIF", "M30")
    assert [d.code for d in check(text, M70)] == ["nc-and-macro"]
    assert run(text, M70).alarm is not None and run(text, M70).alarm.number == 127  # type: ignore[union-attr]


# ---------------------------------------------------------------------------------------------
# elsewhere: today's finding, a dialect-feature error on each line, alarm 114


@pytest.mark.parametrize("profile", ["fanuc-0i", "fanuc-30i", "haas", "gsk980tdi"])
def test_4_block_if_is_a_dialect_feature_and_alarm_114_elsewhere(profile: str) -> None:
    found = coded(check(CHOOSE, profile), "dialect-feature")
    assert [(d.line + 1, d.column, d.end_column) for d in found] == [(3, 0, 17), (5, 0, 4), (7, 0, 5)]
    assert found[0].message.startswith("IF [...] THEN: the block form IF [...] THEN / ELSE / ENDIF is not a macro")
    assert "Mitsubishi M70/M80 and Mazak controls run it" in found[0].message
    m = run(CHOOSE, profile)
    assert m.status == "alarm" and m.alarm is not None and m.alarm.line + 1 == 3
    assert check(CHOOSE, M70) == []


def test_4_block_if_refused_is_said_in_chinese() -> None:
    [d, *_] = coded(check(CHOOSE, FANUC, locale="zh-CN"), "dialect-feature")
    assert "块形式 IF [...] THEN / ELSE / ENDIF" in d.message and "报警 114" in d.message
