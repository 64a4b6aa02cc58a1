"""The one per-line fact cache: what each block says by itself, found once per block.

Blocks are shared by line text (the parser keeps one block per distinct line), so a file of
repeated lines, or many files with the same lines, looks at each text once. For a block the
memo keeps two things, each made the first time it is asked for:

- its ``LineFacts`` (findings, jumps, calls, returns: ``static_checks.line_facts``), which the
  static checks of a document keep per line (``static_lines.py``);
- its ``Sites`` (every jump target and ``#`` variable it mentions: ``sites.py``), which the
  site index of a document or file on disk keeps per line (``site_index.py``) for hover,
  references, highlight and rename.

One ``BlockMemo`` is owned by whoever owns the documents (the language server's ``Documents``,
or a check of the command line) and shared by every static check and site index they make.
It holds its blocks, so lines typed over do not stay for good: it is emptied when it reaches
its limit, which follows the size of the documents being edited (``fit``). The static checks
ask on the analysis thread and the site indexes on the editor's; what one block says is the
same on both, and each answer is kept in one step (``_Entry``), so neither waits for the other
and neither reads half an answer.
"""

from __future__ import annotations

from ...dialects.dialect import Dialect
from ...machine.jump_words import may_hold_jump
from ...syntax.nodes import Block
from ..checks.line_facts import LineContext, LineFacts
from ..checks.static_checks import line_facts
from .sites import Calls, JumpSite, VariableSite, jump_sites, variable_sites

Sites = tuple[tuple[JumpSite, ...], tuple[VariableSite, ...]]
NO_SITES: Sites = ((), ())

_LIMIT_MAX = 300_000
_LIMIT_MIN = 2_000  # entries kept while a document is edited, at least


class _Entry:
    """What one block says: its facts with the context they were found under, and its sites
    with the dialect and call codes they were found with. Each is one attribute, written in one
    step, so a reader on another thread sees a whole answer or none."""

    __slots__ = ("block", "facts", "sites")

    def __init__(self, block: Block) -> None:
        self.block = block
        self.facts: tuple[LineContext, LineFacts | None] | None = None
        self.sites: tuple[Dialect, Calls, Sites] | None = None


class BlockMemo:
    """See the module docstring."""

    def __init__(self) -> None:
        self._entries: dict[int, _Entry] = {}  # id(block) -> entry
        self.limit = _LIMIT_MAX

    def fit(self, lines: int) -> None:
        """A document of ``lines`` lines is being edited: keep about twice its lines (the
        blocks it has and the ones it had), within the memo's bounds."""
        self.limit = max(_LIMIT_MIN, min(_LIMIT_MAX, 2 * lines))

    def _entry(self, block: Block) -> _Entry:
        entries = self._entries
        entry = entries.get(id(block))
        if entry is None or entry.block is not block:
            if len(entries) >= self.limit:
                entries.clear()
            entry = entries[id(block)] = _Entry(block)
        return entry

    def facts(self, block: Block, ctx: LineContext) -> LineFacts | None:
        """What ``block`` says by itself under ``ctx`` (None for a plain line that needs no
        look, or a block that says nothing)."""
        plain = block.plain_text  # after a label too (N10 G01 X5.)
        if plain is not None:  # plain lines are many and rarely repeat: not kept
            return line_facts(block, ctx) if ctx.plain_hint(plain) else None
        entry = self._entries.get(id(block))
        if entry is None or entry.block is not block:
            entry = self._entry(block)
        kept = entry.facts
        if kept is None or kept[0] is not ctx:
            kept = entry.facts = (ctx, line_facts(block, ctx))
        return kept[1]

    def sites(self, block: Block, dialect: Dialect, calls: Calls = None) -> Sites:
        """The jumps and variables of ``block`` under ``dialect`` and the machine file's call
        codes ``calls`` (which words are jumps: ``machine/jump_words.py``)."""
        plain = block.plain_text  # after a label too (N10 G01 X5.)
        if plain is not None:
            if not may_hold_jump(plain):  # and no '#': a plain line holds address-number words only
                return NO_SITES
        elif not block.statements and not block.words and not block.corners:
            return NO_SITES
        entry = self._entry(block)
        kept = entry.sites
        if kept is None or kept[0] is not dialect or kept[1] is not calls:
            found = (tuple(jump_sites(block, dialect, calls)), tuple(variable_sites(block)))
            kept = entry.sites = (dialect, calls, found)
        return kept[2]
