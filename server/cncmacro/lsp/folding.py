"""Folding ranges: ``ide/folding.py``'s folds of a document as the protocol's ``FoldingRange``."""

from __future__ import annotations

from typing import TYPE_CHECKING

from lsprotocol import types

from ..ide.folding import folding_ranges

if TYPE_CHECKING:
    from .server import CncMacroServer


def register(server: CncMacroServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_FOLDING_RANGE)
    def folding_range(ls: CncMacroServer, params: types.FoldingRangeParams) -> list[types.FoldingRange] | None:
        doc = ls.documents.get(params.text_document.uri)
        if doc is None:  # not open: the empty answer (documents.py)
            return None
        parsed = doc.parsed
        return [
            types.FoldingRange(
                start_line=f.start_line,
                end_line=f.end_line,
                kind=types.FoldingRangeKind.Comment if f.comment else None,
            )
            for f in folding_ranges(parsed.program, parsed.blocks)
        ]
