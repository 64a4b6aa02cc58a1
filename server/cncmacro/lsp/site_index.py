"""Which lines of an open document mention jumps or variables, kept up to date by edits.

Hover ("where is #100 written", "which jumps land on N10"), references and rename look only at
these lines. The sites of a block are computed once per block object (blocks are shared by
line text), and an edit only re-examines the lines it replaced and shifts the others, so a
question about a 100k-line file costs time in proportion to its macro lines, not its length.
"""

from __future__ import annotations

from bisect import bisect_left
from collections.abc import Iterable, Iterator
from typing import Any

from ..syntax.nodes import Block
from .sites import JumpSite, VariableSite, jump_sites, variable_sites

Sites = tuple[tuple[JumpSite, ...], tuple[VariableSite, ...]]
_EMPTY: Sites = ((), ())
_memo: dict[int, tuple[Block, Sites]] = {}
_MEMO_LIMIT = 300_000


def block_sites(block: Block) -> Sites:
    """The jumps and variables of a block (memoised per block object)."""
    plain = block.plain
    if plain is not None and "M9" not in plain.upper() and "H8" not in plain.upper():
        return _EMPTY
    if plain is None and not block.statements and not block.words:
        return _EMPTY
    hit = _memo.get(id(block))
    if hit is not None and hit[0] is block:
        return hit[1]
    sites = (tuple(jump_sites(block)), tuple(variable_sites(block)))
    if len(_memo) >= _MEMO_LIMIT:
        _memo.clear()
    _memo[id(block)] = (block, sites)
    return sites


class SiteIndex:
    """The sorted lines of one document whose blocks have sites, found the first time they
    are asked for (not while a document is being opened)."""

    def __init__(self, blocks: list[Block]) -> None:
        self._blocks = blocks
        self._lines: list[int] | None = None

    @property
    def lines(self) -> list[int]:
        if self._lines is None:
            self._lines = [i for i, b in enumerate(self._blocks) if block_sites(b) != _EMPTY]
        return self._lines

    def replaced(self, blocks: list[Block], start: int, old_end: int, new_count: int) -> None:
        """Lines ``start``..``old_end`` (exclusive) became ``new_count`` lines (now in ``blocks``)."""
        if self._lines is None:
            self._blocks = blocks
            return
        lines = self._lines
        lo = bisect_left(lines, start)
        hi = bisect_left(lines, old_end)
        delta = new_count - (old_end - start)
        fresh = [start + k for k in range(new_count) if block_sites(blocks[start + k]) != _EMPTY]
        tail = [x + delta for x in lines[hi:]] if delta else lines[hi:]
        self._lines = lines[:lo] + fresh + tail

    def between(self, start: int, end: int) -> list[int]:
        """The indexed lines in ``start``..``end`` (exclusive)."""
        return self.lines[bisect_left(self.lines, start) : bisect_left(self.lines, end)]


def indexed_lines(server: Any) -> Iterator[tuple[str, list[Block], Iterable[int]]]:
    """(path, blocks, lines worth reading) for every workspace file: an open document's
    indexed lines, every line of a file on disk."""
    open_paths = set()
    for doc in server.documents.by_uri.values():
        open_paths.add(doc.path)
        yield doc.path, doc.parsed.blocks, doc.sites.lines
    for path, loaded in server.index.files.items():
        if path not in open_paths:
            yield path, loaded.program.blocks, range(len(loaded.program.blocks))
