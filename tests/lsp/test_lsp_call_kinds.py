"""Navigation of every kind of call (docs/semantics.md §5), end to end: besides G65/G66/M98,
``M198 P`` and a code that the machine file's ``[calls]`` makes a call (``G100 = 9010``, ``M60``
as a subprogram call) lead to the program they call, and are among its references."""

from __future__ import annotations

from pathlib import Path

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import close_file, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")

CALLS = Path(__file__).resolve().parent / "workspace_calls"


async def _definition(client: LanguageClient, uri: str, line: int, ch: int) -> list[tuple[str, int]]:
    result = await client.text_document_definition_async(
        types.DefinitionParams(types.TextDocumentIdentifier(uri), types.Position(line, ch))
    )
    assert isinstance(result, list)
    return [(r.uri.rsplit("/", 1)[-1], r.range.start.line) for r in result]


async def test_5_calls_definition_of_m198_p_and_of_the_machine_files_call_codes(calls_en: LanguageClient) -> None:
    uri = open_file(calls_en, CALLS / "MAIN.nc")
    m198 = await _definition(calls_en, uri, 1, 7)  # M198 P9010
    g100 = await _definition(calls_en, uri, 2, 2)  # G100 = 9010
    m60 = await _definition(calls_en, uri, 3, 1)  # M60 = 9020 (a subprogram call)
    close_file(calls_en, uri)
    assert m198 == [("O9010.nc", 0)]
    assert g100 == [("O9010.nc", 0)]
    assert m60 == [("O9020.nc", 0)]


async def test_5_calls_references_of_a_program_include_m198_and_the_call_codes(calls_en: LanguageClient) -> None:
    uri = open_file(calls_en, CALLS / "O9010.nc")
    result = await calls_en.text_document_references_async(
        types.ReferenceParams(
            text_document=types.TextDocumentIdentifier(uri),
            position=types.Position(0, 2),  # O9010
            context=types.ReferenceContext(include_declaration=False),
        )
    )
    close_file(calls_en, uri)
    assert result is not None
    found = sorted((r.uri.rsplit("/", 1)[-1], r.range.start.line, r.range.start.character) for r in result)
    assert found == [("MAIN.nc", 1, 5), ("MAIN.nc", 2, 0)]
