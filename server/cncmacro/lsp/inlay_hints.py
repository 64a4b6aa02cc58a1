"""Inlay hints: after each G65/G66 argument, the local it fills (``X10`` shows ``#24``), by the
argument specifications of ``machine.calls``. Only the lines of the requested range are read."""

from __future__ import annotations

from typing import TYPE_CHECKING

from lsprotocol import types

from ..machine.calls import argument_targets
from .call_sites import call_site
from .positions import to_client

if TYPE_CHECKING:
    from .server import CncMacroServer


def register(server: CncMacroServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_INLAY_HINT)
    def inlay_hint(ls: CncMacroServer, params: types.InlayHintParams) -> list[types.InlayHint]:
        doc = ls.documents.get(params.text_document.uri)
        utf16 = ls.documents.utf16
        out: list[types.InlayHint] = []
        r = params.range
        for line in range(r.start.line, min(r.end.line, len(doc.lines) - 1) + 1):
            block = doc.block(line)
            if block is None or (block.plain is not None and "65" not in block.plain and "66" not in block.plain):
                continue
            site = call_site(block, doc.dialect)
            if site is None or not site.arguments:
                continue
            text = doc.line(line)
            for w, n in zip(site.arguments, argument_targets([w.letter for w in site.arguments]), strict=True):
                if n is None:
                    continue
                out.append(
                    types.InlayHint(
                        position=types.Position(line, to_client(text, w.end, utf16)),
                        label=f"#{n}",
                        kind=types.InlayHintKind.Parameter,
                        padding_left=True,
                    )
                )
        return out
