"""A fault in the checker is reported where it happened and takes nothing else with it.

The analysis of a workspace looks at many lines, programs and files. Should one of them make
the checker itself fail (a bug: an exception that no rule of the language raises), that place
gets one ``internal-error`` diagnostic saying the checker, not the program, failed there, and
every other line, run and file is still checked and reported. The exception is logged with its
traceback for whoever fixes the bug.
"""

from __future__ import annotations

import logging

from ..bilingual import pick
from .checks.line_facts import LineFacts, finding
from .diagnostics import Diagnostic, diagnostic

log = logging.getLogger(__name__)

INTERNAL_ERROR = "internal-error"

# what could not be done: (English, Chinese)
LINE = ("check this line", "检查此行")
RUN = ("run this program for the analysis", "为分析运行此程序")
FILE = ("analyse this file", "分析此文件")


def _message(what: tuple[str, str], error: BaseException, locale: str) -> str:
    name = type(error).__name__
    return pick(
        locale,
        f"cncmacro failed to {what[0]} ({name}): a fault of the checker, not of the program; the rest is still checked",
        f"cncmacro 未能{what[1]}（{name}）：这是检查工具的故障，不是程序的错误；其余部分照常检查",
    )


def internal_error(file: str, line: int, what: tuple[str, str], error: BaseException, locale: str) -> Diagnostic:
    """The diagnostic of a checker fault at ``line`` of ``file`` (logged with its traceback)."""
    log.error("internal error while trying to %s (%s, line %d)", what[0], file, line + 1, exc_info=error)
    return diagnostic(file, line, 0, line, 1, INTERNAL_ERROR, _message(what, error, locale))


def line_fault(error: BaseException, locale: str) -> LineFacts:
    """What a line whose static check failed says: only that (the line is not known here; the
    finding goes wherever the block is)."""
    log.error("internal error while checking a line", exc_info=error)
    return LineFacts([finding(0, 1, INTERNAL_ERROR, _message(LINE, error, locale))])
