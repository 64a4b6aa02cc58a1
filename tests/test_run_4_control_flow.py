"""docs/semantics.md §4 "Control flow", run on the interpreter: GOTO search order, IF, WHILE/DO/END,
jumping out of and into loops, and NC words beside a macro statement."""

from __future__ import annotations

import pytest

from running import alarm, final, lines, run


def test_goto_searches_forward_first_then_from_the_start():
    program = lines(
        "#1=0",
        "N10 #1=#1+1",  # the earlier N10
        "IF[#1 GE 2] GOTO 99",
        "GOTO 10",  # the forward search finds the later N10 first
        "#100=1",
        "N10 #101=#101+1",
        "GOTO 10",  # nothing forward: the search wraps to the first N10
        "N99 M30",
    )
    v = final(program)
    assert v[101] == 1 and v[1] == 2 and 100 not in v


def test_goto_computed_target():
    v = final(lines("#1=15", "GOTO [#1+5]", "#100=1", "N20 #101=1", "M30"))
    assert 100 not in v and v[101] == 1


@pytest.mark.parametrize("target", ["0", "100000", "#0"])
def test_goto_out_of_range_is_alarm_128(target):
    assert alarm(lines(f"GOTO {target}" if not target.startswith("#") else f"GOTO{target}", "M30")) == (128, 1)


def test_goto_to_a_missing_label_is_alarm_128():
    assert alarm(lines("#1=3", "GOTO #1", "N4 M30")) == (128, 2)


def test_goto_stays_inside_its_own_program():
    program = lines("O0001", "GOTO 50", "M30", "O0002", "N50 M99")
    assert alarm(program) == (128, 2)


def test_if_then_runs_one_statement():
    v = final(lines("#1=5", "IF[#1 GT 3] THEN #100=1", "IF[#1 GT 9] THEN #101=1", "M30"))
    assert v[100] == 1 and 101 not in v


def test_while_loop_and_nesting_three_deep():
    program = lines(
        "#1=0",
        "#10=0",
        "WHILE[#1 LT 3]DO1",
        "#2=0",
        "WHILE[#2 LT 4]DO2",
        "#3=0",
        "WHILE[#3 LT 5]DO3",
        "#10=#10+1",
        "#3=#3+1",
        "END3",
        "#2=#2+1",
        "END2",
        "#1=#1+1",
        "END1",
        "M30",
    )
    assert final(program)[10] == 60


def test_a_loop_number_may_be_reused_after_its_loop_ends():
    program = lines("#1=0", "WHILE[#1 LT 2]DO1", "#1=#1+1", "END1", "WHILE[#1 LT 5]DO1", "#1=#1+1", "END1", "M30")
    assert final(program)[1] == 5


def test_a_false_while_skips_its_body():
    v = final(lines("WHILE[1 GT 2]DO1", "#100=1", "END1", "#101=1", "M30"))
    assert 100 not in v and v[101] == 1


def test_do_without_while_loops_forever_until_the_budget():
    m = run(lines("DO1", "#1=#1+1", "END1", "M30"), max_blocks=3000)
    assert m.status == "limit" and m.blocks == 3000 and m.L[1] == 1000


def test_jumping_out_of_a_loop_is_allowed():
    program = lines("#1=0", "WHILE[#1 LT 100]DO1", "#1=#1+1", "IF[#1 EQ 7] GOTO 50", "END1", "N50 #100=#1", "M30")
    assert final(program)[100] == 7


def test_jumping_out_then_starting_the_loop_again():
    program = lines(
        "#5=0",
        "N10 #1=0",
        "WHILE[#1 LT 10]DO1",
        "#1=#1+1",
        "IF[#1 EQ 3] GOTO 50",
        "END1",
        "N50 #5=#5+1",
        "IF[#5 LT 4] GOTO 10",
        "M30",
    )
    assert final(program)[5] == 4


def test_jumping_into_a_loop_is_an_error():
    program = lines("GOTO 10", "WHILE[#1 LT 3]DO1", "N10 #1=#1+1", "END1", "M30")
    number, line = alarm(program)
    assert number == 126 and line == 1


def test_do_without_end_is_alarm_124_where_the_condition_is_false():
    # the control looks for END 1 only to go on after the loop (GSK980TDi manual §3.29, docs/semantics.md §4);
    # with #1=0 the body runs and M30 ends the program first (test_4_do_without_end_alarms_only_where_...)
    assert alarm(lines("#1=5", "WHILE[#1 LT 3]DO1", "#1=#1+1", "M30")) == (124, 2)


def test_end_without_do_is_alarm_126():
    assert alarm(lines("#1=1", "END1", "M30")) == (126, 2)


@pytest.mark.parametrize("number", ["0", "4"])
def test_loop_numbers_are_1_to_3(number):
    assert alarm(lines(f"WHILE[#1 LT 3]DO{number}", "#1=#1+1", f"END{number}", "M30")) == (126, 1)


def test_loops_nested_four_deep_are_alarm_126():
    program = lines("DO1", "DO2", "DO3", "DO1", "END1", "END3", "END2", "END1", "M30")
    assert alarm(program)[0] == 126


def test_crossing_loops_alarm():
    program = lines("#1=0", "WHILE[#1 LT 2]DO1", "WHILE[#1 LT 2]DO2", "#1=#1+1", "END1", "END2", "M30")
    number, line = alarm(program)
    assert number == 126 and line == 5


def test_nc_words_and_a_macro_statement_in_one_block_are_alarm_127():
    assert alarm(lines("G01 X10 #1=5", "M30")) == (127, 1)
    # N and block delete may precede a macro statement
    assert final(lines("N5 #1=5", "/ #2=6", "M30"))[2] == 6
    assert 2 not in final(lines("/ #2=6", "M30"), block_delete=True)


def test_block_delete_skips_only_when_the_switch_is_on():
    m = run(lines("G90 G00 X1", "/G00 X2", "/N7 G00 X3", "M30"), block_delete=True)
    assert [mv.end[0] for mv in m.planner.moves] == [1.0]
    m = run(lines("G90 G00 X1", "/G00 X2", "M30"))
    assert [mv.end[0] for mv in m.planner.moves] == [1.0, 2.0]
