"""``cncmacro check``'s output, written as the findings come.

``FindingsReport`` is given the findings of one group of files at a time (``call_groups.py``)
and writes them at once, sorted by file, line and column within the group: text, one line per
finding (``file:line:column: severity: message [code]``), and JSON, the array written element
by element (the same text as the whole array written at the end); both are flushed after each
group, so that a person or a pipe sees the first files' findings while the rest are checked.
SARIF's log names its rules before its results, so it keeps the findings (not the files they
came from) and writes the log at ``close``. It keeps what the exit status needs: whether an
error was found. Hints are left out unless asked for.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import TextIO

from ..analysis import Diagnostic
from ..library.files import shown_text
from .sarif import to_sarif
from .terminal import json_text, printable, shown_name


class FindingsReport:
    """See the module docstring. ``fmt`` is ``text``, ``json`` or ``sarif``."""

    def __init__(self, out: TextIO, fmt: str, hints: bool, version: str) -> None:
        self.out = out
        self.fmt = fmt
        self.hints = hints
        self.version = version
        self.errors = False  # an error was found
        self.written = 0  # findings written (JSON: elements of the array)
        self._held: list[Diagnostic] = []  # SARIF's, until ``close``

    def add(self, diagnostics: Iterable[Diagnostic]) -> None:
        """Write the findings of one group of files."""
        shown = sorted((d for d in diagnostics if self.hints or d.severity != "hint"), key=Diagnostic.sort_key)
        self.errors = self.errors or any(d.severity == "error" for d in shown)
        if self.fmt == "sarif":
            self._held += shown
            return
        write = self.out.write
        for d in shown:
            if self.fmt == "json":
                element = json_text(diagnostic_json(d), indent=2).replace("\n", "\n  ")
                write(("[\n  " if self.written == 0 else ",\n  ") + element)
            else:
                name, message = shown_name(shown_text(d.file)), printable(shown_text(d.message))
                write(f"{name}:{d.line + 1}:{d.column + 1}: {d.severity}: {message} [{d.code}]\n")
            self.written += 1
        self.out.flush()

    def close(self) -> None:
        """End the output: close the JSON array, or write the SARIF log."""
        if self.fmt == "json":
            self.out.write("[]\n" if self.written == 0 else "\n]\n")
        elif self.fmt == "sarif":
            self.out.write(json_text(to_sarif(self._held, self.version), indent=2) + "\n")
        self.out.flush()


def diagnostic_json(d: Diagnostic) -> dict[str, object]:
    """The CLI contract's JSON object: 1-based lines and columns, end column exclusive."""
    return {
        "file": shown_text(d.file),
        "line": d.line + 1,
        "column": d.column + 1,
        "endLine": d.end_line + 1,
        "endColumn": d.end_column + 1,
        "severity": d.severity,
        "code": d.code,
        "message": shown_text(d.message),
    }
