"""docs/semantics.md §4 "Control flow": where a jump lands and which loops it leaves, on the
interpreter (``GOTO``, ``IF..GOTO``, gsk980tdi ``G65 H80``–``H86``) and in the static check,
which must agree: a jump stays in the loops that hold both its line and its target (a loop
holds the lines after its DO up to its END), leaves the others, and may not enter one."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from cncmacro.machine.jumps import LoopSpans
from running import alarm, final, lines
from static_helpers import check, coded


def jumps_into_a_loop(program: str, dialect: str = "fanuc") -> list[int]:
    """The 1-based lines the static check reports as jumping into a loop."""
    return [d.line + 1 for d in coded(check(program, dialect), "jump-into-loop")]


def test_4_control_flow_goto_from_an_inner_loop_into_the_outer_one_keeps_the_outer_loop():
    program = lines(
        "#1=0",
        "#3=0",
        "WHILE[#1 LT 3]DO1",
        "#1=#1+1",
        "#2=0",
        "WHILE[#2 LT 10]DO2",
        "#2=#2+1",
        "IF[#2 EQ 2]GOTO20",
        "END2",
        "N20 #3=#3+#2",
        "END1",
        "M30",
    )
    v = final(program)
    assert (v[1], v[3]) == (3, 6)
    assert jumps_into_a_loop(program) == []


def test_4_control_flow_goto_to_a_labelled_end_stays_in_that_loop():
    program = lines(
        "#1=0",
        "#3=0",
        "WHILE[#1 LT 4]DO1",
        "#1=#1+1",
        "WHILE[1 EQ 1]DO2",
        "#3=#3+1",
        "GOTO20",
        "END2",
        "N20 END1",
        "M30",
    )
    v = final(program)
    assert (v[1], v[3]) == (4, 4)
    assert jumps_into_a_loop(program) == []


def test_4_control_flow_goto_back_to_its_own_loop_head_starts_the_loop_again():
    # Each pass leaves the loop and enters it again at its WHILE: ten passes never count as
    # loops nested more than three deep.
    program = lines("#1=0", "N10 WHILE[#1 LT 10]DO1", "#1=#1+1", "GOTO10", "END1", "M30")
    assert final(program)[1] == 10


def test_4_control_flow_goto_into_an_inner_loop_from_the_outer_one_is_an_error():
    program = lines(
        "#1=0",
        "WHILE[#1 LT 3]DO1",
        "#1=#1+1",
        "GOTO20",
        "WHILE[#2 LT 3]DO2",
        "N20 #2=#2+1",
        "END2",
        "END1",
        "M30",
    )
    assert alarm(program) == (126, 4)
    assert jumps_into_a_loop(program) == [4]


def test_4_control_flow_gsk_h_code_branch_out_of_a_loop_is_allowed():
    program = lines("#1=0", "WHILE[#1 LT 100]DO1", "#1=#1+1", "G65 H81 P50 Q#1 R7", "END1", "N50 #100=#1", "M30")
    assert final(program, "gsk980tdi")[100] == 7
    assert jumps_into_a_loop(program, "gsk980tdi") == []


def test_4_control_flow_gsk_h_code_branch_into_a_loop_is_an_error():
    program = lines("G65 H80 P10", "WHILE[#1 LT 3]DO1", "N10 #1=#1+1", "END1", "M30")
    assert alarm(program, "gsk980tdi") == (126, 1)
    assert jumps_into_a_loop(program, "gsk980tdi") == [1]


# Loops as the tables of a program hold them: DO line -> END line (0-based), DO1 at 2..10
# holding DO2 at 5..8.
NESTED = {2: 10, 5: 8}


@pytest.mark.parametrize(
    ("from_line", "target", "entered", "kept"),
    [
        (7, 9, None, 1),  # out of DO2, still in DO1
        (7, 8, None, 2),  # to END2: still in both
        (7, 5, None, 1),  # to the DO2 line itself: out of DO2, which starts again
        (7, 11, None, 0),  # out of both
        (3, 6, 5, 1),  # into DO2 from DO1
        (0, 3, 2, 0),  # into DO1 from outside
        (0, 2, None, 0),  # to the DO1 line: not inside it
    ],
)
def test_4_control_flow_loops_a_jump_leaves_and_enters(from_line, target, entered, kept):
    spans = LoopSpans(NESTED)
    assert spans.entered(from_line, target) == entered
    if entered is None:
        assert spans.kept(from_line, target) == kept


_loops = st.dictionaries(st.integers(0, 60), st.integers(0, 60)).map(
    lambda pairs: {do: end for do, end in pairs.items() if end > do}
)


@given(_loops, st.integers(-1, 62), st.integers(-1, 62))
def test_4_control_flow_loops_held_are_found_however_loops_lie(loops, from_line, target):
    """Nested, side by side or crossing (a program with a misplaced END): the loops a jump
    enters and stays in are those the rule names, found without looking at every loop."""
    spans = LoopSpans(loops)
    holding = sorted((do, end) for do, end in loops.items() if do < target <= end)
    assert sorted(spans.holding(target)) == holding
    entered = [do for do, end in holding if not do < from_line <= end]
    assert spans.entered(from_line, target) == (min(entered) if entered else None)
    assert spans.kept(from_line, target) == sum(1 for do, end in holding if do < from_line <= end)


def test_4_control_flow_goto_lands_on_a_label_whose_block_does_not_parse():
    """``N20`` stays a label on a line the control cannot read: the GOTO lands there and the run
    stops on that line with the format alarm, not at the GOTO with "no N20" (alarm 128)."""
    program = lines("O0001", "#1=1", "IF[#1 EQ 1] GOTO 20", "#2=5", "N20 G01 X1-2.", "M30")
    assert alarm(program) == (125, 5)
    assert coded(check(program), "undefined-label") == []
