"""The cycle time in the editor (docs/editor.md): a code lens above each O program and each tool
change, and the elapsed time in the hover of a block, from the analysis run; an edit changes
them with the next analysis."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, GSK, diagnostics_for, edit, hover_text, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")

# fanuc-0i: rapids 24000 mm/min, a tool change 3 s.
#   T1 M06 3 s | G00 X100. 0.25 s | G01 X0 F1000 6 s                  -> T1 9.25 s, 100 mm cut, 100 mm rapid
#   T2 M06 3 s | G01 Z-30. F100 18 s | G02 X0 Y0 I10. F628.3 (a full circle of 62.83 mm) 6 s
#                                                                     -> T2 27 s, 92.83 mm cut
#   the program: 36.25 s, 193 mm cut, 100 mm rapid
PROGRAM = "\n".join(
    ["O1000 (TWO TOOLS)", "T1 M06", "G00 X100.", "G01 X0 F1000", "T2 M06", "G01 Z-30. F100",
     "G02 X0 Y0 I10. F628.3", "#1=#3001", "M30", ""]
)  # fmt: skip


async def lenses(client: LanguageClient, uri: str) -> list[tuple[int, str]]:
    got = await client.text_document_code_lens_async(types.CodeLensParams(types.TextDocumentIdentifier(uri)))
    return [(lens.range.start.line, lens.command.title if lens.command else "") for lens in got or []]


async def test_a_lens_above_the_program_and_each_tool_change(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "cycle_two_tools.nc", PROGRAM)
    await diagnostics_for(fanuc_en, uri, 1)
    assert await lenses(fanuc_en, uri) == [
        (0, "≈ 36 s · 193 mm cut · 100 mm rapid"),
        (1, "T1 ≈ 9.2 s · 100 mm cut · 100 mm rapid"),
        (4, "T2 ≈ 27 s · 93 mm cut · 0 mm rapid"),
    ]


async def test_an_edit_changes_the_lenses_with_the_next_analysis(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "cycle_edited.nc", PROGRAM)
    await diagnostics_for(fanuc_en, uri, 1)
    edit(fanuc_en, uri, 2, 3, 8, 12, "500")  # G01 X0 F500: 12 s instead of 6 s
    await diagnostics_for(fanuc_en, uri, 2)
    assert await lenses(fanuc_en, uri) == [
        (0, "≈ 42 s · 193 mm cut · 100 mm rapid"),
        (1, "T1 ≈ 15 s · 100 mm cut · 100 mm rapid"),
        (4, "T2 ≈ 27 s · 93 mm cut · 0 mm rapid"),
    ]


async def test_the_hover_of_a_block_says_when_it_starts(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "cycle_hover.nc", PROGRAM)
    await diagnostics_for(fanuc_en, uri, 1)
    # G01 Z-30. starts after T1 (9.25 s) and the change to T2 (3 s): 12.25 s
    assert "Cycle time: this block starts at ≈ 12 s (the first time it runs)" in await hover_text(fanuc_en, uri, 5, 0)
    # on a variable the hover keeps what it says of it and adds the time: 36.25 s
    text = await hover_text(fanuc_en, uri, 7, 5)
    assert "#3001" in text and "Cycle time: this block starts at ≈ 36 s" in text


async def test_lenses_and_hover_in_chinese_on_a_lathe(gsk_zh: LanguageClient) -> None:
    # gsk980tdi: T0101 indexes the turret (1 s); G99 F0.2 at S500 is 100 mm/min: Z-50 takes 30 s
    text = "O0007\nT0101\nM03 S500\nG99 G01 Z-50. F0.2\nM30\n"
    uri = open_file(gsk_zh, GSK / "O0007.CNC", text)
    await diagnostics_for(gsk_zh, uri, 1)
    assert await lenses(gsk_zh, uri) == [
        (0, "≈ 31 秒 · 切削 50 mm · 快移 0 mm"),
        (1, "T0101 ≈ 31 秒 · 切削 50 mm · 快移 0 mm"),  # its part begins with its own change
    ]
    assert "加工时间：本程序段约在 1.0 秒时开始（首次执行时）" in await hover_text(gsk_zh, uri, 3, 0)


async def test_a_grooving_cycles_pecks_are_in_the_lens(gsk_en: LanguageClient) -> None:
    # gsk980tdi: rapid Z 8000 mm/min; G99 F0.1 at S500 is 50 mm/min. From Z0, G00 Z2: 2 mm rapid.
    # G74 R0.5 / G74 Z-11 Q3000: feeds Z2 -> -1 (3 mm), then from each retract of 0.5 by 3.5 mm
    # to -4, -7, -10, and the last 1.5 mm to -11: 15 mm cut, 18 s; four retracts of 0.5 and the
    # 13 mm back to Z2 at rapid: 15 mm, 0.1125 s. The program: 18.13 s, 15 mm cut, 17 mm rapid.
    text = "O0008\nG99 G97 S500 M03\nG00 X0 Z2.\nG74 R0.5\nG74 Z-11. Q3000 F0.1\nM30\n"
    uri = open_file(gsk_en, GSK / "O0008.CNC", text)
    await diagnostics_for(gsk_en, uri, 1)
    assert await lenses(gsk_en, uri) == [(0, "≈ 18 s · 15 mm cut · 17 mm rapid")]
