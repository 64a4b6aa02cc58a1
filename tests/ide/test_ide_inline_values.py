"""Inline values without a server: each line of the range names every variable it reads or
writes, once, in source order, for the debugger to evaluate; a line of plain words names none."""

from __future__ import annotations

from cncmacro.ide.inline_values import MAX_LINES, InlineExpression, inline_values
from cncmacro.ide.spans import Span

from .documents import document

DOC = document("O0001", "#1=#[#2+1]+#1", "N10 #100=#100+1", "G00 X0", "M99")


def test_a_line_names_each_variable_once_in_source_order() -> None:
    assert inline_values(DOC, 1, 1) == [
        InlineExpression(Span(1, 0, 2), "#1"),
        InlineExpression(Span(1, 3, 10), "#[#2+1]"),
        InlineExpression(Span(1, 5, 7), "#2"),
    ]


def test_a_range_past_the_document_gives_the_variables_of_its_lines_only() -> None:
    assert [(v.span.line, v.expression) for v in inline_values(DOC, 2, 99)] == [(2, "#100")]


def test_a_range_longer_than_the_limit_is_cut() -> None:
    doc = document(*["#1=1"] * (MAX_LINES + 5))
    found = inline_values(doc, 0, MAX_LINES + 4)
    assert len(found) == MAX_LINES and found[-1].span.line == MAX_LINES - 1


def test_a_write_only_variable_is_not_offered_for_a_value() -> None:
    # #3000 is write-only (writing it raises the macro alarm): it has no value to show; #3001 has
    doc = document("O0002", "#3000=1(STOP)", "#1=#3001")
    assert inline_values(doc, 1, 2) == [
        InlineExpression(Span(2, 0, 2), "#1"),
        InlineExpression(Span(2, 3, 8), "#3001"),
    ]
