"""The documents a workspace analysis holds open, and what an edit of one changes.

``WorkspaceDocument`` is one open document with what the analysis keeps of it until it changes:
its own findings, the per-line part of its static checks (kept across edits, line by line), its
literal call targets, how many places may read the clock, and its edits since the last
analysis, each a ``DocumentEdit`` that says where the runs must be taken back to
(``run_rewind.py``). ``WorkspaceDocument.edit`` applies an editor change: the text is parsed
again only where it changed, and the edit says whether it touched the structure (a label, an O
header, ``%`` or a loop marker: ``changes_structure``) or moved the lines after it.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from ..library.dialect_choice import HEADER_LINES, dialect_from_text
from ..library.programs import LoadedFile
from ..syntax.document import ParsedDocument
from ..syntax.nodes import Block
from .checks.static_lines import StaticLines
from .diagnostics import Diagnostic
from .runs.clock_reads import clock_reads


@dataclass(slots=True)
class DocumentEdit:
    """One edit of an open document, as the runs need to know it."""

    start: int
    count: int  # lines of the new text
    structural: bool  # a label, O header, '%' or loop marker was changed, added or removed
    shifted: bool  # lines were added or removed: the lines after the edit moved


@dataclass(slots=True)
class WorkspaceDocument:
    """An open document and what is cached about it."""

    path: str
    doc: ParsedDocument
    loaded: LoadedFile
    version: int | None
    own: list[Diagnostic] | None = None  # syntax + static, until the next change
    static: StaticLines | None = None  # the per-line part of ``own``, kept across edits
    targets: tuple[set[int], set[str]] | None = None  # literal call targets
    edits: list[DocumentEdit] = field(default_factory=list)
    clock_reads: int | None = None  # how many places may read the clock (``clock_reads.py``)
    real: str = ""  # the path with links resolved, found once

    def reads_clock(self) -> bool:
        """Whether a program of this document may read the clock (counted at the first question)."""
        if self.clock_reads is None:
            self.clock_reads = clock_reads(self.doc.lines)
        return self.clock_reads > 0

    def edit(self, start_line: int, start_col: int, end_line: int, end_col: int, text: str, version: int,
             calls_in: Callable[[Block], bool]) -> bool:  # fmt: skip
        """Apply an editor change (0-based positions); ``calls_in`` tells whether a block makes
        a call. True when every run must start again: an O header, or the dialect comment of
        the first lines, changed."""
        doc = self.doc
        n = len(doc.lines)
        sl = min(max(start_line, 0), n - 1)
        el = min(max(end_line, sl), n - 1)
        old = doc.blocks[sl : el + 1]
        before = clock_reads(doc.lines[sl : el + 1]) if self.clock_reads is not None else 0
        doc.apply_change(start_line, start_col, end_line, end_col, text)
        delta = len(doc.lines) - n
        new = doc.blocks[sl : el + 1 + delta]
        if self.clock_reads is not None:
            self.clock_reads += clock_reads(doc.lines[sl : el + 1 + delta]) - before
        self.version = version
        self.own = None
        structural = changes_structure(old, new)
        if self.static is not None:
            self.static.replace(doc.blocks, sl, el + 1 - sl, el + 1 - sl + delta, structural)
        both = old + new
        again = False
        if any(b.program is not None for b in both) or (
            sl < HEADER_LINES and dialect_from_text(doc.lines) != self.loaded.dialect
        ):
            self.loaded.dialect = dialect_from_text(doc.lines)
            again = True
        if self.targets is not None and any(calls_in(b) for b in both):
            self.targets = None
        self.edits.append(DocumentEdit(sl, len(new), structural, delta != 0))
        return again


def changes_structure(old: list[Block], new: list[Block]) -> bool:
    """Whether replacing ``old`` by ``new`` adds, removes or changes a structural block (the
    lines both keep unchanged at their ends, as when Enter splits nothing, do not count; a
    block replaced by one with the same ``structure_key`` changes nothing)."""
    a, b = 0, 0
    while a < len(old) and b < len(new) and old[a] is new[b]:
        a += 1
        b += 1
    x, y = len(old), len(new)
    while x > a and y > b and old[x - 1] is new[y - 1]:
        x -= 1
        y -= 1
    if x - a == y - b and all(o.structure_key() == n.structure_key() for o, n in zip(old[a:x], new[b:y], strict=True)):
        return False  # the same labels, headers and loop markers in the same places (a label line's X typed)
    return any(blk.structural for blk in old[a:x]) or any(blk.structural for blk in new[b:y])
