"""The machine file through the language server (docs/profiles.md "The machine file"): the
workspace ``tests/data/machine_workspace`` narrows the commons, keeps O9000-O9999 on the control,
reads M98 P with 6-digit program numbers, adds a builder's system variable and pallet code
(``[codes]``) and keeps subprograms as ``.txt`` files (``extensions``); and the client
learns the profiles from ``cncmacro/profiles``."""

from __future__ import annotations

from pathlib import Path

import pytest
from lsprotocol import types
from pygls import uris
from pytest_lsp import LanguageClient

from cncmacro.dialects import DIALECTS

from .lsp_session import diagnostics_for, hover_text, open_file, session_fixture

pytestmark = pytest.mark.asyncio(loop_scope="session")

SHOP = Path(__file__).resolve().parent.parent / "data" / "machine_workspace"
shop = session_fixture(SHOP, "en")


async def test_profiles_request_lists_every_profile_with_its_facts(shop: LanguageClient) -> None:
    answer = await shop.protocol.send_request_async("cncmacro/profiles", {})
    assert [p["name"] for p in answer] == list(DIALECTS)
    lathe = {p["name"]: p["lathe"] for p in answer}
    assert lathe["gsk980tdi"] is True and lathe["fanuc-30i"] is False
    assert "fanuc" in next(p for p in answer if p["name"] == "fanuc-0i")["aliases"]


async def test_machine_file_program_on_the_control_and_six_digit_m98_are_clean(shop: LanguageClient) -> None:
    uri = open_file(shop, SHOP / "O1000.nc")
    diags = (await diagnostics_for(shop, uri, 1)).diagnostics
    assert [d.code for d in diags if d.severity is not None and d.severity <= 2] == []
    said = await hover_text(shop, uri, 4, 6)  # G65 P9810
    assert "O9810" in said and "kept on the control" in said
    said = await hover_text(shop, uri, 2, 7)  # #1100
    assert "Pallet clamped (PMC signal from the machine builder)" in said
    dialect = await shop.protocol.send_request_async("cncmacro/documentDialect", {"uri": uri})
    assert (dialect.dialect, dialect.source, dialect.lathe) == ("fanuc-0i", "workspace", False)


async def test_machine_file_commons_the_machine_lacks_are_errors(shop: LanguageClient) -> None:
    uri = open_file(shop, SHOP / "O1001.nc")
    diags = (await diagnostics_for(shop, uri, 1)).diagnostics
    found = sorted((d.range.start.line, d.code) for d in diags if d.severity == 1)
    assert found == [(2, "variable-number"), (3, "program-not-found")]
    [missing] = [d for d in diags if d.code == "variable-number"]
    assert "#100-#199, #500-#999" in missing.message


async def test_machine_file_builder_code_hovers_and_txt_subprogram_is_found(shop: LanguageClient) -> None:
    uri = open_file(shop, SHOP / "O1002.nc")
    diags = (await diagnostics_for(shop, uri, 1)).diagnostics
    assert [(d.range.start.line, d.code) for d in diags if d.severity is not None and d.severity <= 2] == []
    said = await hover_text(shop, uri, 2, 2)  # G120.1
    assert "Pallet change position (machine builder's code)" in said
    found = await shop.text_document_definition_async(
        types.DefinitionParams(types.TextDocumentIdentifier(uri), types.Position(3, 5))  # M98 P1004
    )
    targets = found if isinstance(found, list) else [found]
    assert [Path(uris.to_fs_path(t.uri)).name for t in targets if t is not None] == ["1004.txt"]
