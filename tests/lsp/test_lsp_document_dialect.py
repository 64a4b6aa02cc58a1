"""The dialect each open document is read in, and what decided it (docs/design.md "Dialect
selection": the file's comment, the workspace's ``.cncmacro.toml``, the editor setting, fanuc),
asked for by the editor's status bar with ``cncmacro/documentDialect``."""

from __future__ import annotations

import pytest
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, diagnostics_for, edit, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")


async def dialect_of(client: LanguageClient, uri: str) -> object:
    return await client.protocol.send_request_async("cncmacro/documentDialect", {"uri": uri})


async def test_a_file_comment_decides_over_the_setting_and_an_edit_of_it_is_seen(fanuc_en: LanguageClient) -> None:
    marked = open_file(fanuc_en, FANUC / "lathe.nc", "(cncmacro: dialect=gsk980tdi)\nO0001\nG00 X10 Z2\nM30\n")
    plain = open_file(fanuc_en, FANUC / "mill.nc", "O0002\nG00 X10 Y2\nM30\n")
    await diagnostics_for(fanuc_en, marked, 1)
    answer = await dialect_of(fanuc_en, marked)
    assert (answer.dialect, answer.title, answer.source) == ("gsk980tdi", "GSK980TDi", "file")
    answer = await dialect_of(fanuc_en, plain)
    assert (answer.dialect, answer.source) == ("fanuc-0i", "default")
    edit(fanuc_en, marked, 2, 0, 0, 30, "(LATHE PART)")  # the comment goes: the chain goes on
    await diagnostics_for(fanuc_en, marked, 2)
    assert (await dialect_of(fanuc_en, marked)).source == "default"


async def test_a_document_that_is_not_open_has_no_dialect(fanuc_en: LanguageClient) -> None:
    assert await dialect_of(fanuc_en, (FANUC / "never_opened.nc").as_uri()) is None
