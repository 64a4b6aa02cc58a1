"""Diagnostics: what the analysis reports, with the stable codes of DESIGN.md.

Lines and columns are 0-based here, as in the syntax tree; the command line prints them
1-based and the language server sends them as they are.
"""

from __future__ import annotations

from dataclasses import dataclass

SEVERITIES = ("error", "warning", "information", "hint")


@dataclass(slots=True, frozen=True)
class Diagnostic:
    """One finding in one file."""

    file: str
    line: int
    column: int
    end_line: int
    end_column: int
    severity: str
    code: str
    message: str

    def sort_key(self) -> tuple[str, int, int, str]:
        return (self.file, self.line, self.column, self.code)
