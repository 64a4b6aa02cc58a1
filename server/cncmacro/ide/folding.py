"""Folding ranges: WHILE..END loops, the branches of a block IF (``IF [..] THEN`` up to the line
before its ELSE, the ELSE up to its ENDIF; without ELSE, the IF up to its ENDIF), O programs up
to exactly their last M99/M30/M02 (else up to the next program; which codes end a program is
``machine/program_end.py``'s), and runs of comment-only lines, from the parser's ``Program`` and
blocks. A program's range never ends inside one of its loops or block IFs (an ``M99`` in a loop
body is not the program's end there): it reaches the loop's END (the IF's ENDIF), so that the
two nest, as editors that pair ranges by their lines need."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from ..machine.program_end import end_code
from ..syntax.nodes import Block, Number
from ..syntax.program import Program


@dataclass(frozen=True, slots=True)
class Fold:
    """Lines ``start_line``..``end_line`` fold into the first; ``comment``: a run of comment lines."""

    start_line: int
    end_line: int
    comment: bool = False


def folding_ranges(program: Program, blocks: Sequence[Block]) -> list[Fold]:
    """The loops, then the O programs, then the runs of comment-only lines of a document."""
    out = [Fold(p.do_line, p.end_line) for p in program.loops if p.end_line > p.do_line]
    for f in program.if_blocks:
        if f.else_line is None:
            out.append(Fold(f.if_line, f.endif_line))
            continue
        if f.else_line - 1 > f.if_line:
            out.append(Fold(f.if_line, f.else_line - 1))
        if f.endif_line > f.else_line:
            out.append(Fold(f.else_line, f.endif_line))
    spans = [(p.do_line, p.end_line) for p in program.loops] + [(f.if_line, f.endif_line) for f in program.if_blocks]
    for u in program.units:
        if u.number is None:
            continue
        end = u.end - 1
        while end > u.start and _is_blank(blocks[end]):
            end -= 1
        last = end
        while last > u.start and end_code(blocks[last]) is None:
            last -= 1
        end = last if last > u.start else end
        end = _past_loops(spans, u.start, end)
        if end > u.start:
            out.append(Fold(u.start, end))
    run_start = None
    for i, b in enumerate(blocks):
        comment_only = b.plain is None and bool(b.comments) and b.is_empty
        if comment_only and run_start is None:
            run_start = i
        elif not comment_only and run_start is not None:
            if i - 1 > run_start:
                out.append(Fold(run_start, i - 1, comment=True))
            run_start = None
    if run_start is not None and len(blocks) - 1 > run_start:
        out.append(Fold(run_start, len(blocks) - 1, comment=True))
    return out


def _past_loops(spans: list[tuple[int, int]], start: int, end: int) -> int:
    """``end``, moved to the last line of every loop or block IF (first line, last line) that
    starts in ``start``..``end`` and ends after it."""
    moved = True
    while moved:
        moved = False
        for first, last in spans:
            if start <= first <= end < last:
                end = last
                moved = True
    return end


def _is_blank(b: Block) -> bool:
    """A line after a program's end: empty, or a ``%`` mark."""
    if b.plain is not None:
        return False
    if b.tape:
        return True
    return b.is_empty and not b.comments and not any(w.letter == "M" and isinstance(w.value, Number) for w in b.words)
