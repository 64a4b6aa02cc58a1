"""Hover on the words that mean something by their block: a lathe's T0101 (tool 01, offset 01;
T0100 cancels the offset, as the planner reads it), a mill's T1, the H of G43 (offset H's
geometry + wear: FANUC memory C #11001 + #10001), the L of M98 (the repeat count), the P of G04
(the dwell in the profile's unit: milliseconds on FANUC; on Haas "G04 P10. is a dwell of 10
seconds") and M29, rigid tapping, where the profile's table has it (FANUC; GSK980TDi §3.24.6)."""

from __future__ import annotations

import pytest
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, GSK, HAAS, close_file, hover_text, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")

LATHE = "O1 (cncmacro: dialect=fanuc-0i-lathe)\nT0101\nT0100\nG04 P500\nM29 S500\nM30\n"
MILL = "O2 (cncmacro: dialect=fanuc-0i)\nT1 M06\nG43 H1 Z50.\nM98 P9020 L2\nM30\n"


async def test_lathe_t_is_tool_and_offset_and_g04_p_is_milliseconds(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "words_lathe.nc", LATHE)
    t0101 = await hover_text(fanuc_en, uri, 1, 1)
    t0100 = await hover_text(fanuc_en, uri, 2, 1)
    p = await hover_text(fanuc_en, uri, 3, 5)
    m29 = await hover_text(fanuc_en, uri, 4, 1)
    close_file(fanuc_en, uri)
    assert t0101.startswith("**T** — Tool 1, offset 1; the turret indexes to the tool")
    assert t0100.startswith("**T** — Tool 1, offset 0; offset 0 cancels the tool offset")
    assert p.startswith("**P** — Dwell time, in milliseconds (P1000 = 1 s)")  # P500: 0.5 s
    assert m29.startswith("**M29** — Rigid tapping")


async def test_mill_t_h_of_g43_and_l_of_m98(fanuc_en: LanguageClient, fanuc_zh: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "words_mill.nc", MILL)
    t1 = await hover_text(fanuc_en, uri, 1, 1)
    h1 = await hover_text(fanuc_en, uri, 2, 5)
    l2 = await hover_text(fanuc_en, uri, 3, 11)
    close_file(fanuc_en, uri)
    assert t1.startswith("**T** — Tool number: the tool the next M06 puts in the spindle")
    assert "#11001 + #10001" in h1  # memory C: length geometry #11000+1, wear #10000+1
    assert l2.startswith("**L** — Repeat count: the subprogram runs L times")
    uri = open_file(fanuc_zh, FANUC / "words_mill_zh.nc", MILL)
    l2 = await hover_text(fanuc_zh, uri, 3, 11)
    close_file(fanuc_zh, uri)
    assert l2.startswith("**L** — 重复次数")


async def test_haas_dwell_p_with_a_point_is_seconds(haas_en: LanguageClient) -> None:
    uri = open_file(haas_en, HAAS / "dwell.nc", "O3 (cncmacro: dialect=haas)\nG04 P10.\nG43 H2 Z1.\nM30\n")
    p = await hover_text(haas_en, uri, 1, 5)
    h2 = await hover_text(haas_en, uri, 2, 5)
    close_file(haas_en, uri)
    assert "in milliseconds" in p and "with a decimal point in seconds (P1. = 1 s)" in p
    assert "#2002 + #2202" in h2  # Haas keeps length geometry at #2001…, wear at #2201…


async def test_gsk_t_and_m29(gsk_zh: LanguageClient) -> None:
    uri = open_file(gsk_zh, GSK / "WORDS.CNC", "O4\nT0202\nM29 S300\nM30\n")
    t = await hover_text(gsk_zh, uri, 1, 1)
    m29 = await hover_text(gsk_zh, uri, 2, 1)
    close_file(gsk_zh, uri)
    assert t.startswith("**T** — 刀具号 2，刀补号 2")
    assert "刚性攻丝" in m29
