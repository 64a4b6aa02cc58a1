"""The hover of #0 says what it is once, without repeating its own name."""

from __future__ import annotations

import pytest
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, close_file, hover_text, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")


async def test_hover_on_0_names_it_once(fanuc_en: LanguageClient, fanuc_zh: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "null_en.nc", "O1\n#1=#0\nM30\n")
    text = await hover_text(fanuc_en, uri, 1, 4)
    close_file(fanuc_en, uri)
    assert text.startswith("**#0** — Always vacant, read-only") and text.count("#0") == 1
    uri = open_file(fanuc_zh, FANUC / "null_zh.nc", "O1\n#1=#0\nM30\n")
    text = await hover_text(fanuc_zh, uri, 1, 4)
    close_file(fanuc_zh, uri)
    assert text.startswith("**#0** — 总是空，只读")
