"""A Chinese G-code hover names the modal group and the profile in Chinese, as the rest of the
hover is (the names in the data, ``tables.MODAL_GROUP_NAMES`` and ``Dialect.title_zh``)."""

from __future__ import annotations

import pytest
from pytest_lsp import LanguageClient

from cncmacro.dialects import DIALECTS, get_dialect
from cncmacro.dialects.tables import MODAL_GROUP_NAMES

from .lsp_session import FANUC, HAAS, close_file, hover_text, open_file

ASYNC = pytest.mark.asyncio(loop_scope="session")


@ASYNC
async def test_chinese_g_code_hover_names_group_and_profile_in_chinese(
    fanuc_zh: LanguageClient, fanuc_en: LanguageClient, haas_zh: LanguageClient
) -> None:
    program = "O1 (cncmacro: dialect=fanuc-0i-lathe)\nG99 G01 X10. F0.2\nM30\n"
    uri = open_file(fanuc_zh, FANUC / "names_zh.nc", program)
    g01 = await hover_text(fanuc_zh, uri, 1, 5)
    g99 = await hover_text(fanuc_zh, uri, 1, 1)
    close_file(fanuc_zh, uri)
    assert "模态组: 运动（插补） · *FANUC 0i-TF 车床*" in g01
    assert "模态组: 进给方式" in g99 and "motion" not in g01 and "lathe" not in g01
    uri = open_file(fanuc_en, FANUC / "names_en.nc", program)
    g01 = await hover_text(fanuc_en, uri, 1, 5)
    close_file(fanuc_en, uri)
    assert "modal group: motion · *FANUC 0i-TF lathe*" in g01  # English as before
    uri = open_file(haas_zh, HAAS / "names.nc", "O2 (cncmacro: dialect=haas)\nG54 G00 X0\nM30\n")
    g54 = await hover_text(haas_zh, uri, 1, 1)
    close_file(haas_zh, uri)
    assert "模态组: 工件坐标系 · *Haas NGC 铣床*" in g54


def test_every_modal_group_of_every_profile_has_a_chinese_name() -> None:
    for name in DIALECTS:
        dialect = get_dialect(name)
        assert dialect.shown_title("zh-CN") != dialect.title or dialect.title == "GSK980TDi", name
        for doc in dialect.g_codes():
            if doc.group:
                assert doc.group in MODAL_GROUP_NAMES, (name, doc.code, doc.group)
