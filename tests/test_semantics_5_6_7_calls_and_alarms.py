"""docs/semantics.md §5 "Calls", §6 "Alarms and messages" and §7 "GSK macro A form": as read."""

from __future__ import annotations

from cncmacro.syntax.nodes import Bracket, Number, Output, Unary, Var
from conftest import block, error


def letters(text: str) -> list[str]:
    return [w.letter for w in block(text).words]


def test_g65_with_program_count_and_arguments():
    b = block("G65 P9010 L2 A1 B2 C3 I14 J15 I6 J7 K9 K11 K12 J30")
    assert letters("G65 P9010 L2 A1 B2 C3 I14 J15") == ["G", "P", "L", "A", "B", "C", "I", "J"]
    assert b.word("P").value.text == "9010"
    assert [w.letter for w in b.words[3:]] == list("ABCIJIJKKKJ")


def test_g65_bracketed_program_names():
    assert block("G65 P[CUT] L2").word("P").name == "CUT"
    assert block("G65 P[螺纹切削]").word("P").name == "螺纹切削"
    assert block("G66 P[O1004] L3").word("P").name == "O1004"
    p = block("M98 P[#100] L3").word("P")
    assert p.name is None and isinstance(p.value, Bracket) and p.value.inner == Var(100, 6, 10)


def test_bracketed_name_only_after_p():
    error("X[CUT]")


def test_g65_arguments_with_variables_and_expressions():
    b = block("G65 P9100 X#24 Y-#25 R[#18*2]")
    assert isinstance(b.word("X").value, Var)
    assert isinstance(b.word("Y").value, Unary)
    assert isinstance(b.word("R").value, Bracket)


def test_g66_and_g67():
    assert letters("G66 P0100 L2 A2 B20 C20 I30 J20 K20") == list("GPLABCIJK")
    assert letters("G67") == ["G"]


def test_m98_forms():
    assert block("M98 P30040").word("P").value.text == "30040"
    assert block("M98 P00010040").word("P").value.text == "00010040"
    assert letters("M98 P1000 L3 Q20") == ["M", "P", "L", "Q"]


def test_m99_with_return_label():
    assert block("M99 P10").word("P").value == Number(10.0, "10", 5, 7)


def test_call_with_a_dangling_address_is_an_error():
    error("G65 P")
    error("M98 P1000 L")


def test_external_output():
    b = block("DPRNT[X#2[53]**Y#5[53]]")
    out = b.statements[0]
    assert isinstance(out, Output) and out.command == "DPRNT"
    assert [p.text for p in out.parts if p.text is not None] == ["X", "  Y"]
    assert [(p.variable.number, p.digits, p.decimals) for p in out.parts if p.variable] == [(2, 5, 3), (5, 5, 3)]
    assert block("POPEN").statements[0].command == "POPEN"
    assert block("PCLOS").statements[0].command == "PCLOS"
    error("DPRNT")


def test_alarm_and_stop_messages():
    a = block("#3000=1(TOOL NOT FOUND)").statements[0]
    assert a.target.number == 3000 and a.message == "TOOL NOT FOUND"
    s = block("N5 #3006=1(CHECK PART)").statements[0]
    assert s.message == "CHECK PART"
    assert block("#3000=1").statements[0].message is None


def test_gsk_h_code_form():
    b = block("G65 H01 P#101 Q1005")
    assert letters("G65 H01 P#101 Q1005") == ["G", "H", "P", "Q"]
    assert b.word("P").value == Var(101, 9, 13)
    neg = block("G65 H01 P#101 Q-#102").word("Q").value
    assert isinstance(neg, Unary) and neg.operand.number == 102
    alarm = block("G65 H99 P15(/用户自定义报警);")
    assert alarm.word("P").value.value == 15 and alarm.comments[0].text == "/用户自定义报警"


def test_gsk_h_code_branch_with_variable_target():
    b = block("G65 H81 P#100 Q#101 R#102")
    assert [w.value.number for w in b.words[2:]] == [100, 101, 102]


def test_h_code_needs_values():
    error("G65 H81 P Q#1")
