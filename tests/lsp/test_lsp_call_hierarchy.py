"""Call hierarchy, end to end: a program's callers and callees across the workspace, by every
kind of call (``G65``, the modal ``G66``, ``M98``, ``M198``, the machine file's call codes ``G100`` and ``M60``), and
Haas's local ``M97 P`` call of a label of the program itself."""

from __future__ import annotations

from pathlib import Path

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, close_file, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")

CALLS = Path(__file__).resolve().parent / "workspace_calls"
HAAS = Path(__file__).resolve().parent / "workspace_haas"


async def _prepare(client: LanguageClient, uri: str, line: int, ch: int) -> list[types.CallHierarchyItem]:
    result = await client.text_document_prepare_call_hierarchy_async(
        types.CallHierarchyPrepareParams(types.TextDocumentIdentifier(uri), types.Position(line, ch))
    )
    assert result is not None
    return result


def _where(item: types.CallHierarchyItem) -> tuple[str, str, int]:
    return item.name, item.uri.rsplit("/", 1)[-1], item.selection_range.start.line


async def test_outgoing_calls_of_a_program_name_every_kind_of_call(calls_en: LanguageClient) -> None:
    uri = open_file(calls_en, CALLS / "MAIN.nc")
    [main] = await _prepare(calls_en, uri, 4, 0)  # M30: the program the cursor is in
    out = await calls_en.call_hierarchy_outgoing_calls_async(types.CallHierarchyOutgoingCallsParams(main))
    close_file(calls_en, uri)
    assert _where(main) == ("O0001", "MAIN.nc", 0) and main.detail == "CALLS THE MACROS"
    assert out is not None
    calls = sorted((_where(c.to), [r.start.line for r in c.from_ranges]) for c in out)
    assert calls == [(("O9010", "O9010.nc", 0), [1, 2]), (("O9020", "O9020.nc", 0), [3])]


async def test_incoming_calls_of_a_macro_come_from_every_file_that_calls_it(calls_en: LanguageClient) -> None:
    uri = open_file(calls_en, CALLS / "MAIN.nc")
    [callee] = await _prepare(calls_en, uri, 1, 7)  # M198 P9010: the program it calls
    incoming = await calls_en.call_hierarchy_incoming_calls_async(types.CallHierarchyIncomingCallsParams(callee))
    close_file(calls_en, uri)
    assert _where(callee) == ("O9010", "O9010.nc", 0)
    assert incoming is not None
    assert [(_where(c.from_), [(r.start.line, r.start.character) for r in c.from_ranges]) for c in incoming] == [
        (("O0001", "MAIN.nc", 0), [(1, 5), (2, 0)])
    ]


async def test_g65_and_m98_callers_across_files(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "O9100.nc")
    [macro] = await _prepare(fanuc_en, uri, 0, 2)
    incoming = await fanuc_en.call_hierarchy_incoming_calls_async(types.CallHierarchyIncomingCallsParams(macro))
    close_file(fanuc_en, uri)
    assert incoming is not None
    [(caller, lines)] = [(_where(c.from_), [r.start.line for r in c.from_ranges]) for c in incoming]
    assert caller == ("O0001", "MAIN.nc", 0) and lines == [2, 11, 13]


async def test_a_haas_m97_call_enters_a_label_of_its_own_program(haas_en: LanguageClient) -> None:
    text = "O1000 (LOCAL CALLS)\nM97 P100\nM97 P100\nM30\nN100 #1=#1+1\nM99\n"
    uri = open_file(haas_en, HAAS / "LOCAL.nc", text)
    [label] = await _prepare(haas_en, uri, 1, 6)
    incoming = await haas_en.call_hierarchy_incoming_calls_async(types.CallHierarchyIncomingCallsParams(label))
    [main] = await _prepare(haas_en, uri, 3, 0)
    out = await haas_en.call_hierarchy_outgoing_calls_async(types.CallHierarchyOutgoingCallsParams(main))
    close_file(haas_en, uri)
    assert _where(label) == ("N100 (O1000)", "LOCAL.nc", 4) and label.kind == types.SymbolKind.Method
    assert incoming is not None and [[r.start.line for r in c.from_ranges] for c in incoming] == [[1, 2]]
    assert out is not None and [(_where(c.to), len(c.from_ranges)) for c in out] == [
        (("N100 (O1000)", "LOCAL.nc", 4), 2)
    ]


async def test_a_g66_modal_call_is_a_call_of_its_program(fanuc_en: LanguageClient) -> None:
    """``G66 P9100`` calls O9100 after each move until ``G67``: one call, on the G66 line."""
    text = "O0005 (MODAL)\nG66 P9100 X10. Z-2.\nX20.\nX30.\nG67\nM30\n"
    uri = open_file(fanuc_en, FANUC / "MODAL.nc", text)
    [callee] = await _prepare(fanuc_en, uri, 1, 6)  # the P9100 of G66
    [main] = await _prepare(fanuc_en, uri, 5, 0)  # M30: the program the cursor is in
    out = await fanuc_en.call_hierarchy_outgoing_calls_async(types.CallHierarchyOutgoingCallsParams(main))
    incoming = await fanuc_en.call_hierarchy_incoming_calls_async(types.CallHierarchyIncomingCallsParams(callee))
    close_file(fanuc_en, uri)
    assert _where(callee) == ("O9100", "O9100.nc", 0)
    assert out is not None
    assert [(_where(c.to), [(r.start.line, r.start.character) for r in c.from_ranges]) for c in out] == [
        (("O9100", "O9100.nc", 0), [(1, 4)])
    ]
    assert incoming is not None
    callers = sorted((_where(c.from_), [r.start.line for r in c.from_ranges]) for c in incoming)
    assert callers == [(("O0001", "MAIN.nc", 0), [2, 11, 13]), (("O0005", "MODAL.nc", 0), [1])]
