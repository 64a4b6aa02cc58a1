"""Editing a program with block IFs (docs/editor.md "Formatting", "Sequence numbers", and the
folding of docs/editor.md "Structure"): the formatter writes IF..THEN, ELSE and ENDIF in upper
case and keeps the indentation of the branches; Add Missing Sequence Numbers gives ELSE and ENDIF
no label (one there would be a jump target inside a branch, ``jump-into-if``); renumbering
rewrites a GOTO that leaves a branch; the branches fold. Each edit is proved by running the program
before and after it under ``mitsubishi-m70``."""

from __future__ import annotations

from cncmacro.analysis.editing.sequence_numbers import SequencePlan, add_sequence_numbers, renumber
from cncmacro.dialects import get_dialect
from cncmacro.ide.folding import folding_ranges
from cncmacro.syntax.block_parser import parse_block
from cncmacro.syntax.formatting import COMPACT, SPACED, FormatOptions, format_lines
from cncmacro.syntax.program import build_program
from running import final, lines
from static_helpers import check

M70 = "mitsubishi-m70"

# #1 = 4: 4 GT 2 holds, #2 = 4 * 2 = 8; the GOTO leaves the branch for N50: #3 = 8 + 1 = 9
TEXT = lines(
    "O1000",
    "#1=4",
    "if[#1gt2]then",
    "  #2=#1*2",
    "  goto50",
    "else",
    "  #2=0",
    "endif",
    "N50 #3=#2+1",
    "M30",
)


def _program(text: str):
    return build_program([parse_block(line) for line in text.split("\n")])


def _apply(text: str, plan: SequencePlan) -> str:
    assert plan.error is None and not plan.blockers
    rows = text.split("\n")
    for c in sorted(plan.changes, key=lambda c: (c.line, -c.start)):
        rows[c.line] = rows[c.line][: c.start] + c.text + rows[c.line][c.end :]
    return "\n".join(rows)


def test_formatting_writes_block_if_words_in_upper_case_and_keeps_the_indentation() -> None:
    rows = TEXT.split("\n")
    spaced = format_lines(rows, 0, len(rows) - 1, FormatOptions(SPACED))
    after = "\n".join(spaced.get(k, r) for k, r in enumerate(rows))
    assert after.split("\n")[2:8] == ["IF [#1 GT 2] THEN", "  #2=#1*2", "  GOTO 50", "ELSE", "  #2=0", "ENDIF"]
    compact = format_lines(rows, 0, len(rows) - 1, FormatOptions(COMPACT))
    assert compact[2] == "IF[#1GT2]THEN"
    assert final(after, M70) == final(TEXT, M70) == {1: 4, 2: 8, 3: 9}


def test_adding_sequence_numbers_leaves_else_and_endif_without_one() -> None:
    after = _apply(TEXT, add_sequence_numbers(_program(TEXT), get_dialect(M70), step=10))
    rows = after.split("\n")
    assert rows[5] == "else" and rows[7] == "endif"
    # #1=4 N10, IF N20, #2=#1*2 N30, GOTO N40; the ELSE branch's #2=0 passes N50, which the program has
    assert rows[2].startswith("N20 if") and rows[4] == "  N40 goto50" and rows[6] == "  N60 #2=0"
    assert check(after, M70) == []
    assert final(after, M70) == final(TEXT, M70)


def test_renumbering_rewrites_a_goto_that_leaves_a_branch() -> None:
    after = _apply(TEXT, renumber(_program(TEXT), get_dialect(M70), step=10))
    assert "  goto10" in after.split("\n") and "N10 #3=#2+1" in after.split("\n")
    assert final(after, M70) == final(TEXT, M70)


def test_the_branches_fold_and_the_program_fold_holds_them() -> None:
    text = lines("O1000", "IF [#1 EQ 1] THEN", "#2=1", "M99", "ELSE", "#2=2", "ENDIF", "M30")
    program = _program(text)
    got = sorted((f.start_line, f.end_line) for f in folding_ranges(program, program.blocks))
    # the program's range reaches past the M99 inside the THEN branch to its M30 (line 7)
    assert got == [(0, 7), (1, 3), (4, 6)]
