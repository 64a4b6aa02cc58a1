"""The index of macro lines of a document stays equal to a fresh one across random edits, so
hover, references and rename read the right lines after typing; an open document's is made ahead
of the first question."""

from __future__ import annotations

import asyncio
import random

from cncmacro.analysis.indexes.site_index import SiteIndex
from cncmacro.lsp.site_steps import index_soon
from cncmacro.syntax.document import ParsedDocument, split_lines

LINES = ["G01 X1. Y2.", "#100=#100+1", "N10 G00 X0", "IF[#1 GT 2] GOTO10", "M99 P10", "(NOTE)", "G65 H81 P10 Q#1 R0"]


def test_site_index_follows_random_edits() -> None:
    rnd = random.Random(3)
    doc = ParsedDocument("\n".join(rnd.choice(LINES) for _ in range(200)))
    index = SiteIndex(doc.blocks)
    for _ in range(300):
        n = len(doc.lines)
        sl = rnd.randrange(n)
        el = min(n - 1, sl + rnd.randrange(3))
        text = "\n".join(rnd.choice(LINES) for _ in range(rnd.randrange(3)))
        sc = rnd.randrange(len(doc.lines[sl]) + 1)
        ec = rnd.randrange(len(doc.lines[el]) + 1) if el > sl else max(sc, rnd.randrange(len(doc.lines[el]) + 1))
        doc.apply_change(sl, sc, el, ec, text)
        index.replaced(doc.blocks, sl, el + 1, len(split_lines(text)))
        assert index.lines == SiteIndex(doc.blocks).lines
    assert index.lines  # the edits left macro lines to index


def _answers(index: SiteIndex) -> tuple[object, ...]:
    """What hover, references and rename can ask of an index: every label's jumping lines
    and every variable's writing and mentioning lines."""
    labels = range(1, 40)
    numbers = (1, 2, 100, 101, 102, 103)
    return (
        {n: index.jumps_to(n) for n in labels if index.jumps_to(n)},
        {n: index.writes(n) for n in numbers if index.writes(n)},
        {n: index.mentions(n) for n in numbers if index.mentions(n)},
        [index.sites_at(i) for i in index.lines],
    )


def test_label_and_variable_maps_follow_random_edits() -> None:
    lines = [*LINES, "#101=#102*2", "N20 M99 P10", "GOTO20", "#102=#100", "X1. Y2."]
    rnd = random.Random(11)
    doc = ParsedDocument("\n".join(rnd.choice(lines) for _ in range(150)))
    index = SiteIndex(doc.blocks)
    assert _answers(index)  # the maps are made here, then kept up to date by the edits
    for _ in range(300):
        n = len(doc.lines)
        sl = rnd.randrange(n)
        el = min(n - 1, sl + rnd.randrange(4))
        text = "\n".join(rnd.choice(lines) for _ in range(rnd.randrange(4)))
        sc = rnd.randrange(len(doc.lines[sl]) + 1)
        ec = rnd.randrange(len(doc.lines[el]) + 1) if el > sl else max(sc, rnd.randrange(len(doc.lines[el]) + 1))
        doc.apply_change(sl, sc, el, ec, text)
        index.replaced(doc.blocks, sl, el + 1, len(split_lines(text)))
        assert _answers(index) == _answers(SiteIndex(doc.blocks))


def _edited(doc: ParsedDocument, index: SiteIndex, sl: int, sc: int, el: int, ec: int, text: str) -> None:
    doc.apply_change(sl, sc, el, ec, text)
    index.replaced(doc.blocks, sl, el + 1, len(split_lines(text)))


def test_lines_inserted_or_deleted_above_a_write_move_it() -> None:
    doc = ParsedDocument("O0001\n#100=1\nG01 X1.\n#101=#100\nM30")
    index = SiteIndex(doc.blocks)
    assert index.writes(101) == [3] and index.mentions(100) == [1, 3]
    _edited(doc, index, 1, 0, 1, 0, "G00 X0\nG00 Y0\n")  # two lines above both
    assert index.writes(101) == [5] and index.writes(100) == [3] and index.mentions(100) == [3, 5]
    _edited(doc, index, 0, 5, 4, 0, "\n")  # the two again, and #100=1 with them
    assert index.writes(100) == [] and index.writes(101) == [2] and index.mentions(100) == [2]


def test_a_write_changed_to_another_variable_moves_to_that_variable() -> None:
    doc = ParsedDocument("O0001\n#100=1\n#100=#100+1\nM30")
    index = SiteIndex(doc.blocks)
    assert index.writes(100) == [1, 2]
    _edited(doc, index, 1, 3, 1, 4, "5")  # #100=1 -> #105=1
    assert index.writes(100) == [2] and index.writes(105) == [1]
    assert index.mentions(100) == [2] and index.mentions(105) == [1]


def test_deleting_a_jump_or_its_label_line_updates_the_jumps_to_the_label() -> None:
    doc = ParsedDocument("O0001\nIF[#1 GT 2] GOTO10\nN10 GOTO 20\nGOTO10\nN20 M99 P10\nM30")
    index = SiteIndex(doc.blocks)
    assert index.jumps_to(10) == [1, 3, 4] and index.jumps_to(20) == [2]
    _edited(doc, index, 2, 0, 3, 0, "")  # the label line N10 (with its own jump to N20)
    assert index.jumps_to(10) == [1, 2, 3] and index.jumps_to(20) == []
    _edited(doc, index, 1, 0, 2, 0, "")  # IF .. GOTO10
    assert index.jumps_to(10) == [1, 2] and index.jumps_to(10, 2) == [2]


def test_an_index_made_in_steps_equals_a_fresh_one_across_edits_between_the_steps() -> None:
    """A huge document's index is made a few lines at a time while the user types: edits above,
    inside and below the part made so far all end in the index a fresh one has."""
    lines = [*LINES, "#101=#102*2", "N20 M99 P10", "GOTO20", "#102=#100", "X1. Y2."]
    rnd = random.Random(23)
    doc = ParsedDocument("\n".join(rnd.choice(lines) for _ in range(400)))
    index = SiteIndex(doc.blocks)
    steps = 0
    while not index.build(7):
        steps += 1
        n = len(doc.lines)
        sl = rnd.randrange(n)
        el = min(n - 1, sl + rnd.randrange(3))
        text = "\n".join(rnd.choice(lines) for _ in range(rnd.randrange(3)))
        doc.apply_change(sl, 0, el, len(doc.lines[el]), text)
        index.replaced(doc.blocks, sl, el + 1, len(split_lines(text)))
    assert steps > 20  # it was made in many steps, edited between them
    assert _answers(index) == _answers(SiteIndex(doc.blocks))


def test_a_huge_index_waits_for_its_steps_and_one_of_a_document_still_read_never_is_ready() -> None:
    short = ParsedDocument("\n".join(LINES))
    assert SiteIndex(short.blocks).ready  # made at the first question
    huge = ParsedDocument("\n".join(LINES * 15_000))
    index = SiteIndex(huge.blocks)
    assert not index.ready
    while not index.build(50_000):
        pass
    assert index.ready and _answers(index) == _answers(SiteIndex(huge.blocks))
    reading = SiteIndex(short.blocks, partial=True)
    assert not reading.ready and not reading.build(1_000_000)


def test_an_open_document_s_index_is_made_in_steps_before_any_question() -> None:
    """Once a document's analysis is published, the language server makes its index a step at
    a time between the editor's messages (lsp/site_steps.py), so that the first hover on a
    variable finds it made instead of making it then: a document far under the huge size too."""
    doc = ParsedDocument("\n".join(LINES * 500))  # 3,500 lines, #100=#100+1 on every seventh from line 1
    index = SiteIndex(doc.blocks)
    assert index.ready and not index.made  # answered at once, but not made until asked

    async def published() -> None:
        index_soon(index)
        while not index.made:
            await asyncio.sleep(0)  # the editor's messages would be answered here

    asyncio.run(asyncio.wait_for(published(), 30))
    assert index.writes(100) == list(range(1, 3500, 7))
    assert _answers(index) == _answers(SiteIndex(doc.blocks))
