"""Where a jump lands, as pure functions of the label lines (SEMANTICS.md §4, seed 002).

``GOTO n`` searches forward from the jumping block to the end of the program, then from its
start; ``M99 Pn`` returns to the first Nn after the call line, else the last one before it;
``M98 Q n`` starts at the first Nn of the called program. These take the sorted lines that
carry the label inside the program unit and give the target line (None when there is none),
so that an editor can follow a jump without running the program.
"""

from __future__ import annotations

from bisect import bisect_right


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
