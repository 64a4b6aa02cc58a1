"""Auto-detection (docs/profiles.md): a file that uses what another profile has gets one
``profile-suggestion`` naming it, with quick fixes that write the dialect comment or the machine
file's ``base``; nothing switches by itself."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, actions_for, diagnostics_for, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")

NAMED = "%\nO0001 (PROBE REPORT)\n#1=[#_ABSIO[1]]\n#2=POW[#1,2]\n#3=[#_ABSKP[3]]\nM30\n%\n"
HAAS = "%\nO01002 (HAAS OFFSETS)\nG154 P5\nG110 G00 X0 Y0\n#10500=#3026\nM97 P100\nM30\nN100 G187 P2\nM99\n%\n"


async def test_30i_names_under_fanuc_0i_suggest_fanuc_30i_once(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "probe_30i.nc", NAMED)
    diags = (await diagnostics_for(fanuc_en, uri, 1)).diagnostics
    features = [d for d in diags if d.code == "dialect-feature"]
    [hint] = [d for d in diags if d.code == "profile-suggestion"]
    assert len(features) == 3 and hint.severity == types.DiagnosticSeverity.Information
    assert "FANUC 30i-B Custom Macro" in hint.message and "lines 3, 4, 5" in hint.message
    assert hint.range.start.line == 2
    actions = await actions_for(fanuc_en, uri, hint)
    comment = next(a for a in actions if "(cncmacro: dialect=fanuc-30i)" in a.title)
    [edit] = comment.edit.changes[uri]  # type: ignore[index, union-attr]
    assert (edit.range.start.line, edit.new_text) == (1, "(cncmacro: dialect=fanuc-30i)\n")  # after the %
    base = next(a for a in actions if 'base = "fanuc-30i"' in a.title)
    assert base.edit is not None


async def test_the_suggested_comment_makes_the_file_clean(fanuc_en: LanguageClient) -> None:
    text = NAMED.replace("%\n", "%\n(cncmacro: dialect=fanuc-30i)\n", 1)
    uri = open_file(fanuc_en, FANUC / "probe_30i_marked.nc", text)
    diags = (await diagnostics_for(fanuc_en, uri, 1)).diagnostics
    assert [d.code for d in diags if d.severity is not None and d.severity <= 3] == []


async def test_a_plain_mistake_suggests_nothing(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "plain_mistake.nc", "O0002\n#1=#50\nM30\n")
    diags = (await diagnostics_for(fanuc_en, uri, 1)).diagnostics
    assert [d.code for d in diags if d.code != "not-executed"] == ["variable-number"]


async def test_haas_codes_under_fanuc_0i_suggest_haas_and_its_comment_makes_the_file_clean(
    fanuc_en: LanguageClient,
) -> None:
    uri = open_file(fanuc_en, FANUC / "haas_offsets.nc", HAAS)
    diags = (await diagnostics_for(fanuc_en, uri, 1)).diagnostics
    [hint] = [d for d in diags if d.code == "profile-suggestion"]
    assert "Haas NGC mill" in hint.message and "lines 3, 4, 8" in hint.message  # G154, G110, G187
    actions = await actions_for(fanuc_en, uri, hint)
    comment = next(a for a in actions if "(cncmacro: dialect=haas)" in a.title)
    [edit] = comment.edit.changes[uri]  # type: ignore[index, union-attr]
    assert (edit.range.start.line, edit.new_text) == (1, "(cncmacro: dialect=haas)\n")
    marked = open_file(fanuc_en, FANUC / "haas_offsets_marked.nc", HAAS.replace("%\n", "%\n" + edit.new_text, 1))
    diags = (await diagnostics_for(fanuc_en, marked, 1)).diagnostics
    assert list(diags) == []


async def test_an_m97_call_to_a_label_of_the_file_alone_suggests_haas(fanuc_en: LanguageClient) -> None:
    # no error under fanuc-0i (M97 is an M code the machine may have), yet the program is plainly Haas's
    text = "%\nO01003 (LOCAL CALLS)\nT1 M06\nM97 P100 L2\nM30\nN100 G91 G01 Z-1. F100.\nM99\n%\n"
    uri = open_file(fanuc_en, FANUC / "haas_m97.nc", text)
    diags = (await diagnostics_for(fanuc_en, uri, 1)).diagnostics
    [hint] = [d for d in diags if d.code == "profile-suggestion"]
    assert "Haas NGC mill" in hint.message and "line 4" in hint.message
    assert (hint.range.start.line, hint.range.start.character) == (3, 4)  # on P100
    actions = await actions_for(fanuc_en, uri, hint)
    assert any("(cncmacro: dialect=haas)" in a.title for a in actions)


async def test_an_m97_whose_label_is_missing_suggests_nothing(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "m97_no_label.nc", "O0004\nM97 P100\nM30\n")
    diags = (await diagnostics_for(fanuc_en, uri, 1)).diagnostics
    assert [d for d in diags if d.code == "profile-suggestion"] == []


async def test_an_8_digit_program_number_under_fanuc_0i_suggests_fanuc_30i_whose_m98_p_names_it(
    fanuc_en: LanguageClient,
) -> None:
    # the 0i splits M98 P00012346 into a count and O2346; an 8-digit header says the machine names it whole
    text = "%\nO00012345 (MAIN)\nM98 P00012346 L3\nM30\n%\n"
    uri = open_file(fanuc_en, FANUC / "O00012345.nc", text)
    diags = (await diagnostics_for(fanuc_en, uri, 1)).diagnostics
    [hint] = [d for d in diags if d.code == "profile-suggestion"]
    assert "8 digits" in hint.message and "FANUC 30i-B Custom Macro" in hint.message
    assert "program_digits = 8" in hint.message
    assert (hint.range.start.line, hint.range.start.character, hint.range.end.character) == (1, 0, 9)
    actions = await actions_for(fanuc_en, uri, hint)
    comment = next(a for a in actions if "(cncmacro: dialect=fanuc-30i)" in a.title)
    [edit] = comment.edit.changes[uri]  # type: ignore[index, union-attr]
    marked = open_file(fanuc_en, FANUC / "O00012345_marked.nc", text.replace("%\n", "%\n" + edit.new_text, 1))
    diags = (await diagnostics_for(fanuc_en, marked, 1)).diagnostics
    assert not any(d.code == "profile-suggestion" for d in diags)


async def test_a_5_digit_program_number_suggests_nothing(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "O12345.nc", "%\nO12345 (MAIN)\nG00 X0\nM30\n%\n")
    diags = (await diagnostics_for(fanuc_en, uri, 1)).diagnostics
    assert not any(d.code == "profile-suggestion" for d in diags)
