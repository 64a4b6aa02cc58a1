"""Formatting, end to end: document and range formatting upper-case the words and put one space
between them, or none and with comments aligned when the editor's ``cncMacro.format`` settings
say so; comments keep their case."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, close_file, diagnostics_for, open_file, session_fixture

pytestmark = pytest.mark.asyncio(loop_scope="session")

# a server of its own: the client takes the answer to the formatting it cancels below for a fatal
# error and stops, which the modules sharing a server would inherit
fanuc_en = session_fixture(FANUC, "en")

TEXT = "o0001 (Lower title)\nn10 g01x10.y5. (cut)\nif[#1gt2]goto10\nm30\n"
OPTIONS = types.FormattingOptions(tab_size=4, insert_spaces=True)


def _applied(text: str, edits: list[types.TextEdit]) -> str:
    rows = text.split("\n")
    for e in sorted(edits, key=lambda e: -e.range.start.line):
        assert e.range.start.line == e.range.end.line and e.range.start.character == 0
        rows[e.range.start.line] = e.new_text + rows[e.range.start.line][e.range.end.character :]
    return "\n".join(rows)


async def test_document_and_range_formatting(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "format.nc", TEXT)
    whole = await fanuc_en.text_document_formatting_async(
        types.DocumentFormattingParams(types.TextDocumentIdentifier(uri), OPTIONS)
    )
    ranged = await fanuc_en.text_document_range_formatting_async(
        types.DocumentRangeFormattingParams(
            types.TextDocumentIdentifier(uri), types.Range(types.Position(2, 0), types.Position(3, 0)), OPTIONS
        )
    )
    fanuc_en.set_configuration({"spacing": "compact", "alignComments": True}, section="cncMacro.format")
    try:
        compact = await fanuc_en.text_document_formatting_async(
            types.DocumentFormattingParams(types.TextDocumentIdentifier(uri), OPTIONS)
        )
    finally:
        fanuc_en.set_configuration({}, section="cncMacro.format")
    close_file(fanuc_en, uri)
    assert whole is not None and ranged is not None and compact is not None
    assert _applied(TEXT, whole) == "O0001 (Lower title)\nN10 G01 X10. Y5. (cut)\nIF [#1 GT 2] GOTO 10\nM30\n"
    assert _applied(TEXT, ranged) == "o0001 (Lower title)\nn10 g01x10.y5. (cut)\nIF [#1 GT 2] GOTO 10\nm30\n"
    assert _applied(TEXT, compact) == "O0001         (Lower title)\nN10G01X10.Y5. (cut)\nIF[#1GT2]GOTO10\nM30\n"


async def test_formatting_a_huge_document_blocks_no_hover_and_stops_when_cancelled(fanuc_en: LanguageClient) -> None:
    # 20k macro lines take the formatter about 13 s (each is parsed by the grammar, then again to
    # check it): on the thread that answers requests a hover waited for it all, and $/cancelRequest
    # did not stop it
    import asyncio
    import time

    text = "o0001\n" + "".join(f"#{100 + k % 50}=[#{k % 30 + 1}*SIN[{k}]+{k}.5]/2\n" for k in range(20_000)) + "m30\n"
    uri = open_file(fanuc_en, FANUC / "huge_format.nc", text)
    try:
        await diagnostics_for(fanuc_en, uri, 1)  # its analysis is over: the hovers below wait for nothing else
        await fanuc_en.text_document_hover_async(
            types.HoverParams(types.TextDocumentIdentifier(uri), types.Position(1, 1))
        )
        formatting = asyncio.ensure_future(fanuc_en.text_document_formatting_async(
            types.DocumentFormattingParams(types.TextDocumentIdentifier(uri), OPTIONS)))  # fmt: skip
        await asyncio.sleep(0.3)  # it is under way
        asked = time.monotonic()
        await fanuc_en.text_document_hover_async(
            types.HoverParams(types.TextDocumentIdentifier(uri), types.Position(1, 1))
        )
        assert time.monotonic() - asked < 1.0, "a hover waited behind the formatting"
        assert not formatting.done()
        formatting.cancel()  # the client sends $/cancelRequest
        ended = time.monotonic()
        with pytest.raises(asyncio.CancelledError):
            await formatting
        await fanuc_en.text_document_hover_async(  # the server is free again at once
            types.HoverParams(types.TextDocumentIdentifier(uri), types.Position(1, 1))
        )
        assert time.monotonic() - ended < 1.0
    finally:
        close_file(fanuc_en, uri)
