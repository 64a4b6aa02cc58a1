"""A Mazak EIA/ISO program in the editor, over stdio (docs/semantics.md §3 "``&&`` and ``||``",
docs/profiles.md "mazak-eia"): read as fanuc-0i, its ``&&`` and ``||`` are ``dialect-feature``
errors and its ``WH`` a hint (FANUC reads it too), and the file gets one ``profile-suggestion``
naming ``mazak-eia`` whose quick fix makes the file clean."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, actions_for, close_file, diagnostics_for, hover_text, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")

# lines 0-based: 1 O header, 4 IF with &&, 6 WH, 7 IF with ||, 10 M30
PROGRAM = (
    "%\nO2000 (BORE CHECK)\n#1=3\n#2=0\nIF [[#1 GT 0] && [#1 LT 5]] GOTO 10\n#2=1\n"
    "WH [#2 LT 3] DO1\nIF [[#2 EQ 1] || [#2 EQ 2]] THEN #3=#2\n#2=#2+1\nEND1\nN10 M30\n%\n"
)


async def test_logical_symbols_under_fanuc_suggest_mazak_once_and_its_comment_makes_the_file_clean(
    fanuc_en: LanguageClient,
) -> None:
    uri = open_file(fanuc_en, FANUC / "mazak_fanuc.nc", PROGRAM)
    diags = (await diagnostics_for(fanuc_en, uri, 1)).diagnostics
    features = [d for d in diags if d.code == "dialect-feature"]
    assert [d.range.start.line for d in features] == [4, 7]
    assert "write AND" in features[0].message and "write OR" in features[1].message
    [wh] = [d for d in diags if d.code == "keyword-abbreviation"]
    assert wh.range.start.line == 6 and wh.severity == types.DiagnosticSeverity.Hint
    [hint] = [d for d in diags if d.code == "profile-suggestion"]
    assert "Mazak EIA/ISO (Matrix, Smooth)" in hint.message and "lines 5, 8" in hint.message
    assert hint.range.start.line == 4 and hint.severity == types.DiagnosticSeverity.Information
    actions = await actions_for(fanuc_en, uri, hint)
    comment = next(a for a in actions if "(cncmacro: dialect=mazak-eia)" in a.title)
    [edit] = comment.edit.changes[uri]  # type: ignore[index, union-attr]
    assert (edit.range.start.line, edit.new_text) == (1, "(cncmacro: dialect=mazak-eia)\n")
    assert any('base = "mazak-eia"' in a.title for a in actions)
    close_file(fanuc_en, uri)
    marked = open_file(fanuc_en, FANUC / "mazak_marked.nc", PROGRAM.replace("%\n", "%\n" + edit.new_text, 1))
    diags = (await diagnostics_for(fanuc_en, marked, 1)).diagnostics
    assert [d.code for d in diags if d.severity is not None and d.severity <= 3] == []
    close_file(fanuc_en, marked)


async def test_hover_on_a_logical_symbol_describes_the_word_it_stands_for(fanuc_en: LanguageClient) -> None:
    # line 4 is "IF [[#1 GT 0] && [#1 LT 5]] GOTO 10": the && at columns 14-15; line 7's || at 14-15
    marked = PROGRAM.replace("%\n", "%\n(cncmacro: dialect=mazak-eia)\n", 1)  # the lines move down by one
    uri = open_file(fanuc_en, FANUC / "mazak_hover.nc", marked)
    both = await hover_text(fanuc_en, uri, 5, 15)
    either = await hover_text(fanuc_en, uri, 8, 14)
    close_file(fanuc_en, uri)
    assert both.startswith("`&&` is AND, as this control reads it.") and "a AND b" in both
    assert either.startswith("`||` is OR, as this control reads it.") and "a OR b" in either
    plain = open_file(fanuc_en, FANUC / "mazak_as_fanuc.nc", PROGRAM)  # no profile comment: fanuc-0i
    refused = await hover_text(fanuc_en, plain, 4, 14)
    close_file(fanuc_en, plain)
    assert refused.startswith("`&&` stands for AND on some controls; this one does not read it: write AND.")
