"""Document and range formatting (``textDocument/formatting``, ``rangeFormatting``): the
formatter of ``syntax/formatting.py`` over the document's lines, its settings asked of the editor
for the document (``workspace/configuration``, section ``cncMacro.format``: ``spacing``
``spaced`` | ``compact``, ``alignComments``), defaults where the editor gives none. One text edit
per changed line.

The formatter runs off the thread that answers requests, so a hover sent meanwhile is answered
at once however long the document; a ``$/cancelRequest`` stops it within ``STOP_EVERY`` lines,
and so does an edit of the document (its answer would be for a text that is gone: none is given).
"""

from __future__ import annotations

import asyncio
import logging
import threading
from typing import TYPE_CHECKING, Any

from lsprotocol import types

from ..syntax.formatting import SPACED, SPACINGS, FormatOptions, FormattingStopped, format_lines
from .cursor import doc_range
from .documents import OpenDocument

if TYPE_CHECKING:
    from .server import CncMacroServer

SECTION = "cncMacro.format"
log = logging.getLogger(__name__)


async def format_options(ls: CncMacroServer, uri: str) -> FormatOptions:
    """The editor's ``cncMacro.format`` settings for the document at ``uri``."""
    caps = ls.client_capabilities.workspace
    if caps is None or not caps.configuration:
        return FormatOptions()
    try:
        result = await ls.workspace_configuration_async(
            types.ConfigurationParams(items=[types.ConfigurationItem(scope_uri=uri, section=SECTION)])
        )
    except Exception as e:  # a client that cannot answer gets the defaults
        log.info("workspace/configuration for %s failed: %s", SECTION, e)
        return FormatOptions()
    data: Any = result[0] if result else None
    if not isinstance(data, dict):
        return FormatOptions()
    spacing = data.get("spacing")
    return FormatOptions(spacing if spacing in SPACINGS else SPACED, data.get("alignComments") is True)


async def edits(
    ls: CncMacroServer, doc: OpenDocument, first: int, last: int, options: FormatOptions
) -> list[types.TextEdit] | None:
    """The edits that format lines ``first`` to ``last`` of ``doc``, worked out on another thread;
    None when the request was cancelled or the document changed meanwhile."""
    encoding = ls.documents.encoding
    lines = list(doc.lines)  # the text as it is now: an edit meanwhile changes the document's own list
    version = doc.version
    cancelled = threading.Event()

    def stopped() -> bool:
        return cancelled.is_set() or doc.version != version or ls.documents.by_uri.get(doc.uri) is not doc

    read_end = doc.parsed.program.read_end
    work = asyncio.get_running_loop().run_in_executor(
        None, lambda: format_lines(lines, first, last, options, read_end, stopped)
    )
    try:
        changed = await work
    except FormattingStopped:
        return None
    except asyncio.CancelledError:  # $/cancelRequest: the thread stops at its next look
        cancelled.set()
        raise
    if stopped():
        return None
    return [types.TextEdit(doc_range(doc, i, 0, len(lines[i]), encoding), text) for i, text in sorted(changed.items())]


def register(server: CncMacroServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_FORMATTING)
    async def formatting(ls: CncMacroServer, params: types.DocumentFormattingParams) -> list[types.TextEdit] | None:
        doc = ls.documents.by_uri.get(params.text_document.uri)
        if doc is None:
            return None
        options = await format_options(ls, doc.uri)
        return await edits(ls, doc, 0, len(doc.lines) - 1, options)

    @server.feature(types.TEXT_DOCUMENT_RANGE_FORMATTING)
    async def range_formatting(
        ls: CncMacroServer, params: types.DocumentRangeFormattingParams
    ) -> list[types.TextEdit] | None:
        doc = ls.documents.by_uri.get(params.text_document.uri)
        if doc is None:
            return None
        options = await format_options(ls, doc.uri)
        r = params.range
        last = r.end.line - 1 if r.end.line > r.start.line and r.end.character == 0 else r.end.line
        return await edits(ls, doc, r.start.line, last, options)
