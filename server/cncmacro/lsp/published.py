"""What the editor has been shown of the analysis: each file's diagnostics, the values the runs
left on its lines and its cycle time, each for the version it was analysed at.

An outcome (``outcomes.py``) is published only for the open documents still at the version it
was computed from; a file that is not open (a macro called from an open file) is published
without a version and cleared when a later outcome no longer has it. Before the first analysis
of a huge document ends, its first screen's findings (``WorkspaceAnalysis.first_screen``) are
published at once, and at each edit meanwhile those of the first screen and of the lines edited
so far (``provisional``). Diagnostics are pushed only: a server that also answers
``textDocument/diagnostic`` has each finding shown twice by a client that pulls and takes
pushes too (Neovim 0.10 and later keep the two apart).
"""

from __future__ import annotations

import logging
from typing import TYPE_CHECKING, cast

from lsprotocol import types

from ..analysis import Diagnostic
from ..analysis.first_screen import FIRST_SCREEN_LINES
from ..analysis.runs.cycle_lenses import FileTiming
from ..analysis.workspace import WorkspaceAnalysis
from .cycle_lenses import refresh_code_lenses
from .documents import OpenDocument
from .outcomes import LineValues, Outcome
from .protocol_diagnostics import to_lsp
from .site_steps import index_soon

if TYPE_CHECKING:
    from .server import CncMacroProtocol, CncMacroServer

log = logging.getLogger(__name__)

PROVISIONAL_LINES = 1_000  # edited lines (besides the first screen) whose findings show before its first analysis


class Published:
    """See the module docstring."""

    def __init__(self, server: CncMacroServer) -> None:
        self.server = server
        # per URI: the version, the diagnostics, their protocol form, and how many times published
        self._published: dict[str, tuple[int | None, list[Diagnostic], list[types.Diagnostic], int]] = {}
        self._values: dict[str, tuple[int | None, LineValues]] = {}
        self._timing: dict[str, tuple[int | None, FileTiming | None]] = {}
        self.analysed_once: set[str] = set()  # the URIs an outcome was published for
        self.first_shown: set[str] = set()  # huge documents whose first screen was published
        # per huge document not analysed yet: its first screen's lines, the analysis that
        # checked them and their findings
        self._first_screens: dict[str, tuple[tuple[str, ...], WorkspaceAnalysis, list[Diagnostic]]] = {}
        self._touched: dict[str, set[int]] = {}  # per huge document not analysed yet, the lines edited

    def outcome(self, outcome: Outcome) -> None:
        """Publish a finished analysis (on the editor's thread)."""
        server = self.server
        documents = server.documents.by_uri
        for uri, version in outcome.versions.items():
            doc = documents.get(uri)
            if doc is not None and doc.version != version:
                continue
            if version is not None or doc is not None:
                self._values[uri] = (version, outcome.values.get(uri, {}))
                self._timing[uri] = (version, outcome.timing.get(uri))
            self.analysed_once.add(uri)
            if doc is not None:
                index_soon(doc.sites)  # the document's variable index, in steps, before a hover asks
            self._touched.pop(uri, None)
            self._first_screens.pop(uri, None)
            diags = outcome.found[uri]
            old = self._published.get(uri)
            if old is not None and old[0] == version and old[1] == diags:
                continue
            self._published[uri] = (version, diags, outcome.items[uri], old[3] + 1 if old else 1)
            cast("CncMacroProtocol", server.protocol).send_diagnostics(uri, version, outcome.payloads[uri])
        gone = [] if outcome.partial else [u for u, p in self._published.items() if u not in outcome.versions]
        for uri in [u for u in gone if u not in documents]:
            del self._published[uri]  # a file that is not open, no longer with findings
            server.text_document_publish_diagnostics(types.PublishDiagnosticsParams(uri=uri, diagnostics=[]))
        if server.settings.inlay_values:
            self._refresh_inlay_hints()
        refresh_code_lenses(server)

    def _refresh_inlay_hints(self) -> None:
        caps = self.server.client_capabilities.workspace
        hints = caps.inlay_hint if caps is not None else None
        if hints is not None and hints.refresh_support:
            self.server.workspace_inlay_hint_refresh(None)

    def first_screen(self, analysis: WorkspaceAnalysis, uri: str, path: str, lines: list[str], version: int,
                     extra: list[int] | None = None) -> None:  # fmt: skip
        """Publish the findings that the first lines of a huge document (and the lines of
        ``extra``) earn by themselves (``WorkspaceAnalysis.first_screen``), before the document
        is parsed in full and analysed: the top of the file is what the editor shows first."""
        self.first_shown.add(uri)
        top = tuple(lines[:FIRST_SCREEN_LINES])
        kept = self._first_screens.get(uri)
        try:
            if kept is not None and kept[0] == top and kept[1] is analysis:  # the first screen is as it was
                diags = kept[2] + analysis.first_screen(path, lines, extra or (), head=False)
            else:
                diags = analysis.first_screen(path, lines)
                self._first_screens[uri] = (top, analysis, diags)
                diags = diags + analysis.first_screen(path, lines, extra or (), head=False)
        except Exception:  # the whole analysis will say it
            log.exception("the first screen's findings failed")
            return

        def line_text(_file: str, line: int) -> str:
            return lines[line] if 0 <= line < len(lines) else ""

        encoding = self.server.documents.encoding
        uri_of = self.server.uri_for_path
        converted = [to_lsp(x, line_text, encoding, uri_of) for x in diags]
        self._published[uri] = (version, diags, converted, 1)
        self.server.text_document_publish_diagnostics(
            types.PublishDiagnosticsParams(uri=uri, diagnostics=converted, version=version)
        )

    def provisional(self, analysis: WorkspaceAnalysis, doc: OpenDocument,
                    params: types.DidChangeTextDocumentParams) -> None:  # fmt: skip
        """An edit in a huge document whose first analysis has not ended: what the first screen
        and the lines edited so far earn by themselves, for the new version at once (the whole
        analysis publishes the rest)."""
        touched = self._touched.setdefault(doc.uri, set())
        for change in params.content_changes:
            if isinstance(change, types.TextDocumentContentChangePartial):
                first, last = change.range.start.line, change.range.end.line
                added = change.text.count("\n") - (last - first)
                if added:  # the lines below move
                    moved = {x + added if x > last else x for x in touched if not first < x <= last}
                    touched.clear()
                    touched.update(moved)
                touched.update(range(first, first + change.text.count("\n") + 1))
        lines = [x for x in sorted(touched) if FIRST_SCREEN_LINES <= x < len(doc.lines)][:PROVISIONAL_LINES]
        self.first_screen(analysis, doc.uri, doc.path, doc.lines, doc.version, lines)

    def closed(self, uri: str) -> None:
        """``uri`` was closed: its findings are cleared in the editor, and all kept of it goes."""
        self._touched.pop(uri, None)
        self._first_screens.pop(uri, None)
        self._published.pop(uri, None)
        self._values.pop(uri, None)
        self._timing.pop(uri, None)
        self.analysed_once.discard(uri)
        self.first_shown.discard(uri)
        self.server.text_document_publish_diagnostics(types.PublishDiagnosticsParams(uri=uri, diagnostics=[]))

    def timing(self, doc: OpenDocument) -> FileTiming | None:
        """The cycle time's facts of ``doc`` from the newest analysis, if it analysed this version."""
        got = self._timing.get(doc.uri)
        return got[1] if got is not None and got[0] == doc.version else None

    def values(self, doc: OpenDocument) -> LineValues:
        """The values the newest run left on the lines of ``doc``, if it analysed this version."""
        got = self._values.get(doc.uri)
        return got[1] if got is not None and got[0] == doc.version else {}
