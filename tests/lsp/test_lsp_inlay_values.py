"""Inlay hints of values: with ``cncMacro.inlayHints.values`` on, an assignment shows the value it
left the last time the analysis run passed it; off by default; in both dialects and locales."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, GSK, diagnostics_for, edit, open_file, session_fixture

pytestmark = pytest.mark.asyncio(loop_scope="session")

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


async def test_a_value_the_machine_keeps_shows_as_unknown(
    fanuc_values: LanguageClient, gsk_values_zh: LanguageClient
) -> None:
    # #706 is a common kept on the machine, #1 a local never set (docs/semantics.md §2)
    text = "O0100\n#10=#706*2\n#11=#1\nM30\n"
    uri = open_file(fanuc_values, FANUC / "values_unknown.nc", text)
    await diagnostics_for(fanuc_values, uri, 1)
    assert await value_hints(fanuc_values, uri, 4) == [(1, 10, "= <unknown>"), (2, 6, "= <vacant>")]
    uri = open_file(gsk_values_zh, GSK / "values_unknown.CNC", text.replace("O0100", "O0004"))
    await diagnostics_for(gsk_values_zh, uri, 1)
    assert await value_hints(gsk_values_zh, uri, 4) == [(1, 10, "= <未知>"), (2, 6, "= <空>")]


async def test_values_are_off_by_default(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "values_off.nc", "O0100\n#1=6\n#10=360/#1\nM30\n")
    await diagnostics_for(fanuc_en, uri, 1)
    assert await value_hints(fanuc_en, uri, 4) == []


async def test_gsk_values_in_chinese_show_vacant_as_kong(gsk_values_zh: LanguageClient) -> None:
    text = "O0002\n#1=8\n#10=360/#1 (分度)\n#3=#4\nM30\n"
    uri = open_file(gsk_values_zh, GSK / "values.CNC", text)
    await diagnostics_for(gsk_values_zh, uri, 1)
    assert await value_hints(gsk_values_zh, uri, 5) == [(1, 4, "= 8"), (2, 10, "= 45"), (3, 5, "= <空>")]


async def test_an_if_then_assignment_shows_its_value_only_when_it_ran(fanuc_values: LanguageClient) -> None:
    text = "O0100\n#1=2\nIF[#1 GT 1]THEN #5=#1*10\nIF[#1 GT 9]THEN #6=1\nM30\n"
    uri = open_file(fanuc_values, FANUC / "if_then.nc", text)
    await diagnostics_for(fanuc_values, uri, 1)
    hints = await value_hints(fanuc_values, uri, 5)
    assert (2, 24, "= 20") in hints  # docs/semantics.md §4: the THEN ran
    assert not any(line == 3 for line, _, _ in hints)  # the condition was false: nothing assigned


async def test_a_gsk_g65_h_code_shows_the_value_it_left(gsk_values_zh: LanguageClient) -> None:
    text = "O0003\n#1=8\nG65 H02 P#101 Q#1 R5\nG65 H04 P#102 Q#101 R3 (乘)\nG65 H81 P9 Q1 R1\nN9 M30\n"
    uri = open_file(gsk_values_zh, GSK / "hcodes.CNC", text)
    await diagnostics_for(gsk_values_zh, uri, 1)
    hints = await value_hints(gsk_values_zh, uri, 6)
    assert (2, 20, "= 13") in hints  # docs/semantics.md §7: H02 is addition
    assert (3, 22, "= 39") in hints  # H04 is multiplication
    assert not any(line == 4 for line, _, _ in hints)  # H81 jumps: P is a label, not a variable
