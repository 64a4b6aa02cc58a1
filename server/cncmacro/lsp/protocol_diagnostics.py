"""Analysis diagnostics as the protocol sends them: severities, codes, the ``Unnecessary`` tag
for blocks no run reached, and related places as ``DiagnosticRelatedInformation``. Columns
go out in the position encoding agreed with the client (``positions``), read from each file's
line text, also for a related place in another file the editor has not opened."""

from __future__ import annotations

from collections.abc import Callable

from lsprotocol import types

from ..analysis import Diagnostic
from ..analysis.diagnostics import UNNECESSARY
from .positions import Encoding

SOURCE = "cncmacro"
SEVERITY = {
    "error": types.DiagnosticSeverity.Error,
    "warning": types.DiagnosticSeverity.Warning,
    "information": types.DiagnosticSeverity.Information,
    "hint": types.DiagnosticSeverity.Hint,
}

LineText = Callable[[str, int], str]  # (file, 0-based line) -> the line's text ("" if unknown)


def _range(line_text: LineText, file: str, line: int, column: int, end_line: int, end_column: int,
           encoding: Encoding) -> types.Range:  # fmt: skip
    text, end_text = line_text(file, line), line_text(file, end_line)
    start = encoding.to_client(text, min(column, len(text)))  # a mark just past a line's end stays on it
    end = encoding.to_client(end_text, min(end_column, len(end_text)))
    return types.Range(types.Position(line, start), types.Position(end_line, end))


def to_lsp(d: Diagnostic, line_text: LineText, encoding: Encoding, uri_of: Callable[[str], str]) -> types.Diagnostic:
    """One analysis diagnostic as a protocol diagnostic."""
    related = [
        types.DiagnosticRelatedInformation(
            types.Location(uri_of(r.file), _range(line_text, r.file, r.line, r.column, r.line, r.end_column, encoding)),
            r.message,
        )
        for r in d.related
    ]
    return types.Diagnostic(
        range=_range(line_text, d.file, d.line, d.column, d.end_line, d.end_column, encoding),
        message=d.message,
        severity=SEVERITY.get(d.severity, types.DiagnosticSeverity.Error),
        code=d.code,
        source=SOURCE,
        related_information=related or None,
        tags=[types.DiagnosticTag.Unnecessary] if UNNECESSARY in d.tags else None,
    )
