"""``M99 P n`` returns to ``Nn`` of the program that called the subprogram (docs/semantics.md §4,
docs/editor.md "Navigation"), in the editor as in the run: hover on its ``n`` names the caller's
label, go to definition lands there, in the same file or in another, and the caller's ``Nn``
counts the return among the jumps to it. Where nothing calls the subprogram the hover says so
instead of "not found".

The workspace ``workspace_returns``::

    O6001.nc   O6001: M98 P6002 (line 4), N20 M30 (line 6); O6002: M99 P20 (line 9)
    MAIN.nc    O0001: N5 M98 P7000 (line 2), N20 #3=2 (line 4)
    O7000.nc   O7000: M99 P20 (line 3)
    O7200.nc   O7200: N30 (line 2), M30; O7201, which nothing calls: M99 P30 (line 5)
    O7300.nc   O7300, which nothing calls, the file's only program: N40 (line 2), M99 P40 (line 4)

(lines 1-based here; the requests below are 0-based).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from lsprotocol import types
from pygls.exceptions import JsonRpcException
from pytest_lsp import LanguageClient

from .lsp_session import close_file, diagnostics_for, hover_text, open_file, session_fixture

pytestmark = pytest.mark.asyncio(loop_scope="session")

ROOT = Path(__file__).resolve().parent / "workspace_returns"
returns_en = session_fixture(ROOT, "en")


async def _definition(client: LanguageClient, uri: str, line: int, ch: int) -> list[tuple[str, int, int, int]]:
    result = await client.text_document_definition_async(
        types.DefinitionParams(types.TextDocumentIdentifier(uri), types.Position(line, ch))
    )
    assert isinstance(result, list)
    return [(r.uri.rsplit("/", 1)[-1], r.range.start.line, r.range.start.character, r.range.end.character)
            for r in result]  # fmt: skip


async def _references(client: LanguageClient, uri: str, line: int, ch: int) -> list[tuple[str, int, int]]:
    result = await client.text_document_references_async(
        types.ReferenceParams(
            text_document=types.TextDocumentIdentifier(uri),
            position=types.Position(line, ch),
            context=types.ReferenceContext(include_declaration=True),
        )
    )
    assert result is not None
    return sorted((r.uri.rsplit("/", 1)[-1], r.range.start.line, r.range.start.character) for r in result)


async def test_m99_p_returns_to_the_label_of_its_caller_in_the_same_file(returns_en: LanguageClient) -> None:
    uri = open_file(returns_en, ROOT / "O6001.nc")
    diagnostics = (await diagnostics_for(returns_en, uri, 1)).diagnostics
    said = await hover_text(returns_en, uri, 8, 5)  # the 20 of M99 P20 (0-based line 8)
    landed = await _definition(returns_en, uri, 8, 5)
    label = await hover_text(returns_en, uri, 5, 1)  # N20 of O6001
    references = await _references(returns_en, uri, 5, 1)
    close_file(returns_en, uri)
    assert "undefined-label" not in {d.code for d in diagnostics}
    assert "not found" not in said
    assert "M99 P20 returns to N20 of the calling program:" in said and "- O6001 (O6001.nc), line 6" in said
    assert landed == [("O6001.nc", 5, 0, 3)]  # N20 M30: the N word, columns 0-3
    assert "no jump names it" not in label and "line 9 (M99 P20)" in label
    assert references == [("O6001.nc", 5, 0), ("O6001.nc", 8, 5)]


async def test_m99_p_returns_to_the_label_of_its_caller_in_another_file(returns_en: LanguageClient) -> None:
    sub = open_file(returns_en, ROOT / "O7000.nc")
    said = await hover_text(returns_en, sub, 2, 5)
    landed = await _definition(returns_en, sub, 2, 5)
    close_file(returns_en, sub)
    assert "- O0001 (MAIN.nc), line 4" in said
    assert landed == [("MAIN.nc", 3, 0, 3)]
    main = open_file(returns_en, ROOT / "MAIN.nc")  # O7000.nc is read from disk now
    label = await hover_text(returns_en, main, 3, 1)
    references = await _references(returns_en, main, 3, 1)
    with pytest.raises(JsonRpcException, match=r"M99 P20 of O7000\.nc"):
        await returns_en.text_document_rename_async(
            types.RenameParams(types.TextDocumentIdentifier(main), types.Position(3, 1), new_name="N25")
        )
    close_file(returns_en, main)
    assert "O7000.nc, line 3 (M99 P20)" in label
    assert references == [("MAIN.nc", 3, 0), ("O7000.nc", 2, 5)]


async def test_m99_p_of_a_program_nothing_calls_says_the_callers_are_unknown(returns_en: LanguageClient) -> None:
    uri = open_file(returns_en, ROOT / "O7200.nc")
    said = await hover_text(returns_en, uri, 4, 5)  # M99 P30 of O7201: O7200's N30 is not its caller's
    landed = await returns_en.text_document_definition_async(
        types.DefinitionParams(types.TextDocumentIdentifier(uri), types.Position(4, 5))
    )
    close_file(returns_en, uri)
    assert "not found" not in said
    assert "no call of O7201 was found in the workspace" in said
    assert landed is None


async def test_m99_p_of_a_main_program_goes_on_from_its_own_label(returns_en: LanguageClient) -> None:
    uri = open_file(returns_en, ROOT / "O7300.nc")
    said = await hover_text(returns_en, uri, 3, 5)
    landed = await _definition(returns_en, uri, 3, 5)
    close_file(returns_en, uri)
    assert "Nothing in the workspace calls O7300: as a main program, M99 P40 goes on from its own N40" in said
    assert "line 2" in said
    assert landed == [("O7300.nc", 1, 0, 3)]
