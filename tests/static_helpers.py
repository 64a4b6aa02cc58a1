"""Helpers for the static-diagnostics tests: check a program text and pick findings by code."""

from __future__ import annotations

from cncmacro.analysis.checks.static_checks import static_diagnostics
from cncmacro.analysis.diagnostics import Diagnostic
from cncmacro.dialects import get_dialect
from cncmacro.library.machine_file import MachineSettings
from cncmacro.library.programs import ProgramLibrary
from cncmacro.syntax.document import ParsedDocument


def check(
    text: str,
    dialect: str = "fanuc",
    *,
    file: str = "MAIN.nc",
    library: ProgramLibrary | None = None,
    settings: MachineSettings | None = None,
    locale: str = "en",
) -> list[Diagnostic]:
    """The static diagnostics of ``text`` read as ``file``."""
    doc = ParsedDocument(text)
    return static_diagnostics(doc.program, file, get_dialect(dialect), settings or MachineSettings(), library, locale)


def coded(found: list[Diagnostic], code: str) -> list[Diagnostic]:
    return [d for d in found if d.code == code]


def at(d: Diagnostic) -> tuple[int, int, int, str]:
    """(1-based line, 0-based start column, end column, severity) of a diagnostic."""
    return d.line + 1, d.column, d.end_column, d.severity


def lines(*text: str) -> str:
    return "\n".join(text) + "\n"
