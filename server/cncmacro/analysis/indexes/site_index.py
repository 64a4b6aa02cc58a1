"""Which lines of a document mention jumps or variables, and where each label and variable is,
kept up to date by edits.

Hover ("where is #100 written", "which jumps land on N10"), references and rename look only at
these lines. The sites of a block are found once per block object, in the one per-line fact
cache (``block_memo.py``, owned by whoever owns the documents). A ``SiteIndex`` keeps the sorted lines
that have sites and, from the first question on, maps from a variable number to the lines that
write it and that mention it, and from a label number to the lines that jump to it; an edit only
re-examines the lines it replaced and shifts the others. So the answer to a question costs time
in proportion to the answer, not to the file, and an edit in proportion to the macro lines at
most. Files on disk get one index each, made at the first question and kept by the workspace
index (``workspace_index.py``) until it loads the file again. The index of a huge document
(``STEPPED_FROM`` lines) is not made at a question on the editor's thread, which would hold the
editor up for seconds: it is made in steps (``build``), and until then ``ready`` says so. The
language server makes any open document's index so once its analysis is published, so that the
first hover finds it made (``lsp/site_steps.py``).
"""

from __future__ import annotations

from bisect import bisect_left, insort
from collections.abc import Iterator
from dataclasses import dataclass

from ...dialects import get_dialect
from ...dialects.dialect import Dialect
from ...machine.jump_words import may_hold_jump
from ...syntax.nodes import Block
from .block_memo import NO_SITES, BlockMemo, Sites
from .sites import Calls, JumpSite, VariableSite

Lines = dict[int, list[int]]  # a label or variable number -> its sorted lines
STEPPED_FROM = 100_000  # lines: the index of a document this long is made in steps (``SiteIndex.build``)


class _Maps:
    """Label -> jumping lines, variable -> writing lines, variable -> mentioning lines."""

    def __init__(self) -> None:
        self.jumps: Lines = {}
        self.writes: Lines = {}
        self.mentions: Lines = {}

    def _keyed(self, sites: Sites) -> Iterator[tuple[Lines, int]]:
        for key in {j.label for j in sites[0]}:
            yield self.jumps, key
        for key in {s.number for s in sites[1]}:
            yield self.mentions, key
        for key in {s.number for s in sites[1] if s.write}:
            yield self.writes, key

    def add(self, line: int, sites: Sites, at_end: bool = False) -> None:
        for table, key in self._keyed(sites):
            lines = table.get(key)
            if lines is None:
                table[key] = [line]
            elif at_end:
                lines.append(line)
            else:
                insort(lines, line)

    def remove(self, line: int, sites: Sites) -> None:
        for table, key in self._keyed(sites):
            lines = table[key]
            k = bisect_left(lines, line)
            del lines[k]
            if not lines:
                del table[key]

    def shift(self, at: int, delta: int) -> None:
        """Lines from ``at`` on move by ``delta``."""
        for table in (self.jumps, self.writes, self.mentions):
            for lines in table.values():
                k = bisect_left(lines, at)
                if k < len(lines):
                    lines[k:] = [x + delta for x in lines[k:]]


class SiteIndex:
    """The sorted lines of one document whose blocks have sites, found the first time they
    are asked for (not while a document is being opened), and the maps of ``_Maps`` made from
    them the first time one is asked for. ``dialect`` and ``calls`` (the machine file's call
    codes) decide which words are jumps (``machine/jump_words.py``: Haas ``M97 P``, gsk980tdi
    ``G65 H8x P``, and none in a block that a configured code makes a call)."""

    def __init__(
        self,
        blocks: list[Block],
        dialect: Dialect | None = None,
        calls: Calls = None,
        memo: BlockMemo | None = None,
        partial: bool = False,
    ) -> None:
        """``partial``: ``blocks`` are those of a document still being read (not ``ready``)."""
        self._blocks = blocks
        self.partial = partial
        self.dialect = dialect if dialect is not None else get_dialect(None)
        self.calls = calls
        self.memo = memo if memo is not None else BlockMemo()
        self._lines: list[int] | None = None
        self._sites: list[Sites] = []  # the sites of each of ``_lines``, as they were indexed
        self._maps: _Maps | None = None
        # made in steps (``build``): the lines, sites and maps of the blocks before ``_next``
        self._part: tuple[list[int], list[Sites], _Maps | None] = ([], [], None)
        self._next = 0

    @property
    def ready(self) -> bool:
        """Whether a question is answered at once: the index is made, or the document is short
        enough (under ``STEPPED_FROM`` lines) to make it now."""
        return not self.partial and (self._lines is not None or len(self._blocks) < STEPPED_FROM)

    @property
    def made(self) -> bool:
        """Whether the index is made: a question asks nothing of the blocks but its answer."""
        return self._lines is not None

    def build(self, count: int) -> bool:
        """One step of making the index: the next ``count`` lines (the maps too); True once it
        is made. A huge document's index is made so, between the editor's other messages."""
        if self._lines is None and not self.partial:
            if self._next == 0 and self._part[2] is None:
                self._part = ([], [], _Maps())
            self._scan_to(min(len(self._blocks), self._next + count))
        return self._lines is not None

    @property
    def lines(self) -> list[int]:
        if self._lines is None:
            self._scan_to(len(self._blocks))
        assert self._lines is not None
        return self._lines

    @property
    def maps(self) -> _Maps:
        lines = self.lines  # made in full first: the maps too, when steps had begun them
        if self._maps is None:
            maps = _Maps()
            for line, sites in zip(lines, self._sites, strict=True):
                maps.add(line, sites, at_end=True)
            self._maps = maps
        return self._maps

    def _scan_to(self, stop: int) -> None:
        """Index the blocks from ``_next`` to ``stop``; the index is made once they all are."""
        lines, sites, maps = self._part
        block_sites = self.memo.sites
        dialect, calls = self.dialect, self.calls
        blocks = self._blocks
        for i in range(self._next, stop):
            b = blocks[i]
            p = b.plain  # most lines of a CAM file: passed over here, without a call
            if p is not None and not may_hold_jump(p):
                continue
            s = block_sites(b, dialect, calls)
            if s[0] or s[1]:
                lines.append(i)
                sites.append(s)
                if maps is not None:
                    maps.add(i, s, at_end=True)
        self._next = stop
        if stop >= len(blocks):
            self._lines, self._sites, self._maps = lines, sites, maps
            self._part = ([], [], None)

    def replaced(self, blocks: list[Block], start: int, old_end: int, new_count: int) -> None:
        """Lines ``start``..``old_end`` (exclusive) became ``new_count`` lines (now in ``blocks``)."""
        self._blocks = blocks
        if self._lines is not None:
            self._splice(self._lines, self._sites, self._maps, start, old_end, new_count)
        elif old_end <= self._next:  # made in steps, the edit within the part made so far
            lines, sites, maps = self._part
            self._splice(lines, sites, maps, start, old_end, new_count)
            self._next += new_count - (old_end - start)
        elif start < self._next:  # across where the steps are: looked at again from the edit on
            self._forget_from(start)

    def _splice(
        self, lines: list[int], sites: list[Sites], maps: _Maps | None, start: int, old_end: int, new_count: int
    ) -> None:
        """The edit of ``replaced`` in ``lines``, their ``sites`` and ``maps``."""
        lo = bisect_left(lines, start)
        hi = bisect_left(lines, old_end)
        delta = new_count - (old_end - start)
        fresh_lines: list[int] = []
        fresh_sites: list[Sites] = []
        for k in range(new_count):
            s = self.memo.sites(self._blocks[start + k], self.dialect, self.calls)
            if s[0] or s[1]:
                fresh_lines.append(start + k)
                fresh_sites.append(s)
        if maps is not None:
            for line, old in zip(lines[lo:hi], sites[lo:hi], strict=True):
                maps.remove(line, old)
            if delta:
                maps.shift(old_end, delta)
            for line, new in zip(fresh_lines, fresh_sites, strict=True):
                maps.add(line, new)
        if delta:
            lines[hi:] = [x + delta for x in lines[hi:]]
        lines[lo:hi] = fresh_lines
        sites[lo:hi] = fresh_sites

    def _forget_from(self, start: int) -> None:
        """An edit across ``_next`` while the index is made in steps: the lines from ``start``
        on are looked at again."""
        lines, sites, maps = self._part
        k = bisect_left(lines, start)
        if maps is not None:
            for line, s in zip(lines[k:], sites[k:], strict=True):
                maps.remove(line, s)
        del lines[k:], sites[k:]
        self._next = start

    def reads_with(self, dialect: Dialect, calls: Calls) -> bool:
        """Whether the index was made under ``dialect`` and ``calls`` (else it is made again)."""
        return self.dialect is dialect and self.calls is calls

    def jumps_of(self, block: Block) -> tuple[JumpSite, ...]:
        """The jumps of ``block`` (a block of the document, at the cursor say) by the rule the
        index reads its lines with."""
        return self.memo.sites(block, self.dialect, self.calls)[0]

    def between(self, start: int, end: int) -> list[int]:
        """The indexed lines in ``start``..``end`` (exclusive)."""
        return _within(self.lines, start, end)

    def jumps_to(self, label: int, start: int = 0, end: int | None = None) -> list[int]:
        """The lines (in ``start``..``end``) that jump to N``label``."""
        return _within(self.maps.jumps.get(label, []), start, end)

    def writes(self, number: int, start: int = 0, end: int | None = None) -> list[int]:
        """The lines (in ``start``..``end``) that assign ``#number``."""
        return _within(self.maps.writes.get(number, []), start, end)

    def mentions(self, number: int, start: int = 0, end: int | None = None) -> list[int]:
        """The lines (in ``start``..``end``) that mention ``#number``."""
        return _within(self.maps.mentions.get(number, []), start, end)

    def variable_uses(self, number: int, start: int = 0, end: int | None = None) -> Iterator[tuple[int, VariableSite]]:
        """(line, site) for every mention of ``#number`` on lines ``start``..``end``, a write
        (``site.write``) or a read, in order."""
        for i in self.mentions(number, start, end):
            for s in self.sites_at(i)[1]:
                if s.number == number:
                    yield i, s

    def sites_at(self, line: int) -> Sites:
        """The sites of an indexed ``line`` (none for another line)."""
        lines = self.lines
        k = bisect_left(lines, line)
        return self._sites[k] if k < len(lines) and lines[k] == line else NO_SITES


def _within(lines: list[int], start: int, end: int | None) -> list[int]:
    if start <= 0 and end is None:
        return list(lines)
    return lines[bisect_left(lines, start) : len(lines) if end is None else bisect_left(lines, end)]


@dataclass(frozen=True, slots=True)
class FileSites:
    """One workspace file as searches see it: its path, line texts and site index."""

    path: str
    lines: list[str]
    sites: SiteIndex
