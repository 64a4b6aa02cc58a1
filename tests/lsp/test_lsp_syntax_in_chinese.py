"""docs/semantics.md §1 "Text and blocks" in the editor: a line that does not parse gets its
``syntax`` diagnostic in the client's language (VS Code's ``initialize`` locale)."""

from __future__ import annotations

import pytest
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, diagnostics_for, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")

TEXT = "O0100\n#1=[#2+3\nG01 X1 @\nM30\n"


async def test_1_text_and_blocks_a_chinese_session_gets_chinese_syntax_diagnostics(fanuc_zh: LanguageClient) -> None:
    uri = open_file(fanuc_zh, FANUC / "syntax_zh.nc", TEXT)
    got = await diagnostics_for(fanuc_zh, uri, 1)
    found = [(d.range.start.line, d.range.start.character, d.message) for d in got.diagnostics if d.code == "syntax"]
    assert found == [
        (1, 8, "缺少 ']'：第 4 列的 '[' 没有闭合"),
        (2, 7, "此处不应出现 '@'；应为其他代码字或宏语句"),
    ]


async def test_1_text_and_blocks_an_english_session_keeps_english_syntax_diagnostics(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "syntax_en.nc", TEXT)
    got = await diagnostics_for(fanuc_en, uri, 1)
    found = [(d.range.start.line, d.message) for d in got.diagnostics if d.code == "syntax"]
    assert found == [
        (1, "expected ']' to close the '[' at column 4"),
        (2, "unexpected '@'; expected another word or statement"),
    ]
