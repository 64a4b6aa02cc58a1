"""Files and configuration as shops have them, in the editor (docs/machine-file.md "Program
files", "common", "[codes]"): a DNC folder of ``.txt`` programs without a machine file
(``workspace_txt_programs``: a main program on a tape, ``%`` first, and the subprogram it calls,
``O0810.txt``, whose first line is ``O0810``; a ``README.txt`` beside them), and an OKK 30i whose
machine file adds the common variables #900000-#907399 and a builder's code G120.1
(``workspace_wide_commons``)."""

from __future__ import annotations

from pathlib import Path

import pytest
from lsprotocol import types
from pygls import uris
from pytest_lsp import LanguageClient

from .lsp_session import diagnostics_for, hover_text, open_file, published_where, session_fixture

pytestmark = pytest.mark.asyncio(loop_scope="session")

HERE = Path(__file__).resolve().parent
TXT = HERE / "workspace_txt_programs"
WIDE = HERE / "workspace_wide_commons"
txt_en = session_fixture(TXT, "en")
wide_en = session_fixture(WIDE, "en")
wide_zh = session_fixture(WIDE, "zh-CN")


async def test_a_txt_subprogram_that_starts_with_its_o_number_is_the_callee(txt_en: LanguageClient) -> None:
    uri = open_file(txt_en, TXT / "MAIN.txt")
    diags = (await diagnostics_for(txt_en, uri, 1)).diagnostics
    assert [(d.range.start.line, d.code) for d in diags if d.severity is not None and d.severity <= 2] == []
    found = await txt_en.text_document_definition_async(
        types.DefinitionParams(types.TextDocumentIdentifier(uri), types.Position(3, 6))  # M98 P0810
    )
    targets = found if isinstance(found, list) else [found]
    assert [(Path(uris.to_fs_path(t.uri)).name, t.range.start.line) for t in targets if t is not None] == [
        ("O0810.txt", 0)
    ]


async def test_a_txt_file_of_plain_words_is_no_program_of_the_workspace(txt_en: LanguageClient) -> None:
    symbols = await txt_en.workspace_symbol_async(types.WorkspaceSymbolParams(query="O"))
    files = sorted({Path(uris.to_fs_path(s.location.uri)).name for s in symbols or [] if hasattr(s.location, "range")})
    assert files == ["MAIN.txt", "O0810.txt"]  # README.txt names O0810 but does not start as a program


NOTE_EN = (
    ".cncmacro.toml: common #900000-#907399: common variables of this machine beyond fanuc-30i's list "
    "(#100-#499, #500-#999, #98000-#98499)"
)
NOTE_ZH = (
    ".cncmacro.toml：common #900000-#907399：本机床在 fanuc-30i 所列范围（#100-#499、#500-#999、#98000-#98499）"
    "之外的公共变量"
)


@pytest.mark.parametrize(("locale", "text"), [("en", NOTE_EN), ("zh", NOTE_ZH)])
async def test_common_ranges_beyond_the_profile_are_noted_once_on_the_machine_file(
    wide_en: LanguageClient, wide_zh: LanguageClient, locale: str, text: str
) -> None:
    client = wide_zh if locale == "zh" else wide_en
    machine = (WIDE / ".cncmacro.toml").as_uri()
    shown = await published_where(client, {machine: bool})
    [note] = shown[machine]
    # the text cncmacro check prints after "note:", on the `common` line (0-based line 2)
    assert (note.code, note.severity, note.message) == ("machine-file-note", types.DiagnosticSeverity.Information, text)
    assert note.range.start.line == 2
    uri = open_file(client, WIDE / "O1000.nc")
    diags = (await diagnostics_for(client, uri, 1)).diagnostics
    assert [d.code for d in diags if d.severity is not None and d.severity <= 2] == []  # #900001 is a common here


@pytest.mark.parametrize(
    ("locale", "text"),
    [("en", "Pallet change position (machine builder's code)"), ("zh", "托盘交换位置（机床厂的代码）")],
)
async def test_a_builder_code_of_the_machine_file_hovers_with_its_text_in_the_editor_language(
    wide_en: LanguageClient, wide_zh: LanguageClient, locale: str, text: str
) -> None:
    client = wide_zh if locale == "zh" else wide_en
    uri = open_file(client, WIDE / "O1000.nc")
    said = await hover_text(client, uri, 1, 2)  # G120.1
    assert text in said
    other = "托盘交换位置" if locale == "en" else "Pallet change position"
    assert other not in said
