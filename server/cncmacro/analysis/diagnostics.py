"""Diagnostics: what the analysis reports, with the stable codes of docs/design.md.

Lines and columns are 0-based here, as in the syntax tree; the command line prints them
1-based and the language server sends them as they are. ``related`` points at other places
that explain a finding (the caller of a macro, the first of two duplicate labels); ``tags``
holds ``"unnecessary"`` for code the runs never reached, which editors show faded. A check makes
one with ``diagnostic``, which takes the severity from the code's record (``analysis/codes.py``).
"""

from __future__ import annotations

from dataclasses import dataclass

from .codes import default_severity

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


def diagnostic(
    file: str,
    line: int,
    column: int,
    end_line: int,
    end_column: int,
    code: str,
    message: str,
    related: tuple[Related, ...] = (),
    tags: tuple[str, ...] = (),
    *,
    milder: bool = False,
) -> Diagnostic:
    """A ``Diagnostic`` of ``code`` with the code's default severity, or its milder one where the
    check says the control is lenient (``codes.default_severity``)."""
    severity = default_severity(code, milder)
    return Diagnostic(file, line, column, end_line, end_column, severity, code, message, related, tags)
