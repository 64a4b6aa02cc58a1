"""Document and workspace symbols: ``ide/symbols.py``'s outline and workspace programs as the
protocol's ``DocumentSymbol`` and ``WorkspaceSymbol``."""

from __future__ import annotations

from typing import TYPE_CHECKING

from lsprotocol import types

from ..ide.symbols import OutlineKind, OutlineSymbol, document_symbols, workspace_symbols
from .documents import OpenDocument
from .positions import Encoding, client_region, client_span

if TYPE_CHECKING:
    from .server import CncMacroServer

_KINDS = {
    OutlineKind.PROGRAM: types.SymbolKind.Module,
    OutlineKind.LOOP: types.SymbolKind.Namespace,
    OutlineKind.LABEL: types.SymbolKind.Key,
}


def register(server: CncMacroServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_DOCUMENT_SYMBOL)
    def document_symbol(ls: CncMacroServer, params: types.DocumentSymbolParams) -> list[types.DocumentSymbol] | None:
        doc = ls.documents.get(params.text_document.uri)
        if doc is None:  # not open: the empty answer (documents.py)
            return None
        return [_symbol(doc, s, ls.documents.encoding) for s in document_symbols(doc)]

    @server.feature(types.WORKSPACE_SYMBOL)
    def workspace_symbol(ls: CncMacroServer, params: types.WorkspaceSymbolParams) -> list[types.WorkspaceSymbol]:
        return [
            types.WorkspaceSymbol(
                name=p.name,
                kind=types.SymbolKind.Module,
                location=types.Location(
                    ls.uri_for_path(p.path), types.Range(types.Position(p.line, 0), types.Position(p.line, 0))
                ),
                container_name=p.detail,
            )
            for p in workspace_symbols(ls.index.programs(), params.query)
        ]


def _symbol(doc: OpenDocument, s: OutlineSymbol, encoding: Encoding) -> types.DocumentSymbol:
    return types.DocumentSymbol(
        name=s.name,
        detail=s.detail,
        kind=_KINDS[s.kind],
        range=client_region(encoding, doc.line, s.region),
        selection_range=client_span(encoding, doc.line, s.selection),
        children=[_symbol(doc, c, encoding) for c in s.children] if s.kind is not OutlineKind.LABEL else None,
    )
