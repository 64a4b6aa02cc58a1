"""Diagnostics for the editor: debounced analysis, cancelled by newer versions, pushed and pulled.

Every open/change/close event of a document comes here. After a change the analysis waits a
short pause (``DEBOUNCE_SECONDS``); a newer edit cancels the waiting run, and a result is
published only if the document still has the version it was computed from, together with that
version. The first analysis of a huge file reports work-done progress. ``textDocument/diagnostic``
(pull) answers from the same cache, keyed by version.

``DiagnosticsEngine.analysis`` is the only thing that knows which analysis runs: today
``EditorAnalysis`` (the syntax diagnostics and, when the module exists,
``analysis.static_checks.static_diagnostics``). It receives the open/change/close/file-changed
events and answers ``analyze(path, should_cancel)`` with the interface of
``analysis.workspace.WorkspaceAnalysis``, so switching means constructing that instead.
"""

from __future__ import annotations

import asyncio
import logging
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

from lsprotocol import types

from ..analysis import Diagnostic, syntax_diagnostics
from ..library.machine_file import MachineSettings
from .documents import Edit, OpenDocument
from .positions import to_client

try:  # written by the static checks; optional until it lands
    from ..analysis.static_checks import static_diagnostics as _static_diagnostics
except ImportError:  # pragma: no cover - depends on the tree
    _static_diagnostics = None

try:
    from ..analysis.severity import apply_severities as _apply_severities
except ImportError:  # pragma: no cover - depends on the tree
    _apply_severities = None

if TYPE_CHECKING:
    from .server import CncMacroServer

log = logging.getLogger(__name__)

DEBOUNCE_SECONDS = 0.05
PROGRESS_LINES = 20_000  # a first analysis of a file this long reports progress
SOURCE = "cncmacro"
_SEVERITY = {
    "error": types.DiagnosticSeverity.Error,
    "warning": types.DiagnosticSeverity.Warning,
    "information": types.DiagnosticSeverity.Information,
    "hint": types.DiagnosticSeverity.Hint,
}


@dataclass(slots=True)
class Result:
    """What an analysis gives: the version of the analysed file and diagnostics per file
    (the shape of ``analysis.workspace.AnalysisResult``)."""

    version: int | None
    diagnostics: dict[str, list[Diagnostic]]


class EditorAnalysis:
    """Today's analysis of open documents: the syntax diagnostics and the static checks,
    with the severity settings applied. It takes the events and answers ``analyze`` the way
    ``analysis.workspace.WorkspaceAnalysis`` does, so that one can take its place; the text
    events are no-ops here because the server's documents are already parsed."""

    def __init__(self, server: CncMacroServer) -> None:
        self.server = server

    def open(self, path: str, text: str, version: int | None = None) -> None:
        pass

    def change(
        self, path: str, start_line: int, start_col: int, end_line: int, end_col: int, text: str, version: int
    ) -> None:
        pass

    def close(self, path: str) -> None:
        pass

    def file_changed(self, path: str) -> None:
        pass

    def analyze(self, path: str, should_cancel: Callable[[], bool] | None = None) -> Result | None:
        cancelled = should_cancel or (lambda: False)
        doc = next((d for d in self.server.documents.by_uri.values() if d.path == path), None)
        if doc is None:
            return None
        version = doc.version
        found = syntax_diagnostics(doc.parsed.program, doc.path)
        if _static_diagnostics is not None and not cancelled():
            found += _call_static(self.server, doc)
        if cancelled():
            return None
        overrides = self.server.severity_overrides()
        if overrides:
            found = _override(found, overrides)
        return Result(version, {path: found})


def _call_static(server: CncMacroServer, doc: OpenDocument) -> list[Diagnostic]:
    assert _static_diagnostics is not None
    try:
        return list(
            _static_diagnostics(
                doc.parsed.program,
                doc.path,
                doc.dialect,
                server.machine or MachineSettings(),
                server.index.library(doc),
                server.locale,
            )
        )
    except Exception:  # a fault in a check must not stop the syntax diagnostics
        log.exception("static checks failed on %s", doc.path)
        return []


def _override(found: list[Diagnostic], overrides: dict[str, str]) -> list[Diagnostic]:
    if _apply_severities is not None:
        try:
            return _apply_severities(found, overrides)
        except ValueError as e:
            log.warning("%s", e)
            return found
    from dataclasses import replace

    out = []
    for d in found:
        level = overrides.get(d.code)
        if level == "off":
            continue
        out.append(replace(d, severity=level) if level in _SEVERITY else d)
    return out


def to_lsp(d: Diagnostic, doc: OpenDocument, utf16: bool, uri_of: Callable[[str], str]) -> types.Diagnostic:
    """An analysis diagnostic as the protocol sends it."""
    start = to_client(doc.line(d.line), d.column, utf16)
    end = to_client(doc.line(d.end_line), d.end_column, utf16)
    related = [
        types.DiagnosticRelatedInformation(
            types.Location(
                uri_of(r.file),
                types.Range(types.Position(r.line, r.column), types.Position(r.line, r.end_column)),
            ),
            r.message,
        )
        for r in d.related
    ]
    tags = [types.DiagnosticTag.Unnecessary] if "unnecessary" in d.tags else None
    return types.Diagnostic(
        range=types.Range(types.Position(d.line, start), types.Position(d.end_line, end)),
        message=d.message,
        severity=_SEVERITY.get(d.severity, types.DiagnosticSeverity.Error),
        code=d.code,
        source=SOURCE,
        related_information=related or None,
        tags=tags,
    )


class DiagnosticsEngine:
    """Schedules, cancels and publishes the analysis of open documents."""

    def __init__(self, server: CncMacroServer, delay: float = DEBOUNCE_SECONDS) -> None:
        self.server = server
        self.analysis = EditorAnalysis(server)
        self.delay = delay
        self._tasks: dict[str, asyncio.Task[None]] = {}
        self._results: dict[str, tuple[int, list[types.Diagnostic]]] = {}
        self._analysed_once: set[str] = set()

    # ---- document events
    def opened(self, doc: OpenDocument, text: str) -> None:
        self.analysis.open(doc.path, text, doc.version)
        self._schedule(doc, 0.0)

    def changed(self, doc: OpenDocument, edits: list[Edit]) -> None:
        for e in edits:
            if isinstance(e, str):
                self.analysis.close(doc.path)
                self.analysis.open(doc.path, e, doc.version)
            else:
                self.analysis.change(doc.path, *e, doc.version)
        self._schedule(doc, self.delay)

    def file_changed(self, path: str) -> None:
        self.analysis.file_changed(path)

    def closed(self, doc: OpenDocument) -> None:
        self.analysis.close(doc.path)
        uri = doc.uri
        task = self._tasks.pop(uri, None)
        if task is not None:
            task.cancel()
        self._results.pop(uri, None)
        self._analysed_once.discard(uri)
        self.server.text_document_publish_diagnostics(types.PublishDiagnosticsParams(uri=uri, diagnostics=[]))

    def refresh_all(self) -> None:
        """Analyse every open document again (settings or the workspace changed)."""
        self._results.clear()
        for doc in list(self.server.documents.by_uri.values()):
            self._schedule(doc, 0.0)

    # ---- running
    def _schedule(self, doc: OpenDocument, delay: float) -> None:
        old = self._tasks.pop(doc.uri, None)
        if old is not None:
            old.cancel()
        self._tasks[doc.uri] = asyncio.get_event_loop().create_task(self._run(doc.uri, doc.version, delay))

    async def _run(self, uri: str, version: int, delay: float) -> None:
        if delay:
            await asyncio.sleep(delay)
        if not self.server.settings_ready.is_set():  # the first analyses wait for the settings
            await self.server.settings_ready.wait()
        doc = self.server.documents.by_uri.get(uri)
        if doc is None or doc.version != version:
            return
        token = None
        if uri not in self._analysed_once and len(doc.lines) >= PROGRESS_LINES:
            token = await self._begin_progress(doc)
        try:
            items = self.compute(doc)
        finally:
            if token is not None:
                self.server.work_done_progress.end(token, types.WorkDoneProgressEnd(message="done"))
        self._analysed_once.add(uri)
        if items is None or doc.version != version or self.server.documents.by_uri.get(uri) is not doc:
            return  # a newer edit arrived: its own run publishes
        self.server.text_document_publish_diagnostics(
            types.PublishDiagnosticsParams(uri=uri, diagnostics=items, version=version)
        )

    async def _begin_progress(self, doc: OpenDocument) -> str | None:
        caps = self.server.client_capabilities.window
        if caps is None or not caps.work_done_progress:
            return None
        token = f"cncmacro-analysis-{doc.uri}-{doc.version}"
        try:
            await self.server.work_done_progress.create_async(token)
        except Exception:  # the client refused: analyse without progress
            return None
        self.server.work_done_progress.begin(
            token,
            types.WorkDoneProgressBegin(
                title="cncmacro", message=f"analysing {len(doc.lines)} lines", cancellable=False
            ),
        )
        await asyncio.sleep(0)
        return token

    def compute(self, doc: OpenDocument) -> list[types.Diagnostic] | None:
        """The protocol diagnostics of ``doc``'s current version (cached per version)."""
        cached = self._results.get(doc.uri)
        if cached is not None and cached[0] == doc.version:
            return cached[1]
        version = doc.version
        result = self.analysis.analyze(doc.path, lambda: doc.version != version)
        if result is None or result.version != version:
            return None
        found = result.diagnostics.get(doc.path, [])
        utf16 = self.server.documents.utf16
        items = [to_lsp(d, doc, utf16, self.server.uri_for_path) for d in found if d.file == doc.path]
        self._results[doc.uri] = (version, items)
        return items

    # ---- pull
    def pull(self, params: types.DocumentDiagnosticParams) -> types.DocumentDiagnosticReport:
        doc = self.server.documents.get(params.text_document.uri)
        result_id = f"{doc.version}"
        if params.previous_result_id == result_id and doc.uri in self._results:
            return types.RelatedUnchangedDocumentDiagnosticReport(result_id=result_id)
        items = self.compute(doc) or []
        return types.RelatedFullDocumentDiagnosticReport(items=items, result_id=result_id)
