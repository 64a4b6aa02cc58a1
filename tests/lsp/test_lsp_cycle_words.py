"""The letters of cycle blocks through a real client, on both lathe profiles and in both languages:
hover says what a letter means in the block it is in (G71's U is the depth of cut Δd in its first
block and the finishing allowance Δu in its second), signature help lists the block's letters with
the one under the cursor active, completion offers the letters of the right block; the units
where FANUC 0i-TF and GSK980TDi differ; on a mill G73/G74/G76 are drilling cycles."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, GSK, close_file, described, hover_text, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")

FANUC_LATHE = "(cncmacro: dialect=fanuc-0i-lathe)\n"
ROUGHING = (
    "O0001\n"  # line 1 (after the dialect line, when there is one)
    "G00 X62. Z2.\n"  # 2
    "G71 U2. R1.\n"  # 3: the first block; U at column 4, R at 8
    "G71 P10 Q20 U0.5 W0.1 F0.25\n"  # 4: the second block; P at 4, U at 12, W at 17, F at 22
    "N10 G00 X30.\n"
    "G01 Z-20.\n"
    "N20 X60.\n"
    "G70 P10 Q20\n"  # 8
    "M30\n"
)
THREADING = (
    "O0002\n"
    "G76 P021060 Q50 R0.05\n"  # 2: the first block; P at 4, Q at 12, R at 16
    "G76 X27.4 Z-30. P1300 Q400 F2.\n"  # 3: the second block; P at 16, Q at 22, F at 27
    "G74 R0.5\n"  # 4: R at 4
    "G74 X20. Z-20. P3000 Q5000 R0.2 F0.1\n"  # 5: P at 15, R at 27
    "G90 X40. Z-30. R-2. F0.2\n"  # 6: R at 15
    "G92 X29.2 Z-20. F1.5\n"  # 7: F at 16
    "G50 S2000\n"  # 8: S at 4
    "G96 S180\n"  # 9: S at 4
    "M30\n"
)


async def hover_at(client: LanguageClient, uri: str, line: int, column: int) -> str:
    return await hover_text(client, uri, line, column)


async def signature_at(client: LanguageClient, uri: str, line: int, column: int) -> types.SignatureHelp | None:
    return await client.text_document_signature_help_async(
        types.SignatureHelpParams(types.TextDocumentIdentifier(uri), types.Position(line, column))
    )


async def completion_at(client: LanguageClient, uri: str, line: int, column: int) -> list[types.CompletionItem]:
    result = await client.text_document_completion_async(
        types.CompletionParams(types.TextDocumentIdentifier(uri), types.Position(line, column))
    )
    assert isinstance(result, types.CompletionList)
    return list(result.items)


async def test_g71_u_is_the_depth_of_cut_in_the_first_block_and_the_allowance_in_the_second(
    fanuc_en: LanguageClient, gsk_en: LanguageClient
) -> None:
    uri = open_file(fanuc_en, FANUC / "rough.nc", FANUC_LATHE + ROUGHING)
    first = await hover_at(fanuc_en, uri, 3, 4)
    second = await hover_at(fanuc_en, uri, 4, 12)
    retract = await hover_at(fanuc_en, uri, 3, 8)
    close_file(fanuc_en, uri)
    assert first.startswith("**G71** first block — **U(Δd)**: depth of each cut (a radius, no sign)")
    assert "`G71 U(Δd) R(e)` (first block)" in first and "*FANUC 0i-TF lathe*" in first
    assert second.startswith("**G71** second block — **U(Δu)**: finishing allowance in X (a diameter, signed)")
    assert "`G71 P(ns) Q(nf) U(Δu) W(Δw) F S T` (second block)" in second
    assert "**R(e)**: retract after each cut (at 45°)" in retract
    uri = open_file(gsk_en, GSK / "rough.CNC", ROUGHING)  # the workspace's machine file: gsk980tdi
    first = await hover_at(gsk_en, uri, 2, 4)
    second = await hover_at(gsk_en, uri, 3, 12)
    close_file(gsk_en, uri)
    assert first.startswith("**G71** first block — **U(Δd)**: depth of each cut (a radius")
    assert "`G71 U(Δd) R(e) F S T` (first block)" in first and "*GSK980TDi*" in first  # F S T in either block
    assert "`G71 P(ns) Q(nf) U(Δu) W(Δw) F S T K J` (second block)" in second and "finishing allowance" in second


async def test_cycle_words_speak_chinese_in_a_chinese_session(fanuc_zh: LanguageClient, gsk_zh: LanguageClient) -> None:
    uri = open_file(fanuc_zh, FANUC / "rough_zh.nc", FANUC_LATHE + ROUGHING)
    first = await hover_at(fanuc_zh, uri, 3, 4)
    second = await hover_at(fanuc_zh, uri, 4, 12)
    close_file(fanuc_zh, uri)
    assert first.startswith("**G71** 第一程序段 — **U(Δd)**: 每次切深（半径值，无符号）")
    assert second.startswith("**G71** 第二程序段 — **U(Δu)**: X方向精加工余量（直径值，带符号）")
    assert "depth" not in first + second
    uri = open_file(gsk_zh, GSK / "thread_zh.CNC", THREADING)
    k = await hover_at(gsk_zh, uri, 2, 16)
    close_file(gsk_zh, uri)
    assert k.startswith("**G76** 第二程序段 — **P(k)**: 螺纹牙高（半径值），单位为最小输入增量，")
    assert "或由状态参数№182.7选择为mm" in k


async def test_g76_k_and_delta_d_are_least_increments_on_fanuc_and_a_parameter_chooses_on_gsk(
    fanuc_en: LanguageClient, gsk_en: LanguageClient
) -> None:
    uri = open_file(fanuc_en, FANUC / "thread.nc", FANUC_LATHE + THREADING)
    m_r_a = await hover_at(fanuc_en, uri, 2, 4)
    dmin = await hover_at(fanuc_en, uri, 2, 12)
    k = await hover_at(fanuc_en, uri, 3, 16)
    depth = await hover_at(fanuc_en, uri, 3, 22)
    lead = await hover_at(fanuc_en, uri, 3, 27)
    close_file(fanuc_en, uri)
    assert m_r_a.startswith("**G76** first block — **P(m r a)**: six digits: finishing passes m")
    assert "**Q(Δdmin)**: minimum depth of cut (a radius), in least input increments, no decimal point" in dmin
    assert "**P(k)**: height of the thread (a radius), in least input increments, no decimal point (µm" in k
    assert "**Q(Δd)**: depth of the first cut (a radius), in least input increments, no decimal point" in depth
    assert "**F(L)**: lead of the thread" in lead
    uri = open_file(gsk_en, GSK / "thread.CNC", THREADING)
    k = await hover_at(gsk_en, uri, 2, 16)
    close_file(gsk_en, uri)
    assert "**P(k)**: height of the thread (a radius), in least input increments, or in mm as state parameter " \
           "182.7 chooses" in k  # fmt: skip


async def test_g74_r_is_the_return_in_its_first_block_and_the_relief_in_its_second(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "groove.nc", FANUC_LATHE + THREADING)
    e = await hover_at(fanuc_en, uri, 4, 4)
    step = await hover_at(fanuc_en, uri, 5, 15)
    relief = await hover_at(fanuc_en, uri, 5, 27)
    close_file(fanuc_en, uri)
    assert e.startswith("**G74** first block — **R(e)**: return after each peck along Z")
    assert step.startswith("**G74** second block — **P(Δi)**: X step between the passes")
    assert relief.startswith("**G74** second block — **R(Δd)**: relief at the bottom of each pass")


async def test_single_cycles_g50_and_g96_say_what_r_f_and_s_are(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "single.nc", FANUC_LATHE + THREADING)
    taper = await hover_at(fanuc_en, uri, 6, 15)
    lead = await hover_at(fanuc_en, uri, 7, 16)
    clamp = await hover_at(fanuc_en, uri, 8, 4)
    surface = await hover_at(fanuc_en, uri, 9, 4)
    close_file(fanuc_en, uri)
    assert taper.startswith("**G90** — **R**: taper: X at the start of the cut minus at its end (a radius, signed)")
    assert "`G90 X Z U W R F`" in taper and "block)" not in taper  # one block: no first or second
    assert lead.startswith("**G92** — **F(L)**: lead of the thread")
    assert clamp.startswith("**G50** — **S**: maximum spindle speed (rev/min)")
    assert surface.startswith("**G96** — **S**: surface speed (m/min")


async def test_hover_on_the_cycle_code_names_the_block_it_writes(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "code.nc", FANUC_LATHE + ROUGHING)
    first = described(await hover_at(fanuc_en, uri, 3, 1))
    second = described(await hover_at(fanuc_en, uri, 4, 1))
    close_file(fanuc_en, uri)
    assert first.startswith("**G71** — Stock removal in turning")
    assert first.endswith("this block: `G71 U(Δd) R(e)` (first block)")
    assert second.endswith("this block: `G71 P(ns) Q(nf) U(Δu) W(Δw) F S T` (second block)")


async def test_on_a_mill_g73_g74_g76_are_drilling_cycles(fanuc_en: LanguageClient) -> None:
    text = "O0003\nG73 X10. Y5. Z-20. R2. Q3. F100.\nG74 X0 Y0 Z-15. R3. P300 F150.\nG76 X5. Z-10. R2. Q0.5 F80.\nM30\n"
    uri = open_file(fanuc_en, FANUC / "drill.nc", text)  # no dialect line: fanuc-0i, a mill
    peck = await hover_at(fanuc_en, uri, 1, 23)
    dwell = await hover_at(fanuc_en, uri, 2, 20)
    shift = await hover_at(fanuc_en, uri, 3, 18)
    code = await hover_at(fanuc_en, uri, 1, 1)
    close_file(fanuc_en, uri)
    assert peck.startswith("**G73** — **Q**: depth of each peck") and "*FANUC 0i Custom Macro B*" in peck
    # a FANUC tap dwells P at the bottom and again at R ("P_ : Dwell time at the bottom of the hole and
    # at point R when a return is made", docs/semantics.md §9)
    assert dwell.startswith("**G74** — **P**: dwell at the bottom of the hole and again at the R point")
    assert shift.startswith("**G76** — **Q**: shift off the wall at the bottom")
    assert "first block" not in peck + dwell + shift and "Δ" not in peck + dwell + shift
    assert "peck drilling" in code.lower()


async def test_signature_help_lists_the_letters_of_the_block_under_the_cursor(
    fanuc_en: LanguageClient, gsk_zh: LanguageClient
) -> None:
    uri = open_file(fanuc_en, FANUC / "sig.nc", FANUC_LATHE + ROUGHING)
    first = await signature_at(fanuc_en, uri, 3, 9)  # on R1.
    second = await signature_at(fanuc_en, uri, 4, 19)  # on W0.1
    none = await signature_at(fanuc_en, uri, 2, 5)  # G00 X62.: no cycle
    close_file(fanuc_en, uri)
    assert first is not None and second is not None and none is None
    assert first.signatures[0].label == "G71 U(Δd) R(e)" and first.active_parameter == 1
    assert first.signatures[0].documentation == "first block"
    sig = second.signatures[0]
    assert sig.label == "G71 P(ns) Q(nf) U(Δu) W(Δw) F S T" and second.active_parameter == 3
    assert sig.parameters is not None and sig.parameters[3].label == (22, 27)  # "W(Δw)"
    assert sig.parameters[3].documentation == "finishing allowance in Z (signed)"
    uri = open_file(gsk_zh, GSK / "sig.CNC", ROUGHING)
    second = await signature_at(gsk_zh, uri, 3, 5)  # on P10
    close_file(gsk_zh, uri)
    assert second is not None and second.active_parameter == 0
    assert second.signatures[0].documentation == "第二程序段"
    params = second.signatures[0].parameters
    assert params is not None and params[0].documentation == "精加工形状第一个程序段的顺序号N"


async def test_a_block_being_typed_after_a_first_block_is_the_second(fanuc_en: LanguageClient) -> None:
    text = FANUC_LATHE + "O0004\nG00 X62. Z2.\nG71 U2. R1.\nG71 \nM30\n"
    uri = open_file(fanuc_en, FANUC / "typing.nc", text)
    items = await completion_at(fanuc_en, uri, 4, 4)
    help_ = await signature_at(fanuc_en, uri, 4, 4)
    fresh = open_file(fanuc_en, FANUC / "fresh.nc", FANUC_LATHE + "O0005\nG71 \nM30\n")
    first_items = await completion_at(fanuc_en, fresh, 2, 4)
    close_file(fanuc_en, uri)
    close_file(fanuc_en, fresh)
    letters = [i.label for i in items if i.kind == types.CompletionItemKind.Field]
    assert letters == ["P", "Q", "U", "W", "F", "S", "T"]
    by_letter = {i.label: i for i in items}
    assert by_letter["U"].detail == "G71 second block: U(Δu)"
    assert by_letter["U"].documentation == "finishing allowance in X (a diameter, signed)"
    assert help_ is not None and help_.signatures[0].label.startswith("G71 P(ns) Q(nf)")
    assert [i.label for i in first_items if i.kind == types.CompletionItemKind.Field] == ["U", "R"]


async def test_completion_leaves_out_the_letters_the_block_has(gsk_en: LanguageClient) -> None:
    text = "O0006\nG71 U2. R1.\nG71 P10 Q20 U\nM30\n"  # the U is being typed: the line does not parse
    uri = open_file(gsk_en, GSK / "typing.CNC", text)
    items = await completion_at(gsk_en, uri, 2, 13)
    help_ = await signature_at(gsk_en, uri, 2, 13)
    close_file(gsk_en, uri)
    letters = [i.label for i in items if i.kind == types.CompletionItemKind.Field]
    assert letters == ["U", "W", "F", "S", "T", "K", "J"]  # P and Q are written
    assert help_ is not None and help_.active_parameter == 2  # U(Δu)


DRILLING = (
    "O0003\n"
    "G00 X60. Z5. C0\n"  # 2
    "G83 Z-18. R-3. Q4000 P300 F120.\n"  # 3: R at 10, Q at 15
    "G80\n"
    "G84 Z-20. F1.5\n"  # 5: F at 10
    "G80\n"
    "M30\n"
)


async def test_a_lathe_drilling_cycles_letters_differ_by_control(
    fanuc_en: LanguageClient, gsk_en: LanguageClient, gsk_zh: LanguageClient
) -> None:
    # FANUC 0i-TF: R is the distance to the R point, Q the peck in increments; GSK980TDi: R is the
    # retract after each peck, and the rigid tap's F is its lead whatever G98/G99 says
    uri = open_file(fanuc_en, FANUC / "drill.nc", FANUC_LATHE + DRILLING)
    r = await hover_at(fanuc_en, uri, 3, 10)
    q = await hover_at(fanuc_en, uri, 3, 15)
    close_file(fanuc_en, uri)
    assert r.startswith("**G83** — **R**: from the initial level to the R point, signed (along X a radius)")
    assert q.startswith("**G83** — **Q**: depth of each peck, in least input increments, no decimal point")
    uri = open_file(gsk_en, GSK / "drill.CNC", DRILLING)
    r = await hover_at(gsk_en, uri, 2, 10)
    lead = await hover_at(gsk_en, uri, 4, 10)
    close_file(gsk_en, uri)
    assert r.startswith("**G83** — **R**: retract after each peck (mm, a radius; 1 when left out), kept")
    # the GSK980TDi writes F(I) (§3.24.6, "G84 X(U)__ C(H)__ Z(W)__ P__ F(I)__ K__M__"): its L is no lead
    assert lead.startswith("**G84** — **F**: lead of the tap (per spindle turn, whatever G98/G99)")
    uri = open_file(gsk_zh, GSK / "drill_zh.CNC", DRILLING)
    lead = await hover_at(gsk_zh, uri, 4, 10)
    close_file(gsk_zh, uri)
    assert lead.startswith("**G84** — **F**: 螺纹导程（主轴每转，与G98/G99无关）")
