"""Where an answer of the editor layer points: lines and code-point columns (Python's string
indices), as the parser counts them. The language server turns them into the client's columns."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True, slots=True)
class Span:
    """Code-point columns ``start``..``end`` on one ``line``."""

    line: int
    start: int
    end: int


@dataclass(frozen=True, slots=True)
class Region:
    """From column ``start_column`` of ``start_line`` to column ``end_column`` of ``end_line``."""

    start_line: int
    start_column: int
    end_line: int
    end_column: int
