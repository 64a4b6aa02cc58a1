"""After any sequence of edits, the incrementally kept document equals a fresh parse.

docs/design.md "How the analysis stays incremental": an edit re-parses only its own lines and the
cross-line structure (units, labels, loops) is patched or rebuilt; this must never differ
from parsing the final text from scratch.
"""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from cncmacro.syntax.block_parser import BlockCache
from cncmacro.syntax.document import ParsedDocument
from cncmacro.syntax.program import build_program
from strategies import line

POOL = [
    "O1000 (MAIN)",
    "N10 G00 X0 Y0",
    "WHILE[#1 LT 3]DO1",
    "END1",
    "DO2",
    "END2",
    "N20 #1=#1+1",
    "IF[#1 LT 3]GOTO10",
    "IF[#1 LT 3]THEN",
    "ELSE",
    "ENDIF",
    "%",
    "O2000",
    "M99",
    "G01 X10. F100",
    "N10 M30",
    "(COMMENT)",
    "",
    "#100=5",
    "\x1a",
]

pool_line = st.one_of(st.sampled_from(POOL), line())


@st.composite
def edit(draw, n_lines: int):
    start_line = draw(st.integers(0, n_lines - 1))
    end_line = draw(st.integers(start_line, min(n_lines - 1, start_line + 3)))
    start_col = draw(st.integers(0, 12))
    end_col = draw(st.integers(0, 12))
    text = "\n".join(draw(st.lists(pool_line, min_size=0, max_size=3)))
    if draw(st.booleans()):
        text = text[: draw(st.integers(0, max(0, len(text))))]
    return start_line, start_col, end_line, end_col, text


@settings(max_examples=300, deadline=None)
@given(st.lists(pool_line, min_size=1, max_size=25), st.data())
def test_edits_equal_full_parse(lines, data):
    doc = ParsedDocument("\n".join(lines), BlockCache())
    for _ in range(data.draw(st.integers(1, 8))):
        doc.apply_change(*data.draw(edit(len(doc.lines))))
        fresh = ParsedDocument(doc.text, BlockCache())
        assert doc.lines == fresh.lines
        assert doc.blocks == fresh.blocks
        assert doc.program == fresh.program
        assert doc.program == build_program(doc.blocks)


@settings(max_examples=300, deadline=None)
@given(st.lists(pool_line, min_size=1, max_size=25), st.integers(1, 6), st.data())
def test_a_document_read_in_steps_and_edited_meanwhile_equals_a_full_parse(lines, step, data):
    """A huge file is parsed a step at a time while the editor goes on: edits that come
    between the steps change its text and the lines parsed so far; once read, it is the
    document its final text gives, and any line asked for meanwhile is that line's block."""
    doc = ParsedDocument("\n".join(lines), BlockCache(), in_steps=step)
    while True:
        for _ in range(data.draw(st.integers(0, 2))):
            doc.apply_change(*data.draw(edit(len(doc.lines))))
        fresh = ParsedDocument(doc.text, BlockCache())
        assert [doc.block_at(i) for i in range(len(doc.lines))] == fresh.blocks
        if doc.parse_more(step):
            break
    fresh = ParsedDocument(doc.text, BlockCache())
    assert not doc.partial
    assert doc.lines == fresh.lines and doc.blocks == fresh.blocks
    assert doc.program == fresh.program
    doc.apply_change(*data.draw(edit(len(doc.lines))))  # and it is edited as any other
    assert doc.program == ParsedDocument(doc.text, BlockCache()).program


def test_one_line_edit_parses_one_line():
    cache = BlockCache()
    # lines that take parsing (a variable in each): plain words, labelled or not, are made
    # afresh as cheaply as they are looked up, and are not cached
    doc = ParsedDocument("\n".join(f"N{i} G01 X{i}.5 Y#{i % 30 + 1}" for i in range(1, 2001)), cache)
    before = cache.parsed
    doc.apply_change(1000, 0, 1000, 0, "#1=#1+2\n")
    doc.apply_change(500, 5, 500, 7, "X9")
    assert cache.parsed - before == 2  # the inserted line and the edited one; the rest is cached
    assert doc.program.labels[1001] == [1001]


def test_edit_positions_past_the_end_are_clamped():
    doc = ParsedDocument("G00 X0\nG01 X1")
    doc.apply_change(5, 99, 9, 99, "\nM30")
    assert doc.lines == ["G00 X0", "G01 X1", "M30"]


def test_text_typed_above_a_leading_percent_makes_it_the_end_of_the_tape():
    """docs/semantics.md §1: a '%' before any program text starts the tape, one after text ends it;
    a one-line edit that changes nothing else must still move the end."""
    doc = ParsedDocument("\n%\nO1\n#1=1\n%\nJUNK\n", BlockCache())
    assert doc.program.tape_end == 4
    doc.apply_change(0, 0, 0, 0, "G00 X0")
    assert doc.program.tape_end == 1 == build_program(doc.blocks).tape_end
    doc.apply_change(0, 0, 0, 6, "")
    assert doc.program.tape_end == 4 == build_program(doc.blocks).tape_end
