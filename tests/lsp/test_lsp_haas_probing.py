"""Haas's probing macros on the control through a real client: hover on the P of ``G65 P9811``
says what the macro does, which arguments it reads (those the call gives marked) and what it
writes, in English and in Chinese, and that it lives on the control; signature help on the call
lists its documented letters. Read as ``fanuc-0i`` the same text knows no such program."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, HERE, close_file, described, hover_text, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")

HAAS = HERE / "workspace_haas"

TEXT = "%\nO01002 (PROBE TOP)\nG65 P9832\nG65 P9811 Z-10. S1.\nG65 P9833\nM30\n%\n"
P9811, ON_Z = (3, 5), (3, 12)  # the P of the call, and the Z argument


async def signature_at(client: LanguageClient, uri: str, at: tuple[int, int]) -> types.SignatureHelp | None:
    return await client.text_document_signature_help_async(
        types.SignatureHelpParams(types.TextDocumentIdentifier(uri), types.Position(*at))
    )


async def test_hover_on_g65_p9811_describes_the_single_surface_cycle_in_english(
    haas_en: LanguageClient, fanuc_en: LanguageClient
) -> None:
    uri = open_file(haas_en, HAAS / "probing.nc", TEXT)
    said = described(await hover_text(haas_en, uri, *P9811))
    close_file(haas_en, uri)
    assert said.startswith("**O9811** — Single surface measurement (Renishaw Inspection Plus)")
    assert "Touches one surface along X, Y or Z" in said
    assert "- **Z** — expected Z of the surface (measure along Z) *(given in this call)*" in said
    assert "- **S** — work offset to set from the result: 1–6 for G54–G59" in said and "*(given in this call)*" in said
    assert "- **X** — expected X of the surface (measure along X)\n" in said  # not given: no mark
    assert "Results it writes:" in said and "- **#185** — X position measured" in said
    assert "- **#198** — out-of-tolerance flag" in said
    assert said.endswith("the run returns from it at once. A file with this number in the workspace would be run in "
                         "its place, to set what the caller reads.")  # fmt: skip
    assert "Program: kept on the control (Haas NGC mill keeps O9000–O9999 there" in said
    uri = open_file(fanuc_en, FANUC / "probing.nc", TEXT)  # FANUC 0i keeps its 9000 series, undocumented here
    said = described(await hover_text(fanuc_en, uri, *P9811))
    help_ = await signature_at(fanuc_en, uri, ON_Z)
    close_file(fanuc_en, uri)
    assert said.startswith("**O9811** — Program: kept on the control (FANUC 0i Custom Macro B keeps O9000–O9999")
    assert help_ is None


async def test_hover_on_g65_p9811_speaks_chinese_in_a_chinese_session(haas_zh: LanguageClient) -> None:
    uri = open_file(haas_zh, HAAS / "probing.nc", TEXT)
    said = await hover_text(haas_zh, uri, *P9811)
    close_file(haas_zh, uri)
    assert said.startswith("**O9811** — 单面测量（雷尼绍 Inspection Plus）")
    assert "- **Z** — 表面的预期Z位置（沿Z测量） *(本次调用已给出)*" in said
    assert "自变量:" in said and "写入的结果变量:" in said and "- **#188** — 测得的尺寸（宽度或直径）" in said
    assert "程序: 存放在数控系统内" in said and "Touches" not in said


async def test_signature_help_on_the_call_lists_the_documented_letters(
    haas_en: LanguageClient, haas_zh: LanguageClient
) -> None:
    uri = open_file(haas_en, HAAS / "probing.nc", TEXT)
    help_ = await signature_at(haas_en, uri, ON_Z)
    close_file(haas_en, uri)
    assert help_ is not None
    sig = help_.signatures[0]
    assert sig.label == "O9811(X, Y, Z, Q, S, T, F, V, H, M, W)"
    assert help_.active_parameter == 2  # Z, the argument under the cursor
    assert (
        sig.parameters is not None and sig.parameters[2].documentation == "expected Z of the surface (measure along Z)"
    )
    assert str(sig.documentation).startswith("Single surface measurement (Renishaw Inspection Plus): Touches one")
    uri = open_file(haas_zh, HAAS / "probing.nc", TEXT)
    help_ = await signature_at(haas_zh, uri, ON_Z)
    close_file(haas_zh, uri)
    assert help_ is not None and help_.signatures[0].parameters is not None
    assert help_.signatures[0].parameters[2].documentation == "表面的预期Z位置（沿Z测量）"
