"""GSK980TDi writes "not equal" as ``NE`` or ``<>`` (its manual, §3.29.2 "转移和循环", the
table of condition operators: "NE 或 <> 不等于", and its example ``IF[3<>2]GOTO2``). Both readers
of a line take ``<>`` as NE; a GSK program runs it; a FANUC control, which has only NE, stops
with alarm 114 on it, as on the other C-style relations."""

from __future__ import annotations

from cncmacro.syntax.block_parser import parse_with_grammar
from cncmacro.syntax.lines import prepare
from cncmacro.syntax.nodes import Number, Relation
from conftest import block
from running import alarm, final, lines


def test_both_readers_take_angle_brackets_as_not_equal():
    fast = block("IF[3<>2]GOTO2").statements[0].condition.inner
    assert fast == Relation("NE", "<>", Number(3.0, "3", 3, 4), Number(2.0, "2", 6, 7), 3, 7)
    prep = prepare("IF[3<>2]GOTO2")
    assert parse_with_grammar(prep.code, prep).statements[0].condition.inner == fast


def test_the_manuals_example_jumps_when_the_values_differ():
    # IF[3<>2]GOTO2 jumps over #1=5, so N2 copies the 1 set first
    program = lines("#1=1", "IF[3<>2]GOTO2", "#1=5", "N2 #2=#1", "IF[#2<>1]GOTO9", "#3=7", "N9 M30")
    v = final(program, "gsk980tdi")
    assert (v[2], v.get(3)) == (1, 7)  # #2 is 1: the second IF does not jump, #3 is set


def test_a_while_on_angle_brackets_loops_until_equal():
    # three turns: #3 goes 0 -> 3, #4 counts them; an IF..THEN on <> that does not hold sets nothing
    program = lines("#3=0", "#4=0", "WHILE[#3<>3]DO1", "#3=#3+1", "#4=#4+1", "END1", "IF[#3<>3]THEN#5=1", "M30")
    v = final(program, "gsk980tdi")
    assert (v[3], v[4], v.get(5)) == (3, 3, None)


def test_angle_brackets_are_alarm_114_on_fanuc():
    assert alarm(lines("#1=5", "IF[#1<>5] THEN #100=1", "M30")) == (114, 2)
