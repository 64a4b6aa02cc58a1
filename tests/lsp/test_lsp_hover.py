"""Hover, end to end: system variables, locals, commons, G/M codes, functions, N labels and O
programs, in both dialects and both locales."""

from __future__ import annotations

import pytest
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, GSK, close_file, diagnostics_for, edit, hover_text, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")


async def test_hover_5001_is_the_x_block_end_position_in_english(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "MAIN.nc")
    text = await hover_text(fanuc_en, uri, 12, 4)  # #3=#5001+...
    close_file(fanuc_en, uri)
    assert "**#5001**" in text
    assert "X axis block end position, work coordinates, without tool offset" in text
    assert "readable while the axis moves" in text
    assert "unit: mm" in text and "access: read-only" in text and "axis: X" in text


async def test_hover_4120_is_the_modal_t_code(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "MAIN.nc")
    text = await hover_text(fanuc_en, uri, 12, 10)
    close_file(fanuc_en, uri)
    assert "**#4120**" in text and "T code" in text


async def test_hover_5001_in_chinese(fanuc_zh: LanguageClient) -> None:
    uri = open_file(fanuc_zh, FANUC / "MAIN.nc")
    text = await hover_text(fanuc_zh, uri, 12, 4)
    close_file(fanuc_zh, uri)
    assert "系统变量" in text
    assert "程序段终点位置" in text and "不含刀具补偿" in text
    assert "只读" in text and "轴: X" in text


async def test_hover_local_shows_the_argument_letters(fanuc_en: LanguageClient, fanuc_zh: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "O9100.nc")
    text = await hover_text(fanuc_en, uri, 3, 6)  # X#24
    close_file(fanuc_en, uri)
    assert "**#24** — Local variable" in text
    assert "argument specification I: **X**" in text
    assert "argument specification II: **K7**" in text
    uri = open_file(fanuc_zh, FANUC / "O9100.nc")
    text = await hover_text(fanuc_zh, uri, 3, 12)  # Z#18
    close_file(fanuc_zh, uri)
    assert "局部变量" in text and "自变量指定I: **R**" in text and "自变量指定II: **K5**" in text


async def test_hover_common_lists_where_it_is_written(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "MAIN.nc")
    text = await hover_text(fanuc_en, uri, 4, 5)  # IF[#101 LT #100]
    assert "**#101** — Common variable" in text
    assert "MAIN.nc:4" in text
    text = await hover_text(fanuc_en, uri, 1, 1)  # #100=5
    close_file(fanuc_en, uri)
    assert "MAIN.nc:2" in text and "O9100.nc:6" in text  # written in both files


async def test_hover_g_and_m_codes_come_from_the_dialect(fanuc_en: LanguageClient, gsk_zh: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "MAIN.nc")
    text = await hover_text(fanuc_en, uri, 11, 1)  # M98
    close_file(fanuc_en, uri)
    assert text.startswith("**M98**") and "FANUC" in text
    uri = open_file(gsk_zh, GSK / "CUT.CNC")
    text = await hover_text(gsk_zh, uri, 1, 1)  # G01
    close_file(gsk_zh, uri)
    assert text.startswith("**G01**") and "直线插补" in text and "GSK980TDi" in text


async def test_hover_function_shows_its_signature(fanuc_en: LanguageClient, fanuc_zh: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "MAIN.nc")
    text = await hover_text(fanuc_en, uri, 12, 16)  # SIN[30]
    close_file(fanuc_en, uri)
    assert "SIN[a]" in text and "Sine" in text
    uri = open_file(fanuc_zh, FANUC / "MAIN.nc")
    text = await hover_text(fanuc_zh, uri, 4, 0)  # IF
    close_file(fanuc_zh, uri)
    assert "IF" in text and "条件" in text


async def test_hover_label_lists_the_jumps_to_it(fanuc_en: LanguageClient, gsk_zh: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "MAIN.nc")
    text = await hover_text(fanuc_en, uri, 3, 1)  # N10
    close_file(fanuc_en, uri)
    assert "**N10**" in text and "jumps to it" in text and "line 5 (GOTO)" in text
    uri = open_file(gsk_zh, GSK / "MAIN.CNC")
    text = await hover_text(gsk_zh, uri, 4, 18)  # GOTO20 -> N20
    close_file(gsk_zh, uri)
    assert "**N20**" in text and "跳转到此处" in text and "行 5" in text


async def test_hover_program_shows_title_and_file(fanuc_en: LanguageClient, gsk_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "MAIN.nc")
    text = await hover_text(fanuc_en, uri, 2, 6)  # P9100
    close_file(fanuc_en, uri)
    assert "**O9100** (DRILL CYCLE)" in text and "O9100.nc" in text
    uri = open_file(gsk_en, GSK / "MAIN.CNC")
    text = await hover_text(gsk_en, uri, 2, 6)  # P[CUT]
    assert "CUT" in text and "CUT.CNC" in text
    text = await hover_text(gsk_en, uri, 6, 4)  # #5001 on the lathe
    close_file(gsk_en, uri)
    assert "**#5001**" in text and "System variable" in text and "GSK980TDi" in text


async def test_hover_g65_argument_names_the_local_it_fills(gsk_en: LanguageClient) -> None:
    uri = open_file(gsk_en, GSK / "MAIN.CNC")
    text = await hover_text(gsk_en, uri, 2, 12)  # U1.
    close_file(gsk_en, uri)
    assert "**U** → **#21**" in text


async def test_hover_follows_the_dialect_comment_before_the_workspace(fanuc_en: LanguageClient) -> None:
    text = "(cncmacro: dialect=gsk980tdi)\nO0005\n#1=#5001\nG01 U1.\n"
    uri = open_file(fanuc_en, FANUC / "lathe.nc", text)
    variable = await hover_text(fanuc_en, uri, 2, 4)
    code = await hover_text(fanuc_en, uri, 3, 1)
    close_file(fanuc_en, uri)
    assert "GSK980TDi" in variable and "GSK980TDi" in code


async def test_hover_on_a_gsk_h_code_shows_the_command(gsk_en: LanguageClient, gsk_zh: LanguageClient) -> None:
    text = "O0002\nG65 H02 P#101 Q#102 R5\nG65 H99 P3005\n"
    uri = open_file(gsk_en, GSK / "hcodes.CNC", text)
    got = await hover_text(gsk_en, uri, 1, 5)
    assert "G65 H02 P#i Q#j R#k" in got and "addition" in got
    assert "alarm" in (await hover_text(gsk_en, uri, 2, 5)).lower()
    uri = open_file(gsk_zh, GSK / "hcodes_zh.CNC", text)
    assert "加法" in await hover_text(gsk_zh, uri, 1, 5)


async def test_hover_places_follow_edits_to_writes_and_jumps(fanuc_en: LanguageClient) -> None:
    text = "O0001\n#150=1\nN10 #151=#150\nIF[#151 GT 2] GOTO10\nGOTO10\nM30\n"
    uri = open_file(fanuc_en, FANUC / "moving.nc", text)
    assert "moving.nc:2" in await hover_text(fanuc_en, uri, 2, 10)  # #150 read on N10's line
    assert "line 4 (GOTO)" in await hover_text(fanuc_en, uri, 2, 1)  # N10
    edit(fanuc_en, uri, 2, 1, 0, 0, "G00 X0\nG00 Y0\n")  # two lines above the write of #150
    common = await hover_text(fanuc_en, uri, 4, 10)
    assert "moving.nc:2" not in common and "moving.nc:4" in common
    label = await hover_text(fanuc_en, uri, 4, 1)
    assert "line 6 (GOTO)" in label and "line 7 (GOTO)" in label
    edit(fanuc_en, uri, 3, 3, 3, 4, "2")  # #150=1 -> #152=1
    assert "not written" in (await hover_text(fanuc_en, uri, 4, 10)).lower()
    assert "moving.nc:4" in await hover_text(fanuc_en, uri, 3, 2)
    edit(fanuc_en, uri, 4, 5, 0, 20, "")  # IF[#151 GT 2] GOTO10 -> an empty line
    label = await hover_text(fanuc_en, uri, 4, 1)
    assert "line 6" not in label and "line 7 (GOTO)" in label
    edit(fanuc_en, uri, 5, 4, 0, 3, "")  # the label goes: N10 #151=#150 -> #151=#150
    jump = await hover_text(fanuc_en, uri, 6, 5)  # GOTO10
    close_file(fanuc_en, uri)
    assert "N10: not found" in jump and "line 7 (GOTO)" in jump


async def test_1_hover_on_an_abbreviated_macro_word_shows_the_whole_word(
    fanuc_en: LanguageClient, fanuc_zh: LanguageClient, gsk_en: LanguageClient
) -> None:
    text = "O0001\n#1=0\nWH[#1LT3]DO1\n#1=#1+1\nEN1\n#2=AT[1]/[2]\nM30\n"
    uri = open_file(fanuc_en, FANUC / "short.nc", text)
    text_wh = await hover_text(fanuc_en, uri, 2, 1)
    text_at = await hover_text(fanuc_en, uri, 5, 4)
    close_file(fanuc_en, uri)
    assert text_wh.startswith("**WH** — short for **WHILE**")
    assert "WHILE [" in text_wh  # the statement's own description follows
    assert text_at.startswith("**AT** — short for **ATAN**") and "ATAN[" in text_at
    uri = open_file(fanuc_zh, FANUC / "short.nc", text)
    text_en = await hover_text(fanuc_zh, uri, 4, 0)
    close_file(fanuc_zh, uri)
    assert text_en.startswith("**EN** — **END** 的缩写")
    uri = open_file(gsk_en, GSK / "short.nc", text)
    text_gsk = await hover_text(gsk_en, uri, 2, 0)
    close_file(gsk_en, uri)
    assert "short for **WHILE**" in text_gsk and "does not read abbreviations" in text_gsk


async def test_hover_on_a_30i_name_shows_its_number_and_description(
    fanuc_en: LanguageClient, fanuc_zh: LanguageClient
) -> None:
    text = "(cncmacro: dialect=fanuc-30i)\nO0001\n#1=[#_ABSIO[1]]\n#2=[#_DATE]+[#_ABSIO[#9]]\n[#_NOPE]=1\nM30\n"
    uri = open_file(fanuc_en, FANUC / "names30i.nc", text)
    absio = await hover_text(fanuc_en, uri, 2, 7)  # ABSIO
    date = await hover_text(fanuc_en, uri, 3, 6)
    any_axis = await hover_text(fanuc_en, uri, 3, 17)  # #_ABSIO[#9]: n known when it runs
    unknown = await hover_text(fanuc_en, uri, 4, 3)
    close_file(fanuc_en, uri)
    assert absio.startswith("**#_ABSIO[1]** = **#5001**") and "X axis block end position" in absio
    assert "access: read-only" in absio and "FANUC 30i-B" in absio
    assert "**#_DATE** = **#3011**" in date and "YYYYMMDD" in date
    assert "#5001 … #5004 (n = 1 … 4)" in any_axis and "block end position of axis n" in any_axis
    assert "#_NOPE" in unknown and "(1098)" in unknown
    uri = open_file(fanuc_zh, FANUC / "names30i_zh.nc", text)
    zh = await hover_text(fanuc_zh, uri, 2, 7)
    close_file(fanuc_zh, uri)
    assert "#5001" in zh and "程序段终点位置" in zh and "只读" in zh


async def test_hover_on_a_name_in_a_0i_file_says_the_dialect_has_none(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "names0i.nc", "O0001\n#1=[#_ABSIO[1]]\nM30\n")
    text = await hover_text(fanuc_en, uri, 1, 7)
    close_file(fanuc_en, uri)
    assert "no system variable names" in text and "FANUC 0i" in text


async def test_1_text_and_blocks_corner_words_have_no_diagnostics_and_hover_names_them(
    fanuc_en: LanguageClient, fanuc_zh: LanguageClient
) -> None:
    # no ,C on the last move: before M30 it is FANUC's PS0051 "MISSING MOVE AFTER CHF/CNR" (docs/semantics.md §8)
    text = "O1000\nG90 G17 G00 X0 Y0\nG01 X50. ,R5. F500.\nY50. ,C3.\nG01 X20 Y30\nM30\n"
    uri = open_file(fanuc_en, FANUC / "corners.nc", text)
    got = await diagnostics_for(fanuc_en, uri, 1)
    assert list(got.diagnostics) == []
    radius = await hover_text(fanuc_en, uri, 2, 10)  # the R of ,R5.
    chamfer = await hover_text(fanuc_en, uri, 3, 5)  # the comma of ,C3.
    close_file(fanuc_en, uri)
    assert "**,R** — corner radius" in radius and "sharp corner" in radius
    assert "**,C** — chamfer" in chamfer
    uri = open_file(fanuc_zh, FANUC / "corners_zh.nc", text)
    assert "拐角圆弧" in await hover_text(fanuc_zh, uri, 2, 10)
    close_file(fanuc_zh, uri)
