"""Chamfering and corner rounding written with a comma (``G01 X50. ,R5.``, ``Y50. ,C3.``): FANUC's
optional chamfering and corner R and Haas's corner rounding are read, checked and run, not
reported as a syntax error (docs/semantics.md §1 "corner words", §8 "Chamfer and corner words").
"""

from __future__ import annotations

import pytest

from analysis_helpers import analyse_files
from cncmacro.syntax.block_parser import parse_block
from cncmacro.syntax.nodes import Bracket, CornerWord, Number, Var
from cncmacro.syntax.walk import iter_nodes, nodes_at
from running import lines, run
from static_helpers import at, check, coded

REAL = lines(
    "O1000",
    "G90 G17 G00 X0 Y0",
    "G01 X50. ,R5. F500.",
    "Y50. ,C3.",
    "G01 X20 Y30",
    "M30",
)
PROFILES = ("fanuc-0i", "fanuc-30i", "haas")


@pytest.mark.parametrize("profile", PROFILES)
def test_1_text_and_blocks_corner_words_check_clean_where_the_control_has_them(tmp_path, profile):
    assert analyse_files(tmp_path, {"O1000.nc": REAL}, dialect=profile) == []


@pytest.mark.parametrize("profile", PROFILES)
def test_8_machine_corner_words_cut_the_corner_between_the_moves(profile):
    m = run(REAL, profile)
    assert m.status == "completed", m.alarm
    ends = [(mv.line + 1, mv.mode, tuple(round(v, 6) for v in mv.end[:2])) for mv in m.planner.moves]
    # ,R5 between +X and +Y (a left turn of 90°): tangent 5·tan(45°) = 5 from the corner X50 Y0, so
    # X45 Y0, then G03 about X45 Y5 to X50 Y5. ,C3 between +Y and the line to X20 Y30 (direction
    # (-30, -20)/√1300): X50 Y47, then X50 - 3·30/36.05551 = 47.503849, Y50 - 3·20/36.05551 = 48.335899.
    # (A ,C on the last move, before M30, is FANUC's PS0051 "MISSING MOVE AFTER CHF/CNR":
    # test_corner_next_block_alarms_ps0051_ps0052.py)
    assert ends == [
        (2, 0.0, (0.0, 0.0)),
        (3, 1.0, (45.0, 0.0)),
        (3, 3.0, (50.0, 5.0)),
        (4, 1.0, (50.0, 47.0)),
        (4, 1.0, (47.503849, 48.335899)),
        (5, 1.0, (20.0, 30.0)),
    ]


def test_1_text_and_blocks_a_corner_word_is_its_own_node_with_exact_columns():
    b = parse_block("G01 X50. ,R5. F500.")
    assert [w.letter for w in b.words] == ["G", "X", "F"]  # ,R is not the arc radius R
    assert b.corners == (CornerWord("R", Number(5.0, "5.", 11, 13), 9, 13),)
    glued = parse_block("X50.,C#1")
    assert glued.corners == (CornerWord("C", Var(1, 6, 8), 4, 8),)
    angle = parse_block("G01 X20. ,A[#1+15.]")
    assert isinstance(angle.corners[0].value, Bracket) and (angle.corners[0].start, angle.corners[0].end) == (9, 19)
    assert parse_block("x1 ,r-2.").corners[0].letter == "R"
    arc = parse_block("G03 X80. Y55. R30. ,R8.")
    assert [w.letter for w in arc.words] == ["G", "X", "Y", "R"] and arc.corners[0].value.value == 8.0
    assert [type(n).__name__ for n in nodes_at(glued, 7)] == ["CornerWord", "Var"]
    assert Var(1, 6, 8) in list(iter_nodes(glued))  # references and rename find the #1


def test_1_text_and_blocks_a_comma_before_another_letter_is_still_a_syntax_error():
    [p] = parse_block("G01 X50. ,B5.").problems
    assert (p.start, p.end) == (9, 10)
    assert ",C (chamfer), ,R (corner radius) or ,A (angle)" in p.message


def test_8_machine_a_vacant_corner_value_is_dropped_and_the_caller_is_told(tmp_path):
    # FANUC drops an address whose value is vacant (§2): ,R#18 without R rounds nothing, the
    # move runs, and the analysis says which call left R out
    files = {
        "O1000.nc": lines("O1000", "G90 G00 X0 Y0", "G65 P1001 X50.", "M30"),
        "O1001.nc": lines("O1001", "G01 X#24 ,R#18 F500.", "Y50.", "M99"),
    }
    found = analyse_files(tmp_path, files)
    [d] = found
    assert (d.code, d.line + 1, d.severity) == ("vacant-argument", 2, "information")
    assert "#18 (R)" in d.message
    m = run(lines("O1000", "G90 G00 X0 Y0", "G01 X50. ,R#1 F500.", "Y50.", "M30"))
    assert m.status == "completed" and [mv.end[:2] for mv in m.planner.moves][-2:] == [(50.0, 0.0), (50.0, 50.0)]


def test_8_machine_a_corner_value_is_computed_when_the_block_runs():
    m = run(lines("O1000", "#1=0", "G01 X50. ,R[5/#1] F500.", "Y50.", "M30"))
    assert (m.status, m.alarm.number, m.alarm.line + 1) == ("alarm", 112, 3)


def test_8_machine_a_corner_word_without_a_move_is_a_warning_not_an_alarm():
    text = lines("O1000", "G00 X10. ,R2.", "G01 ,C1. F100.", "M30")
    found = check(text)
    assert [(d.code, *at(d)) for d in found] == [
        ("corner-word", 2, 9, 13, "warning"),
        ("corner-word", 3, 4, 8, "warning"),
    ]
    assert "G00" in found[0].message
    assert run(text).status == "completed"


def test_4_control_flow_a_corner_word_beside_a_macro_statement_is_alarm_127():
    text = lines("O1000", "#1=2 ,R3.", "M30")
    assert [(d.code, *at(d)) for d in check(text)] == [("nc-and-macro", 2, 5, 9, "error")]
    m = run(text)
    assert (m.alarm.number, m.alarm.line + 1) == (127, 2)


def test_1_text_and_blocks_corner_words_are_a_warning_on_gsk980tdi_and_still_run():
    # GSK980TDi's manual writes chamfers as L and corner arcs as D: ,C/,R are not documented there
    found = coded(check(REAL, "gsk980tdi"), "corner-word")
    assert [(d.line + 1, d.severity) for d in found] == [(3, "warning"), (4, "warning")]
    assert "L" in found[0].message and "D" in found[0].message
    assert run(REAL, "gsk980tdi").status == "completed"
    zh = coded(check(REAL, "gsk980tdi", locale="zh-CN"), "corner-word")
    assert "拐角圆弧" in zh[0].message
