"""What the first screen of a huge document earns by itself, before the document is analysed.

A document of a hundred thousand lines is parsed in steps in the editor; meanwhile the top of
the file, which the editor shows first, gets the findings each of its first
``FIRST_SCREEN_LINES`` lines earns by itself (syntax and the per-line static findings, the
user's severities applied), and so does each line edited before the first analysis ends. The
checks that connect lines (labels, loops, calls) and the runs need the whole document and come
with its analysis, which finds these again: nothing shown here is taken back by it.
"""

from __future__ import annotations

from collections.abc import Sequence

from ..bilingual import is_chinese
from ..syntax.document import ParsedDocument
from .checks import static_checks
from .checks.line_facts import LineContext
from .checks.static_lines import StaticLines
from .checks.syntax_check import syntax_findings
from .diagnostics import Diagnostic
from .indexes.block_memo import BlockMemo
from .severity import apply_severities

FIRST_SCREEN_LINES = 2_000  # the lines of a huge document checked first, before the whole


def first_screen_findings(path: str, lines: list[str], extra: Sequence[int], head: bool,
                          ctx: LineContext, memo: BlockMemo, locale: str,
                          severities: dict[str, str]) -> list[Diagnostic]:  # fmt: skip
    """What each of the first ``FIRST_SCREEN_LINES`` of ``lines`` (unless not ``head``), and
    each line of ``extra``, earns by itself, read with ``ctx``."""
    top = ParsedDocument("\n".join(lines[:FIRST_SCREEN_LINES]) if head else "")
    found: list[Diagnostic] = []
    if head:
        static = StaticLines(top.blocks, ctx, memo)
        found, _ = static.line_diagnostics(min(top.program.read_end, len(top.lines)), path, locale)
    chinese = is_chinese(locale)
    for line in extra:
        block = top.cache.get(lines[line])
        found.extend(syntax_findings(block.problems, line, path, chinese, ctx.dialect))
        facts = memo.facts(block, ctx)
        if facts is not None:
            found.extend(static_checks.findings_of(facts, line, path))
    return apply_severities(found, severities)
