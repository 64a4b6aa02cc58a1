"""The per-line part of a document's syntax and static checks, kept line by line across edits.

``StaticLines`` holds, for each line that has any, the syntax problems of its block and what
the block says by itself (``LineFacts``: findings, jumps, calls, returns). Both are pure
functions of the block and the ``LineContext``, and blocks are shared per line text, so the
facts come from the one per-line fact cache (``block_memo.py``): a file of repeated lines
checks each text once. An
edit calls ``replace`` with the lines it replaced: only the new lines are looked at, and the
lines after them are renumbered (a cost in proportion to the lines that have facts, not to
the file). ``diagnostics`` then adds the cross-line checks (labels, loops, call targets),
which look only at the lines with facts and at the document's labels and markers. Their
result is kept until an edit could change it: lines added or removed, a structural block
changed (a label, header, ``%`` or loop marker), a line with a jump, call or return before or
after the edit, or another program library (files on disk changed). Typing into the
coordinates of a 100k-line program so costs no label check at all.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TypeVar

from ...bilingual import is_chinese
from ...dialects.dialect import Dialect
from ...library.programs import ProgramLibrary
from ...syntax.nodes import Block, Problem
from ...syntax.program import Program
from ..diagnostics import Diagnostic
from ..indexes.block_memo import BlockMemo
from .line_facts import LineContext, LineFacts
from .static_checks import cross_line_diagnostics, findings_of
from .syntax_check import syntax_findings

_V = TypeVar("_V")
_CHUNK = 5_000  # lines looked at between two reports of how far the look got (and chances to stop)


class StaticLines:
    """See the module docstring."""

    def __init__(self, blocks: list[Block], ctx: LineContext, memo: BlockMemo | None = None,
                 looked: Callable[[int, int], None] | None = None, fill: bool = True) -> None:  # fmt: skip
        self.ctx = ctx
        self.memo = memo if memo is not None else BlockMemo()
        self.facts: dict[int, LineFacts] = {}  # line -> facts, only lines that have some
        self.problems: dict[int, tuple[Problem, ...]] = {}  # line -> syntax problems
        # the cross-line findings, with the program and library they were found with
        self._cross: tuple[Program, ProgramLibrary | None, list[Diagnostic]] | None = None
        self.looked = looked  # ``looked(lines done, lines)`` after each chunk of a long look
        self.filled = 0  # the lines before this one have been looked at
        if fill:
            self.fill(blocks)

    def fill(self, blocks: list[Block], should_stop: Callable[[], bool] | None = None) -> bool:
        """Look at the lines not looked at yet, a chunk at a time; False when ``should_stop``
        said stop between two chunks (the next call goes on from there, and an edit meanwhile
        is taken into account by ``replace``). Only a whole look gives whole answers."""
        total = len(blocks)
        while self.filled < total:
            end = min(self.filled + _CHUNK, total)
            self._fill(blocks, self.filled, end)
            self.filled = end
            if self.looked is not None and total > _CHUNK:
                self.looked(end, total)
            if end < total and should_stop is not None and should_stop():
                return False
        return True

    def _fill(self, blocks: list[Block], start: int, end: int) -> None:
        facts_of = self.memo.facts
        ctx = self.ctx
        hint = ctx.plain_hint
        facts = self.facts
        problems = self.problems
        for line in range(start, end):
            block = blocks[line]
            plain = block.plain
            if plain is not None and not hint(plain):  # most lines of a CAM file: passed over here
                continue
            if block.problems:
                problems[line] = block.problems
            f = facts_of(block, ctx)
            if f is not None:
                facts[line] = f

    def replace(self, blocks: list[Block], start: int, old_count: int, new_count: int, structural: bool = True) -> None:
        """Lines ``start`` .. ``start + old_count`` were replaced by ``new_count`` lines
        (``blocks`` is the document's new block list; ``structural``: the edit changed a
        label, header, ``%`` or loop marker)."""
        end = start + old_count
        delta = new_count - old_count
        self.memo.fit(len(blocks))
        if structural or delta or self._connects(start, end):
            self._cross = None
        if start >= self.filled:  # not looked at yet: the look comes to these lines later
            return
        _shift(self.facts, start, end, delta)
        _shift(self.problems, start, end, delta)
        self.filled = self.filled + delta if self.filled >= end else start + new_count
        self._fill(blocks, start, start + new_count)
        if self._connects(start, start + new_count):
            self._cross = None

    def _connects(self, start: int, end: int) -> bool:
        """Whether a line of ``start`` .. ``end`` has a jump, a call or a return."""
        facts = self.facts
        for line in range(start, end):
            f = facts.get(line)
            if f is not None and (f.jumps or f.calls or f.returns):
                return True
        return False

    def call_targets(self, read_end: int) -> tuple[set[int], set[str]]:
        """The literal program numbers and names that the document's calls name (on the lines
        before ``read_end``, the end of the tape)."""
        numbers: set[int] = set()
        names: set[str] = set()
        for line, f in self.facts.items():
            if line >= read_end:
                continue
            for c in f.calls:
                if c.number is not None:
                    numbers.add(c.number)
                elif c.name is not None:
                    names.add(c.name.strip().lower())
        return numbers, names

    def call_sites(self, read_end: int) -> list[tuple[int, int | None, str | None]]:
        """(line, program number, lower-case name) of each call with a literal target (on the
        lines before ``read_end``, the end of the tape)."""
        out: list[tuple[int, int | None, str | None]] = []
        for line, f in self.facts.items():
            if line >= read_end:
                continue
            for c in f.calls:
                if c.number is not None:
                    out.append((line, c.number, None))
                elif c.name is not None:
                    out.append((line, None, c.name.strip().lower()))
        return out

    def line_diagnostics(
        self, read_end: int, file: str, locale: str
    ) -> tuple[list[Diagnostic], list[tuple[int, LineFacts]]]:
        """The findings each line before ``read_end`` (the end of the tape) earns by itself, and
        the lines with jumps, calls or returns, with their facts, for the cross-line checks."""
        out: list[Diagnostic] = []
        chinese = is_chinese(locale)
        for line in sorted(self.problems):
            if line >= read_end:
                break
            out.extend(syntax_findings(self.problems[line], line, file, chinese, self.ctx.dialect))
        collected: list[tuple[int, LineFacts]] = []
        for line in sorted(self.facts):
            if line >= read_end:
                break
            facts = self.facts[line]
            if facts.findings:
                out.extend(findings_of(facts, line, file))
            if facts.jumps or facts.calls or facts.returns:
                collected.append((line, facts))
        return out, collected

    def diagnostics(self, program: Program, file: str, dialect: Dialect, library: ProgramLibrary | None,
                    locale: str) -> list[Diagnostic]:  # fmt: skip
        """Syntax and static diagnostics of the document (``program`` is its current parse)."""
        out, collected = self.line_diagnostics(program.read_end, file, locale)  # nothing after the closing '%' is read
        kept = self._cross
        if kept is None or kept[0] is not program or kept[1] is not library:
            kept = self._cross = (program, library, cross_line_diagnostics(program, file, dialect, library, locale,
                                                                           collected, self.ctx))  # fmt: skip
        out.extend(kept[2])
        return out


def _shift(table: dict[int, _V], start: int, end: int, delta: int) -> None:
    """Renumber the entries of ``table`` after an edit that replaced lines ``start``..``end``
    (exclusive) with ``delta`` lines more: those inside it go, those after it move (none moves
    when the count of lines stayed: the usual edit of a coordinate costs its own lines only)."""
    if not delta:
        for line in range(start, end):
            table.pop(line, None)
        return
    moved = {}
    for line in [x for x in table if x >= start]:
        value = table.pop(line)
        if line >= end:
            moved[line + delta] = value
    table.update(moved)
