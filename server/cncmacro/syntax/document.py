"""A document kept parsed across edits.

The text is held as a list of lines. An edit replaces a range of lines; only the lines whose
text is new are parsed (blocks come from a ``BlockCache`` keyed by line text), the block list
is spliced, and the ``Program`` is patched: labels moved, units and loops re-derived from the
few marker lines. So a one-line edit costs one line's parse and a look at the labels, never a
pass over the blocks.
"""

from __future__ import annotations

from .block_parser import BlockCache, collector_paused, shared_cache
from .nodes import Block
from .program import Program, build_program, first_mark_turned, update_program


def split_lines(text: str) -> list[str]:
    """Lines as an editor counts them: a break is CRLF, LF or a lone CR."""
    if "\r" in text:
        text = text.replace("\r\n", "\n").replace("\r", "\n")
    return text.split("\n")


def head_lines(text: str, count: int) -> list[str]:
    """The first ``count`` lines of ``text`` as ``split_lines`` counts them, without splitting
    the rest (a file of lone CR breaks is split whole)."""
    end = -1
    for _ in range(count):
        end = text.find("\n", end + 1)
        if end < 0:
            break
    return split_lines(text if end < 0 else text[:end])[:count]


class ParsedDocument:
    """The lines, blocks and program of one document, updated in place by edits."""

    def __init__(self, text: str, cache: BlockCache | None = None, *, in_steps: int | None = None) -> None:
        """``in_steps``: parse only that many first lines now, and the rest through ``parse_more``
        (a huge file opened in the editor, which answers meanwhile); until then the document is
        ``partial``: ``blocks`` holds the lines parsed so far, ``block_at`` parses any other line
        on its own, ``program`` is that of the first lines, and an edit changes its lines (and
        the blocks of those parsed already)."""
        self.cache = cache if cache is not None else shared_cache
        self.lines: list[str] = []
        self.blocks: list[Block] = []
        self._structural: list[bool] = []
        self.program: Program
        if in_steps is None:
            self.set_text(text)
            return
        self.lines = split_lines(text)
        self.parse_more(in_steps)
        if self.partial:
            self.program = build_program(self.blocks)

    @property
    def partial(self) -> bool:
        """Whether some lines are not parsed yet (``in_steps``)."""
        return len(self.blocks) < len(self.lines)

    def parse_more(self, count: int) -> bool:
        """Parse the next ``count`` lines of a partial document; True once every line is parsed
        (the program is then found, as ``set_text`` does)."""
        done = len(self.blocks)
        with collector_paused():
            self.blocks += self.cache.get_many(self.lines[done : done + count])
        if self.partial:
            return False
        self._finish()
        return True

    def _finish(self) -> None:
        """Every line is parsed: find the program."""
        self._structural = [b.structural for b in self.blocks]
        self.program = build_program(self.blocks, self._structural)

    def block_at(self, line: int) -> Block:
        """The block of ``line`` (one of the document's), parsed on its own in a partial document."""
        if line < len(self.blocks):
            return self.blocks[line]
        return self.cache.get(self.lines[line])

    # ---- whole text
    def set_text(self, text: str) -> None:
        """Replace the whole text (a document opened, or a full-sync change)."""
        self.lines = split_lines(text)
        with collector_paused():
            self.blocks = self.cache.get_many(self.lines)
        self._structural = [b.structural for b in self.blocks]
        self.program = build_program(self.blocks, self._structural)

    @property
    def text(self) -> str:
        return "\n".join(self.lines)

    # ---- edits
    def replace_lines(self, start: int, end: int, new_lines: list[str]) -> None:
        """Replace lines ``start`` to ``end`` (exclusive) by ``new_lines``."""
        get = self.cache.get
        if self.partial:  # the lines parsed so far stay the first ones; the program comes at the end
            if start < len(self.blocks):
                self.blocks[start:end] = [get(line) for line in new_lines]
            self.lines[start:end] = new_lines
            if not self.partial:  # the edit took away the lines left to parse
                self._finish()
            return
        new_blocks = [get(line) for line in new_lines]
        old_blocks = self.blocks[start:end]
        self.lines[start:end] = new_lines
        self.blocks[start:end] = new_blocks
        self._structural[start:end] = [b.structural for b in new_blocks]
        if (
            len(new_blocks) == len(old_blocks)
            and all(o.structure_key() == b.structure_key() for o, b in zip(old_blocks, new_blocks, strict=True))
            and not first_mark_turned(self.program, start, 0)
        ):
            return  # the program (which holds self.blocks) is unchanged
        update_program(self.program, start, old_blocks, new_blocks)

    def apply_change(self, start_line: int, start_col: int, end_line: int, end_col: int, text: str) -> None:
        """Apply an editor change: the text between two positions (0-based line and column,
        in code points) becomes ``text``. Positions past the end are clamped."""
        n = len(self.lines)
        start_line = min(max(start_line, 0), n - 1)
        end_line = min(max(end_line, start_line), n - 1)
        first = self.lines[start_line]
        last = self.lines[end_line]
        start_col = min(max(start_col, 0), len(first))
        end_col = min(max(end_col, 0), len(last))
        if end_line == start_line:
            end_col = max(end_col, start_col)
        merged = first[:start_col] + text + last[end_col:]
        self.replace_lines(start_line, end_line + 1, split_lines(merged))
