"""Navigation, end to end: definition of jumps and calls (across files), references of labels,
programs and variables, and renaming an N label with every jump to it."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pygls.exceptions import JsonRpcException
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, GSK, close_file, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")


def _pos(uri: str, line: int, ch: int) -> tuple[types.TextDocumentIdentifier, types.Position]:
    return types.TextDocumentIdentifier(uri), types.Position(line, ch)


async def _definition(client: LanguageClient, uri: str, line: int, ch: int) -> list[types.Location]:
    result = await client.text_document_definition_async(types.DefinitionParams(*_pos(uri, line, ch)))
    assert isinstance(result, list)
    return result


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


async def test_definition_of_a_goto_is_its_n_label(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "MAIN.nc")
    [loc] = await _definition(fanuc_en, uri, 4, 22)  # GOTO10
    close_file(fanuc_en, uri)
    assert loc.uri == uri and loc.range.start == types.Position(3, 0) and loc.range.end == types.Position(3, 3)


async def test_definition_of_p_is_the_called_program_in_another_file(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "MAIN.nc")
    [g65] = await _definition(fanuc_en, uri, 2, 6)  # G65 P9100
    [m98] = await _definition(fanuc_en, uri, 11, 5)  # M98 P9100
    close_file(fanuc_en, uri)
    assert g65.uri == (FANUC / "O9100.nc").as_uri() and g65.range.start.line == 0
    assert m98.uri == g65.uri


async def test_definition_of_a_bracketed_name_on_gsk(gsk_zh: LanguageClient) -> None:
    uri = open_file(gsk_zh, GSK / "MAIN.CNC")
    [loc] = await _definition(gsk_zh, uri, 2, 7)  # P[CUT]
    [jump] = await _definition(gsk_zh, uri, 4, 17)  # GOTO20
    close_file(gsk_zh, uri)
    assert loc.uri == (GSK / "CUT.CNC").as_uri() and loc.range.start.line == 0
    assert jump.range.start.line == 3


async def test_references_of_a_label_program_and_variables(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "MAIN.nc")
    assert await _references(fanuc_en, uri, 3, 1) == [("MAIN.nc", 3, 0), ("MAIN.nc", 4, 21)]
    program = await _references(fanuc_en, uri, 2, 6)
    assert ("O9100.nc", 0, 0) in program
    assert [r for r in program if r[0] == "MAIN.nc"] == [("MAIN.nc", 2, 4), ("MAIN.nc", 11, 4), ("MAIN.nc", 13, 8)]
    common = await _references(fanuc_en, uri, 1, 1)  # #100: both files
    assert common == [("MAIN.nc", 1, 0), ("MAIN.nc", 4, 11), ("O9100.nc", 5, 0), ("O9100.nc", 5, 5)]
    local = await _references(fanuc_en, uri, 5, 7)  # #1 stays in O0001
    close_file(fanuc_en, uri)
    assert local == [("MAIN.nc", 5, 6), ("MAIN.nc", 9, 0), ("MAIN.nc", 9, 3)]


async def test_rename_a_label_updates_every_jump(fanuc_en: LanguageClient, gsk_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "MAIN.nc")
    result = await fanuc_en.text_document_rename_async(types.RenameParams(*_pos(uri, 4, 22), new_name="N20"))
    close_file(fanuc_en, uri)
    assert result is not None and result.changes is not None
    edits = sorted((e.range.start.line, e.range.start.character, e.new_text) for e in result.changes[uri])
    assert edits == [(3, 0, "N20"), (4, 21, "20")]
    uri = open_file(gsk_en, GSK / "MAIN.CNC")
    result = await gsk_en.text_document_rename_async(types.RenameParams(*_pos(uri, 3, 1), new_name="30"))
    close_file(gsk_en, uri)
    assert result is not None and result.changes is not None
    assert sorted((e.range.start.line, e.new_text) for e in result.changes[uri]) == [(3, "N30"), (4, "30")]


async def test_rename_onto_a_label_the_program_has_is_refused(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "RENAME.nc", "O0001\n#1=1\nIF[#1 EQ 1] GOTO 20\nN10 #2=1\nN20 #3=1\nM30\n")
    with pytest.raises(JsonRpcException, match="N20 is already a label"):
        await fanuc_en.text_document_rename_async(types.RenameParams(*_pos(uri, 3, 1), new_name="N20"))
    close_file(fanuc_en, uri)
