"""One parse per line text for the whole process: the files the workspace index reads and the
documents an editor opens share the block cache, and the grammar parsers are shared between the
editor's thread and the analysis thread."""

from __future__ import annotations

import threading

from cncmacro.library.programs import load_text
from cncmacro.syntax import block_parser
from cncmacro.syntax.block_parser import parse_block, shared_cache, warm_up
from cncmacro.syntax.document import ParsedDocument


def test_a_file_read_from_its_folder_is_not_parsed_again_when_opened():
    text = "\n".join(["O0123 (SHARED)", *[f"N{k} #{100 + k % 50}=[#1+{k}]*2" for k in range(1, 400)], "M30"])
    load_text("folder/O0123.nc", text)  # the workspace index reads the folder
    parsed = shared_cache.parsed
    doc = ParsedDocument(text)  # the editor opens the file
    assert shared_cache.parsed == parsed
    assert doc.program.units[0].number == 123 and len(doc.program.labels) == 399


def test_lines_that_need_the_grammar_parse_alike_on_several_threads_at_once():
    # DPRNT and unfinished lines are read by the grammar, not the fast path
    texts = [f"DPRNT[X#{k}[53]]" if k % 2 else f"N{k} #{k}=[#{k}+1" for k in range(1, 60)]
    expected = [parse_block(t) for t in texts]
    got: dict[int, list[object]] = {}

    def read(n: int) -> None:
        got[n] = [parse_block(t) for t in texts]

    threads = [threading.Thread(target=read, args=(n,)) for n in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(got[n] == expected for n in range(4))


def test_warm_up_leaves_a_grammar_parser_ready():
    with block_parser._idle_lock:
        block_parser._idle.clear()
    warm_up()
    assert len(block_parser._idle) == 1
    warm_up()  # one is enough
    assert len(block_parser._idle) == 1
    assert parse_block("#1=#[2]").problems == ()
