"""Syntax diagnostics: every problem the parser found on a line, as a ``syntax`` diagnostic,
its message in English or, for a Chinese locale, in Chinese.

A problem that names a control's alarm (``Problem.alarm``) is said here, the one place its
number is written into the text, as the profile shows it: "(alarm 114)" on FANUC and GSK,
"(alarm)" on Haas, which documents none of these numbers (docs/semantics.md §6).
"""

from __future__ import annotations

from ...bilingual import in_language, is_chinese
from ...dialects import get_dialect
from ...dialects.dialect import Dialect
from ...syntax.nodes import Problem
from ...syntax.program import Program
from ..diagnostics import Diagnostic


def problem_message(problem: Problem, dialect: Dialect, chinese: bool) -> str:
    """The parser's message for ``problem`` in one language, with its alarm as ``dialect`` shows it."""
    message = in_language(problem.said(dialect.block_if), chinese)
    if problem.alarm is None:
        return message
    said = dialect.alarm_said(problem.alarm, 3)
    return f"{message}（{said.zh}）" if chinese else f"{message} ({said})"


def syntax_findings(
    problems: tuple[Problem, ...], line: int, file: str, chinese: bool, dialect: Dialect
) -> list[Diagnostic]:
    """The syntax problems of the block on ``line`` as diagnostics."""
    return [
        Diagnostic(
            file, line, p.start, line, max(p.end, p.start + 1), p.severity, "syntax",
            problem_message(p, dialect, chinese),
        )
        for p in problems
    ]  # fmt: skip


def syntax_diagnostics(
    program: Program, file: str, locale: str | None = None, dialect: Dialect | None = None
) -> list[Diagnostic]:
    """One diagnostic for each problem on each block of ``program``, read on ``dialect`` (the
    default profile when not given)."""
    chinese = is_chinese(locale)
    shown = dialect if dialect is not None else get_dialect()
    out: list[Diagnostic] = []
    for line in range(program.read_end):  # nothing after the closing '%' is read
        out.extend(syntax_findings(program.blocks[line].problems, line, file, chinese, shown))
    return out
