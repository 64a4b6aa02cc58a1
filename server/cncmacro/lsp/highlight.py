"""Document highlight: ``ide/highlight.py``'s uses of the name under the cursor as the protocol's
``DocumentHighlight`` (written ones as Write, the others as Read). In a huge file whose site
index is still being made in steps (``site_steps.py``) nothing is marked meanwhile, rather than
the editor waiting seconds at each move of the cursor."""

from __future__ import annotations

from typing import TYPE_CHECKING

from lsprotocol import types

from ..ide.highlight import highlights
from .cursor import cursor_at
from .navigation import machine_calls
from .positions import client_span
from .site_steps import index_soon

if TYPE_CHECKING:
    from .server import CncMacroServer


def register(server: CncMacroServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_DOCUMENT_HIGHLIGHT)
    def document_highlight(
        ls: CncMacroServer, params: types.DocumentHighlightParams
    ) -> list[types.DocumentHighlight] | None:
        cur = cursor_at(ls, params.text_document.uri, params.position)
        if cur is None:
            return None
        if not cur.doc.sites.ready:  # a huge file not indexed yet: nothing marked until it is
            index_soon(cur.doc.sites)
            return None
        found = highlights(cur.doc, cur.line, cur.column, machine_calls(ls, cur.doc.path))
        if found is None:
            return None
        return [
            types.DocumentHighlight(
                client_span(cur.encoding, cur.doc.line, h.span),
                types.DocumentHighlightKind.Write if h.write else types.DocumentHighlightKind.Read,
            )
            for h in found
        ]
