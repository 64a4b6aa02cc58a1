"""Folding without a server: a WHILE loop folds from its DO to its END, an O program from its
header to its last end code (M30, M99), and a run of comment-only lines into its first."""

from __future__ import annotations

from cncmacro.ide.folding import Fold, folding_ranges

from .documents import document

TWO_PROGRAMS = (
    "%",  # 0
    "O0001 (MAIN)",  # 1
    "#1=0",
    "WHILE[#1 LT 3] DO1",  # 3
    "#1=#1+1",
    "END1",  # 5
    "M30",  # 6
    "(A NOTE)",  # 7
    "(ANOTHER NOTE)",  # 8
    "O0002",  # 9
    "G00 X0",
    "M99",  # 11
    "%",  # 12
)


def test_a_loop_a_program_up_to_its_end_code_and_a_run_of_comments_fold() -> None:
    doc = document(*TWO_PROGRAMS)
    assert folding_ranges(doc.parsed.program, doc.parsed.blocks) == [
        Fold(3, 5),  # WHILE .. DO1 to END1
        Fold(1, 6),  # O0001 to its M30, not the comments after it
        Fold(9, 11),  # O0002 to its M99, not the closing %
        Fold(7, 8, comment=True),
    ]


def test_a_program_whose_m99_is_inside_a_loop_folds_to_the_loops_end() -> None:
    doc = document("O0001", "WHILE[#1 LT 3] DO1", "#1=#1+1", "M99", "END1", "G00 X0")
    assert folding_ranges(doc.parsed.program, doc.parsed.blocks) == [Fold(1, 4), Fold(0, 4)]  # not (0, 3)


def test_a_single_comment_line_does_not_fold() -> None:
    doc = document("O0001", "(ONE NOTE)", "G00 X0", "M30")
    assert folding_ranges(doc.parsed.program, doc.parsed.blocks) == [Fold(0, 3)]
