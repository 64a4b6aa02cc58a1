"""The outline and the workspace's programs without a server: each O program holds its labels
and loops, a label sits in the innermost loop around it, and a workspace search matches a
program's name or title."""

from __future__ import annotations

from cncmacro.analysis.indexes.workspace_index import ProgramEntry
from cncmacro.ide.spans import Region, Span
from cncmacro.ide.symbols import OutlineKind, OutlineSymbol, ProgramSymbol, document_symbols, workspace_symbols

from .documents import document


def test_each_program_holds_its_labels_and_a_label_inside_a_loop_sits_in_the_loop() -> None:
    doc = document(
        "O0001 (MAIN)",  # 0
        "N10 #1=0",
        "WHILE[#1 LT 3] DO1",  # 2
        "N20 #1=#1+1",
        "END1",  # 4
        "M30",
        "O0002",  # 6
        "M99",
    )
    n20 = OutlineSymbol("N20", OutlineKind.LABEL, Region(3, 0, 3, 3), Span(3, 0, 3))
    loop = OutlineSymbol("DO1 … END1", OutlineKind.LOOP, Region(2, 0, 4, 4), Span(2, 0, 18), children=(n20,))
    n10 = OutlineSymbol("N10", OutlineKind.LABEL, Region(1, 0, 1, 3), Span(1, 0, 3))
    assert document_symbols(doc) == [
        OutlineSymbol("O0001", OutlineKind.PROGRAM, Region(0, 0, 5, 3), Span(0, 0, 12), "MAIN", (n10, loop)),
        OutlineSymbol("O0002", OutlineKind.PROGRAM, Region(6, 0, 7, 3), Span(6, 0, 5), ""),
    ]


def test_a_file_without_an_o_line_is_one_program_named_by_its_file() -> None:
    doc = document("G00 X0", "M30", path="/shop/facing.nc")
    assert [(s.name, s.region) for s in document_symbols(doc)] == [("facing", Region(0, 0, 1, 3))]


def test_the_first_programs_symbol_holds_the_lead_in_before_its_o_line() -> None:
    doc = document("%", "O0001", "M30")
    assert [(s.name, s.region, s.selection) for s in document_symbols(doc)] == [
        ("O0001", Region(0, 0, 2, 3), Span(1, 0, 5))
    ]


PROGRAMS = [
    ProgramEntry("O0001", 1, "MAIN", "/shop/main.nc", 1, 7, True),
    ProgramEntry("O9100", 9100, "Drill Pattern", "/shop/macros/drill.nc", 0, 12, True),
]


def test_a_workspace_search_matches_a_programs_name_or_title_ignoring_case() -> None:
    assert workspace_symbols(PROGRAMS, " drill ") == [
        ProgramSymbol("O9100", "Drill Pattern — drill.nc", "/shop/macros/drill.nc", 0)
    ]
    assert [p.name for p in workspace_symbols(PROGRAMS, "o00")] == ["O0001"]


def test_an_empty_workspace_search_lists_every_program() -> None:
    assert [(p.name, p.detail) for p in workspace_symbols(PROGRAMS, "")] == [
        ("O0001", "MAIN — main.nc"),
        ("O9100", "Drill Pattern — drill.nc"),
    ]
