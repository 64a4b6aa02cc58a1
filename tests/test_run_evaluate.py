"""Macro text typed while a run is stopped (``machine.evaluate``): the debugger's watch, hover,
console and breakpoint conditions follow the same rules as a program line (docs/semantics.md §2,
§3, §6), and asking for a pause stops even an endless loop."""

from __future__ import annotations

import pytest

from cncmacro.machine.evaluate import (
    EvaluationError,
    assign,
    compile_condition,
    evaluate,
    holds,
    is_assignment,
    set_variable,
)
from cncmacro.machine.status import CANCEL_CHECK
from running import lines, machine

CALLING = lines("O0001", "#1=3", "#100=2", "G65 P9100 A2.5 B4.", "M30", "O9100", "#3=#1+#2", "M99")


def stopped_in_macro():
    m = machine(CALLING)
    m.run_until(lambda mm: len(mm.frames) == 2)
    return m


def test_3_expressions_typed_while_stopped_follow_the_program_rules():
    m = stopped_in_macro()
    assert evaluate(m, "#1+#2*2") == 10.5
    assert evaluate(m, "ROUND[2.5]+FIX[-1.7]") == 2
    assert evaluate(m, "#[#100]") == 4  # #100 is 2: #[2] is this level's B argument
    assert evaluate(m, "ATAN[1]/[1]") == 45
    assert evaluate(m, "#3") is None


def test_3_an_expression_is_evaluated_in_the_level_asked_for():
    m = stopped_in_macro()
    assert evaluate(m, "#1") == 2.5
    assert evaluate(m, "#1", level=0) == 3
    assert m.L[1] == 2.5  # the machine's own locals are untouched afterwards


def test_3_alarms_while_evaluating_are_errors_and_leave_the_run_alone():
    m = stopped_in_macro()
    with pytest.raises(EvaluationError, match="alarm 112"):
        evaluate(m, "#1/#0")
    with pytest.raises(EvaluationError, match="alarm 119"):
        evaluate(m, "SQRT[-1]")
    assert m.status == "paused" and m.alarm is None
    assert m.run() == "completed"


def test_1_a_mistake_in_the_text_is_reported_at_its_own_column():
    m = stopped_in_macro()
    with pytest.raises(EvaluationError, match="column 4"):
        evaluate(m, "#1+[2")
    with pytest.raises(EvaluationError):
        evaluate(m, "")
    with pytest.raises(EvaluationError, match="one line"):
        evaluate(m, "#1\n#2")


def test_2_vacant_in_conditions_differs_by_dialect():
    for dialect, eq_zero in (("fanuc", False), ("gsk980tdi", True)):
        m = machine(lines("#2=1", "M30"), dialect)
        assert holds(m, compile_condition(m, "#1 EQ #0")) is True
        assert holds(m, compile_condition(m, "#1 EQ 0")) is eq_zero
        assert holds(m, compile_condition(m, "[#1 EQ #0] AND [#2 GE 0]")) is True


def test_3_c_style_relations_only_on_gsk980tdi():
    gsk = machine(lines("#1=5", "M30"), "gsk980tdi")
    gsk.step()
    assert holds(gsk, compile_condition(gsk, "#1==5")) is True
    fanuc = machine(lines("#1=5", "M30"))
    fanuc.step()
    with pytest.raises(EvaluationError, match="alarm 114"):
        holds(fanuc, compile_condition(fanuc, "#1==5"))
    with pytest.raises(EvaluationError):
        compile_condition(fanuc, "#1")  # a condition needs a relation


def test_6_assignments_from_the_console_get_every_check_of_a_program_line():
    m = stopped_in_macro()
    assert assign(m, "#100=5") == (100, 5)
    assert m.C[100] == 5
    assert assign(m, "#[#100+95]=#1") == (100, 2.5)
    with pytest.raises(EvaluationError, match="alarm 116"):
        assign(m, "#0=1")
    with pytest.raises(EvaluationError, match="alarm 116"):
        assign(m, "#4001=1")
    with pytest.raises(EvaluationError, match="alarm 3001"):
        assign(m, "#3000=1(STOP)")
    with pytest.raises(EvaluationError, match="not an assignment"):
        assign(m, "G01 X#100")
    assert m.status == "paused"


def test_2_a_named_variable_set_from_the_console_is_the_one_a_program_line_sets():
    # [#_OFSHW[2]] is #10002 on the 30i: the console writes there, not to the local #2, and a
    # name without a subscript ([#_CLOCK1], #3001) is written as a program line writes it
    m = machine(lines("O0001", "[#_OFSHW[2]]=7", "#2=1", "M30"), "fanuc-30i")
    m.run_until(lambda mm: mm.blocks >= 2)
    assert m.S.get(10002) == 7 and m.L[2] == 1
    assert assign(m, "[#_OFSHW[2]]=5") == (10002, 5)
    assert m.S.get(10002) == 5 and m.L[2] == 1
    assert assign(m, "[#_CLOCK1]=0")[0] == 3001


def test_2_setting_a_variable_to_vacant_and_to_an_expression():
    m = stopped_in_macro()
    assert set_variable(m, 2, "") is None and m.L[2] is None
    assert set_variable(m, 2, "#1*2") == 5
    assert set_variable(m, 1, "7", level=0) == 7 and m.frames[0].locals[1] == 7 and m.L[1] == 2.5


def test_what_counts_as_an_assignment():
    assert is_assignment("#100=5") and is_assignment(" #[#1] = 3") and is_assignment("#1=#2==3")
    assert not is_assignment("#1==2") and not is_assignment("#1 EQ 2") and not is_assignment("#1<=2")


def test_a_pause_request_stops_an_endless_loop_and_the_run_goes_on():
    m = machine(lines("#1=0", "WHILE[#1 GE 0]DO1", "#1=#1+1", "END1", "M30"), max_blocks=10**9)
    m.request_pause()
    assert m.run() == "paused" and m.blocks == CANCEL_CHECK
    assert m.message is None and m.frames[-1].pc in (1, 2, 3)
    assert m.run(1000, is_limit=False) == "paused" and m.blocks == CANCEL_CHECK + 1000
