"""Where things are mentioned on one block: jumps to N labels, variables read and written,
function and keyword names. Every feature that searches (references, rename, hover's "written
at", signature help's "reads") asks these questions of cached blocks, one block at a time.
Which words of a block are jumps is the interpreter's rule (``machine/jump_words.py``, on the
call ``recognise_call`` finds), so they depend on the dialect and the machine file's call codes.
"""

from __future__ import annotations

import re
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from typing import Protocol

from ...dialects.dialect import Dialect
from ...machine.jump_words import SUBPROGRAM_LABEL, jump_words, may_hold_jump
from ...syntax.nodes import Assign, Block, Expr, Goto, If, Number, Var
from ...syntax.walk import iter_nodes

Calls = Mapping[str, object] | None  # the machine file's call codes


@dataclass(frozen=True, slots=True)
class JumpSite:
    """A literal label number a block jumps to: ``kind`` is ``GOTO``, ``M99``, ``M98 Q`` (M198's
    Q too), ``H8x`` or a local subprogram call (``M97 P`` where the dialect has Haas's), as
    ``machine/jump_words.py`` names them; ``start``/``end`` cover the number. Haas's
    conditional ``[cond] M99 P n`` is an ``IF..GOTO`` (``syntax.nodes.If``): its P is a ``GOTO``
    site, landing as GOTO does."""

    label: int
    kind: str
    start: int
    end: int


@dataclass(frozen=True, slots=True)
class VariableSite:
    number: int
    start: int
    end: int
    write: bool


def _literal_int(node: object) -> int | None:
    if isinstance(node, Number) and node.value == int(node.value) and node.value > 0:
        return int(node.value)
    return None


def starts_from_the_top(kind: str) -> bool:
    """Whether a jump of this kind lands on the first N label of its program, searching from
    the program's start (``M98 Q``, a local call ``M97 P``), rather than by the GOTO or M99 P
    rule (``machine.jumps``)."""
    return kind == SUBPROGRAM_LABEL or (kind.startswith("M") and kind.endswith(" P"))


def _jump_targets(block: Block, dialect: Dialect, calls: Calls) -> Iterator[tuple[str, Expr]]:
    """(kind, target as written) of every jump a block makes: literal or computed."""
    if block.plain is not None and not may_hold_jump(block.plain):
        return
    for s in block.statements:
        target = s.target if isinstance(s, Goto) else s.goto if isinstance(s, If) else None
        if target is not None:
            yield "GOTO", target
    if block.words:
        for kind, w in jump_words(block.words, dialect, calls):
            if w.value is not None:  # always: jump_words names no P[NAME]
                yield kind, w.value


def jump_sites(block: Block, dialect: Dialect, calls: Calls = None) -> list[JumpSite]:
    """The jumps of a block to literal label numbers under ``dialect`` and the machine file's
    call codes ``calls`` (``machine/jump_words.py``)."""
    out: list[JumpSite] = []
    for kind, target in _jump_targets(block, dialect, calls):
        n = _literal_int(target)
        if n is not None:
            out.append(JumpSite(n, kind, target.start, target.end))
    return out


def computed_jump_sites(block: Block, dialect: Dialect, calls: Calls = None) -> list[tuple[str, int, int]]:
    """(kind, start, end) of the jumps of a block whose label the run computes: ``GOTO #1``,
    ``IF [..] GOTO [#2+10]``, ``M99 P#3``, ``G65 H81 P#4`` (the kinds of ``JumpSite``)."""
    return [(kind, t.start, t.end) for kind, t in _jump_targets(block, dialect, calls) if not isinstance(t, Number)]


def variable_sites(block: Block) -> list[VariableSite]:
    """Every ``#n`` with a literal number on the block, and whether it is assigned there."""
    if block.plain is not None and "#" not in block.plain:
        return []
    out: list[VariableSite] = []
    targets = set()
    for node in iter_nodes(block):
        if isinstance(node, Assign) and isinstance(node.target, Var):
            targets.add(id(node.target))
        elif isinstance(node, Var):
            out.append(VariableSite(node.number, node.start, node.end, id(node) in targets))
    return out


_WORD = re.compile(r"[A-Za-z]+")


def word_at(line: str, column: int) -> tuple[str, int, int] | None:
    """The run of letters under ``column`` (or ending at it) with its range."""
    for m in _WORD.finditer(line):
        if m.start() <= column <= m.end():
            return m.group(0), m.start(), m.end()
        if m.start() > column:
            break
    return None


class JumpIndex(Protocol):
    """What ``label_jumps`` asks of a document's site index (``site_index.SiteIndex``)."""

    def jumps_to(self, label: int, start: int = 0, end: int | None = None) -> list[int]: ...

    def sites_at(self, line: int) -> tuple[tuple[JumpSite, ...], tuple[VariableSite, ...]]: ...


class IndexedDocument(Protocol):
    """An open document with its site index (the language server's ``OpenDocument``)."""

    @property
    def sites(self) -> JumpIndex: ...


def label_jumps(doc: IndexedDocument, start: int, end: int, label: int) -> Iterator[tuple[int, JumpSite]]:
    """(line, jump) for every jump to ``label`` on lines ``start`` to ``end`` of an open
    document (read from its site index: the lines that jump there, not every line)."""
    sites = doc.sites
    for i in sites.jumps_to(label, start, end):
        for j in sites.sites_at(i)[0]:
            if j.label == label:
                yield i, j
