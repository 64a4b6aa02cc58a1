"""What follows the closing ``%`` (docs/semantics.md §1): a hint, never an error.

The tape ends at its closing ``%`` (``syntax/program.py`` decides which line that is). A
control reading the tape stops there, so whatever a file holds after it (a DOS end-of-file
byte 0x1A, a second copy, notes, junk) is not part of the program: it is not checked, run or
reported. Only when there is such text does the closing ``%`` get one ``after-tape-end`` hint
saying how many lines are passed over.
"""

from __future__ import annotations

from itertools import islice

from ...bilingual import pick
from ...syntax.program import Program
from ..diagnostics import Diagnostic, diagnostic


def tape_diagnostics(program: Program, file: str, locale: str) -> list[Diagnostic]:
    """The ``after-tape-end`` hint on the closing ``%`` when text follows it."""
    end = program.tape_end
    if end is None:
        return []
    blocks = program.blocks
    after = [k for k, b in enumerate(islice(blocks, end + 1, None), start=end + 1) if not b.is_empty]
    if not after:
        return []
    last = after[-1] + 1  # 1-based
    n = last - end - 1
    what = "the line after it is" if n == 1 else f"the {n} lines after it (to line {last}) are"
    message = pick(
        locale,
        f"the tape ends at this '%': {what} not part of the program and not read",
        f"纸带在此 '%' 处结束：其后的 {n} 行（至第 {last} 行）不属于程序，不会被读取",
    )
    return [diagnostic(file, end, 0, end, 1, "after-tape-end", message)]
