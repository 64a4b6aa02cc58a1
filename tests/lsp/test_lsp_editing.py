"""Completion, signature help, code actions, inlay hints and the workspace index, end to end."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, GSK, close_file, diagnostics_for, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")


async def _complete(client: LanguageClient, uri: str, line: int, ch: int) -> list[types.CompletionItem]:
    result = await client.text_document_completion_async(
        types.CompletionParams(types.TextDocumentIdentifier(uri), types.Position(line, ch))
    )
    assert isinstance(result, types.CompletionList)
    return list(result.items)


async def test_completion_after_hash_offers_system_variables_with_docs(
    fanuc_en: LanguageClient, gsk_zh: LanguageClient
) -> None:
    uri = open_file(fanuc_en, FANUC / "c1.nc", "O0001\n#1=#50\n")
    items = {i.label: i for i in await _complete(fanuc_en, uri, 1, 6)}
    close_file(fanuc_en, uri)
    x = items["#5001"]
    # the unit: mm once the analysis has timed the program (it runs in G21), both units before
    assert "block end position" in x.documentation.value
    assert x.detail in ("read-only, mm", "read-only, mm (inch under G20)")
    assert x.text_edit is not None and x.text_edit.range.start.character == 3
    uri = open_file(gsk_zh, GSK / "c1.CNC", "O0001\n#1=#\n")
    items = {i.label: i for i in await _complete(gsk_zh, uri, 1, 4)}
    close_file(gsk_zh, uri)
    assert "程序段终点" in items["#5001"].documentation.value and items["#5001"].detail.startswith("只读, mm")


async def test_completion_after_goto_offers_labels_and_after_p_programs(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "c2.nc", "O0001\nN10 #1=1\nN20 #2=2\nGOTO\nG65 P\n")
    labels = [i.label for i in await _complete(fanuc_en, uri, 3, 4)]
    programs = {i.label: i.detail for i in await _complete(fanuc_en, uri, 4, 5)}
    close_file(fanuc_en, uri)
    assert labels == ["10", "20"]
    assert programs["9100"] == "O9100 DRILL CYCLE" and "1" in programs


async def test_completion_of_g65_arguments_shows_the_local_each_fills(gsk_en: LanguageClient) -> None:
    uri = open_file(gsk_en, GSK / "c3.CNC", "O0001\nG65 P[CUT] \n")
    items = {i.label: i for i in await _complete(gsk_en, uri, 1, 11)}
    close_file(gsk_en, uri)
    assert items["X"].detail == "fills #24" and items["U"].detail == "fills #21"
    assert items["U"].preselect and items["W"].preselect and not items["X"].preselect  # CUT reads #21 and #23
    assert "WHILE" in items and "SQRT" in items


async def test_completion_of_keywords_and_functions(fanuc_zh: LanguageClient) -> None:
    uri = open_file(fanuc_zh, FANUC / "c4.nc", "O0001\n#1=SQ\n")
    items = {i.label: i for i in await _complete(fanuc_zh, uri, 1, 5)}
    close_file(fanuc_zh, uri)
    assert items["SQRT"].detail == "SQRT[a]" and "平方根" in str(items["SQRT"].documentation)
    assert items["IF"].kind == types.CompletionItemKind.Keyword


async def test_completion_after_g_or_m_offers_the_profiles_codes_with_what_each_does(
    fanuc_en: LanguageClient, gsk_zh: LanguageClient
) -> None:
    uri = open_file(fanuc_en, FANUC / "c5.nc", "O0001\nG\nG00 X1. M\nX1.G0\n(G\n")
    g = await _complete(fanuc_en, uri, 1, 1)
    m = await _complete(fanuc_en, uri, 2, 9)
    glued = await _complete(fanuc_en, uri, 3, 5)  # a G word glued to the number before it, a digit typed
    comment = [i.label for i in await _complete(fanuc_en, uri, 4, 2)]
    close_file(fanuc_en, uri)
    codes = {i.label: i for i in g}
    assert [i.label for i in g[:2]] == ["G00", "G01"]  # the profile's table, in its order, first
    assert codes["G01"].detail == "Linear interpolation at feedrate F"  # as hover says it
    assert codes["G01"].text_edit is not None and codes["G01"].text_edit.range.start.character == 0
    assert {i.label: i.detail for i in m}["M03"] == "Spindle on clockwise"
    edit = next(i for i in glued if i.label == "G01").text_edit
    assert edit is not None and (edit.range.start.character, edit.range.end.character) == (3, 5)
    assert "G00" not in comment
    uri = open_file(gsk_zh, GSK / "c5.CNC", "O0001\nM\n")
    gsk = {i.label: i.detail for i in await _complete(gsk_zh, uri, 1, 1)}
    close_file(gsk_zh, uri)
    assert gsk["M03"] == "主轴正转"


async def test_completion_of_g65_arguments_lists_what_the_macro_reads_first(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "c6.nc", "O0001\nG65 P9100 \n")
    items = await _complete(fanuc_en, uri, 1, 10)
    close_file(fanuc_en, uri)
    assert [i.label for i in items[:3]] == ["R", "X", "Z"]  # O9100 reads #18, #24, #26


async def test_completion_after_m98_p_offers_the_files_own_program_last(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "O0998.nc", "O0998 (MAIN)\nM98 P\nM30\n")
    items = await _complete(fanuc_en, uri, 1, 5)
    close_file(fanuc_en, uri)
    labels = [i.label for i in items]
    assert labels[0] != "998" and labels[-1] == "998"
    assert sorted(labels, key=lambda label: next(i.sort_text for i in items if i.label == label)) == labels


async def test_signature_help_on_g65_shows_what_the_macro_reads(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "MAIN.nc")
    result = await fanuc_en.text_document_signature_help_async(
        types.SignatureHelpParams(types.TextDocumentIdentifier(uri), types.Position(2, 18))  # on Z-2.
    )
    close_file(fanuc_en, uri)
    assert result is not None
    sig = result.signatures[0]
    assert sig.label == "O9100(#18 (R), #24 (X), #26 (Z))"
    assert result.active_parameter == 2


async def test_code_actions_split_the_g65_block_and_clamp_l(fanuc_en: LanguageClient, gsk_zh: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "MAIN.nc")
    actions = await fanuc_en.text_document_code_action_async(
        types.CodeActionParams(
            types.TextDocumentIdentifier(uri),
            types.Range(types.Position(13, 0), types.Position(13, 0)),
            types.CodeActionContext(diagnostics=[]),
        )
    )
    close_file(fanuc_en, uri)
    edits = {a.title: a.edit.changes[uri][0].new_text for a in actions}  # type: ignore[union-attr,index]
    assert edits["Split: move G00 to a block before the G65"] == "G00\nG65 P9100 X1. L20000"
    assert edits["Clamp the repeat count to 9999"] == "L9999"
    uri = open_file(gsk_zh, GSK / "ca.CNC", "O0001\nN5 G01 G65 P[CUT] U1. L0 (切削)\n")
    actions = await gsk_zh.text_document_code_action_async(
        types.CodeActionParams(
            types.TextDocumentIdentifier(uri),
            types.Range(types.Position(1, 0), types.Position(1, 5)),
            types.CodeActionContext(diagnostics=[]),
        )
    )
    close_file(gsk_zh, uri)
    texts = sorted(a.edit.changes[uri][0].new_text for a in actions)  # type: ignore[union-attr,index]
    assert texts == ["L1", "N5 G01\nG65 P[CUT] U1. L0 (切削)"]
    assert "拆分：把 G01 移到 G65 之前的单独程序段" in [a.title for a in actions]


async def test_5_calls_a_letter_after_g65_is_an_argument_so_no_split_and_no_finding(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "m_argument.nc", "O0001\nN10 G65 P9100 A1. M5.\nM30\n", version=1)
    found = await diagnostics_for(fanuc_en, uri, 1)
    actions = await fanuc_en.text_document_code_action_async(
        types.CodeActionParams(
            types.TextDocumentIdentifier(uri),
            types.Range(types.Position(1, 0), types.Position(1, 22)),
            types.CodeActionContext(diagnostics=list(found.diagnostics)),
        )
    )
    close_file(fanuc_en, uri)
    assert [d.code for d in found.diagnostics if d.range.start.line == 1] == []  # M5. is argument M (#13)
    assert [a.title for a in actions or []] == []


async def test_inlay_hints_name_the_local_each_argument_fills(fanuc_en: LanguageClient, gsk_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "hints.nc", "O0001\nG65 P9100 A1 I2 J3 I4 X5\n")
    hints = await fanuc_en.text_document_inlay_hint_async(
        types.InlayHintParams(
            types.TextDocumentIdentifier(uri), types.Range(types.Position(0, 0), types.Position(2, 0))
        )
    )
    close_file(fanuc_en, uri)
    assert [(h.position.character, h.label) for h in hints] == [
        (12, "#1"),
        (15, "#4"),
        (18, "#5"),
        (21, "#7"),
        (24, "#24"),
    ]
    uri = open_file(gsk_en, GSK / "MAIN.CNC")
    hints = await gsk_en.text_document_inlay_hint_async(
        types.InlayHintParams(
            types.TextDocumentIdentifier(uri), types.Range(types.Position(0, 0), types.Position(8, 0))
        )
    )
    close_file(gsk_en, uri)
    assert [(h.position.line, h.label) for h in hints] == [(2, "#21"), (2, "#23")]


async def test_watched_file_changes_update_the_program_index(gsk_en: LanguageClient, tmp_path_factory) -> None:  # type: ignore[no-untyped-def]
    new = GSK / "O0777.CNC"
    try:
        new.write_text("O0777 (NEW SUB)\nM99\n", "utf-8")
        gsk_en.workspace_did_change_watched_files(
            types.DidChangeWatchedFilesParams([types.FileEvent(new.as_uri(), types.FileChangeType.Created)])
        )
        found = await gsk_en.workspace_symbol_async(types.WorkspaceSymbolParams(query="new sub"))
        assert [s.name for s in found] == ["O0777"]
    finally:
        new.unlink()
    gsk_en.workspace_did_change_watched_files(
        types.DidChangeWatchedFilesParams([types.FileEvent(new.as_uri(), types.FileChangeType.Deleted)])
    )
    assert await gsk_en.workspace_symbol_async(types.WorkspaceSymbolParams(query="new sub")) == []


async def test_1_quick_fix_writes_an_abbreviated_macro_word_in_full(fanuc_en: LanguageClient) -> None:
    text = "O0001\n#1=0\nWH[#1LT3]DO1\n#1=#1+1\nEN1\nM30\n"
    uri = open_file(fanuc_en, FANUC / "expand.nc", text, version=1)
    published = await diagnostics_for(fanuc_en, uri, 1)
    hints = [d for d in published.diagnostics if d.code == "keyword-abbreviation"]
    assert [(d.range.start.line, d.severity) for d in hints] == [(2, types.DiagnosticSeverity.Hint),
                                                                  (4, types.DiagnosticSeverity.Hint)]  # fmt: skip
    actions = await fanuc_en.text_document_code_action_async(
        types.CodeActionParams(
            types.TextDocumentIdentifier(uri),
            types.Range(types.Position(2, 0), types.Position(2, 0)),
            types.CodeActionContext(diagnostics=hints),
        )
    )
    close_file(fanuc_en, uri)
    [action] = actions  # type: ignore[misc]
    assert action.title == "Write WHILE in full" and action.kind == types.CodeActionKind.QuickFix
    [change] = action.edit.changes[uri]  # type: ignore[union-attr,index]
    assert (change.range.start.line, change.range.start.character, change.range.end.character) == (2, 0, 2)
    assert change.new_text == "WHILE"
    assert [d.code for d in action.diagnostics or []] == ["keyword-abbreviation"]
