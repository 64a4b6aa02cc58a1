"""Where a jump lands and which loops it leaves, as pure functions of line numbers (docs/semantics.md §4, seed 002).

``GOTO n`` (also ``IF .. GOTO n`` and the gsk980tdi ``G65 H80``–``H86`` branches) searches forward
from the jumping block to the end of the program, then from its start; ``M99 Pn`` returns to the
first Nn after the call line, else the last one before it; ``M98 Q n`` starts at the first Nn of
the called program. The landing functions take the sorted lines that carry the label inside the
program unit and give the target line (None when there is none). A loop (``DO`` line → ``END``
line) holds the lines after its ``DO`` up to its ``END``: a jump stays in the loops that hold both
its line and its target, leaves the others, and may not enter one from outside. The interpreter
(``CompiledFile`` caches the answers per line and label) and the editor features both ask here.
"""

from __future__ import annotations

from bisect import bisect_right
from collections.abc import Mapping


def goto_line(label_lines: list[int], from_line: int) -> int | None:
    """The line ``GOTO n`` on ``from_line`` lands on."""
    if not label_lines:
        return None
    k = bisect_right(label_lines, from_line)
    return label_lines[k] if k < len(label_lines) else label_lines[0]


def return_line(label_lines: list[int], call_line: int) -> int | None:
    """The line ``M99 Pn`` returns to in the caller that called from ``call_line``."""
    if not label_lines:
        return None
    k = bisect_right(label_lines, call_line)
    return label_lines[k] if k < len(label_lines) else label_lines[k - 1]


def first_line(label_lines: list[int]) -> int | None:
    """The line ``M98 Q n`` starts at: the first Nn of the program."""
    return label_lines[0] if label_lines else None


def entered_loop(loops: Mapping[int, int], from_line: int, target: int) -> int | None:
    """The ``DO`` line of a loop (``loops`` maps ``DO`` line → ``END`` line) that a jump from
    ``from_line`` to ``target`` enters from outside, or None when it enters none."""
    for do, end in loops.items():
        if do < target <= end and not do < from_line <= end:
            return do
    return None


def loops_kept(loops: Mapping[int, int], from_line: int, target: int) -> int:
    """How many loops a jump from ``from_line`` to ``target`` stays in: those that hold both
    lines. Loops nest, so they are the outermost of the loops running on ``from_line``; the
    jump leaves the ones inside them."""
    return sum(1 for do, end in loops.items() if do < target <= end and do < from_line <= end)
