"""Inlay hints of values: with ``cncMacro.inlayHints.values`` on, an assignment shows the value it
left the last time the analysis run passed it; off by default; in both dialects and locales."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, GSK, diagnostics_for, edit, open_file, session_fixture

pytestmark = pytest.mark.asyncio(loop_scope="module")

fanuc_values = session_fixture(FANUC, "en", {"inlayHints": {"values": True}})
gsk_values_zh = session_fixture(GSK, "zh-CN", {"inlayHints": {"values": True}})


async def value_hints(client: LanguageClient, uri: str, lines: int) -> list[tuple[int, int, str]]:
    hints = await client.text_document_inlay_hint_async(
        types.InlayHintParams(
            types.TextDocumentIdentifier(uri), types.Range(types.Position(0, 0), types.Position(lines, 0))
        )
    )
    return [(h.position.line, h.position.character, str(h.label)) for h in hints or [] if str(h.label).startswith("=")]


async def test_an_assignment_shows_the_value_it_left(fanuc_values: LanguageClient) -> None:
    text = "O0100\n#1=6\n#10=360/#1 (STEP)\n#11=#12\nM30\n"
    uri = open_file(fanuc_values, FANUC / "values.nc", text)
    await diagnostics_for(fanuc_values, uri, 1)
    assert await value_hints(fanuc_values, uri, 5) == [(1, 4, "= 6"), (2, 10, "= 60"), (3, 7, "= <vacant>")]
    edit(fanuc_values, uri, 2, 1, 3, 4, "8")  # #1=8: 360/8
    await diagnostics_for(fanuc_values, uri, 2)
    assert (2, 10, "= 45") in await value_hints(fanuc_values, uri, 5)


async def test_values_are_off_by_default(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "values_off.nc", "O0100\n#1=6\n#10=360/#1\nM30\n")
    await diagnostics_for(fanuc_en, uri, 1)
    assert await value_hints(fanuc_en, uri, 4) == []


async def test_gsk_values_in_chinese_show_vacant_as_kong(gsk_values_zh: LanguageClient) -> None:
    text = "O0002\n#1=8\n#10=360/#1 (分度)\n#3=#4\nM30\n"
    uri = open_file(gsk_values_zh, GSK / "values.CNC", text)
    await diagnostics_for(gsk_values_zh, uri, 1)
    assert await value_hints(gsk_values_zh, uri, 5) == [(1, 4, "= 8"), (2, 10, "= 45"), (3, 5, "= <空>")]
