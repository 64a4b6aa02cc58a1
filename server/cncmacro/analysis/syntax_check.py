"""Syntax diagnostics: every problem the parser found on a line, as a ``syntax`` diagnostic."""

from __future__ import annotations

from ..syntax.program import Program
from .diagnostics import Diagnostic


def syntax_diagnostics(program: Program, file: str) -> list[Diagnostic]:
    """One diagnostic for each problem on each block of ``program``."""
    out: list[Diagnostic] = []
    for line, block in enumerate(program.blocks):
        for p in block.problems:
            out.append(Diagnostic(file, line, p.start, line, max(p.end, p.start + 1), p.severity, "syntax", p.message))
    return out
