"""The cycle time in the editor: a code lens above each O program and each tool change, and the
elapsed time in the hover of any block.

``≈ 3 min 12 s · 1,842 mm cut · 6,300 mm rapid`` above the O line of a program that an analysis
run started from and completed, and ``T2 ≈ 48 s · 310 mm cut · 1,020 mm rapid`` above each tool
change (that tool's part, up to the next change or the end). The hover of a block adds when it
first starts; a length variable's hover and completion take the program's unit from the same totals
(``program_inch``). All of it comes from the analysis the server already runs
(``analysis/runs/cycle_lenses.py``): a request runs nothing, and a document edited since its last
analysis shows nothing until the next one.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from lsprotocol import types

from ..analysis.runs.cycle_summary import duration_text, tool_name, totals_text
from .texts import t

if TYPE_CHECKING:
    from .cursor import Cursor
    from .documents import OpenDocument
    from .server import CncMacroServer


def register(server: CncMacroServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_CODE_LENS)
    def code_lens(ls: CncMacroServer, params: types.CodeLensParams) -> list[types.CodeLens] | None:
        doc = ls.documents.get(params.text_document.uri)
        if doc is None:  # not open: the empty answer (documents.py)
            return None
        timing = ls.diagnostics.timing(doc)
        if timing is None:
            return []
        lenses: list[tuple[int, str]] = [(line, totals_text(t, ls.locale)) for line, t in timing.programs.items()]
        lathe = doc.dialect.lathe
        lenses += [
            (line, f"{tool_name(tool, lathe)} {totals_text(t, ls.locale)}") for line, (tool, t) in timing.tools.items()
        ]
        return [
            types.CodeLens(
                range=types.Range(types.Position(line, 0), types.Position(line, 0)),
                command=types.Command(title=title, command=""),
            )
            for line, title in sorted(lenses)
            if 0 <= line < len(doc.lines)
        ]


def elapsed_text(ls: CncMacroServer, doc: OpenDocument, line: int) -> str | None:
    """The hover's line on when the block on ``line`` first starts, or None."""
    timing = ls.diagnostics.timing(doc)
    seconds = timing.elapsed.get(line) if timing is not None else None
    if seconds is None:
        return None
    shown = duration_text(seconds, ls.locale)
    return t("starts_at", ls.locale, shown=shown)


def program_inch(ls: CncMacroServer, cur: Cursor) -> bool | None:
    """Whether the program under the cursor is in inches: from the analysis run that started
    from it and completed (its totals' unit, as the code lens shows it), else None (not known:
    a subprogram takes its caller's unit)."""
    timing = ls.diagnostics.timing(cur.doc)
    if timing is None:
        return None
    totals = timing.programs.get(cur.doc.parsed.program.unit_at(cur.line).start)
    return None if totals is None else totals.inch


def refresh_code_lenses(server: CncMacroServer) -> None:
    """Ask the client for the lenses again after an analysis, when it can be asked (a session
    that was never initialised has no capabilities to ask by)."""
    client = getattr(server.protocol, "client_capabilities", None)
    caps = client.workspace if client is not None else None
    lenses = caps.code_lens if caps is not None else None
    if lenses is not None and lenses.refresh_support:
        server.workspace_code_lens_refresh(None)
