"""Formatting (docs/editor.md "Formatting"): words upper case, one space between words or none,
comments aligned if asked, and nothing else: comments, DPRNT text and program names keep their
case, shortened keywords stay shortened, a line the grammar rejects is left alone. That it never
changes a run is proved on the whole corpus in test_editing_keeps_runs.py."""

from __future__ import annotations

from cncmacro.syntax.formatting import COMPACT, SPACED, FormatOptions, format_lines


def _formatted(*lines: str, spacing: str = SPACED, align: bool = False, read_end: int | None = None) -> list[str]:
    out = format_lines(lines, 0, len(lines) - 1, FormatOptions(spacing, align), read_end)
    return [out.get(i, x) for i, x in enumerate(lines)]


def test_words_are_upper_case_with_one_space_between_them():
    assert _formatted("n10g01x10.y-5.  f100", "if[#1gt10]goto20", "while[#1 le 3]do1", "end1") == [
        "N10 G01 X10. Y-5. F100",
        "IF [#1 GT 10] GOTO 20",
        "WHILE [#1 LE 3] DO 1",
        "END 1",
    ]


def test_compact_puts_no_space_between_words():
    assert _formatted("N10 G01 X10. Y-5. (CUT)", "IF [#1 GT 10] GOTO 20", spacing=COMPACT) == [
        "N10G01X10.Y-5.(CUT)",
        "IF[#1GT10]GOTO20",
    ]


def test_comments_dprnt_text_and_program_names_keep_their_case():
    assert _formatted("#3000=1(Tool broken)", "dprnt[x#1[53]mm]", "g65 p[cut] x1.") == [
        "#3000=1 (Tool broken)",
        "DPRNT[x#1[53]mm]",
        "G65 P[cut] X1.",
    ]


def test_a_shortened_keyword_stays_shortened():
    assert _formatted("wh[#1lt3]do1") == ["WH [#1 LT 3] DO 1"]


def test_block_delete_indentation_and_what_follows_the_end_of_block_stay():
    assert _formatted("  /2g0x1.;(after)", "/g1 x2.") == ["  /2 G0 X1.;(after)", "/ G1 X2."]


def test_aligned_comments_start_in_one_column():
    assert _formatted("G0 X1. (A)", "G01 X10. Y20. (B)", "(ALONE)", align=True) == [
        "G0 X1.        (A)",
        "G01 X10. Y20. (B)",
        "(ALONE)",
    ]


def test_lines_with_errors_tape_marks_and_after_the_tape_end_are_left_alone():
    lines = ["%", "g01 x[1", "m30", "%", "g01 x1."]
    assert _formatted(*lines, read_end=3) == ["%", "g01 x[1", "M30", "%", "g01 x1."]


def test_formatting_twice_changes_nothing():
    once = _formatted("o1000(t)", "n5 #1 = #2 + sin[30] (x)", "g1x#1 ,r2.", align=True)
    assert not format_lines(once, 0, len(once) - 1, FormatOptions(SPACED, True))


def test_a_line_nested_too_deeply_to_compare_is_left_as_written():
    # 600 chained operators parse, but comparing the formatted parse with the first one recursed
    # past Python's limit: formatting the document failed; the line now stays as it is
    chain = "if[#1 le " + "+".join(["1"] * 600) + "]goto1"
    lines = ["o1", chain, "g01 x1.", "m30"]
    changed = format_lines(lines, 0, len(lines) - 1, FormatOptions())
    assert 1 not in changed and changed[2] == "G01 X1." and changed[0] == "O1"
