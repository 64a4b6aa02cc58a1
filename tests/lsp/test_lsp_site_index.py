"""The language server's index of macro lines stays equal to a fresh one across random edits,
so hover, references and rename read the right lines after typing."""

from __future__ import annotations

import random

from cncmacro.lsp.site_index import SiteIndex
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
