"""docs/semantics.md §1 "Text and blocks": lines, comments, spaces, block delete, N and O."""

from __future__ import annotations

import pytest

from analysis_helpers import analyse_files
from cncmacro.syntax import parse_block
from cncmacro.syntax.nodes import Assign, Goto, If, While
from conftest import block, error


def test_trailing_semicolon_is_end_of_block():
    b = block("G00 X100 Z100;")
    assert [w.letter for w in b.words] == ["G", "X", "Z"]
    assert not b.problems


def test_text_after_semicolon_is_an_error():
    p = error("G00 X100; G01 X5")
    assert "one line holds one block" in p.message
    assert (p.start, p.end) == (10, 16)


def test_percent_line_is_a_tape_mark():
    assert block("%").tape
    assert not block("G00 X0").tape


def test_comment_after_a_value_and_after_goto():
    b = block("#111=600(BASE)")
    assert isinstance(b.statements[0], Assign)
    assert b.comments[0].text == "BASE"
    g = block("GOTO1(SKIP)").statements[0]
    assert isinstance(g, Goto) and g.target.value == 1


def test_comment_in_the_middle_of_a_block_keeps_columns():
    b = block("G01 (CUT) X10.5")
    x = b.word("X")
    assert (x.start, x.end) == (10, 15)


def test_unclosed_comment_is_a_warning_not_an_error():
    b = parse_block("G00 X0 (NO END")
    assert [p.severity for p in b.problems] == ["warning"]
    assert b.comments[0].text == "NO END" and not b.comments[0].closed
    assert [w.letter for w in b.words] == ["G", "X"]


@pytest.mark.parametrize(
    "text, kind",
    [
        ("IF[#1GT#2]GOTO10", If),
        ("WHILE[#1LE10]DO1", While),
        ("N941#3000=1(MSG)", Assign),
        ("IF [ #1 GT #2 ] GOTO 10", If),
    ],
)
def test_spaces_are_insignificant(text, kind):
    assert isinstance(block(text).statements[0], kind)


def test_motion_block_without_spaces():
    b = block("G01X10.Y-#5")
    assert [w.letter for w in b.words] == ["G", "X", "Y"]


def test_keywords_win_over_address_letters():
    # GOTO is not G + OTO, END is not E + ND, DO is not D + O
    assert isinstance(block("GOTO10").statements[0], Goto)
    assert block("END1").statements and not block("END1").words
    # but an address followed by a value stays an address
    assert [w.letter for w in block("D01 E5. G01").words] == ["D", "E", "G"]


def test_block_delete_plain_and_numbered():
    assert block("/G00 X0").block_delete == 0
    assert block("/3 G00 X0").block_delete == 3
    assert block("G00 X0").block_delete is None


def test_label_right_after_block_delete():
    b = block("/N10 G00 X0")
    assert b.block_delete == 0 and b.label == 10
    b = block("/2N20#1=5")
    assert b.block_delete == 2 and b.label == 20


def test_slash_after_start_is_not_block_delete():
    error("G00 /X0")


def test_sequence_number_at_start():
    b = block("N10 G00 X0")
    assert b.label == 10 and b.label_span == (0, 3)
    assert [w.letter for w in b.words] == ["G", "X"]


def test_sequence_number_must_be_literal():
    b = parse_block("N#1 G00 X0")
    assert b.label is None
    assert "sequence number must be written as a number" in b.problems[0].message


def test_program_header_with_title_and_statements():
    b = block("O1234 (BOLT CIRCLE) #1=2")
    assert b.program == 1234 and b.title == "BOLT CIRCLE"
    assert isinstance(b.statements[0], Assign)


def test_program_number_must_be_whole():
    b = parse_block("O12.5")
    assert b.program is None and b.problems


@pytest.mark.parametrize("dialect", ["fanuc-0i", "fanuc-30i", "haas", "gsk980tdi"])
def test_a_program_number_written_with_a_decimal_point_is_an_error_as_o12_34_is(tmp_path, dialect):
    # O takes no decimal point (FANUC alarm 007): "O1234." is refused as "O12.34" is, with the
    # same finding on the O line (line 0), and no other error or warning in these programs
    found = {}
    for header in ("O1234.", "O12.34"):
        diags = analyse_files(tmp_path, {"MAIN.nc": f"{header}\n#1=1\nM30\n"}, dialect)
        found[header] = [(d.line, d.severity, d.code, d.message) for d in diags if d.severity in ("error", "warning")]
    assert (
        found["O1234."]
        == found["O12.34"]
        == [
            (0, "error", "syntax", "a program number must be a whole number written without a decimal point"),
        ]
    )
    assert parse_block("O1234").program == 1234 and not parse_block("O1234").problems


def test_lower_case_is_read_as_upper_case():
    b = block("g01 x10. if[#1 gt 2]goto5")
    assert [w.letter for w in b.words] == ["G", "X"]


def test_over_long_line_is_reported_not_parsed():
    b = parse_block("X1" * 5000)
    assert b.has_error and "too long" in b.problems[0].message


def test_full_width_semicolon_is_a_warning():
    b = parse_block("G65 P0012 J12 K22；")
    assert [p.severity for p in b.problems] == ["warning"]
    assert [w.letter for w in b.words][-1] == "K"
