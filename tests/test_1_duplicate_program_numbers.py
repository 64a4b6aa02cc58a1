"""docs/semantics.md §1 "Text and blocks": a file with two programs under one O number.

The control keeps one program per number, the first it reads (a second copy is FANUC alarm 073
when it is loaded), so the later header is ignored. One rule (``ProgramUnit.duplicate``) serves the
check, the run, the editor and the debugger: the check warns on the ignored header
(``duplicate-program``) and analyses only the kept program, the run executes the kept program and
says so, and a call of the number reaches the kept program.
"""

from __future__ import annotations

from pathlib import Path

from analysis_helpers import analyse_files
from cncmacro.syntax.document import ParsedDocument
from running import final, run
from static_helpers import at, check, coded, lines
from test_cli_run import cli

TWICE = lines("O0100", "M30", "O0100 (OLD COPY)", "#100=1/0", "M30")


def test_1_a_repeated_o_number_marks_the_later_header_as_a_duplicate():
    program = ParsedDocument(TWICE).program
    assert [(u.number, u.start, u.duplicate) for u in program.units] == [(100, 0, False), (100, 2, True)]
    assert program.unit_numbered(100) is program.units[0]


def test_1_an_edit_that_adds_a_second_header_marks_it_as_a_duplicate():
    doc = ParsedDocument(lines("O0100", "M30", "O0200", "M30"))
    doc.apply_change(2, 0, 2, 5, "O0100")
    assert [u.duplicate for u in doc.program.units] == [False, True]
    doc.apply_change(2, 0, 2, 5, "O0300")
    assert [u.duplicate for u in doc.program.units] == [False, False]


def test_1_check_warns_duplicate_program_on_the_ignored_header():
    [d] = coded(check(TWICE), "duplicate-program")
    assert at(d) == (3, 0, 5, "warning")
    assert "line 1" in d.message and "073" in d.message
    assert [(r.line, r.column, r.end_column) for r in d.related] == [(0, 0, 5)]
    [zh] = coded(check(TWICE, locale="zh-CN"), "duplicate-program")
    assert "重复" in zh.message


def test_1_check_analyses_the_kept_program_not_the_ignored_copy(tmp_path: Path):
    found = analyse_files(tmp_path, {"O0100.nc": TWICE})
    assert [(d.line + 1, d.code) for d in found] == [(3, "duplicate-program")]  # no division by zero


def test_1_a_call_from_the_ignored_copy_does_not_count_as_a_caller(tmp_path: Path):
    text = lines("O0100", "#101=1", "M30", "O0100", "G65 P9001", "M30", "O9001", "#102=1/0", "M99")
    found = analyse_files(tmp_path, {"O0100.nc": text})
    # nothing the control keeps calls O9001, so it runs on its own and its division is found
    assert sorted((d.line + 1, d.code) for d in found) == [
        (4, "duplicate-program"),
        (8, "division-by-zero"),
        (9, "not-executed"),
    ]


def test_1_run_executes_the_kept_program_and_a_call_reaches_it():
    assert final(TWICE) == {}
    text = lines("O0001", "G65 P100", "M30", "O0100", "#100=1", "M99", "O0100", "#100=2", "M99")
    assert final(text)[100] == 1


def test_1_run_notes_the_ignored_header(tmp_path: Path):
    m = run(TWICE)
    assert [(n.line + 1, n.subject) for n in m.notes] == [(3, "duplicate-program")]
    path = tmp_path / "O0100.nc"
    path.write_text(TWICE, encoding="utf-8")
    code, out, _ = cli("run", str(path))
    assert code == 0
    assert "note at O0100.nc:3: O0100 repeats the program number of line 1" in out
    assert "status: completed" in out
