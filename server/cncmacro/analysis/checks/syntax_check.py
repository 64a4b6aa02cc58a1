"""Syntax diagnostics: every problem the parser found on a line, as a ``syntax`` diagnostic,
its message in English or, for a Chinese locale, in Chinese."""

from __future__ import annotations

from ...bilingual import in_language, is_chinese
from ...syntax.program import Program
from ..diagnostics import Diagnostic


def syntax_diagnostics(program: Program, file: str, locale: str | None = None) -> list[Diagnostic]:
    """One diagnostic for each problem on each block of ``program``."""
    chinese = is_chinese(locale)
    out: list[Diagnostic] = []
    for line in range(program.read_end):  # nothing after the closing '%' is read
        for p in program.blocks[line].problems:
            message = in_language(p.message, chinese)
            out.append(Diagnostic(file, line, p.start, line, max(p.end, p.start + 1), p.severity, "syntax", message))
    return out
