"""Inline values while a debug session is paused: ``textDocument/inlineValue`` answers with
``ide/inline_values.py``'s variables of each line of the asked range, as expressions for the
editor to evaluate through the debug adapter."""

from __future__ import annotations

from typing import TYPE_CHECKING

from lsprotocol import types

from ..ide.inline_values import inline_values
from .positions import client_span

if TYPE_CHECKING:
    from .server import CncMacroServer


def register(server: CncMacroServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_INLINE_VALUE)
    def inline_value(ls: CncMacroServer, params: types.InlineValueParams) -> list[types.InlineValue] | None:
        doc = ls.documents.get(params.text_document.uri)
        if doc is None:  # not open: the empty answer (documents.py)
            return None
        encoding = ls.documents.encoding
        found = inline_values(doc, params.range.start.line, params.range.end.line)
        return [
            types.InlineValueEvaluatableExpression(
                range=client_span(encoding, doc.line, v.span), expression=v.expression
            )
            for v in found
        ]
