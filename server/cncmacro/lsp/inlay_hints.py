"""Inlay hints: after each G65/G66 argument, the local it fills (``X10`` shows ``#24``), by the
argument specifications of ``machine.calls``; and, with the setting ``cncMacro.inlayHints.values``,
at the end of an assignment the value it left the last time the analysis run passed the line
(``#10=360/#1`` shows ``= 60``), from the newest analysis of the document's current version.
Only the lines of the requested range are read."""

from __future__ import annotations

from typing import TYPE_CHECKING

from lsprotocol import types

from ..analysis.indexes.call_sites import call_site
from ..machine.calls import argument_targets
from ..planner.numbers import format_plain
from .positions import Encoding
from .texts import t

if TYPE_CHECKING:
    from .server import CncMacroServer


def register(server: CncMacroServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_INLAY_HINT)
    def inlay_hint(ls: CncMacroServer, params: types.InlayHintParams) -> list[types.InlayHint] | None:
        doc = ls.documents.get(params.text_document.uri)
        if doc is None:  # not open: the empty answer (documents.py)
            return None
        encoding = ls.documents.encoding
        out: list[types.InlayHint] = []
        r = params.range
        last = min(r.end.line, len(doc.lines) - 1)
        if ls.settings.inlay_values:
            values = ls.diagnostics.values(doc)
            for line in range(r.start.line, last + 1):
                written = values.get(line)
                if written:
                    out.append(_value_hint(doc.line(line), line, written, ls.locale, encoding))
        for line in range(r.start.line, last + 1):
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
                        position=types.Position(line, encoding.to_client(text, w.end)),
                        label=f"#{n}",
                        kind=types.InlayHintKind.Parameter,
                        padding_left=True,
                    )
                )
        return out


def _value_hint(text: str, line: int, written: list[tuple[int, float | None]], locale: str,
                encoding: Encoding) -> types.InlayHint:  # fmt: skip
    """``= 60`` at the end of the line's code (before a comment)."""
    end = len(text.split("(", 1)[0].split(";", 1)[0].rstrip())
    shown = ", ".join(t("vacant", locale) if v is None else t("unknown", locale) if v != v else format_plain(v)
                      for _, v in written)  # fmt: skip
    return types.InlayHint(
        position=types.Position(line, encoding.to_client(text, end)),
        label=f"= {shown}",
        padding_left=True,
        tooltip=", ".join(f"#{n}" for n, _ in written),
    )
