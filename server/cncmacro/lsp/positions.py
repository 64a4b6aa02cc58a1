"""Columns between the editor and the parser.

The syntax tree counts columns in code points; LSP clients count UTF-16 code units unless they
agree on UTF-32. The two differ only on lines with characters outside the Basic Multilingual
Plane (Chinese comments are inside it), so the conversion is a quick check on most lines.
"""

from __future__ import annotations

import re

_ASTRAL = re.compile("[\U00010000-\U0010ffff]")


def has_astral(line: str) -> bool:
    """True when ``line`` has a character outside the Basic Multilingual Plane (its UTF-16
    columns then differ from its code-point columns)."""
    return _ASTRAL.search(line) is not None


def to_code_points(line: str, column: int, utf16: bool = True) -> int:
    """The code-point column of a client column on ``line``."""
    if not utf16 or _ASTRAL.search(line) is None:
        return min(max(column, 0), len(line))
    units = 0
    for i, ch in enumerate(line):
        if units >= column:
            return i
        units += 2 if ord(ch) > 0xFFFF else 1
    return len(line)


def to_client(line: str, column: int, utf16: bool = True) -> int:
    """The client column of a code-point column on ``line``."""
    if not utf16 or _ASTRAL.search(line) is None:
        return column
    return column + sum(1 for ch in line[:column] if ord(ch) > 0xFFFF)
