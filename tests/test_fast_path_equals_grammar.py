"""The hand-written fast path builds exactly the lark grammar's tree, or leaves the line to it.

docs/semantics.md §1–§7 are defined by the grammar in ``block.lark``; the fast path only exists
for speed, so on every line it accepts it must agree with the grammar to the last column.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings

from camgen import cam_program
from cncmacro.syntax.assemble import assemble
from cncmacro.syntax.block_parser import BlockCache, _plain_line_pattern, parse_block, parse_with_grammar
from cncmacro.syntax.fastpath import plain_words, read_items
from cncmacro.syntax.lines import prepare
from strategies import line

ROOT = Path(__file__).resolve().parent.parent


def check_line(text: str) -> bool:
    """Assert the contract for one line; True when the fast path accepted it."""
    prep = prepare(text)
    if not prep.code.strip():  # nothing for either reader: comments, ';', '%' or blank
        assert parse_block(text).problems == prep.problems
        return False
    reference = parse_with_grammar(prep.code, prep)
    items = plain_words(prep.code)
    if items is None:
        items = read_items(prep.code)
    if items is not None:
        assert assemble(items, prepare(text)) == reference, text
    assert parse_block(text) == reference, text
    return items is not None


@settings(max_examples=1500, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(line())
def test_generated_lines(text):
    check_line(text)


def real_lines() -> list[str]:
    lines = cam_program(3000, seed=7).splitlines()
    for path in sorted((ROOT / "examples").rglob("*")):
        if path.is_file() and path.suffix.lower() in (".nc", ".cnc"):
            lines += path.read_text(encoding="utf-8").splitlines()
    return lines


def test_real_lines():
    lines = real_lines()
    accepted = sum(check_line(t) for t in lines)
    assert accepted > 0.9 * len(lines)  # the fast path does take the common forms


@pytest.mark.parametrize(
    "text",
    ["G65 P[CUT] L2", "DPRNT[X#2[53]]", "#1=[1 LT 2]", "IF[#1]GOTO1", "X[#1 GT 2]", "#1=SIN[#2 GT 1]", "x5y.5",
     "#1=[#_ABSIO[1]]", "[#_UO[#2+1]]=1", "#_DATE=1", "X#_ABSIO[2]", "#1=POW[2,3]", "#1=ATAN[1,2]",
     "#1=PRM[1320,1]/[2]", "#1=ADP[#24]", "[1]=2", "N50 [#100 LT 10] M99 P10", "[#1EQ#0]M99P#2",
     "[#1 LT 2] M99"],
)  # fmt: skip
def test_lines_the_fast_path_leaves_to_the_grammar(text):
    check_line(text)


@pytest.mark.parametrize(
    "text",
    ["G01 X50. ,R5. F500.", "Y50. ,C3.", "G01 X20 Y30 ,C3", "X50.,R5.", "N10 G01 X1 ,R#1(CORNER)", "G01 Z-2. ,A[#1+15]",
     "g01 x5 ,c.5;", "/ X1 , R2."],
)  # fmt: skip
def test_1_text_and_blocks_corner_words_are_read_by_the_grammar_alone(text):
    """A line with a comma word (docs/semantics.md §1) is left to the grammar, which reads it."""
    assert not check_line(text)
    block = parse_block(text)
    assert block.problems == () and len(block.corners) == 1


@pytest.mark.parametrize(
    "text",
    ["N10 G01 X5. Y-3.", "  n20 g1 x.5\tz-1. ", "N000123 G1 X1.5", "N123456789 X1", "N１２ X１", "N7 M98 P1234"],
)  # fmt: skip
def test_1_text_and_blocks_a_label_then_plain_words_is_read_as_the_grammar_reads_it(text):
    """A sequence number followed by plain words (a line in ten of a CAM program) is made without
    reading its words; asked for, they are the grammar's, to the column."""
    block = parse_block(text)
    assert block.plain_tail is not None and block._words is None
    assert check_line(text)
    assert BlockCache().get_many([text]) == [block]


@pytest.mark.parametrize(
    "text", ["N1 N2 X1", "N1 O2", "N1 M99 O2", "N1.5 X1", "N1234567890 X1", "N10G01X5.", "N10 X1 (C)"]
)
def test_1_text_and_blocks_other_labelled_lines_take_the_general_path(text):
    """An N or O after the label, a label with a point or of ten digits, words not apart, a
    comment: the general path reads these."""
    assert parse_block(text).plain_tail is None
    check_line(text)


@pytest.mark.skipif(sys.version_info < (3, 11), reason="Python 3.10's re has no possessive quantifiers to compare")
def test_python_3_10_reads_the_same_plain_lines_as_3_11():
    """Python 3.10 gets the plain-line pattern without possessive quantifiers; it must accept
    exactly the lines the possessive one does, or a line would parse differently there. The
    lines: real ones, and each with a digit, a point or a blank added or taken away at its end."""
    with_possessive = re.compile(_plain_line_pattern("+")).fullmatch
    without = re.compile(_plain_line_pattern("")).fullmatch
    accepted = 0
    for text in real_lines():
        code = prepare(text).code
        for variant in (code, code + "5", code + ".", code + " ", code + ".5678", code[:-1], " " + code + "\t"):
            assert (with_possessive(variant) is None) == (without(variant) is None), variant
            accepted += with_possessive(variant) is not None
    assert accepted > 5000  # the comparison did cover lines the pattern accepts
