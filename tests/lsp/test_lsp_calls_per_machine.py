"""A call finds only a program of its own machine: a control holds the programs of its own
memory, and a file whose dialect comment names another control is another machine's program,
though it lies in the same folder (docs/editor.md, "Where a call finds its program"). The editor
(``program-not-found``, go to definition, the call hierarchy, where ``M99 P`` returns) and
``cncmacro check`` decide it by one rule, ``ProgramLibrary.on_machine``: the calling file and
the called file are read in the same profile. A file without a comment is read in its folder's
profile.

The workspace ``workspace_calls_per_machine`` (no machine file: its profile is fanuc-0i)::

    O1000.nc   fanuc-0i (unmarked)             M98 P1001 (1), M98 P2000 (2), M98 P2002 (3),
                                               M98 P3000 (4), N30 M30 (5)
    O1001.nc   (cncmacro: dialect=fanuc-0i)    #101=1, M99
    O2000.nc   (cncmacro: dialect=gsk980tdi)   M98 P2001 (1), M98 P2002 (2), M98 P3000 (3), N30 M30 (4)
    O2001.nc   fanuc-0i (unmarked)             #101=2, M99
    O2002.nc   (cncmacro: dialect=gsk980tdi)   #101=3, M99 P30 (2)
    LATHE.nc   (cncmacro: dialect=gsk980tdi)   O3000: #101=4, M99 (found by its header only)

Worked out by hand (lines 0-based), the FANUC machine being O1000, O1001 and O2001, the
GSK980TDi machine O2000, O2002 and LATHE.nc's O3000:

- O1000: P1001 is found (O1001 names the folder's profile); P2000, P2002 (files named for them)
  and P3000 (a header in LATHE.nc) are GSK980TDi programs: ``program-not-found`` on lines 2, 3, 4.
- O2000: P2001 is a FANUC file: ``program-not-found`` on line 1; P2002 and P3000 are found.
- O2002's callers are O2000 alone (line 2), so its ``M99 P30`` lands on O2000's N30 (line 4)
  only, not on O1000's N30 (line 5).
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

ROOT = Path(__file__).resolve().parent / "workspace_calls_per_machine"
calls_per_machine_en = session_fixture(ROOT, "en")


async def _codes(client: LanguageClient, path: Path) -> list[tuple[int, str]]:
    """The line and code of each error and warning the editor shows on ``path`` (opened, then closed)."""
    uri = open_file(client, path)
    diags = (await diagnostics_for(client, uri, 1)).diagnostics
    close_file(client, uri)
    return sorted((d.range.start.line, str(d.code)) for d in diags if d.severity is not None and d.severity <= 2)


def _checked() -> dict[str, list[tuple[int, str]]]:
    """The same, as ``cncmacro check`` of the whole folder finds them, by file name."""
    out, err = io.StringIO(), io.StringIO()
    check_paths([str(ROOT)], out, err, "json")
    found: dict[str, list[tuple[int, str]]] = {}
    for d in json.loads(out.getvalue()):
        found.setdefault(Path(d["file"]).name, []).append((d["line"] - 1, d["code"]))
    return {name: sorted(codes) for name, codes in found.items()}


async def test_check_finds_only_the_programs_of_the_calling_files_machine() -> None:
    assert _checked() == {
        "O1000.nc": [(2, "program-not-found"), (3, "program-not-found"), (4, "program-not-found")],
        "O2000.nc": [(1, "program-not-found")],
    }


async def test_check_says_the_file_named_for_the_program_is_another_machines() -> None:
    out, err = io.StringIO(), io.StringIO()
    check_paths([str(ROOT / "O1000.nc")], out, err, "json")
    [message] = [d["message"] for d in json.loads(out.getvalue()) if d["line"] == 3]
    assert "O2000.nc is a GSK980TDi program, another machine's" in message


async def test_a_fanuc_call_does_not_find_a_gsk980tdi_program_beside_it(calls_per_machine_en: LanguageClient) -> None:
    expected = [(2, "program-not-found"), (3, "program-not-found"), (4, "program-not-found")]
    assert await _codes(calls_per_machine_en, ROOT / "O1000.nc") == expected


async def test_a_gsk980tdi_call_finds_its_own_machines_programs_only(calls_per_machine_en: LanguageClient) -> None:
    assert await _codes(calls_per_machine_en, ROOT / "O2000.nc") == [(1, "program-not-found")]


async def _definition(client: LanguageClient, path: Path, line: int, ch: int) -> list[tuple[str, int]]:
    uri = open_file(client, path)
    found = await client.text_document_definition_async(
        types.DefinitionParams(types.TextDocumentIdentifier(uri), types.Position(line, ch))
    )
    close_file(client, uri)
    if found is None:
        return []
    items = found if isinstance(found, list) else [found]
    return sorted((f.uri.rsplit("/", 1)[-1], f.range.start.line) for f in items if isinstance(f, types.Location))


async def test_definition_of_a_call_to_another_machines_program_goes_nowhere(
    calls_per_machine_en: LanguageClient,
) -> None:
    assert await _definition(calls_per_machine_en, ROOT / "O1000.nc", 2, 5) == []  # M98 P2000
    assert await _definition(calls_per_machine_en, ROOT / "O2000.nc", 2, 5) == [("O2002.nc", 0)]  # M98 P2002
    assert await _definition(calls_per_machine_en, ROOT / "O2000.nc", 3, 5) == [("LATHE.nc", 0)]  # M98 P3000


async def test_m99_p_returns_to_the_callers_of_its_own_machine(calls_per_machine_en: LanguageClient) -> None:
    # M99 P30 in O2002 (line 2, its 30 at column 5): O2000's N30 (line 4), not O1000's (line 5)
    assert await _definition(calls_per_machine_en, ROOT / "O2002.nc", 2, 5) == [("O2000.nc", 4)]


async def test_incoming_calls_of_a_gsk980tdi_program_leave_the_fanuc_caller_out(
    calls_per_machine_en: LanguageClient,
) -> None:
    uri = open_file(calls_per_machine_en, ROOT / "O2002.nc")
    prepared = await calls_per_machine_en.text_document_prepare_call_hierarchy_async(
        types.CallHierarchyPrepareParams(types.TextDocumentIdentifier(uri), types.Position(0, 2))
    )
    assert prepared is not None
    incoming = await calls_per_machine_en.call_hierarchy_incoming_calls_async(
        types.CallHierarchyIncomingCallsParams(prepared[0])
    )
    close_file(calls_per_machine_en, uri)
    assert incoming is not None
    callers = [(c.from_.uri.rsplit("/", 1)[-1], [r.start.line for r in c.from_ranges]) for c in incoming]
    assert callers == [("O2000.nc", [2])]
