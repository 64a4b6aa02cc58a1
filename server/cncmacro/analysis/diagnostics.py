"""Diagnostics: what the analysis reports, with the stable codes of docs/design.md.

Lines and columns are 0-based here, as in the syntax tree; the command line prints them
1-based and the language server sends them as they are. ``related`` points at other places
that explain a finding (the caller of a macro, the first of two duplicate labels); ``tags``
holds ``"unnecessary"`` for code the runs never reached, which editors show faded.
"""

from __future__ import annotations

from dataclasses import dataclass

SEVERITIES = ("error", "warning", "information", "hint")
UNNECESSARY = "unnecessary"


@dataclass(slots=True, frozen=True)
class Related:
    """Another place that explains a diagnostic (0-based, like ``Diagnostic``)."""

    file: str
    line: int
    column: int
    end_column: int
    message: str


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
    related: tuple[Related, ...] = ()
    tags: tuple[str, ...] = ()

    def sort_key(self) -> tuple[str, int, int, str]:
        return (self.file, self.line, self.column, self.code)
