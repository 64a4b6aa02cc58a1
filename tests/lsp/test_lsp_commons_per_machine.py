"""Commons and system variables are one memory per machine, not per folder: hover's "written
at" and find-references on ``#100`` list the files of the same machine only, that is the files
read with the same machine file in the same profile (docs/editor.md, "Navigation"). A file whose
dialect comment names another control, or a folder with its own machine file, is another machine.

The workspace ``workspace_mixed_controls`` (no machine file at its top)::

    O1000.nc              fanuc-0i (the default)         #100=1 (line 2), #500=2 (line 3), M98 P1001
    O1001.nc              (cncmacro: dialect=fanuc-0i)   #100=#100+1 (line 2), #500=#500+#100 (line 3)
    O2000.nc              (cncmacro: dialect=gsk980tdi)  #100=5 (line 2), #500=6 (line 3)
    lathe/.cncmacro.toml  base = "gsk980tdi"
    lathe/O3000.nc        gsk980tdi by its machine file   #100=7 (line 2), #500=8 (line 3)

O1000 and O1001 are one FANUC machine (the one unmarked, the other naming the same profile):
they share #100 (a caller and its subprogram) and #500. O2000 is a GSK980TDi in the same folder,
O3000 a GSK980TDi under its own machine file: each is a machine of its own.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import close_file, hover_text, open_file, session_fixture

pytestmark = pytest.mark.asyncio(loop_scope="session")

ROOT = Path(__file__).resolve().parent / "workspace_mixed_controls"
mixed_en = session_fixture(ROOT, "en")


async def _references(client: LanguageClient, path: Path, line: int, ch: int) -> list[tuple[str, int, int]]:
    """(file relative to the workspace, line, column) of every reference, the writes too."""
    uri = open_file(client, path)
    result = await client.text_document_references_async(
        types.ReferenceParams(
            text_document=types.TextDocumentIdentifier(uri),
            position=types.Position(line, ch),
            context=types.ReferenceContext(include_declaration=True),
        )
    )
    close_file(client, uri)
    assert result is not None
    root = ROOT.as_uri() + "/"
    return sorted((r.uri.removeprefix(root), r.range.start.line, r.range.start.character) for r in result)


async def _hover(client: LanguageClient, path: Path, line: int, ch: int) -> str:
    uri = open_file(client, path)
    text = await hover_text(client, uri, line, ch)
    close_file(client, uri)
    return text


async def test_references_of_a_common_stay_on_one_fanuc_machine(mixed_en: LanguageClient) -> None:
    # #100 in O1000 (line 1, 0-based): O1000 writes it at 1:0; O1001 writes it at 1:0 and reads it
    # at 1:5 and 2:10 (#500=#500+#100: '#500=' 5 characters, '#500+' 5 more); O2000's and O3000's
    # #100 are other machines'
    assert await _references(mixed_en, ROOT / "O1000.nc", 1, 1) == [
        ("O1000.nc", 1, 0),
        ("O1001.nc", 1, 0),
        ("O1001.nc", 1, 5),
        ("O1001.nc", 2, 10),
    ]
    # #500 from the subprogram: O1000's write (2:0), O1001's write (2:0) and read (2:5)
    assert await _references(mixed_en, ROOT / "O1001.nc", 2, 1) == [
        ("O1000.nc", 2, 0),
        ("O1001.nc", 2, 0),
        ("O1001.nc", 2, 5),
    ]


async def test_references_of_a_common_in_a_gsk_file_leave_the_fanuc_files_out(mixed_en: LanguageClient) -> None:
    # O2000 (GSK980TDi by its comment) shares its folder with two FANUC files and nothing else
    # of its machine: its #100 and #500 are its own
    assert await _references(mixed_en, ROOT / "O2000.nc", 1, 1) == [("O2000.nc", 1, 0)]
    assert await _references(mixed_en, ROOT / "O2000.nc", 2, 1) == [("O2000.nc", 2, 0)]
    # O3000 is a GSK980TDi too, but read with lathe/.cncmacro.toml: another machine than O2000
    assert await _references(mixed_en, ROOT / "lathe" / "O3000.nc", 2, 1) == [("lathe/O3000.nc", 2, 0)]


async def test_hover_written_at_lists_the_files_of_the_same_machine_only(mixed_en: LanguageClient) -> None:
    fanuc = await _hover(mixed_en, ROOT / "O1000.nc", 1, 1)  # #100: lines 2 of O1000 and O1001 (1-based)
    assert "O1000.nc:2" in fanuc and "O1001.nc:2" in fanuc
    assert "O2000.nc" not in fanuc and "O3000.nc" not in fanuc
    gsk = await _hover(mixed_en, ROOT / "O2000.nc", 2, 1)  # #500: line 3 of O2000 only
    assert "O2000.nc:3" in gsk
    assert "O1000.nc" not in gsk and "O1001.nc" not in gsk and "O3000.nc" not in gsk
