"""Document highlight, end to end: the cursor on a variable marks its writes and reads in the
file (a local only within its O program), on an N label or a jump the label and every jump to
it, on an O header or a call's program the header and every call to that program; elsewhere
nothing is marked."""

from __future__ import annotations

import pytest
from lsprotocol import types
from pytest_lsp import LanguageClient

from .lsp_session import FANUC, close_file, open_file

pytestmark = pytest.mark.asyncio(loop_scope="session")

READ, WRITE = types.DocumentHighlightKind.Read, types.DocumentHighlightKind.Write

TWO_PROGRAMS = """O0001
#1=5
#100=#1*2
M98 P0002
M30
O0002
#1=#100+1
#100=#1
M99
"""

CALLS = """O0001
G65 P9100 X10.
G66 P9100 Z-2.
X5.
G67
M98 P9100
M98 P30040
M98 P0040
M30
O9100
#1=#24
M99
O0040
M99
"""


async def _highlights(
    client: LanguageClient, uri: str, line: int, ch: int
) -> list[tuple[int, int, int, types.DocumentHighlightKind | None]] | None:
    result = await client.text_document_document_highlight_async(
        types.DocumentHighlightParams(types.TextDocumentIdentifier(uri), types.Position(line, ch))
    )
    if result is None:
        return None
    assert all(h.range.start.line == h.range.end.line for h in result)
    return [(h.range.start.line, h.range.start.character, h.range.end.character, h.kind) for h in result]


async def test_a_variable_marks_its_write_and_its_reads(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "MAIN.nc")
    on_read = await _highlights(fanuc_en, uri, 4, 5)  # IF[#101 LT #100]
    on_write = await _highlights(fanuc_en, uri, 3, 5)  # N10 #101=#101+1
    close_file(fanuc_en, uri)
    assert on_read == on_write == [(3, 4, 8, WRITE), (3, 9, 13, READ), (4, 3, 7, READ)]


async def test_a_label_marks_itself_and_the_jumps_to_it(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "MAIN.nc")
    on_jump = await _highlights(fanuc_en, uri, 4, 22)  # GOTO10
    on_label = await _highlights(fanuc_en, uri, 3, 1)  # N10
    close_file(fanuc_en, uri)
    assert on_jump == on_label == [(3, 0, 3, WRITE), (4, 21, 23, READ)]


async def test_a_local_is_marked_in_its_own_program_a_common_in_the_whole_file(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "TWO.nc", TWO_PROGRAMS)
    local = await _highlights(fanuc_en, uri, 1, 1)  # #1 of O0001
    common = await _highlights(fanuc_en, uri, 2, 1)  # #100
    close_file(fanuc_en, uri)
    assert local == [(1, 0, 2, WRITE), (2, 5, 7, READ)]
    assert common == [(2, 0, 4, WRITE), (6, 3, 7, READ), (7, 0, 4, WRITE)]


async def test_nothing_is_marked_on_a_code(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "MAIN.nc")
    result = await _highlights(fanuc_en, uri, 14, 1)  # M30
    close_file(fanuc_en, uri)
    assert not result


async def test_a_program_header_marks_itself_and_every_call_to_it(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "CALLS.nc", CALLS)
    on_header = await _highlights(fanuc_en, uri, 9, 2)  # O9100
    close_file(fanuc_en, uri)
    assert on_header == [(1, 4, 9, READ), (2, 4, 9, READ), (5, 4, 9, READ), (9, 0, 5, WRITE)]


async def test_a_call_marks_the_program_it_names_and_the_other_calls_to_it(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "CALLS.nc", CALLS)
    on_g65 = await _highlights(fanuc_en, uri, 1, 6)  # G65 P9100
    on_g66 = await _highlights(fanuc_en, uri, 2, 6)  # G66 P9100 (a modal call)
    on_m98 = await _highlights(fanuc_en, uri, 5, 6)  # M98 P9100
    close_file(fanuc_en, uri)
    assert on_g65 == on_g66 == on_m98 == [(1, 4, 9, READ), (2, 4, 9, READ), (5, 4, 9, READ), (9, 0, 5, WRITE)]


async def test_an_m98_p_with_a_count_marks_the_program_of_its_last_four_digits(fanuc_en: LanguageClient) -> None:
    """``M98 P30040`` calls O0040 three times (fanuc-0i: the last four digits name the program)."""
    uri = open_file(fanuc_en, FANUC / "CALLS.nc", CALLS)
    on_count = await _highlights(fanuc_en, uri, 6, 6)  # M98 P30040
    on_header = await _highlights(fanuc_en, uri, 12, 2)  # O0040
    close_file(fanuc_en, uri)
    assert on_count == on_header == [(6, 4, 10, READ), (7, 4, 9, READ), (12, 0, 5, WRITE)]


async def test_nothing_is_marked_on_a_call_argument_or_a_code_of_no_call(fanuc_en: LanguageClient) -> None:
    uri = open_file(fanuc_en, FANUC / "CALLS.nc", CALLS)
    on_argument = await _highlights(fanuc_en, uri, 1, 11)  # X10. of G65 P9100 X10.
    on_g67 = await _highlights(fanuc_en, uri, 4, 1)  # G67
    on_m30 = await _highlights(fanuc_en, uri, 8, 1)  # M30
    close_file(fanuc_en, uri)
    assert not on_argument and not on_g67 and not on_m30
