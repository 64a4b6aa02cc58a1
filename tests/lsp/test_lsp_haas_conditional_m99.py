"""Haas's conditional jump ``[cond] M99 P n`` (docs/semantics.md §4) in the editor, through a real
client: a Haas document that uses it has no errors, go to definition on the P leads to its N line,
hover on the condition answers and hover on the M99 says it is a conditional jump; read as
``fanuc-0i`` the line is a ``dialect-feature`` error with a quick fix that writes it as IF..GOTO."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, HERE, close_file, diagnostics_for, hover_text, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")


TEXT = "%\nO01050 (COUNT TO 10)\n#100=0\nN10 #100=#100+1\nN50 [#100 LT 10] M99 P10\nM30\n%\n"
N10, P10, COND_VAR, COND_OP, M99 = (3, 0), (4, 22), (4, 6), (4, 11), (4, 18)  # 0-based line and column


async def test_haas_conditional_m99_checks_clean_and_its_p_leads_to_the_label(
    haas_en: LanguageClient, fanuc_en: LanguageClient
) -> None:
    uri = open_file(haas_en, HERE / "workspace_haas" / "count.nc", TEXT)
    try:
        found = (await diagnostics_for(haas_en, uri, 1)).diagnostics
        assert [d for d in found if d.severity == types.DiagnosticSeverity.Error] == []
        got = await haas_en.text_document_definition_async(
            types.DefinitionParams(types.TextDocumentIdentifier(uri), types.Position(*P10))
        )
        assert isinstance(got, list) and len(got) == 1
        assert (got[0].uri, got[0].range.start.line, got[0].range.start.character) == (uri, *N10)
        assert "#100" in await hover_text(haas_en, uri, *COND_VAR)  # the condition's variable
        await haas_en.text_document_hover_async(  # and its operator: an answer or none, no fault
            types.HoverParams(types.TextDocumentIdentifier(uri), types.Position(*COND_OP))
        )
        assert "jumps to it" in await hover_text(haas_en, uri, *N10)
        said = await hover_text(haas_en, uri, *M99)  # not "return from a subprogram"
        assert said.startswith("**[cond] M99 P n** — Conditional jump (Haas): to block Nn when the condition holds")
    finally:
        close_file(haas_en, uri)
    fanuc = open_file(fanuc_en, FANUC / "count.nc", TEXT)
    try:
        found = (await diagnostics_for(fanuc_en, fanuc, 1)).diagnostics
        errors = [(d.range.start.line, d.code) for d in found if d.severity == types.DiagnosticSeverity.Error]
        assert errors == [(4, "dialect-feature")]
        said = await hover_text(fanuc_en, fanuc, *M99)
        assert "FANUC 0i Custom Macro B does not read it: the control stops at this block with alarm 114" in said
        refused = [d for d in found if d.code == "dialect-feature"]
        actions = await fanuc_en.text_document_code_action_async(
            types.CodeActionParams(
                types.TextDocumentIdentifier(fanuc),
                types.Range(types.Position(4, 0), types.Position(4, 0)),
                types.CodeActionContext(diagnostics=refused),
            )
        )
        [fix] = [a for a in actions or [] if isinstance(a, types.CodeAction) and a.title.startswith("Write it as")]
        assert fix.title == "Write it as IF [#100 LT 10] GOTO 10" and list(fix.diagnostics or []) == refused
        assert fix.edit is not None and fix.edit.changes is not None
        [edit] = fix.edit.changes[fanuc]
        rewritten = (edit.range.start.line, edit.range.start.character, edit.range.end.character, edit.new_text)
        assert rewritten == (4, 4, 24, "IF [#100 LT 10] GOTO 10")
    finally:
        close_file(fanuc_en, fanuc)


async def test_the_if_goto_quick_fix_keeps_a_comment_written_inside_the_jump(fanuc_en: LanguageClient) -> None:
    # the comment between the condition and M99 used to be dropped by the rewrite
    text = TEXT.replace("N50 [#100 LT 10] M99 P10", "N50 [#100 LT 10] (AGAIN) M99 P10")
    uri = open_file(fanuc_en, FANUC / "count_note.nc", text)
    try:
        found = (await diagnostics_for(fanuc_en, uri, 1)).diagnostics
        refused = [d for d in found if d.code == "dialect-feature"]
        actions = await fanuc_en.text_document_code_action_async(
            types.CodeActionParams(
                types.TextDocumentIdentifier(uri),
                types.Range(types.Position(4, 0), types.Position(4, 0)),
                types.CodeActionContext(diagnostics=refused),
            )
        )
        [fix] = [a for a in actions or [] if isinstance(a, types.CodeAction) and a.title.startswith("Write it as")]
        assert fix.edit is not None and fix.edit.changes is not None
        [edit] = fix.edit.changes[uri]
        # "N50 " is 4 characters; "[#100 LT 10] (AGAIN) M99 P10" is 28
        assert (edit.range.start.character, edit.range.end.character) == (4, 32)
        assert edit.new_text == "IF [#100 LT 10] GOTO 10 (AGAIN)"
    finally:
        close_file(fanuc_en, uri)
