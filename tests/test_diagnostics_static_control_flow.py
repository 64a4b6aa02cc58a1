"""Static diagnostics of docs/semantics.md §4 "Control flow" (and the M98 Q / M99 P labels of §5):
labels, loops and jumps, checked without running the program, and in agreement with the run."""

from __future__ import annotations

from running import alarm
from static_helpers import at, check, coded, lines

# ---------------------------------------------------------------- undefined-label


def test_4_control_flow_goto_to_a_missing_label_is_an_error():
    text = lines("O1000", "#1=1", "GOTO 20", "N10 #1=2", "M30")
    found = coded(check(text), "undefined-label")
    assert [at(d) for d in found] == [(3, 5, 7, "error")]
    assert "N20" in found[0].message
    assert alarm(text)[0] == 128  # the run agrees


def test_4_control_flow_goto_to_an_existing_label_is_fine_forward_and_backward():
    text = lines("O1000", "N10 #1=#1+1", "IF[#1 LT 3] GOTO 10", "GOTO 30", "#2=1", "N30 M30")
    assert check(text) == []


def test_4_control_flow_if_goto_searches_only_its_own_o_program():
    text = lines("O1000", "IF[#1 EQ 0] GOTO 50", "M30", "O2000", "N50 M99")
    found = coded(check(text), "undefined-label")
    assert [at(d) for d in found] == [(2, 17, 19, "error")]
    assert "O1000" in found[0].message


def test_4_control_flow_goto_with_a_variable_target_is_left_to_the_run():
    assert check(lines("O1000", "#1=77", "GOTO #1", "M30")) == []


def test_4_control_flow_goto_bracketed_literal_target_is_checked():
    found = coded(check(lines("O1000", "GOTO[40]", "M30")), "undefined-label")
    assert [at(d) for d in found] == [(2, 4, 8, "error")]


def test_7_h_code_branch_to_a_missing_label_is_an_error_on_gsk980tdi():
    text = lines("O0300", "G65 H81 P40 Q#1 R0", "N30 M30")
    found = coded(check(text, "gsk980tdi"), "undefined-label")
    assert [at(d) for d in found] == [(2, 9, 11, "error")]
    assert check(lines("O0300", "G65 H81 P30 Q#1 R0", "N30 M30"), "gsk980tdi") == []


# ---------------------------------------------------------------- label-range


def test_4_control_flow_goto_label_outside_1_to_99999_is_an_error():
    text = lines("O1000", "GOTO 100000", "M30")
    found = coded(check(text), "label-range")
    assert [at(d) for d in found] == [(2, 5, 11, "error")]
    assert coded(check(text), "undefined-label") == []
    assert alarm(text) == (128, 2)
    assert [at(d) for d in coded(check(lines("O1000", "IF[#1 EQ 0] GOTO 0", "M30")), "label-range")] == [
        (2, 17, 18, "error")
    ]


def test_4_control_flow_goto_99999_is_in_range():
    assert check(lines("O1000", "GOTO 99999", "N99999 M30")) == []


# ---------------------------------------------------------------- duplicate-label


def test_4_control_flow_duplicate_label_that_is_a_jump_target_is_a_warning():
    text = lines("O1000", "GOTO 10", "N10 #1=1", "N10 #1=2", "M30")
    found = coded(check(text), "duplicate-label")
    assert [at(d) for d in found] == [(4, 0, 3, "warning")]
    assert found[0].related and found[0].related[0].line == 2


def test_4_control_flow_duplicate_label_nobody_jumps_to_is_not_reported():
    assert check(lines("O1000", "N10 G00 X0", "N10 G00 X1", "M30")) == []


def test_4_control_flow_same_label_in_two_o_programs_is_not_a_duplicate():
    assert check(lines("O1000", "GOTO 10", "N10 M30", "O2000", "N10 M99")) == []


# ---------------------------------------------------------------- loops


def test_4_control_flow_do_without_end_is_a_loop_mismatch():
    # a warning by itself: the control raises 124 only where the condition is false (docs/semantics.md §4)
    text = lines("O1000", "#1=5", "WHILE[#1 LT 3] DO1", "#1=#1+1", "M30")
    found = coded(check(text), "loop-mismatch")
    assert [at(d) for d in found] == [(3, 0, 18, "warning")]
    assert "124" in found[0].message
    assert alarm(text)[0] == 124


def test_4_control_flow_end_without_do_and_crossing_loops_are_loop_mismatches():
    found = coded(check(lines("O1000", "#1=1", "END 2", "M30")), "loop-mismatch")
    assert [at(d) for d in found] == [(3, 0, 5, "error")]
    crossing = lines("O1000", "WHILE[#1 LT 3] DO1", "WHILE[#2 LT 3] DO2", "END1", "END2", "M30")
    found = coded(check(crossing), "loop-mismatch")
    assert [at(d) for d in found] == [(4, 0, 4, "error")]
    assert found[0].related[0].line == 2


def test_4_control_flow_paired_nested_loops_are_fine():
    text = lines("O1000", "WHILE[#1 LT 3] DO1", "WHILE[#2 LT 3] DO2", "#2=#2+1", "END2", "#1=#1+1", "END1", "M30")
    assert check(text) == []


def test_4_control_flow_loop_number_outside_1_to_3_is_an_error():
    text = lines("O1000", "WHILE[#1 LT 3] DO4", "#1=#1+1", "END4", "M30")
    found = coded(check(text), "loop-number")
    assert [at(d) for d in found] == [(2, 17, 18, "error"), (4, 3, 4, "error")]
    assert coded(check(text), "loop-mismatch") == []
    assert alarm(text) == (126, 2)


def test_4_control_flow_loops_nested_four_deep_are_a_loop_number_error():
    text = lines("O1000", "DO1", "DO2", "DO3", "WHILE[#1 LT 1] DO1", "END1", "END3", "END2", "END1", "M30")
    found = coded(check(text), "loop-number")
    assert [at(d) for d in found] == [(5, 0, 18, "error")]
    three = lines("O1000", "WHILE[#1 LT 1] DO1", "WHILE[#1 LT 1] DO2", "WHILE[#1 LT 1] DO3", "END3", "END2",
                  "END1", "M30")  # fmt: skip
    assert check(three) == []


def test_4_control_flow_a_loop_number_may_be_reused_after_its_loop_ends():
    text = lines("O1000", "WHILE[#1 LT 3] DO1", "#1=#1+1", "END1", "WHILE[#2 LT 3] DO1", "#2=#2+1", "END1", "M30")
    assert check(text) == []


# ---------------------------------------------------------------- jump-into-loop


def test_4_control_flow_goto_into_loop_is_an_error():
    text = lines("O1000", "GOTO 10", "WHILE[#1 LT 3] DO1", "N10 #1=#1+1", "END1", "M30")
    found = coded(check(text), "jump-into-loop")
    assert [at(d) for d in found] == [(2, 5, 7, "error")]
    assert {r.line for r in found[0].related} == {2, 3}
    assert alarm(text) == (126, 2)


def test_4_control_flow_jumping_out_of_a_loop_or_within_it_is_allowed():
    out_of = lines("O1000", "WHILE[#1 LT 3] DO1", "IF[#1 EQ 2] GOTO 20", "N10 #1=#1+1", "END1", "N20 M30")
    within = lines("O1000", "WHILE[#1 LT 3] DO1", "GOTO 10", "#2=1", "N10 #1=#1+1", "END1", "M30")
    assert check(out_of) == []
    assert check(within) == []


# ---------------------------------------------------------------- M98 Q and M99 P (§5)


def test_5_calls_m98_q_to_a_label_missing_in_the_called_program_is_an_error():
    text = lines("O1000", "M98 P2000 Q30", "M30", "O2000", "N20 G00 X1", "M99")
    found = coded(check(text), "undefined-label")
    assert [at(d) for d in found] == [(2, 10, 13, "error")]
    assert "O2000" in found[0].message
    assert check(lines("O1000", "M98 P2000 Q20", "M30", "O2000", "N20 G00 X1", "M99")) == []


def test_5_calls_m98_q_without_p_looks_in_the_current_program():
    assert [at(d) for d in coded(check(lines("O1000", "M98 Q5", "M30")), "undefined-label")] == [(2, 4, 6, "error")]
    assert check(lines("O1000", "M98 Q5 L1", "M30", "N5 M99")) == []


def test_5_calls_m99_p_in_a_called_program_needs_the_label_in_its_caller():
    text = lines("O1000", "M98 P2000", "N50 M30", "O2000", "G00 X1", "M99 P60")
    found = coded(check(text), "undefined-label")
    assert [at(d) for d in found] == [(6, 4, 7, "error")]
    assert found[0].related[0].line == 1  # the call
    assert check(lines("O1000", "M98 P2000", "N50 M30", "O2000", "G00 X1", "M99 P50")) == []


def test_5_calls_m99_p_in_the_main_program_jumps_in_itself():
    found = coded(check(lines("O1000", "M98 P2000", "M99 P70", "O2000", "M99")), "undefined-label")
    assert [at(d) for d in found] == [(3, 4, 7, "error")]
    assert check(lines("O1000", "N70 M98 P2000", "M99 P70", "O2000", "M99")) == []


def test_5_calls_m99_p_in_a_program_called_from_elsewhere_is_left_to_the_run():
    assert check(lines("O9100", "G00 X1", "M99 P60"), file="O9100.nc") == []
