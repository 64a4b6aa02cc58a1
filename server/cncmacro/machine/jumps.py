"""Where a jump lands and which loops it leaves, as pure functions of line numbers (docs/semantics.md §4, seed 002).

``GOTO n`` (also ``IF .. GOTO n`` and the gsk980tdi ``G65 H80``–``H86`` branches) searches forward
from the jumping block to the end of the program, then from its start; ``M99 Pn`` returns to the
first Nn after the call line, else the last one before it; ``M98 Q n`` starts at the first Nn of
the called program. The landing functions take the sorted lines that carry the label inside the
program unit and give the target line (None when there is none). A loop (``DO`` line → ``END``
line) holds the lines after its ``DO`` up to its ``END``: a jump stays in the loops that hold both
its line and its target, leaves the others, and may not enter one from outside. The interpreter
(``CompiledFile`` caches the answers per line and label) and the editor features both ask here,
through ``LoopSpans``.
"""

from __future__ import annotations

from bisect import bisect_left, bisect_right
from collections.abc import Iterable, Iterator, Mapping
from typing import Protocol


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


class _Branches(Protocol):
    """A block IF as ``syntax.program.IfBlock`` gives it: its branches as (marker line, last line)."""

    @property
    def spans(self) -> tuple[tuple[int, int], ...]: ...


def branch_entered(blocks: Iterable[_Branches], from_line: int, target: int) -> tuple[int, int] | None:
    """The branch of a block IF (its marker line and last line) that a jump from ``from_line``
    to ``target`` enters from outside, or None. A branch holds the lines after its IF (or ELSE)
    up to its ELSE (or ENDIF): a jump may leave one, as it leaves a loop, and may stay inside
    one, but may not land in one it is not in (docs/semantics.md §4, "Block IF")."""
    for block in blocks:
        for first, last in block.spans:
            if first < target <= last and not first < from_line <= last:
                return first, last
    return None


class LoopSpans:
    """The loops of a program (``DO`` line → ``END`` line), kept so that the loops holding a
    line are found in time in proportion to how many hold it (and how deep loops nest around
    it), not to how many the program has: a CAM program of a million lines has tens of
    thousands, and every jump asks."""

    __slots__ = ("_dos", "_ends", "_outer")

    def __init__(self, loops: Mapping[int, int]) -> None:
        pairs = sorted(loops.items())
        self._dos = [do for do, _ in pairs]
        self._ends = [end for _, end in pairs]
        # for each loop, the nearest loop before it that ends after it (-1: none); the loops
        # between the two end no later than it, so a line after its end is after theirs too
        outer: list[int] = []
        stack: list[int] = []
        for k, end in enumerate(self._ends):
            while stack and self._ends[stack[-1]] <= end:
                stack.pop()
            outer.append(stack[-1] if stack else -1)
            stack.append(k)
        self._outer = outer

    def holding(self, line: int) -> Iterator[tuple[int, int]]:
        """The loops (``DO`` line, ``END`` line) that hold ``line``: it is after the ``DO`` and
        at most the ``END``; innermost first."""
        ends = self._ends
        k = bisect_left(self._dos, line) - 1  # the last loop whose DO is before the line
        while k >= 0:
            if ends[k] >= line:
                yield self._dos[k], ends[k]
                k -= 1
            else:
                k = self._outer[k]

    def entered(self, from_line: int, target: int) -> int | None:
        """The ``DO`` line of the outermost loop that a jump from ``from_line`` to ``target``
        enters from outside, or None when it enters none."""
        entered = [do for do, end in self.holding(target) if not do < from_line <= end]
        return min(entered) if entered else None

    def kept(self, from_line: int, target: int) -> int:
        """How many loops a jump from ``from_line`` to ``target`` stays in: those that hold both
        lines. Loops nest, so they are the outermost of the loops running on ``from_line``; the
        jump leaves the ones inside them."""
        return sum(1 for do, end in self.holding(target) if do < from_line <= end)
