"""10,000 edits in a row leave the language server's memory flat (a leak test): the documents,
the analysis and its runs, the published results and the scheduled tasks all keep only what
the current version needs. The edits type and delete on a few lines, through the server's own
notification handlers, with the analysis running every 50 edits as it would between bursts
of typing; the memory Python holds after 2,000 edits and after 10,000 must agree. The table of
interned strings, which grows in steps for the whole process, is left out of the count."""

from __future__ import annotations

import asyncio
import gc
import tracemalloc

from lsprotocol import types

from fuzzing import LspTarget

EDITS = 10_000
WARM_UP = 2_000
SETTLE_EVERY = 50
ALLOWED_GROWTH = 256_000  # bytes between the warm-up and the end: 32 bytes an edit
NOT_COUNTED = [
    tracemalloc.Filter(False, "*pathlib.py"),
    tracemalloc.Filter(False, "<frozen importlib._bootstrap*>"),
    tracemalloc.Filter(False, tracemalloc.__file__),  # the first snapshot itself
]
PROGRAM = "\n".join(
    ["O0001 (STORM)", "#100=0", "WHILE[#100 LT 20]DO1", "G01 X#100 Y[#100*2] F300", "#100=#100+1", "END1"]
    + [f"N{k} G01 X{k}.5 Y-{k}.25" for k in range(1, 40)]
    + ["G65 P9100 A1", "M30", "O9100", "#101=#1*2", "M99"]
)
TYPED = ["", "#", "#1", "#10", "#102", "#102=", "#102=[", "#102=[#1", "#102=[#100", "#102=[#100+1]"]


def _change(uri: str, version: int, line: int, text: str) -> types.DidChangeTextDocumentParams:
    return types.DidChangeTextDocumentParams(
        text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=version),
        content_changes=[
            types.TextDocumentContentChangePartial(
                range=types.Range(types.Position(line, 0), types.Position(line, 1000)), text=text
            )
        ],
    )


def test_10000_edits_in_a_row_keep_the_servers_memory_flat() -> None:
    target = LspTarget()
    uri = "file:///storm/O0001.nc"
    change = target.features[types.TEXT_DOCUMENT_DID_CHANGE]
    hover = target.features[types.TEXT_DOCUMENT_HOVER]
    samples: dict[int, tracemalloc.Snapshot] = {}

    async def storm() -> None:
        item = types.TextDocumentItem(uri=uri, language_id="cncmacro", version=1, text=PROGRAM)
        target.features[types.TEXT_DOCUMENT_DID_OPEN](types.DidOpenTextDocumentParams(text_document=item))
        for v in range(2, EDITS + 2):
            line = 7 + (v // len(TYPED)) % 3  # typing on three lines in turn
            change(_change(uri, v, line, TYPED[v % len(TYPED)]))
            if v % SETTLE_EVERY == 0:
                await target._settle()
                hover(types.HoverParams(text_document=types.TextDocumentIdentifier(uri), position=types.Position(1, 1)))
                target.published.clear()
            if v in (WARM_UP, EDITS):
                await target._settle()
                gc.collect()
                samples[v] = tracemalloc.take_snapshot().filter_traces(NOT_COUNTED)

    tracemalloc.start()
    try:
        target.loop.run_until_complete(storm())
    finally:
        tracemalloc.stop()
        target.close()
    growth = sum(stat.size_diff for stat in samples[EDITS].compare_to(samples[WARM_UP], "filename"))
    assert growth < ALLOWED_GROWTH, f"memory grew by {growth} bytes from edit {WARM_UP} to edit {EDITS}"
    doc_version = target.server.documents.get(uri).version
    assert doc_version == EDITS + 1
    asyncio.set_event_loop(None)
