"""The block IF of ``mitsubishi-m70`` in the editor, over stdio (docs/semantics.md §4 "Block IF",
docs/profiles.md "mitsubishi-m70"): its branches fold, and a FANUC file that writes it gets one
``profile-suggestion`` naming ``mitsubishi-m70`` (and ``mazak-eia``) whose quick fix makes the file clean.
Read as fanuc-0i, the same text has three ``dialect-feature`` errors instead."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, actions_for, close_file, diagnostics_for, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")

# lines 0-based: 1 O header, 3 IF, 6 ELSE, 9 ENDIF, 10 M30
PROGRAM = (
    "%\nO1000 (PART FAMILY)\n#1=2\nIF [#1 EQ 1] THEN\n#2=10.\nG01 X#2 F100\nELSE\n#2=20.\nG01 X#2 F100\nENDIF\nM30\n%\n"
)
MARKED = PROGRAM.replace("%\n", "%\n(cncmacro: dialect=mitsubishi-m70)\n", 1)


async def test_block_if_branches_fold_inside_their_program(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "block_if_fold.nc", MARKED)
    ranges = await fanuc_en.text_document_folding_range_async(
        types.FoldingRangeParams(types.TextDocumentIdentifier(uri))
    )
    close_file(fanuc_en, uri)
    # with the comment on line 1: IF 4 .. ELSE 7 .. ENDIF 10, the program 2 .. M30 11
    got = sorted((r.start_line, r.end_line) for r in ranges)
    assert got == [(2, 11), (4, 6), (7, 10)]


async def test_block_if_under_fanuc_suggests_mitsubishi_once_and_its_comment_makes_the_file_clean(
    fanuc_en: LanguageClient,
) -> None:
    uri = open_file(fanuc_en, FANUC / "block_if_fanuc.nc", PROGRAM)
    diags = (await diagnostics_for(fanuc_en, uri, 1)).diagnostics
    features = [d for d in diags if d.code == "dialect-feature"]
    [hint] = [d for d in diags if d.code == "profile-suggestion"]
    assert [d.range.start.line for d in features] == [3, 6, 9]
    assert "Mitsubishi M70/M80" in hint.message and "lines 4, 7, 10" in hint.message
    also = "the profile mazak-eia (Mazak EIA/ISO (Matrix, Smooth)) reads IF..THEN / ELSE / ENDIF blocks too"
    assert also in hint.message
    assert hint.range.start.line == 3 and hint.severity == types.DiagnosticSeverity.Information
    actions = await actions_for(fanuc_en, uri, hint)
    comment = next(a for a in actions if "(cncmacro: dialect=mitsubishi-m70)" in a.title)
    [edit] = comment.edit.changes[uri]  # type: ignore[index, union-attr]
    assert (edit.range.start.line, edit.new_text) == (1, "(cncmacro: dialect=mitsubishi-m70)\n")
    assert any('base = "mitsubishi-m70"' in a.title for a in actions)
    close_file(fanuc_en, uri)
    marked = open_file(fanuc_en, FANUC / "block_if_marked.nc", PROGRAM.replace("%\n", "%\n" + edit.new_text, 1))
    diags = (await diagnostics_for(fanuc_en, marked, 1)).diagnostics
    assert [d.code for d in diags if d.severity is not None and d.severity <= 3] == []
    close_file(fanuc_en, marked)
