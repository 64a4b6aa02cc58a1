"""GSK980TDi G31 (manual §3.16.2: "跳转信号变为“1”时绝对坐标位置被存储在用户宏变量中(#995～#999
分别对应 X，Z，Y，4th，5th)"): the G31 hover says where the skip position goes, and #995–#999
say what G31 writes there, instead of calling them plain commons nothing writes."""

from __future__ import annotations

import pytest
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, GSK, close_file, hover_text, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")

PROGRAM = "O3001\nG31 X10 F100\n#1=#995+#996+#997\nM30\n"


async def test_gsk_g31_hover_names_995_to_999(gsk_en: LanguageClient, gsk_zh: LanguageClient) -> None:
    uri = open_file(gsk_en, GSK / "SKIP1.CNC", PROGRAM)
    text = await hover_text(gsk_en, uri, 1, 1)
    close_file(gsk_en, uri)
    assert "#995 (X), #996 (Z), #997 (Y), #998 (C), #999 (B)" in text
    assert "clamped at 200 mm/min" in text
    uri = open_file(gsk_zh, GSK / "SKIP2.CNC", PROGRAM)
    text = await hover_text(gsk_zh, uri, 1, 1)
    close_file(gsk_zh, uri)
    assert "#995 (X)、#996 (Z)、#997 (Y)" in text and "200 mm/min" in text


async def test_gsk_995_and_996_say_g31_writes_x_and_z(gsk_en: LanguageClient, gsk_zh: LanguageClient) -> None:
    uri = open_file(gsk_en, GSK / "SKIP3.CNC", PROGRAM)
    x = await hover_text(gsk_en, uri, 2, 4)  # #995
    z = await hover_text(gsk_en, uri, 2, 9)  # #996: Z, not Y (the manual's order X, Z, Y)
    close_file(gsk_en, uri)
    assert "G31 stores here the absolute X position where the skip signal came on" in x
    assert "absolute Z position" in z
    uri = open_file(gsk_zh, GSK / "SKIP4.CNC", PROGRAM)
    y = await hover_text(gsk_zh, uri, 2, 14)  # #997
    close_file(gsk_zh, uri)
    assert "G31 跳转信号变为“1”时，在此存储 Y 轴的绝对坐标位置" in y


async def test_fanuc_commons_and_g31_say_nothing_of_skip_commons(fanuc_en: LanguageClient) -> None:
    # FANUC keeps the skip position in #5061…, not in commons
    uri = open_file(fanuc_en, FANUC / "skip.nc", "O3002\nG31 X10 F100\n#1=#995\nM30\n")
    g31 = await hover_text(fanuc_en, uri, 1, 1)
    common = await hover_text(fanuc_en, uri, 2, 4)
    close_file(fanuc_en, uri)
    assert "#995" not in g31 and "skip signal" not in common
