"""Inline values for a paused debug session: ``textDocument/inlineValue`` names each variable a
line reads or writes, at its columns, for the editor to evaluate through the debug adapter."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")


async def inline_values(client: LanguageClient, uri: str, first: int, last: int) -> list[tuple[int, int, int, str]]:
    values = await client.text_document_inline_value_async(
        types.InlineValueParams(
            text_document=types.TextDocumentIdentifier(uri),
            range=types.Range(types.Position(first, 0), types.Position(last, 0)),
            context=types.InlineValueContext(
                frame_id=1, stopped_location=types.Range(types.Position(last, 0), types.Position(last, 0))
            ),
        )
    )
    out = []
    for v in values or []:
        assert isinstance(v, types.InlineValueEvaluatableExpression)
        out.append((v.range.start.line, v.range.start.character, v.range.end.character, v.expression or ""))
    return out


async def test_each_variable_of_a_line_is_an_expression_to_evaluate(fanuc_en: LanguageClient) -> None:
    text = "O0100\n#1=6 (COUNT)\n#10=360/#1+#1\nG01 X#10 Y#[#1+2] F100\nG00 X10. Y5.\nIF[#10 GT 1] GOTO 9\nN9 M30\n"
    uri = open_file(fanuc_en, FANUC / "inline_values.nc", text)
    assert await inline_values(fanuc_en, uri, 0, 6) == [
        (1, 0, 2, "#1"),  # the assignment's target: the value it holds now
        (2, 0, 3, "#10"),
        (2, 8, 10, "#1"),  # once per line, though read twice
        (3, 5, 8, "#10"),
        (3, 10, 17, "#[#1+2]"),  # an indirect variable as written, and the variable in it
        (3, 12, 14, "#1"),
        (5, 3, 6, "#10"),
    ]


async def test_the_server_offers_inline_values(fanuc_en: LanguageClient) -> None:
    assert fanuc_en.server_capabilities.inline_value_provider  # type: ignore[attr-defined]


async def test_only_the_asked_lines_are_answered(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "inline_values_range.nc", "O0100\n#1=1\n#2=2\n#3=3\nM30\n")
    assert [v[3] for v in await inline_values(fanuc_en, uri, 2, 2)] == ["#2"]
    assert await inline_values(fanuc_en, uri, 40, 50) == []
