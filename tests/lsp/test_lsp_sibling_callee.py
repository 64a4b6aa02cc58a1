"""A call finds its program in any folder of the same machine, in the editor as in
``cncmacro check`` (``library/callee_folders.py``, docs/editor.md): the control holds all its
programs in one memory, so ``G65 P5100`` in ``main/O1000.nc`` runs ``macros/O5100.nc``. The
sub-folder ``lathe`` has its own machine file (gsk980tdi): it is another machine, whose programs
a call from outside it does not find, nor does a call from inside it find the mill's.

The workspace ``workspace_sibling_folders``::

    .cncmacro.toml          fanuc-0i
    main/O1000.nc           G65 P5100 A1.   (O5100 is in macros/)
    main/O1001.nc           G65 P5200 A1.   (O5200 is only in lathe/)
    macros/O5100.nc
    lathe/.cncmacro.toml    gsk980tdi
    lathe/O2000.nc          G65 P5100 A1.   (O5100 is the mill's)
    lathe/O5200.nc
"""

from __future__ import annotations

import io
import json
from pathlib import Path

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from cncmacro.cli.check import check_paths

from .lsp_session import close_file, diagnostics_for, open_file, session_fixture

pytestmark = pytest.mark.asyncio(loop_scope="session")

ROOT = Path(__file__).resolve().parent / "workspace_sibling_folders"
sibling_en = session_fixture(ROOT, "en")


async def _codes(client: LanguageClient, path: Path) -> list[tuple[int, str]]:
    """The line and code of each error and warning the editor shows on ``path`` (opened, then closed)."""
    uri = open_file(client, path)
    diags = (await diagnostics_for(client, uri, 1)).diagnostics
    close_file(client, uri)
    return sorted((d.range.start.line, str(d.code)) for d in diags if d.severity is not None and d.severity <= 2)


def _checked(path: Path) -> list[tuple[int, str]]:
    """The same, as ``cncmacro check`` of the whole workspace finds them."""
    out, err = io.StringIO(), io.StringIO()
    check_paths([str(ROOT)], out, err, "json")
    return sorted((d["line"] - 1, d["code"]) for d in json.loads(out.getvalue()) if d["file"] == str(path))


async def test_a_call_finds_its_program_in_a_sibling_folder_of_the_same_machine(sibling_en: LanguageClient) -> None:
    caller = ROOT / "main" / "O1000.nc"
    assert await _codes(sibling_en, caller) == [] == _checked(caller)


async def test_definition_of_p_lands_in_the_sibling_folder(sibling_en: LanguageClient) -> None:
    uri = open_file(sibling_en, ROOT / "main" / "O1000.nc")
    found = await sibling_en.text_document_definition_async(
        types.DefinitionParams(types.TextDocumentIdentifier(uri), types.Position(1, 5))  # the P of G65 P5100
    )
    close_file(sibling_en, uri)
    assert isinstance(found, list) and len(found) == 1
    assert found[0].uri == (ROOT / "macros" / "O5100.nc").as_uri() and found[0].range.start.line == 0


async def test_a_folder_with_its_own_machine_file_is_not_searched_from_outside(sibling_en: LanguageClient) -> None:
    caller = ROOT / "main" / "O1001.nc"  # G65 P5200: O5200 is only in lathe/, another machine
    assert await _codes(sibling_en, caller) == [(1, "program-not-found")] == _checked(caller)


async def test_a_folder_with_its_own_machine_file_does_not_find_the_programs_outside(
    sibling_en: LanguageClient,
) -> None:
    caller = ROOT / "lathe" / "O2000.nc"  # G65 P5100: O5100 is the mill's, in macros/
    assert await _codes(sibling_en, caller) == [(1, "program-not-found")] == _checked(caller)
