"""The status bar names the profile a file is read in (``cncmacro/documentDialect``'s ``title``)
in the editor's language: in a Chinese locale the profile's Chinese title, as hover's last line
names it (``Dialect.shown_title``: ``FANUC 0i-TF 车床``); in English the English one. The Select
Dialect picker labels each profile with ``cncmacro/profiles``' ``titleZh`` in a Chinese VS Code."""

from __future__ import annotations

import pytest
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, close_file, diagnostics_for, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")

LATHE = "O0001 (cncmacro: dialect=fanuc-0i-lathe)\nG00 X10. Z2.\nM30\n"
MILL = "O0002\nG00 X10. Y2.\nM30\n"


async def _said(client: LanguageClient, name: str, text: str) -> tuple[str, str, str]:
    uri = open_file(client, FANUC / name, text)
    await diagnostics_for(client, uri, 1)
    answer = await client.protocol.send_request_async("cncmacro/documentDialect", {"uri": uri})
    close_file(client, uri)
    return answer.dialect, answer.title, answer.source


async def test_the_status_bar_names_the_profile_in_chinese_under_a_chinese_locale(fanuc_zh: LanguageClient) -> None:
    assert await _said(fanuc_zh, "lathe.nc", LATHE) == ("fanuc-0i-lathe", "FANUC 0i-TF 车床", "file")
    assert await _said(fanuc_zh, "mill.nc", MILL) == ("fanuc-0i", "FANUC 0i 用户宏程序B", "default")


async def test_the_status_bar_names_the_profile_in_english_under_an_english_locale(fanuc_en: LanguageClient) -> None:
    assert await _said(fanuc_en, "lathe.nc", LATHE) == ("fanuc-0i-lathe", "FANUC 0i-TF lathe", "file")


async def test_the_profile_list_gives_each_title_in_chinese_for_the_picker(fanuc_zh: LanguageClient) -> None:
    # Select Dialect labels each profile with its Chinese title in a Chinese VS Code; a profile
    # with no Chinese title (GSK980TDi, a Chinese control's own name) keeps its title
    answer = await fanuc_zh.protocol.send_request_async("cncmacro/profiles", {})
    titles = {p["name"]: (p["title"], p["titleZh"]) for p in answer}
    assert titles["fanuc-0i-lathe"] == ("FANUC 0i-TF lathe", "FANUC 0i-TF 车床")
    assert titles["haas"] == ("Haas NGC mill", "Haas NGC 铣床")
    assert titles["gsk980tdi"] == ("GSK980TDi", "GSK980TDi")
