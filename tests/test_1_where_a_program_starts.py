"""docs/semantics.md §1 "Text and blocks", "Where a program starts": an O line that holds a
sequence number (``O100 N5``) is the program's first block, an O header alone is not a block,
and neither is a ``%`` mark.

One rule (``machine/block_roles.py``) serves the run, the check and the debugger, so the line a
run begins on, the line a breakpoint stops on and the lines the check calls not executed agree.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from analysis_helpers import analyse_files
from cncmacro.debugging.breakpoints import Asked, Breakpoints
from running import final, lines, machine

# The run begins on the O line (its N is the sequence number at once), and GOTO 5 lands there.
LABELLED = lines(
    "O0100 N5",
    "IF [#1 LT 1] THEN #101 = #4114",  # the first pass only
    "#1 = #1 + 1",
    "IF [#1 LT 2] GOTO 5",
    "#102 = #4114",
    "M30",
)


def test_1_where_a_program_starts_an_o_line_with_a_sequence_number_is_the_first_block():
    assert final(LABELLED) == {1: 2.0, 101: 5.0, 102: 5.0}


@pytest.mark.parametrize("call", ["M98 P0100", "G65 P0100"])
def test_1_where_a_program_starts_a_called_program_begins_on_its_labelled_o_line(call):
    text = lines("O0001", call, "M30", "O0100 N5", "#101 = #4114", "M99")
    assert final(text)[101] == 5.0


def test_1_where_a_program_starts_a_header_alone_and_a_percent_are_passed_over():
    assert machine(lines("O0100", "#1=1", "M30")).frames[-1].pc == 1
    assert machine(lines("%", "#1=1", "M30", "%")).frames[-1].pc == 1
    assert machine(lines("%", "(TITLE)", "O0100 N5", "#1=1", "M30", "%")).frames[-1].pc == 2


STARTS = [
    lines("O0100 N5", "#1=1", "M30"),
    lines("O0100 (TITLE)", "(COMMENT)", "#1=1", "M30"),
    lines("O0100 #1=1", "M30"),
    lines("%", "G00 X1.", "M30", "%"),
    lines("%", "O0100 N5 (TITLE)", "M30", "%"),
    lines("", "(ONLY A COMMENT)", "O0100", "", "N10 G00 X1.", "M30"),
]


@pytest.mark.parametrize("text", STARTS)
def test_1_where_a_program_starts_the_run_and_a_breakpoint_on_the_first_line_agree(text, tmp_path: Path):
    path = tmp_path / "MAIN.nc"
    path.write_text(text, encoding="utf-8")
    [bp] = Breakpoints().set_lines(str(path), [Asked(0)])
    assert bp.verified
    assert bp.line == machine(text).frames[-1].pc


def test_1_where_a_program_starts_a_labelled_o_line_a_call_passes_is_not_executed(tmp_path: Path):
    def not_executed(sub: str) -> list[tuple[int, int]]:
        text = lines("O0001", "M98 P0002 Q7", "M30", sub, "#1=1", "N7 #2=2", "M99")
        found = analyse_files(tmp_path, {"O0001.nc": text})
        return [(d.line + 1, d.end_line + 1) for d in found if d.code == "not-executed"]

    assert not_executed("O0002 N5") == [(4, 5)]  # M98 Q7 starts at N7: the O line's N5 never runs
    assert not_executed("O0002") == [(5, 5)]  # a header alone is never a block to run


def test_1_where_a_program_starts_a_labelled_o_line_the_run_enters_is_executed(tmp_path: Path):
    text = lines("O0001", "M98 P0002", "M30", "O0002 N5", "#1=1", "M99")
    found = analyse_files(tmp_path, {"O0001.nc": text})
    assert [d for d in found if d.code == "not-executed"] == []
