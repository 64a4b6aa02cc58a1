"""docs/semantics.md §4 "Control flow": GOTO, IF, WHILE/DO/END, as read and paired."""

from __future__ import annotations

from pathlib import Path

from analysis_helpers import analyse_files
from cncmacro.syntax.document import ParsedDocument
from cncmacro.syntax.nodes import Assign, Bracket, Do, End, Goto, If, Number, Var, While
from conftest import block, error
from running import run
from static_helpers import lines


def test_goto_forms():
    assert isinstance(block("GOTO 10").statements[0].target, Number)
    assert isinstance(block("GOTO#1").statements[0].target, Var)
    assert isinstance(block("GOTO[#1+10]").statements[0].target, Bracket)


def test_goto_needs_a_target():
    error("GOTO")
    error("GOTO-5")


def test_if_goto_and_if_then():
    g = block("IF[#1 GT 10] GOTO 99").statements[0]
    assert isinstance(g, If) and g.goto.value == 99 and g.then is None
    t = block("IF[#1 EQ #0] THEN #3000=1(X MISSING)").statements[0]
    assert isinstance(t.then, Assign) and t.then.message == "X MISSING"


def test_if_then_takes_one_assignment_only():
    assert error("IF[#1 GT 0] THEN GOTO 5").message.startswith("after THEN comes one assignment or output statement")
    error("IF[#1 GT 0] THEN WHILE[#1 LT 2] DO1")
    # IF [..] THEN alone is the block form (tests/test_semantics_4_block_if.py), not a syntax error


def test_if_then_goto_suggests_only_the_if_forms_the_profile_has(tmp_path: Path) -> None:
    # GSK980TDi (manual §3.29) and FANUC 0i have IF [..] GOTO n and IF [..] THEN <statement>,
    # no ENDIF: the message points to IF [..] GOTO n; a profile with the block form of IF
    # (Mitsubishi M70) still hears of IF [..] THEN closed by ENDIF
    text = lines("O1000", "IF [#1 EQ 1] THEN GOTO 10", "N10 M30")
    only = (
        "after THEN comes one assignment or output statement (IF [cond] THEN #1=..); "
        "a jump is written IF [cond] GOTO n, without THEN"
    )
    only_zh = "THEN 之后只能是一条赋值或输出语句（IF [条件] THEN #1=..）；跳转写作 IF [条件] GOTO n，不写 THEN"

    def syntax(dialect: str, locale: str = "en") -> list[tuple[int, int, str]]:
        found = analyse_files(tmp_path, {"O1000.nc": text}, dialect, locale=locale)
        return [(d.line + 1, d.column, d.message) for d in found if d.code == "syntax"]

    for dialect in ("gsk980tdi", "fanuc"):
        assert syntax(dialect) == [(2, 18, only)]
        assert syntax(dialect, "zh-CN") == [(2, 18, only_zh)]
        m = run(text, dialect)
        assert m.alarm is not None and m.alarm.message == f"the block does not parse: {only}"
    [(_, _, block_form)] = syntax("mitsubishi-m70")
    assert block_form.endswith("or nothing: the block form IF [cond] THEN, closed by ENDIF on a later line")


def test_while_do_end_and_bare_do():
    w = block("WHILE[#1 LE 10] DO 2").statements[0]
    assert isinstance(w, While) and w.loop.value == 2
    assert isinstance(block("DO1").statements[0], Do)
    assert isinstance(block("END 3").statements[0], End)


def test_while_needs_do():
    error("WHILE[#1 LE 10]")
    error("END")


def program(text: str):
    return ParsedDocument(text).program


def test_loops_pair_and_nest():
    p = program("WHILE[#1LT3]DO1\nWHILE[#2LT3]DO2\nEND2\nEND1\n")
    assert [(x.number, x.do_line, x.end_line) for x in p.loops] == [(2, 1, 2), (1, 0, 3)]
    assert p.loop_problems == []


def test_loop_number_reused_after_its_loop_ends():
    p = program("DO1\nEND1\nDO1\nEND1")
    assert len(p.loops) == 2 and not p.loop_problems


def test_do_without_end_and_end_without_do():
    p = program("WHILE[#1LT3]DO1\nG00 X0\n")
    assert [(q.kind, q.line) for q in p.loop_problems] == [("do-without-end", 0)]
    p = program("G00 X0\nEND2\n")
    assert [(q.kind, q.line) for q in p.loop_problems] == [("end-without-do", 1)]


def test_crossing_loops():
    p = program("DO1\nDO2\nEND1\nEND2\n")
    assert ("crossing", 2) in [(q.kind, q.line) for q in p.loop_problems]


def test_loops_do_not_pair_across_programs():
    p = program("O1\nDO1\nM99\nO2\nEND1\nM99\n")
    kinds = sorted(q.kind for q in p.loop_problems)
    assert kinds == ["do-without-end", "end-without-do"]


def test_labels_keep_duplicates_in_order():
    p = program("N10 G00 X0\nN20 X1\nN10 X2\n")
    assert p.labels == {10: [0, 2], 20: [1]}


def test_goto_statement_kinds():
    assert isinstance(block("N5 GOTO 5").statements[0], Goto)


def test_4_control_flow_three_bracketed_conditions_joined_by_and_or_read_left_to_right():
    from running import final, lines

    text = lines("#7=82", "IF[[#7 NE 81] AND [#7 NE 82] AND [#7 NE 83]] GOTO 5", "#1=1",
                 "N5 IF[[#7 EQ 1] OR [#7 EQ 2] OR [#7 EQ 82]] THEN #2=9", "M30")  # fmt: skip
    got = final(text)
    assert got[1] == 1 and got[2] == 9
